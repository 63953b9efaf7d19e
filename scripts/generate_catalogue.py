"""Generate the stock catalogue from the MOOS-IvP and MOOS core C++ sources.

Usage::

    python scripts/generate_catalogue.py SRC [-o moos_lint/semantics/catalogue/stock.json]
        [--commit SHA] [--repository URL]

``SRC`` is a work tree of https://github.com/moos-ivp/moos-ivp (which vendors
MOOS core in ``MOOS_Jul2724/``). Every app and behavior is read with
moos-lint's own C++ extractor (:mod:`moos_lint.frontends.cpp`): the configuration
parameters an app compares its config lines against, the variables it
``Notify``s and ``Register``s; for behaviors the parameters their
``setParam`` compares against (base classes included, ``IvPBehavior``'s
generic keys among them) and the variables they post.

What the extractor cannot see is added by hand in :data:`CORRECTIONS`; every
entry so changed lists the correction in its ``corrected`` field.
"""

from __future__ import annotations

import argparse
import dataclasses
import glob
import json
import os
import re
import subprocess
import sys
from collections.abc import Iterable
from typing import Any

from moos_lint.files.source import SourceFile, read_source
from moos_lint.files.suffixes import is_cpp, is_cpp_source
from moos_lint.frontends.cpp.app import build_apps
from moos_lint.frontends.cpp.model import AppModel
from moos_lint.semantics.catalogue import DELEGATE, OPTIONAL_BLOCK, READS_ORIGIN

_POST = re.compile(
    r"\bpost(?:Int|Bool|Repeatable|Event)?Message\s*\(\s*\"([A-Za-z0-9_]+)\"", re.MULTILINE
)
#: a literal name and a suffix the configuration may set, empty by default:
#: ``postMessage(("LOITER_MODE" + m_var_suffix), ...)`` posts LOITER_MODE (BHV_Loiter.cpp:554,
#: ``m_var_suffix`` set only by the ``var_suffix`` parameter, :208)
_POST_SUFFIXED = re.compile(
    r"\bpost(?:Int|Bool|Repeatable|Event)?Message\s*\(\s*\(\s*\"([A-Za-z0-9_]*[A-Za-z0-9])\"\s*"
    r"\+\s*m_\w*suffix\s*\)",
    re.MULTILINE,
)
#: a literal prefix and a run-time rest: ``postMessage(("RANGE_AVD_" + m_contact), ...)``
#: posts under ``RANGE_AVD_`` with the contact's name as given (BHV_AvoidCollision.cpp:522)
_POST_PREFIX = re.compile(
    r"\bpost(?:Int|Bool|Repeatable|Event)?Message\s*\(\s*\(?\s*\"([A-Z][A-Z0-9_]*_)\"\s*\+\s*(?!m_\w*suffix\b)",
    re.MULTILINE,
)
#: a VarDataPair an app builds from a literal name is one it posts: pMarineViewer's
#: connection posts and default mouse-click posts (PMV_MOOSApp.cpp:51-54, PMV_Viewer.cpp:92-93)
_PAIR = re.compile(r"\bVarDataPair\s+\w+\s*\(\s*\"([A-Za-z0-9_]+)\"")
_LINK = re.compile(r"TARGET_LINK_LIBRARIES\s*\(([^)]*)\)", re.IGNORECASE | re.DOTALL)
_NAME = re.compile(r"^[A-Za-z0-9_]+$")

_APPCAST = "MOOS_Jul2724/MOOSCore/Core/libMOOS/Thirdparty/AppCasting/AppCastingMOOSApp.cpp"

#: Parameters read by base classes (``CMOOSApp``, ``AppCastingMOOSApp``): every app accepts them.
BASE_PARAMS = {
    "CMOOSApp": {
        "params": [
            "apptick",
            "maxapptick",
            "iteratemode",
            "commstick",
            "sortmailbytime",
            "catchcommandmessages",
            "moos_time_warp",
            "moos_timewarp_delay_factor",
            "moos_timewarp_scale_factor",
            "moos_app_name",
            "moos_name",
            "moos_file",
            "moos_host",
            "moos_port",
            "moos_iterate_mode",
            "moos_quiet",
            "moos_configuration_audit",
            "moos_apptick",
            "moos_max_apptick",
            "moos_commstick",
        ],
        # the keys CMOOSApp reads from the block are added from MOOSApp.cpp itself
        # (:func:`base_params`): these are the switches it also takes on the command line
        "provenance": "MOOS_Jul2724/MOOSCore/Core/libMOOS/App/MOOSApp.cpp:548-591,1149 (by hand)",
        # GetConfigurationParam(double) takes only values starting with a digit or `-`
        "param_forms": {
            "apptick": {
                "form": "moos_double",
                "at": "MOOS_Jul2724/MOOSCore/Core/libMOOS/Utils/ProcessConfigReader.cpp:265",
            },
            "maxapptick": {
                "form": "moos_double",
                "at": "MOOS_Jul2724/MOOSCore/Core/libMOOS/Utils/ProcessConfigReader.cpp:265",
            },
            # GetConfigurationParam(int) takes any value, through atoi: `four` is 0 (and the
            # comms client then ticks at 1 Hz, MOOSCommClient.cpp:416-417)
            "commstick": {
                "form": "moos_int",
                "at": "MOOS_Jul2724/MOOSCore/Core/libMOOS/Utils/ProcessConfigReader.cpp:366-376",
            },
        },
    },
    "AppCastingMOOSApp": {
        "params": [
            "comms_policy",
            "app_logging",
            "deprecated_ok",
            "term_report_interval",
            "max_appcast_events",
            "max_appcast_run_warnings",
        ],
        "publishes": ["APPCAST", "APP_LOG"],
        "publish_suffixes": ["_ITER_GAP", "_ITER_LEN"],
        "subscribes": ["APPCAST_REQ", "LOADCAST_REQ", "TERM_REPORT_INTERVAL", "COMMS_POLICY"],
        "provenance": (
            "MOOS_Jul2724/MOOSCore/Core/libMOOS/Thirdparty/AppCasting/"
            "AppCastingMOOSApp.cpp:233-275,384-420,455-458 (by hand)"
        ),
        # preOnStartUp compares the lower-cased value with a fixed set and warns
        # "Invalid ..." for any other, keeping the default
        "param_forms": {
            "comms_policy": {"form": "enum:open|lean|dire", "at": _APPCAST + ":251-253"},
            "app_logging": {"form": "enum:true|log|file|off", "at": _APPCAST + ":259-265"},
            "deprecated_ok": {"form": "enum:true|false", "at": _APPCAST + ":268-274"},
        },
    },
}

#: Behavior parameters read outside the behavior classes.
BEHAVIOR_EXTRA_PARAMS = {
    "name": "ivp/src/lib_helmivp/BehaviorSet.cpp:399",
    "descriptor": "ivp/src/lib_helmivp/BehaviorSet.cpp:399",
    "templating": "ivp/src/lib_helmivp/BehaviorSpec.cpp:60-85",
    "max_spawnings": "ivp/src/lib_helmivp/BehaviorSpec.cpp:60-85",
}

#: IvPBehavior's parameters that set one member: a later line replaces an earlier one (the
#: helm hands a behavior's lines to setParam in order), with the lines that set them.
BEHAVIOR_SINGLE_PARAMS = {
    "pwt": "ivp/src/lib_behaviors/IvPBehavior.cpp:192-199",
    "priwt": "ivp/src/lib_behaviors/IvPBehavior.cpp:192-199",
    "priority": "ivp/src/lib_behaviors/IvPBehavior.cpp:192-199",
    "perpetual": "ivp/src/lib_behaviors/IvPBehavior.cpp:278-281",
    "duration": "ivp/src/lib_behaviors/IvPBehavior.cpp:285-295",
    "updates": "ivp/src/lib_behaviors/IvPBehavior.cpp:311-316",
}

#: The value forms of IvPBehavior's own parameters, which every behavior takes: the helm
#: hands each line to ``IvPBehavior::setParam`` first (BehaviorSet.cpp:399-405), and a
#: line it refuses, which no stock behavior's own setParam takes, fails the behavior.
_IVPBEHAVIOR = "ivp/src/lib_behaviors/IvPBehavior.cpp"
BEHAVIOR_GENERIC_FORMS = {
    **{
        key: {"form": "nonneg", "at": _IVPBEHAVIOR + ":192-199"}
        for key in ("pwt", "priwt", "priority")
    },
    "comms_policy": {"form": "enum:open|lean|dire", "at": _IVPBEHAVIOR + ":210-217"},
    "duration_idle_decay": {"form": "bool", "at": _IVPBEHAVIOR + ":231-234"},
    # any word but `true` (in any case) sets it false, without a warning
    "perpetual": {"form": "true_word", "at": _IVPBEHAVIOR + ":278-282"},
    "duration": {
        "form": "enum_or_nonneg:no-time-limit|-1",
        "at": _IVPBEHAVIOR + ":285-295",
        "same": [["no-time-limit", "-1"]],
    },
}

