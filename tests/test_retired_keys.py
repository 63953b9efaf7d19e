"""The keys older MOOS-IvP releases read that today's does not: how they are found, and
what the catalogue answers."""

from __future__ import annotations

import importlib.util
import os

from moos_lint.semantics.catalogue import stock

_SCRIPT = os.path.join(os.path.dirname(__file__), "..", "scripts", "retired_keys.py")


def _retired():
    spec = importlib.util.spec_from_file_location("retired_keys", _SCRIPT)
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(module)
    return module.retired


def test_keys_gone_since_an_older_tree_with_the_newest_that_read_them():
    today = {
        "apps": {"pMarineViewer": {"params": ["tiff_file"]}},
        "behaviors": {"BHV_AvoidObstacle": {"params": ["poly", "allowable_ttc"]}},
        "base_classes": {"CMOOSApp": {"params": ["apptick"]}},
        "behavior_extra_params": {"templating": ""},
    }
    old = {
        "apps": {
            "pMarineViewer": {"params": ["tiff_file", "time_warp", "AppTick"]},
            "pGone": {"params": ["x"]},  # gone altogether: not a retired key
        },
        "behaviors": {
            "BHV_AvoidObstacle": {"params": ["poly", "activation_dist", "templating"]},
        },
    }
    newer = {"apps": {"pMarineViewer": {"params": ["time_warp"]}}, "behaviors": {}}
    got = _retired()(today, [(old, "June 2015"), (newer, "August 2019")])
    assert got == {
        "apps": {"pMarineViewer": {"time_warp": "August 2019"}},
        "behaviors": {"BHV_AvoidObstacle": {"activation_dist": "June 2015"}},
    }


def test_the_shipped_catalogue_answers_in_any_case():
    cat = stock()
    assert cat.retired_key("behaviors", "bhv_avoidobstacle", "Activation_Dist") == "June 2015"
    assert cat.retired_key("behaviors", "BHV_AvoidObstacle", "poly") is None
    assert cat.retired_key("apps", "uFldNodeComms", "VERBOSE") == "August 2023"
    assert cat.copy().retired_key("apps", "uQueryDB", "max_time") == "January 2021"
    # a key the old app compared but no old mission set (a field of a value): left out
    assert cat.retired_key("apps", "uFldNodeBroker", "ip") is None


def test_only_keys_the_old_files_set(tmp_path):
    module_retired = _retired()
    spec = importlib.util.spec_from_file_location("retired_keys", _SCRIPT)
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(module)
    (tmp_path / "m.moos").write_text(
        "ProcessConfig = uFldNodeBroker\n{\n  shadow_shore = ip=1.2.3.4, name=x\n}\n"
    )
    (tmp_path / "v.bhv").write_text("Behavior = BHV_AvoidObstacle\n{\n  activation_dist = 20\n}\n")
    used = module.used_keys(str(tmp_path))
    assert used == {
        "apps": {"ufldnodebroker": {"shadow_shore"}},
        "behaviors": {"bhv_avoidobstacle": {"activation_dist"}},
    }
    today = {"apps": {"uFldNodeBroker": {"params": []}}, "behaviors": {}}
    old = {"apps": {"uFldNodeBroker": {"params": ["shadow_shore", "ip", "name"]}}}
    got = module_retired(today, [(old, "August 2022")], used)
    assert got == {"apps": {"uFldNodeBroker": {"shadow_shore": "August 2022"}}, "behaviors": {}}
