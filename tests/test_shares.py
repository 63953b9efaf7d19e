"""What pShare sends and hears: the routes that tie a mission to another folder's."""

from __future__ import annotations

from moos_lint.frontends.nsplug import Preprocessor, parsed
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.semantics.shares import input_routes, output_shares


def test_keyed_output_arrives_under_its_dest_name_on_each_route():
    value = "src_name=START, dest_name=BUOY_START, route=multicast_8 & localhost:9201"
    assert output_shares(value) == [("BUOY_START", ("multicast_8", "localhost:9201"))]
    assert output_shares("src_name = START , route = multicast_8") == [("START", ("multicast_8",))]


def test_arrow_output_names_its_destination_only_when_given():
    assert output_shares("NAV_X->localhost:9201") == [("NAV_X", ("localhost:9201",))]
    assert output_shares("NAV_X->OTHER_X:localhost:9201 & multicast_7") == [
        ("OTHER_X", ("localhost:9201", "multicast_7"))
    ]
    assert output_shares("A->multicast_3, B->C:multicast_4") == [
        ("A", ("multicast_3",)),
        ("C", ("multicast_4",)),
    ]


def test_a_share_with_a_macro_or_a_wildcard_is_not_known():
    assert output_shares("src_name=START_$(VNAME), route=multicast_8") == []
    assert output_shares("src_name=NAV_*, route=multicast_8") == []
    assert output_shares("src_name=START, route=$(ROUTE)") == []


def test_input_routes(tmp_path):
    mission = tmp_path / "buoy.moos"
    mission.write_text(
        "ProcessConfig = pShare\n{\n"
        "  input = route = localhost:9201 & multicast_8\n"
        "  input = localhost:9300\n"
        "  input = route = $(SHARE_LISTEN)\n"
        "}\n"
    )
    moos = parsed(Preprocessor().expand(str(mission)), parse_moos)
    (block,) = moos.blocks
    assert input_routes(block) == {"localhost:9201", "multicast_8", "localhost:9300"}