#: Hand corrections: app -> fields to add, and why.
CORRECTIONS: dict[str, dict] = {
    "pEchoVar": {
        "param_prefixes": ["flip"],
        "why": '`flip:N = ...` keys are matched with strncmp(param, "flip", 4) (EchoVar.cpp:143)',
    },
    "pMarineViewer": {
        "reports_unhandled": True,
        "why": "the final else hands other keys to PMV_Viewer::setParam, then "
        "MarineViewer::setParam and VPlug_GeoSettings::setParam, whose keys are all listed "
        "(PMV_MOOSApp.cpp, lib_marineview, lib_geometry): checked by hand",
    },
    "pShare": {
        "params": [
            "input",
            "output",
            "multicast_base_port",
            "multicast_address",
            "verbose",
            "share",
        ],
        "keys_complete": True,
        "why": "read with GetRepeatedConfigurations and "
        "GetParameterFromCommandLineOrConfigurationFile (Share.cpp:213-308); no other key "
        "is read, so the list is complete (`Share` lines: earlier pShare versions of "
        "themoos/essential-moos)",
    },
    "pLogger": {
        "params": ["log", "wildcardpattern", "wildcardomitpattern"],
        "keys_complete": True,
        "why": "`Log` lines are read from the whole block with GetConfiguration and "
        "`WildCardPattern`/`WildCardOmitPattern` with GetTokenValPair (MOOSLogger.cpp:340-428); "
        "every other key is a GetConfigurationParam call (MOOSLogger.cpp:230-389), so the "
        "list is complete",
    },
    "pNodeReporter": {
        "publishes": ["NODE_REPORT_LOCAL"],
        "why": "the node report variable defaults to NODE_REPORT_LOCAL (NodeReporter.cpp:714)",
    },
    "uFldNodeBroker": {
        "param_forms": {
            "bridge": {"form": "fields:src", "at": "ivp/src/uFldNodeBroker/NodeBroker.cpp:337-352"},
            "try_shore_host": {
                "form": "fields:pshare_route",
                "at": "ivp/src/uFldNodeBroker/NodeBroker.cpp:391-405",
            },
        },
        "why": "`bridge = src=VAR, alias=VAR2` is rejected without a `src=` field "
        "(handleConfigBridge); `try_shore_host = pshare_route=HOST:PORT` without a "
        "`pshare_route=` field (handleConfigTryShoreHost)",
    },
    "uFldShoreBroker": {
        "param_forms": {
            "bridge": {
                "form": "fields:src",
                "at": "ivp/src/uFldShoreBroker/ShoreBroker.cpp:592-614",
            }
        },
        "why": "`bridge = src=VAR, alias=VAR2` is rejected without a `src=` field "
        "(handleConfigBridge)",
    },
    # apps whose start-up loop sees every line of the block and ignores the keys it does
    # not compare (or reports them with reportConfigWarning, which the extractor does not
    # take for reportUnhandledConfigWarning): their key lists are complete
    "uFldContactRangeSensor": {
        "reports_unhandled": True,
        "why": 'every key the start-up loop does not match ends in reportConfigWarning("Unhandled '
        'config: " + line) (CRS_App_HP.cpp:123-166)',
    },
    "pXRelay": {
        "keys_complete": True,
        "why": "the start-up loop compares each line's key with incoming_var and outgoing_var "
        "and ignores the others (PXR_MOOSApp.cpp:141-156)",
    },
    "uTermCommand": {
        "keys_complete": True,
        "why": "the start-up loop compares each line's key with CMD and ignores the others "
        "(TermCommand.cpp:81-93)",
    },
    "uHelmScope": {
        "keys_complete": True,
        "why": "the start-up loop compares each line's key with PAUSED, DISPLAY_MOOS_SCOPE, "
        "DISPLAY_BHV_POSTS, DISPLAY_VIRGINS, TRUNCATED_OUTPUT, BEHAVIORS_CONCISE and VAR and "
        "ignores the others (HelmScope.cpp:234-257)",
    },
    "uFldScope": {
        "keys_complete": True,
        "why": "the start-up loops compare each line's key with SCOPE, then LAYOUT, and ignore "
        "the others (UFS_MOOSApp.cpp:95-122)",
    },
    "uPokeDB": {
        "keys_complete": True,
        "why": "the start-up loop handles poke and prints any other line as unhandled to the "
        "console only (PokeDB.cpp:252-270)",
    },
    "uMAC": {
        "keys_complete": True,
        "why": "the start-up loop still compares only the template's FOO (AppCastMonitor.cpp:"
        "177-187): uMAC reads no key of its own",
    },
    "pHelmIvP": {
        "publishes": ["DESIRED_HEADING", "DESIRED_SPEED", "DESIRED_DEPTH"],
        "why": "DESIRED_<DOMAIN> are named from the domain (HelmIvP.cpp:541-543); MODE and "
        "any other mode variable only as the behavior files' set blocks name them "
        "(ModeSet.cpp:53-91): the mission model reads those from the files",
    },
}

_SRC = "ivp/src/"


_MARINE = "ivp/src/lib_behaviors-marine/"

#: Hand corrections for behaviors: class -> value forms its ``setParam`` enforces, and why.
#: ``convex_polygon``, ``waypoints`` and ``point`` are judged by
#: :mod:`moos_lint.semantics.geometry_forms`.
#: ``enum:a|b`` values are compared lower-cased, as these ``setParam`` do.
BEHAVIOR_CORRECTIONS: dict[str, dict] = {
    "BHV_Waypoint": {
        "param_forms": {
            "capture_line": {
                "form": "enum:true|false|absolute",
                "at": "ivp/src/lib_behaviors-marine/BHV_Waypoint.cpp:437-440",
            },
            "efficiency_measure": {
                "form": "enum:all|off",
                "at": "ivp/src/lib_behaviors-marine/BHV_Waypoint.cpp:405-411",
            },
        },
        "why": "capture_line and efficiency_measure return false for a value outside a fixed "
        "set, compared after tolower",
    },
    "BHV_Loiter": {
        "param_forms": {
            "clockwise": {
                "form": "enum:best|true|false|on|off|yes|no|toggle",
                "at": "ivp/src/lib_behaviors-marine/BHV_Loiter.cpp:148-155",
            },
            "polygon": {"form": "convex_polygon", "at": _MARINE + "BHV_Loiter.cpp:98-103"},
        },
        "why": "clockwise takes `best` or a setBooleanOnString value, else returns false; "
        "polygon returns false unless string2Poly gives a convex polygon",
    },
    "BHV_OpRegion": {
        "param_forms": {
            "polygon": {"form": "convex_polygon", "at": _MARINE + "BHV_OpRegion.cpp:124-127"},
        },
        "why": "polygon returns false unless string2Poly gives a convex polygon",
    },
    "BHV_OpRegionRecover": {
        "param_forms": {
            "polygon": {
                "form": "convex_polygon",
                "at": _MARINE + "BHV_OpRegionRecover.cpp:108-111",
            },
        },
        "why": "polygon returns false unless string2Poly gives a convex polygon",
    },
    "BHV_AvoidObstacle": {
        "param_forms": {
            key: {
                "form": "convex_polygon",
                "at": "ivp/src/lib_dep_behaviors/BHV_AvoidObstacle.cpp:100-103",
            }
            for key in ("polygon", "points", "poly")
        },
        "why": "polygon, points and poly return false unless string2Poly gives a convex polygon",
    },
    "BHV_AbortToPoint": {
        "param_forms": {
            "point": {"form": "point", "at": _MARINE + "BHV_AbortToPoint.cpp:84-87"},
        },
        "why": "point returns false unless string2Point gives a valid point",
    },
    "BHV_StationKeep": {
        "param_forms": {
            key: {"form": "point", "at": _MARINE + "BHV_StationKeep.cpp:112-115"}
            for key in ("station_pt", "point")
        },
        "why": "station_pt and point return false unless string2Point gives a valid point",
    },
    "BHV_BearingLine": {
        "param_forms": {
            "bearing_point": {"form": "point", "at": _MARINE + "BHV_BearingLine.cpp:59-77"},
        },
        "why": "bearing_point returns false unless string2Point gives a valid point",
    },
    "BHV_LegRun": {
        "param_forms": {
            key: {
                "form": "point",
                "at": "ivp/src/lib_bhvutil/LegRun.cpp:117-124,203-207,217-221",
            }
            for key in ("p1", "p2", "vx1", "vx2")
        },
        "why": "p1, p2 (and the deprecated vx1, vx2) go to LegRun::setParam "
        "(BHV_LegRun.cpp:169), which returns false unless string2Point gives a valid point",
    },
    "BHV_HeadingBias": {
        "param_forms": {
            "bias": {"form": "enum:right|left", "at": _MARINE + "BHV_HeadingBias.cpp:51-63"},
        },
        "why": "bias returns false unless the lower-cased value is right or left",
    },
}
BEHAVIOR_CORRECTIONS["BHV_Timer"] = {
    "param_forms": {},
    # names the behavior posts under: a parameter's value (else its default), and the
    # value of ``post_suffix``'s parameter joined with `_`
    "post_params": {"var_status_idle": "TIMER_IDLE", "var_status_running": "TIMER_RUNNING"},
    "post_suffix": "status_suffix",
    "why": "posts m_var_status_idle + m_var_status_suffix and m_var_status_running + "
    "m_var_status_suffix; var_status_idle and var_status_running set the names (defaults "
    "TIMER_IDLE, TIMER_RUNNING), status_suffix the suffix, `_` put before it when missing "
    "(ivp/src/lib_behaviors-marine/BHV_Timer.cpp:36-38, 46-55, 68-72)",
}
BEHAVIOR_CORRECTIONS["BHV_Waypoint"]["param_forms"].update(
    {
        # `empty`/`start`, else string2SegList, else string2Poly; false when both are empty
        **{
            key: {"form": "waypoints", "at": _MARINE + "BHV_Waypoint.cpp:196-208"}
            for key in ("polygon", "points", "xpoints")
        },
        "point": {"form": "point|start|empty", "at": _MARINE + "BHV_Waypoint.cpp:239-250"},
        "newpt": {"form": "point", "at": _MARINE + "BHV_Waypoint.cpp:259-262"},
        # `forever` (any case) in one branch, a whole number 0 or more in another: each
        # sets whether the points repeat endlessly, the last line naming it wins
        "repeat": {"form": "enum_or_uint:forever", "at": _MARINE + "BHV_Waypoint.cpp:400-423"},
    }
)
BEHAVIOR_CORRECTIONS["BHV_Waypoint"]["why"] += (
    "; polygon, points and xpoints return false when neither string2SegList nor string2Poly "
    "reads a vertex, point and newpt when string2Point gives no valid point; repeat takes "
    "`forever` (compared lower-cased) or a number that isNumber and atoi find 0 or more"
)


_NAV = [
    "NAV_X",
    "NAV_Y",
    "NAV_LAT",
    "NAV_LONG",
    "NAV_HEADING",
    "NAV_SPEED",
    "NAV_DEPTH",
    "NAV_Z",
    "NAV_PITCH",
    "NAV_YAW",
    "NAV_HEADING_OVER_GROUND",
    "NAV_SPEED_OVER_GROUND",
    "NAV_ALTITUDE",
]
for _sim in ("uSimMarine", "uSimMarineV22", "uSimMarineV23"):
    CORRECTIONS[_sim] = {
        "publishes": _NAV,
        "why": 'NAV_* are posted as prefix + "_X" with the prefix NAV by default '
        "(uSimMarineV22/USM_MOOSApp.cpp:600-648)",
    }


_USM_ENUMS = {
    # key -> (form, USM_MOOSApp.cpp line V22, V23, USM_Model.cpp lines V22, V23)
    "thrust_mode_diff": ("enum:differential|true|normal|false", 377, 354, "200-211", "199-210"),
    "thrust_mode_reverse": ("enum:reverse|true|normal|false", 379, 356, "217-228", "216-227"),
    "thrust_reflect": ("enum:true|false", 375, 352, "600-610", "601-611"),
}
for _sim, _col in (("uSimMarineV22", 1), ("uSimMarineV23", 2)):
    CORRECTIONS[_sim]["param_forms"] = {
        key: {
            "form": f[0],
            "at": f"ivp/src/{_sim}/USM_MOOSApp.cpp:{f[_col]}; USM_Model.cpp:{f[_col + 2]}",
        }
        for key, f in _USM_ENUMS.items()
    }
    CORRECTIONS[_sim]["why"] += (
        "; thrust_mode_diff, thrust_mode_reverse and thrust_reflect go to USM_Model setters "
        "that return false, keeping the default, for a value outside a fixed set"
    )

_BRS = "ivp/src/uFldBeaconRangeSensor/BRS_App.cpp:"
CORRECTIONS["uFldBeaconRangeSensor"] = {
    "param_forms": {
        "report_vars": {"form": "enum:both|short|long", "at": _BRS + "156-157,662-671"},
        "ping_payments": {
            "form": "enum:upon_response|upon_request|upon_accept",
            "at": _BRS + "154-155,646-657",
        },
        "ground_truth": {"form": "bool", "at": _BRS + "164-165"},
        "verbose": {"form": "bool", "at": _BRS + "166-167"},
    },
    "why": "OnStartUp records `handled[param] = setter(value)` and reports unhandled lines; "
    "report_vars and ping_payments take a fixed set (lower-cased), ground_truth and verbose "
    "setBooleanOnString",
}

CORRECTIONS["pObstacleMgr"] = {
    "param_forms": {
        key: {
            "form": "convex_polygon",
            "at": "ivp/src/pObstacleMgr/ObstacleManager.cpp:202-203,489-491",
        }
        for key in ("given_obstacle", "given_obstable")
    },
    "why": "given_obstacle is rejected (unhandled) unless string2Poly gives a convex polygon",
}

CORRECTIONS["uTimerScript"] = {
    "param_forms": {
        "event": {"form": "timer_event", "at": "ivp/src/uTimerScript/TS_MOOSApp.cpp:496-573"},
    },
    "why": "addNewEvent drops an event without var= or val= and warns about any field but "
    "var, val, time, amt and quit, skipping it (a misspelt time= posts the event at 0)",
}


def _fact(app: str, key: str, why: str) -> None:
    """One more hand fact (a boolean set true, unless ``key`` says otherwise) for ``app``."""
    value = not key.startswith("!")
    entry = CORRECTIONS.setdefault(app, {})
    entry[key.lstrip("!")] = value
    entry["why"] = f"{entry['why']}; {why}" if entry.get("why") else why


# Apps that run as intended without a ProcessConfig block although the extractor cannot
# tell (they do not declare ``must_have_moosblock=false``).
_fact(
    "uMAC",
    "!needs_process_config",
    "reads its block only when there is one (ivp/src/uMAC/AppCastMonitor.cpp:177)",
)
_fact(
    "pLogger",
    "!needs_process_config",
    "without a block it warns 'unusual but not terminal' and logs every variable "
    "(wildcard logging) (MOOS_Jul2724/MOOSEssentials/Essentials/pLogger/MOOSLogger.cpp:"
    "363, 393)",
)
_fact(
    "uFunctionVis",
    "!needs_process_config",
    "a plain CMOOSApp whose start-up reads no configuration "
    "(ivp/src/uFunctionVis/FV_MOOSApp.cpp:155-159)",
)
_fact(
    "uPokeDB",
    "!needs_process_config",
    "ignores a missing block: what it pokes comes from the command line "
    "(ivp/src/uPokeDB/PokeDB.cpp:252, PokeDB_Info.cpp:55)",
)
# Tools users start by hand with the mission file: their block is read although no
# Run line launches them. Evidence: the usage line of each.
for _app, _usage in (
    ("uXMS", "uXMS/XMS_Info.cpp:55"),
    ("uMAC", "uMAC/AppCastMonitor_Info.cpp:59"),
    ("uMACView", "uMACView/UMV_Info.cpp:54"),
    ("uPokeDB", "uPokeDB/PokeDB_Info.cpp:55"),
    ("uQueryDB", "uQueryDB/QueryDB_Info.cpp:60"),
    ("uMayFinish", "uMayFinish/MayFinish_Info.cpp:38"),
    ("uTermCommand", "uTermCommand/TermCommand_Info.cpp:51"),
    ("uHelmScope", "uHelmScope/HelmScope_Info.cpp:52"),
    ("uCommand", "uCommand/UCMD_Info.cpp:49"),
):
    _fact(_app, "launched_manually", f"started by hand: `{_app} file.moos` ({_SRC}{_usage})")
# Observers: they register for whatever they are told to show or log, so what they
# subscribe to is not read by a consumer, and their dynamic subscriptions are no reader.
for _app, _at in (
    ("uXMS", "ivp/src/uXMS/XMS.cpp:185,832"),
    ("uMAC", "ivp/src/uMAC/AppCastMonitor.cpp:202"),
    ("uMACView", "ivp/src/uMACView/UMV_MOOSApp.cpp:151-154,293 (appcasts, watch clusters)"),
    ("uHelmScope", "ivp/src/uHelmScope/HelmScope.cpp:483,524"),
    ("pMarineViewer", "ivp/src/pMarineViewer/PMV_MOOSApp.cpp:262-291"),
    ("pRealm", "ivp/src/pRealm/Realm.cpp:184-262"),
    ("uFldScope", "ivp/src/uFldScope/UFS_MOOSApp.cpp:138"),
    ("pLogger", "MOOS_Jul2724/MOOSEssentials/Essentials/pLogger/MOOSLogger.cpp:224-439"),
):
    _fact(_app, "observer", f"an observer: registers for what it is told to show or log ({_at})")
# Apps whose run-time subscriptions are the variables their configuration names, which
# moos_lint.semantics.variables reads from their blocks: not open-ended.
for _app, _at in (
    ("pHelmIvP", "pHelmIvP/HelmIvP.cpp:1186 (the behaviors' variables)"),
    ("pShare", "MOOS_Jul2724/MOOSEssentials/Essentials/pShare/Share.cpp:757 (output routes)"),
    ("uFldNodeBroker", "uFldNodeBroker/NodeBroker.cpp:337-352 (bridge src)"),
    ("uFldShoreBroker", "uFldShoreBroker/ShoreBroker.cpp:592-645 (bridge src, qbridge)"),
    ("uTimerScript", "uTimerScript/TS_MOOSApp.cpp:470-471 (condition, forward_var, pause_var)"),
    ("pEchoVar", "pEchoVar/EchoVar.cpp:194-197 (echo sources, conditions)"),
    ("pNodeReporter", "pNodeReporter/NodeReporter.cpp:297-313 (NAV_*, riders)"),
    ("uProcessWatch", "uProcessWatch/ProcessWatch.cpp:611 (<PROC>_STATUS of watched apps)"),
    ("pContactMgrV20", "pContactMgrV20/ContactMgrV20.cpp:357-361 (disable_var, enable_var)"),
    ("pBasicContactMgr", "dep_pBasicContactMgr/BasicContactMgr.cpp:404-406 (alerts)"),
    ("pDeadManPost", "pDeadManPost/DeadManPost.cpp:183 (heartbeat_var)"),
    ("pObstacleMgr", "pObstacleMgr/ObstacleManager.cpp:283-297 (point_var)"),
    ("pXRelay", "pXRelay/PXR_MOOSApp.cpp:84 (incoming_var)"),
    ("uFldCollisionDetect", "uFldCollisionDetect/CollisionDetector.cpp:420 (condition)"),
    ("uQueryDB", "uQueryDB/QueryDB.cpp:265-272 (conditions)"),
    ("uPlotViewer", "uPlotViewer/UPV_MOOSApp.cpp:123 (plot_var)"),
    ("pMissionEval", "pMissionEval/MissionEval.cpp:306-313 (lead/pass/fail conditions)"),
):
    where = _at if _at.startswith("MOOS_") else _SRC + _at
    _fact(_app, "subscriptions_from_config", f"subscribes to what its block names ({where})")

# Dynamic subscriptions that are no reader of the mission's variables.
_fact(
    "uMemWatch",
    "!subscribes_dynamic",
    "its only run-time subscriptions are <CLIENT>_PID, the process id each DB client "
    "posts (ivp/src/uMemWatch/MemWatch.cpp:148-158)",
)

#: programs pAntler launches that are not configured by a ProcessConfig block of their own
PROGRAMS: dict[str, dict] = {
    "MOOSDB": {
        "needs_process_config": False,
        "why": "reads the top-of-file settings only "
        "(MOOS_Jul2724/MOOSCore/Core/libMOOS/DB/MOOSDB.cpp:278-320)",
        # its own variables, kept up to date by the database itself (MOOSDB.cpp: DB_TIME
        # and DB_UPTIME in OnStartUp and DoVarUpdates, DB_CLIENTS on each connection,
        # DB_EVENT, DB_QOS, DB_RWSUMMARY and DB_VARSUMMARY in their summaries)
        "publishes": [
            "DB_CLIENTS",
            "DB_EVENT",
            "DB_QOS",
            "DB_RWSUMMARY",
            "DB_TIME",
            "DB_UPTIME",
            "DB_VARSUMMARY",
        ],
    },
    "pAntler": {
        "needs_process_config": False,
        "why": "reads the ANTLER block, under the name ANTLER "
        "(MOOS_Jul2724/MOOSEssentials/Essentials/pAntler/Antler.cpp:379-383)",
    },
    "uMS": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "the MOOS scope GUI, started by hand; it asks for the server to watch "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uMS/uMS.cpp:139)",
        # its poke dialog posts a variable of any name the user types
        "posts_any": "what its user pokes (the MOOS scope's poke dialog, "
        "MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uMS/ScopeGrid.cpp:257-285)",
    },
    "uPlayback": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "the alog playback GUI, started by hand: its main only opens the window, and it "
        "reads no mission file "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uPlayBack/uPlayBackMain.cpp:45-55)",
        "posts_any": "the variables of the log it replays "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uPlayBack/PlaybackWindow.cpp:505-516)",
    },
    "uIndexedPlayback": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "the indexed alog playback GUI, started by hand: its main only opens the "
        "window, and it reads no mission file "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uIndexedPlayBack/uPlayBackMain.cpp:45-54)",
        "posts_any": "the variables of the log it replays "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Graphical/uIndexedPlayBack/PlaybackWindow.cpp:523-534)",
    },
    "iMatlab": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "core MOOS's MATLAB mex file, started from MATLAB with the mission file, "
        "`iMatlab('init','CONFIG_FILE',file)`, never by Antler: it reads the block named by "
        "its MOOSNAME parameter, iMatlab by default "
        "(MOOS_Jul2724/MOOSMatlab/iMatlab/iMatlab.cpp:352-385)",
    },
    "iRemote": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "core MOOS's keyboard remote control, started by hand in a terminal with the "
        "mission file (`iRemoteLite mission.moos`): it runs as iRemote and reads its keys "
        "with MOOSGetch "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Console/iRemoteLite/iRemoteLiteMain.cpp:42-52, "
        "MOOSRemoteLite.cpp:232)",
    },
    "uPoke": {
        "needs_process_config": False,
        "launched_manually": True,
        "why": "pokes one variable given on its command line (server, port, name, value), and "
        "reads no mission file "
        "(MOOS_Jul2724/MOOSToolsUI/Tools/Console/uPoke/main.cpp:60-97)",
    },
}

#: apps the extractor does not see as apps (no CMOOSApp class), described by hand
EXTRA_APPS: dict[str, dict] = {
    "pMOOSBridge": {
        "source": "MOOS_Jul2724/MOOSEssentials/Essentials/pMOOSBridge",
        "base": "",
        "params": ["share", "udpshare", "loopback", "bridgefrequency", "udplisten"],
        "params_from_libraries": {},
        "param_forms": {},
        "reports_unhandled": False,
        "delegates_other_keys": False,
        "publishes": [],
        "publish_prefixes": [],
        "publish_suffixes": [],
        "publishes_dynamic": True,
        "subscribes": [],
        "subscribe_prefixes": [],
        "subscribes_dynamic": True,
        "needs_process_config": True,
        "needs_origin": False,
        "corrected": [
            "CMOOSBridge is not a CMOOSApp: keys read by hand from MOOSBridge.cpp:205-401"
        ],
    },
}


#: a key CMOOSApp reads from its block: ``GetConfigurationParam("APPTICK", ...)``, and the
#: switches it reads from the command line or else the block
#: (``GetParameterFromCommandLineOrConfigurationFile("moos_suicide_phrase", ...)``,
#: MOOSApp.hxx: ``m_MissionReader.GetConfigurationParam(sOption, vF)`` first)
_BASE_READ = re.compile(
    r"\b(?:m_MissionReader\s*\.\s*GetConfigurationParam"
    r"|Get(?:Parameter|Flag)FromCommandLineOrConfigurationFile)\s*\(\s*\"(\w+)\""
)
MOOS_APP = "MOOSCore/Core/libMOOS/App/MOOSApp.cpp"


def base_params(src: str, moos: str) -> dict:
    """:data:`BASE_PARAMS`, with every key ``MOOSApp.cpp`` reads from an app's block (the
    ``moos_suicide_*`` switches among them), each with the line it is read at."""
    out = json.loads(json.dumps(BASE_PARAMS))
    path = os.path.join(moos, *MOOS_APP.split("/"))
    text = _read(path)
    if not text:
        return out
    app = out["CMOOSApp"]
    lines: list[int] = []
    for m in _BASE_READ.finditer(text):
        key = m.group(1).lower()
        lines.append(text.count("\n", 0, m.start()) + 1)
        if key not in app["params"]:
            app["params"].append(key)
    if lines:
        spans = ",".join(str(n) for n in sorted(set(lines)))
        app["provenance"] = f"{_rel(path, src)}:{spans} (every key read from the block)"
    return out


def _git_commit(src: str) -> tuple[str, str]:
    try:
        out = subprocess.run(
            ["git", "-C", src, "log", "-1", "--format=%H %cs"],
            capture_output=True,
            text=True,
            timeout=20,
            check=False,
        ).stdout.split()
    except OSError:
        return "", ""
    return (out[0], out[1]) if len(out) == 2 else ("", "")


def _cpp_files(folder: str) -> list[str]:
    out: list[str] = []
    for dirpath, _dirs, files in os.walk(folder):
        out.extend(os.path.join(dirpath, f) for f in files if is_cpp(f))
    return sorted(out)


def _linked_libs(folder: str) -> list[str]:
    path = os.path.join(folder, "CMakeLists.txt")
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
    except OSError:
        return []
    libs: list[str] = []
    for m in _LINK.finditer(text):
        libs.extend(t for t in m.group(1).split() if _NAME.match(t))
    return libs


#: ``m_var_index = "WPT_INDEX";``: a variable a behavior posts under a default name
_VAR_DEFAULT = re.compile(r"\b(m_\w*var\w*)\s*=\s*\"([A-Z][A-Z0-9_]*)\"\s*;")
_INFO_VARS = re.compile(r"addInfoVars\(\s*\"([^\"]+)\"")
#: a behavior's constructor setting its duration to a number other than IvPBehavior's -1
#: (``m_duration = 0;``: BHV_ConstantSpeed times out at once unless given a duration)
_DURATION_DEFAULT = re.compile(r"^\s*m_duration\s*=\s*(-?[\d.]+)\s*;", re.MULTILINE)
#: a behavior that stops the helm when the helm's domain lacks a variable it decides:
#: ``if(!m_domain.hasDomain("depth")) { postEMessage(...); return(0); }`` in its
#: onRunState (BHV_ConstantDepth.cpp). postEMessage posts BHV_ERROR and marks the behavior's
#: state not ok (IvPBehavior.cpp), and the helm engine then halts the helm
#: (HelmEngine.cpp: ``if(!m_bhv_set->stateOK(bhv_ix)) m_helm_report.setHalted(true)``)
_DOMAIN_NEEDED = re.compile(
    r"if\s*\(\s*!\s*m_domain\.hasDomain\(\s*\"(\w+)\"\s*\)\s*\)\s*\{?\s*postEMessage\("
)
#: a behavior that ends by itself (not only when its duration runs out): it calls
#: IvPBehavior's ``setComplete()``, which posts the endflags (IvPBehavior.cpp), or posts
#: its endflags itself (BHV_LegRun: ``postFlags(m_end_flags)``)
_COMPLETES = re.compile(r"\bsetComplete\s*\(|\bpostFlags\s*\(\s*(?:\"endflags\"|m_end_flags\b)")
_DELEGATE_MEMBER = re.compile(r"\b(m_\w+)\s*(?:\.|->)\s*setParam\s*\(\s*param\b")
_TAIL = re.compile(r"\+\s*\"([A-Z0-9_]+)\"\s*\)?$")


def _names(items: Iterable) -> tuple[list[str], list[str], list[str], bool]:
    """Static names, known prefixes and suffixes of dynamic names, and whether any is unknown."""
    static, prefixes, suffixes, dynamic = set(), set(), set(), False
    for it in items:
        n = it.name
        if n.text is not None:
            static.add(n.text)
        elif n.prefix:
            prefixes.add(n.prefix)
        else:
            m = _TAIL.search(n.source.strip())
            if m and m.group(1).startswith("_"):
                suffixes.add(m.group(1))
            else:
                dynamic = True
    return sorted(static), sorted(prefixes), sorted(suffixes), dynamic


def _rel(path: str, src: str) -> str:
    return os.path.relpath(path, src).replace(os.sep, "/")


def _read(path: str) -> str:
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            return fh.read()
    except OSError:
        return ""


def _moos_core(src: str) -> str:
    """The core MOOS folder of a moos-ivp tree: where its ``MOOS`` link points (``MOOS_Jul2724``
    today, ``MOOS_Jul0519`` in 2019), else the newest ``MOOS_*`` folder."""
    link = os.path.join(src, "MOOS")
    if os.path.isdir(link):
        return os.path.realpath(link)
    found = sorted(glob.glob(os.path.join(src, "MOOS_*")))
    return found[-1] if found else os.path.join(src, "MOOS_Jul2724")


def generate(src: str, commit: str = "", repository: str = "", strict: bool = True) -> dict:
    """The catalogue of the moos-ivp tree ``src``. ``strict``: a correction or extra fact for
    an app the tree does not have is an error (for the tree the catalogue is made from; an
    older release read for its retired keys lacks some of today's apps)."""
    src = os.path.abspath(src)
    sha, date = _git_commit(src)
    commit = commit or sha
    ivp = os.path.join(src, "ivp", "src")
    moos = _moos_core(src)
    core = [
        os.path.join(moos, "MOOSEssentials", "Essentials"),
        os.path.join(moos, "MOOSCore", "Core", "MOOSDB"),
    ]
    folders = sorted(
        os.path.join(ivp, d) for d in os.listdir(ivp) if os.path.isdir(os.path.join(ivp, d))
    )
    for core_dir in core:
        if os.path.isdir(core_dir):
            if os.path.exists(os.path.join(core_dir, "CMakeLists.txt")) and core_dir.endswith(
                "MOOSDB"
            ):
                folders.append(core_dir)
            else:
                folders.extend(
                    os.path.join(core_dir, d)
                    for d in sorted(os.listdir(core_dir))
                    if os.path.isdir(os.path.join(core_dir, d))
                )
    files: list[str] = []
    for f in folders:
        files.extend(_cpp_files(f))
    # every file, not only those that mention the MOOS API: parsers of
    # configuration often live in GUI, settings and behavior classes
    sources = {}
    for path in files:
        got = read_source(path)
        if isinstance(got, SourceFile):
            sources[path] = got
    # every source the tree holds, built by this release's CMake or not: a file one
    # release leaves out (lib_marineview/VehicleSet.cpp) another may build, and a key
    # the catalogue knows is never reported as unread
    models = build_apps(sources, strays=True)
    top = set(folders)
    by_folder = {m.folder: m for m in models}
    # library folders by CMake target name (lib_marine_pid -> marine_pid)
    lib_folder = {
        os.path.basename(f)[4:]: f for f in folders if os.path.basename(f).startswith("lib_")
    }

    # every class, for behaviors' base chains
    class_params: dict[str, set[str]] = {}
    class_forms: dict[str, dict[str, dict[str, str]]] = {}
    class_bases: dict[str, list[str]] = {}
    class_file: dict[str, str] = {}
    for m in models:
        for cf in m.files:
            for c in cf.classes:
                class_bases.setdefault(c.name, []).extend(c.bases)
                if is_cpp_source(cf.path) or c.name not in class_file:
                    class_file.setdefault(c.name, cf.path)
    for m in models:
        for cf in m.files:
            if not is_cpp_source(cf.path):
                continue
            stem = os.path.splitext(os.path.basename(cf.path))[0]
            class_params.setdefault(stem, set()).update(_keys(cf))
            class_forms.setdefault(stem, {}).update(_forms(cf, src))
            if stem in class_file:
                class_file[stem] = cf.path

    apps: dict[str, dict] = {}
    for m in models:
        if not m.is_app or not m.process_name or m.folder not in top:
            continue
        if m.process_name_source == "folder" and not any(f.has_main for f in m.files):
            continue
        apps[m.process_name] = _app_entry(m, src, by_folder, lib_folder)
    for name, entry in EXTRA_APPS.items():
        apps.setdefault(name, dict(entry))
    for name, corr in CORRECTIONS.items():
        if name not in apps:
            if not strict:
                continue
            raise SystemExit(f"a correction names an app the sources do not have: {name}")
        if name in apps:
            entry = apps[name]
            for key, vals in corr.items():
                if key == "why":
                    continue
                if isinstance(vals, bool):
                    entry[key] = vals
                elif isinstance(vals, dict):
                    entry[key] = {**entry.get(key, {}), **vals}
                else:
                    entry[key] = sorted(set(entry.get(key, [])) | set(vals))
            entry.setdefault("corrected", []).append(corr["why"])

    behaviors: dict[str, dict] = {}
    class_forms["IvPBehavior"] = {**class_forms.get("IvPBehavior", {}), **BEHAVIOR_GENERIC_FORMS}
    for cls, path in sorted(class_file.items()):
        if not cls.startswith("BHV_"):
            continue
        chain = _bhv_chain(cls, class_bases)
        if not chain:
            continue
        params: set[str] = set()
        forms: dict[str, dict[str, str]] = {}
        for base in reversed(chain):
            params |= class_params.get(base, set())
            forms.update(class_forms.get(base, {}))
        text = _read(path)
        header = _read(os.path.splitext(path)[0] + ".h")
        delegated = []
        for member in sorted(set(_DELEGATE_MEMBER.findall(text))):
            m_type = re.search(r"(\w+)\s*\*?\s*\b" + re.escape(member) + r"\s*;", header)
            if m_type and m_type.group(1) in class_params:
                params |= class_params[m_type.group(1)]
                delegated.append(m_type.group(1))
        posts = set(_POST.findall(text)) | set(_POST_SUFFIXED.findall(text))
        post_prefixes = set(_POST_PREFIX.findall(text))
        reads: set[str] = set()
        for lit in _INFO_VARS.findall(text):
            reads.update(v.strip() for v in lit.split(",") if _NAME.match(v.strip()))
        for member, var in _VAR_DEFAULT.findall(text):
            # ``addInfoVars(m_mark_variable)``: a name the behavior reads, else one it posts
            if re.search(r"addInfoVars\(\s*" + re.escape(member) + r"\b", text):
                reads.add(var)
            else:
                posts.add(var)
        entry = {
            "source": _rel(path, src),
            "bases": chain[1:],
            "params": sorted(p for p in params if _param_like(p)),
            "posts": sorted(posts),
            "post_prefixes": sorted(post_prefixes),
            "reads": sorted(reads),
            "params_from_members": delegated,
            "param_forms": dict(sorted(forms.items())),
        }
        dur = _DURATION_DEFAULT.search(text)
        if dur is not None and float(dur.group(1)) != -1:
            line = text.count("\n", 0, dur.start(1)) + 1
            at = f"{_rel(path, src)}:{line}"
            entry["defaults"] = {"duration": {"value": dur.group(1), "at": at}}
        completes = _completes(chain, class_file, src)
        if completes is not None:
            entry["completes"] = completes
        needed = {}
        for m in _DOMAIN_NEEDED.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            needed.setdefault(m.group(1), f"{_rel(path, src)}:{line}")
        if needed:
            entry["domains"] = dict(sorted(needed.items()))
        bhv_corr = BEHAVIOR_CORRECTIONS.get(cls)
        if bhv_corr:
            entry["param_forms"] = dict(sorted({**forms, **bhv_corr["param_forms"]}.items()))
            for key in ("post_params", "post_suffix"):
                if key in bhv_corr:
                    entry[key] = bhv_corr[key]
            entry["corrected"] = [bhv_corr["why"]]
        behaviors[cls] = entry
    return {
        "source": {
            "repository": repository or "https://github.com/moos-ivp/moos-ivp",
            "commit": commit,
            "date": date,
            "generator": "python scripts/generate_catalogue.py SRC",
            "extractor": "moos_lint.frontends.cpp (tree-sitter)",
        },
        "base_classes": base_params(src, moos),
        "behavior_extra_params": BEHAVIOR_EXTRA_PARAMS,
        "behavior_single_params": BEHAVIOR_SINGLE_PARAMS,
        "apps": dict(sorted(apps.items(), key=lambda kv: kv[0].lower())),
        "programs": PROGRAMS,
        "behaviors": behaviors,
        "editor_behaviors": editor_behaviors(src, set(behaviors)),
        "executables": executables(src),
        "background_images": background_images(src),
    }


def background_images(src: str) -> dict[str, dict[str, object]]:
    """The background images MOOS-IvP ships for pMarineViewer's ``tiff_file`` (``ivp/data``)
    whose ``.info`` file places them on the earth: the image's file name -> its edges and
    the ``.info`` file they come from (read as :func:`image_box` reads one)."""
    from moos_lint.semantics.background_images import image_box

    data = os.path.join(src, "ivp", "data")
    out: dict[str, dict[str, object]] = {}
    names = sorted(os.listdir(data)) if os.path.isdir(data) else []
    for name in names:
        if not name.endswith(".info"):
            continue
        box = image_box(_read(os.path.join(data, name)), f"ivp/data/{name}")
        if box is not None:
            out[name[: -len(".info")] + ".tif"] = dataclasses.asdict(box)
    return out


def executables(src: str) -> list[str]:
    """Every program the tree's CMakeLists.txt files build (``add_executable``, names
    resolved through ``set()`` as the C++ front end reads them): the names a Run line may
    start, MOOS-IvP's and the core MOOS it ships, in their own case."""
    from moos_lint.frontends.cpp.cmake import executables_in

    names: set[str] = set()
    for here, dirs, files in os.walk(src):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "build")
        if "CMakeLists.txt" in files:
            names.update(executables_in(here))
    return sorted((n for n in names if re.fullmatch(r"[A-Za-z][\w.-]*", n)), key=str.lower)


#: a behavior's entry in MOOS-IvP's Emacs mode: ``'("BHV_Name" "param" ...)``
_EL_ENTRY = re.compile(r"'\(\s*\"(BHV_\w+)\"")
EDITOR_BEHAVIORS = "editor-modes/moos-bhvs.el"


def editor_behaviors(src: str, stock: set[str]) -> dict[str, dict]:
    """The behavior kinds MOOS-IvP's editor mode (``editor-modes/moos-bhvs.el``) lists that
    the tree does not build: behaviors of MIT's other public trees (moos-ivp-swarm,
    moos-ivp-pavlab: ``BHV_TaskMuster``, ``BHV_ConvoyV21``, ...) that missions load through
    ``IVP_BEHAVIOR_DIRS``. Only their kinds are kept: the editor's keyword lists are for
    completion, not a complete parameter list to judge a behavior by."""
    text = _read(os.path.join(src, EDITOR_BEHAVIORS))
    out: dict[str, dict] = {}
    for name in _EL_ENTRY.findall(text):
        if name not in stock:
            out.setdefault(name, {"source": EDITOR_BEHAVIORS})
    return dict(sorted(out.items()))


_LINES: dict[str, list[str]] = {}
_SUBJECT = re.compile(r"(\w+)\s*(?:[=!]=\s*|,\s*)$")


def _line(path: str, n: int) -> str:
    if path not in _LINES:
        _LINES[path] = _read(path).splitlines()
    lines = _LINES[path]
    return lines[n - 1] if 0 < n <= len(lines) else ""


def _key_sites(cf) -> list[tuple[str, int]]:
    """The configuration keys of one file and their lines: literals compared with a key."""
    out = []
    for p in cf.config_params:
        before = _line(cf.path, p.span.line)[: max(p.span.col - 1, 0)]
        m = _SUBJECT.search(before)
        if m and "val" in m.group(1).lower():
            continue  # ``param_val == "true"``: a value, not a key
        out.append((p.text, p.span.line))
    return out


def _keys(cf) -> set[str]:
    return {k for k, _ in _key_sites(cf)}


#: MBUtils setters (ivp/src/lib_mbutil/MBUtils.cpp) -> the value form they accept
SETTER_FORMS = {
    "setBooleanOnString": "bool",
    "setDoubleOnString": "number",
    "setNonNegDoubleOnString": "nonneg",
    "setPosDoubleOnString": "positive",
    "setUIntOnString": "uint",
    "setPosUIntOnString": "posuint",
    "setIntOnString": "int",
}
_SETTER = re.compile(r"\b(" + "|".join(SETTER_FORMS) + r")\s*\(")
_LEAD = re.compile(r"\s*\{?\s*(?:\w+\s*=\s*|return\s*\(?\s*|ok\s*=\s*\w+\s*&&\s*)?")
#: ``setX(member, value)``: the whole value goes to the setter
_SETTER_CALL = re.compile(r"\w+\s*\(\s*[\w.>-]+\s*,\s*\w+\s*(?:,\s*\w+\s*)?\)")
_NEXT_KEY = re.compile(r"(?:param|key|config)\w*\s*==\s*\"", re.IGNORECASE)


#: ``isNumber(value) && (dval >= 0)`` written into the key's own condition or the first
#: statement of its branch: any other value leaves the key unhandled
_INLINE = re.compile(
    r"^\W*(?:if\s*\(\s*)?isNumber\s*\(\s*\w+\s*\)\s*\)?"
    r"(?:\s*&&\s*\(?\s*\w+\s*(>=|>)\s*0(?:\.0*)?\s*\)?)?"
)


#: ``m_desired_depth = vclip_min(dval, 0);`` (MBUtils: vclip, vclip_min, vclip_max)
_CLIP = re.compile(
    r"^\s*[\w.>-]+\s*=\s*vclip(_min|_max)?\s*\(\s*\w+\s*,\s*(-?[\d.]+)\s*"
    r"(?:,\s*(-?[\d.]+)\s*)?\)\s*;"
)


def _clipped(lines: list[str], n: int) -> str | None:
    """``clip:LO,HI`` (a bound empty when there is none) for a key whose branch, checked a
    number inline, keeps it clipped to bounds: ``m_desired_depth = vclip_min(dval, 0)``
    on the line after the key's. A value beyond a bound is taken as the bound."""
    m = _CLIP.match(lines[n]) if n < len(lines) else None
    if m is None:
        return None
    which, a, b = m.group(1), float(m.group(2)), m.group(3)
    if which is None and b is not None:
        return f"clip:{a:g},{float(b):g}"
    if which == "_min" and b is None:
        return f"clip:{a:g},"
    if which == "_max" and b is None:
        return f"clip:,{a:g}"
    return None


def _inline_form(lines: list[str], n: int, rest: str) -> str | None:
    """The value form a key's branch checks inline (``number``, ``nonneg``, ``positive``)."""
    text = rest.split("//", 1)[0]
    # the key's condition may go on with more alternatives (`(param == "a") ||`)
    k = n
    while text.rstrip().endswith("||") and k < len(lines) and k < n + 3:
        nxt = lines[k].split("//", 1)[0]
        text = nxt[nxt.rfind('"') + 1 :] if _NEXT_KEY.search(nxt) else nxt
        k += 1
    after = text.split(")", 1)[1] if text.lstrip().startswith(")") else text
    candidates = [after.lstrip(") ").lstrip("&").strip()]
    if after.strip() in ("", "{", ")", ") {", "){") and k < len(lines):
        candidates.append(lines[k].strip())
    for chunk in candidates:
        m = _INLINE.match(chunk)
        if m and "isNumber" in chunk[: m.end()]:
            return {">=": "nonneg", ">": "positive"}.get(m.group(1) or "", "number")
    return None


_LOWERED = re.compile(r"^(?:std::)?string\s+(\w+)\s*=\s*tolower\s*\(\s*(\w+)\s*\)\s*;$")
_WORD_TEST = re.compile(r'^\(?\s*(?:tolower\s*\(\s*(\w+)\s*\)|(\w+))\s*==\s*"([^"]*)"\s*\)?$')
_NUMBER_TEST = re.compile(
    r"^isNumber\s*\(\s*(\w+)\s*\)"
    r"(?:\s*&&\s*\(\s*(ato[if])\s*\(\s*(\w+)\.c_str\(\)\s*\)\s*(>=|>)\s*0\s*\))?$"
)
_REJECT = re.compile(
    r"^(?:reportConfigWarning\s*\(.*\)|\w+\s*=\s*false|return\s*\(?\s*false\s*\)?)\s*;$"
)
#: (atoi or atof, comparison) -> the number form
_NUMBER_FORMS = {
    (None, None): "number",
    ("atoi", ">="): "uint",
    ("atoi", ">"): "posuint",
    ("atof", ">="): "nonneg",
    ("atof", ">"): "positive",
}


def _condition(text: str) -> tuple[str, str] | None:
    """``if(COND) rest`` -> (COND, rest), the condition on one line."""
    m = re.match(r"^(?:else\s+)?if\s*\(", text)
    if not m:
        return None
    depth, i = 1, m.end()
    while i < len(text) and depth:
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        i += 1
    return (text[m.end() : i - 1].strip(), text[i:].strip()) if not depth else None


def _words_or_number(lines: list[str], n: int, rest: str) -> tuple[str, list[list[str]]] | None:
    """``enum_or_<number form>:a|b`` for a key's branch of this shape, with the groups of
    words one branch takes together (``if((str == "end") || (str == "all-posted"))``: the
    app stores them alike), else None::

        string str = tolower(value);            // optional
        if((str == "a") || (str == "b")) ...    // one or more branches of words
        else if(isNumber(value) && (atoi(value.c_str()) >= 0)) ...
        else
          reportConfigWarning(...);             // or `handled = false;`, `return(false);`

    Any other value is rejected, so the words and numbers are all the key takes.
    """
    code = [ln.split("//", 1)[0].strip() for ln in lines[n:]]
    if rest.split("//", 1)[0].strip() not in (") {", "){"):
        return None
    k, value, lowered = 0, None, None
    m = _LOWERED.match(code[0]) if code else None
    if m:
        lowered, value, k = m.group(1), m.group(2), 1
    words: list[str] = []
    groups: list[list[str]] = []
    number = None

    def skip_body(after: str, k: int) -> int | None:
        """The line after a branch whose condition ends line ``k`` with ``after``."""
        if after.startswith("{"):
            depth = 0
            for j in range(k, min(k + 40, len(code))):
                text = after if j == k else code[j]
                depth += text.count("{") - text.count("}")
                if depth == 0:
                    return j + 1
            return None
        if after:
            return k + 1 if after.endswith(";") else None
        return k + 2 if k + 1 < len(code) and code[k + 1].endswith(";") else None

    while k < len(code) and number is None:
        cond = _condition(code[k])
        if cond is None or code[k].startswith("if") != (k == (1 if lowered else 0)):
            return None
        test, after = cond
        num = _NUMBER_TEST.match(test)
        if num:
            if num.group(3) not in (None, num.group(1)) or (value or num.group(1)) != num.group(1):
                return None
            number = _NUMBER_FORMS[(num.group(2), num.group(4))]
        else:
            groups.append([])
            for part in test.split("||"):
                w = _WORD_TEST.match(part.strip())
                if not w:
                    return None
                subject = w.group(1) or w.group(2)
                if w.group(1):  # tolower(value) == "a"
                    if value not in (None, subject):
                        return None
                    value = subject
                elif subject != lowered:
                    return None
                if w.group(3) != w.group(3).lower() or "|" in w.group(3):
                    return None
                words.append(w.group(3))
                groups[-1].append(w.group(3))
        nxt = skip_body(after, k)
        if nxt is None:
            return None
        k = nxt
    if number is None or not words or k >= len(code):
        return None
    # the final `else` rejects any other value, and ends the key's branch
    if code[k] == "else":
        reject, k = (code[k + 1] if k + 1 < len(code) else ""), k + 2
    elif code[k].startswith("else "):
        reject, k = code[k][len("else ") :].strip(), k + 1
    else:
        return None
    if not _REJECT.match(reject) or k >= len(code) or code[k] != "}":
        return None
    form = f"enum_or_{number}:" + "|".join(dict.fromkeys(words))
    return form, [list(dict.fromkeys(g)) for g in groups if len(set(g)) > 1]


_ATOF_LOCAL = re.compile(
    r"^(?:double|float|int|long)\s+(\w+)\s*=\s*ato[fil]\s*\(\s*(\w+)\.c_str\(\)\s*\)\s*;$"
)
_GUARD_NUMBER = re.compile(r"^!\s*isNumber\s*\(\s*(\w+)\s*\)$")
_GUARD_BOUND = re.compile(r"^(\w+)\s*(<=|<|>=|>)\s*(-?\d+(?:\.\d*)?)$")
_RETURN_FALSE = re.compile(r"^return\s*\(?\s*false\s*\)?\s*;$")


def _unwrapped(text: str) -> str:
    """``text`` without the parentheses around all of it."""
    text = text.strip()
    while text.startswith("(") and text.endswith(")"):
        depth = 0
        for i, ch in enumerate(text):
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if depth == 0 and i < len(text) - 1:
                return text
        text = text[1:-1].strip()
    return text


def _alternatives(test: str) -> list[str]:
    """``a || (b) || c`` split at its top-level ``||``."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(test):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth == 0 and test.startswith("||", i):
            parts.append(test[start:i])
            start = i + 2
    return [*parts, test[start:]]


def _guard_form(lines: list[str], n: int, rest: str) -> str | None:
    """The value form of a key's branch that rejects other values with a guard::

        if(param == "period") {
          double dval = atof(value.c_str());
          if((dval <= 0) || (!isNumber(value)))
            return(false);

    ``number``, ``nonneg``, ``positive`` or ``range:[lo,hi)`` (a bound the guard rejects
    beyond); None for any other shape (a guard without ``!isNumber`` lets words through
    as 0, and is not read).
    """
    # (one key of the branch, or one of its alternatives: `(param == "radius") ||
    # (param == "capture_radius")) {`)
    opening = "".join(_OTHER_KEY.sub("", rest.split("//", 1)[0]).split())
    if opening not in ("){", ")){"):
        return None
    code = [ln.split("//", 1)[0].strip() for ln in lines[n : n + 4]]
    k, local, value, top = 0, None, None, False
    m = _ATOF_LOCAL.match(code[0]) if code else None
    if m:
        local, value, k = m.group(1), m.group(2), 1
    else:  # a number the function reads before its branches (BHV_Waypoint's ``dval``)
        local, value = _top_local(lines, n) or (None, None)
        top = local is not None
    cond = _condition(code[k]) if k < len(code) else None
    if cond is None or code[k].startswith("else"):
        return None
    test, after = cond
    if not _RETURN_FALSE.match(after) and not (
        not after and k + 1 < len(code) and _RETURN_FALSE.match(code[k + 1])
    ):
        return None
    number, lo, hi = False, None, None
    for atom in (_unwrapped(a) for a in _alternatives(test)):
        g = _GUARD_NUMBER.match(atom)
        if g:
            if value not in (None, g.group(1)):
                return None
            value, number = g.group(1), True
            continue
        b = _GUARD_BOUND.match(atom)
        if not b or local is None or b.group(1) != local:
            return None
        op, c = b.group(2), float(b.group(3))
        if op in ("<", "<="):
            if lo is not None:
                return None
            lo = (c, op == "<")  # the lowest value taken, and whether it is taken itself
        else:
            if hi is not None:
                return None
            hi = (c, op == ">")
    # without ``!isNumber``, a word reads as 0: the guard tells the form only when it
    # rejects 0 (``if(dval <= 0) return(false)``: BHV_Waypoint's ``radius``)
    if not number and (not top or hi is not None or lo != (0.0, False)):
        return None
    if hi is None and lo in (None, (0.0, True), (0.0, False)):
        return {None: "number", (0.0, True): "nonneg", (0.0, False): "positive"}[lo]
    low = f"{'[' if lo[1] else '('}{lo[0]:g}" if lo else "("
    high = f"{hi[0]:g}{']' if hi[1] else ')'}" if hi else ")"
    return f"range:{low},{high}"


#: another key the branch takes alike (``|| (param == "capture_radius")``)
_OTHER_KEY = re.compile(r'\|\|\s*\(\s*\w+\s*==\s*"[^"]*"\s*\)')
_SET_PARAM = re.compile(r"::setParam\s*\(\s*(?:const\s+)?(?:std::)?string\s*&?\s*\w+\s*,")


def _top_local(lines: list[str], n: int) -> tuple[str, str] | None:
    """(local, value) for ``double dval = atof(value.c_str());`` among the first lines of
    the ``setParam`` that line ``n`` (1-based) lies in, before its first branch."""
    for i in range(n - 2, max(-1, n - 600), -1):
        if _SET_PARAM.search(lines[i]):
            for line in lines[i + 1 : min(n - 1, i + 8)]:
                code = line.split("//", 1)[0].strip()
                m = _ATOF_LOCAL.match(code)
                if m:
                    return m.group(1), m.group(2)
                if code.startswith(("if", "else")):
                    return None
            return None
    return None


def _forms(cf, src: str) -> dict[str, dict[str, str]]:
    """Keys whose value goes straight to an MBUtils setter that rejects other forms."""
    out: dict[str, dict[str, str]] = {}
    bad: set[str] = set()
    lines = _LINES.get(cf.path) or _read(cf.path).splitlines()
    for key, n in _key_sites(cf):
        text = lines[n - 1] if 0 < n <= len(lines) else ""
        at = text.find('"' + key)
        rest = text[at + len(key) + 2 :] if at >= 0 else text
        window = [rest, *lines[n : n + 1]]
        form = None
        for i, chunk in enumerate(window):
            if i and _NEXT_KEY.search(chunk):
                break
            m = _SETTER.search(chunk)
            if m:
                lead = chunk[: m.start()]
                if i == 0:
                    lead = lead.rsplit(")", 1)[-1] if ")" in lead else lead
                call = _SETTER_CALL.match(chunk, m.start())
                if _LEAD.fullmatch(lead) and call:
                    form = SETTER_FORMS[m.group(1)]
                break
            if chunk.strip() not in ("", "{", ")", "){", ") {") and i:
                break
        if form is None:
            form = _inline_form(lines, n, rest)
            if form is not None:
                form = _clipped(lines, n) or form
        same: list[list[str]] = []
        if form is None:
            got = _words_or_number(lines, n, rest)
            if got is not None:
                form, same = got
        if form is None:
            form = _guard_form(lines, n, rest)
        if form is None:
            bad.add(key)
            continue
        prev = out.get(key)
        if prev and prev["form"] != form:
            bad.add(key)
        out[key] = {"form": form, "at": f"{_rel(cf.path, src)}:{n}"}
        if same:
            out[key]["same"] = same
    return {k: v for k, v in out.items() if k not in bad}


def _param_like(p: str) -> bool:
    return bool(re.match(r"^[a-z0-9_@:.\[\]+-]+$", p)) and len(p) < 60


def _completes(chain: list[str], class_file: dict[str, str], src: str) -> str | bool | None:
    """Where a behavior of the class ``chain`` ends by itself (the first ``setComplete()``
    or post of its endflags in its class or a base other than IvPBehavior, as
    ``path:line``), False when none of them does (it ends only when a duration runs out,
    or when a spawned behavior's contact is gone), None when a source is not found."""
    for cls in chain[:-1]:  # (the last is IvPBehavior)
        path = class_file.get(cls)
        if path is None or not is_cpp_source(path):
            return None
        for n, line in enumerate(_read(path).splitlines(), 1):
            code = line.split("//", 1)[0]
            if _COMPLETES.search(code) and "::setComplete" not in code:  # (not its definition)
                return f"{_rel(path, src)}:{n}"
    return False


def _bhv_chain(cls: str, bases: dict[str, list[str]]) -> list[str]:
    def walk(name: str, seen: frozenset) -> list[str]:
        if name == "IvPBehavior":
            return [name]
        if name in seen:
            return []
        for b in bases.get(name, ()):
            ch = walk(b, seen | {name})
            if ch:
                return [name, *ch]
        return []

    return walk(cls, frozenset())


_WORD = re.compile(r"\w+")


def _stem(path: str) -> str:
    """The class a MOOS-IvP source file is named after (``PIDEngine.cpp`` -> PIDEngine)."""
    return os.path.splitext(os.path.basename(path))[0]


def _app_entry(m: AppModel, src: str, by_folder: dict, lib_folder: dict) -> dict:
    text = "".join(_read(cf.path) for cf in m.files)
    params = set().union(*(_keys(cf) for cf in m.files)) if m.files else set()
    from_libs: dict[str, list[str]] = {}
    lib_files: list[tuple[str, Any]] = []  # (library folder, file) of every library the app links
    for lib in _linked_libs(m.folder):
        folder = lib_folder.get(lib)
        lm = by_folder.get(folder) if folder else None
        if folder is None or lm is None or lm is m:
            continue
        lib_files.extend((folder, cf) for cf in lm.files)
    # A library file's keys count when the app reaches the file's class: the app's code
    # names it (MOOS-IvP keeps one class per file: `PIDEngine m_pengine;` hands lines to
    # PIDEngine.cpp), or a library file the app reaches does (MarineViewer -> VPlug_*).
    # Linking a library does not credit the app with every key the library compares.
    reached: set[str] = set()
    words = set(_WORD.findall(text))
    grew = True
    while grew:
        grew = False
        for _folder, cf in lib_files:
            if cf.path not in reached and _stem(cf.path) in words:
                reached.add(cf.path)
                words |= set(_WORD.findall(_read(cf.path)))
                grew = True
    for folder, cf in lib_files:
        if cf.path in reached:
            got = _keys(cf) - params
            if got:
                key = _rel(folder, src)
                from_libs[key] = sorted(
                    set(from_libs.get(key, [])) | {p for p in got if _param_like(p)}
                )
    forms: dict[str, dict[str, str]] = {}
    for cf in m.files:
        forms.update(_forms(cf, src))
    delegates = bool(DELEGATE.search(text))
    base = m.base_chain[-1] if m.base_chain else ""
    pubs, pub_prefixes, pub_suffixes, pub_dynamic = _names(m.publications)
    subs, sub_prefixes, _sub_suffixes, sub_dynamic = _names(m.subscriptions)
    entry = {
        "source": _rel(m.folder, src),
        "base": base,
        "params": sorted(p for p in params if _param_like(p)),
        "params_from_libraries": from_libs,
        # value forms enforced by the app's parser: key -> {form, at: source line}
        "param_forms": dict(sorted(forms.items())),
        # IvP apps report "Unhandled config line" for any other key: the list is the parser's
        "reports_unhandled": "reportUnhandledConfigWarning" in text and not delegates,
        # a final ``else`` hands any other key to code whose keys are not listed
        "delegates_other_keys": delegates,
        "publishes": sorted(set(pubs) | set(_PAIR.findall(text))),
        "publish_prefixes": pub_prefixes,
        "publish_suffixes": pub_suffixes,
        "publishes_dynamic": pub_dynamic,
        "subscribes": subs,
        "subscribe_prefixes": sub_prefixes,
        "subscribes_dynamic": sub_dynamic,
        # every app needs its block unless its start-up declares it optional
        # (AppCastingMOOSApp.cpp:308-368: "No mission config block found" otherwise)
        "needs_process_config": not OPTIONAL_BLOCK.search(text),
        "needs_origin": bool(READS_ORIGIN.search(text)),
    }
    return entry


def write_json(data: dict, output: str) -> None:
    """``data`` as the catalogue files are written, to ``output`` (``-``: standard output)."""
    text = json.dumps(data, indent=1, sort_keys=False) + "\n"
    if output == "-":
        sys.stdout.write(text)
    else:
        with open(output, "w", encoding="utf-8") as fh:
            fh.write(text)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python scripts/generate_catalogue.py")
    ap.add_argument("src", help="a moos-ivp work tree")
    ap.add_argument("-o", "--output", default="-")
    ap.add_argument("--commit", default="")
    ap.add_argument("--repository", default="")
    args = ap.parse_args(argv)
    if not os.path.isdir(os.path.join(args.src, "ivp", "src")):
        print(f"{args.src}: not a moos-ivp work tree (no ivp/src)", file=sys.stderr)
        return 2
    data = generate(args.src, args.commit, args.repository)
    write_json(data, args.output)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
