"""goby's MOOS apps: the .proto catalogue step and the protobuf-text block reader."""

from __future__ import annotations

from moos_lint.frontends.nsplug import Line
from moos_lint.frontends.parsers.protobuf_text import looks_like_text_format, read_block
from moos_lint.semantics.catalogue import goby, text_format_app, text_format_schema


def _lines(text: str) -> list[Line]:
    return [Line(t, t, "m.moos", i) for i, t in enumerate(text.split("\n"), 1)]


def test_generator_reads_messages_enums_and_extensions(tmp_path):
    app = tmp_path / "src" / "apps" / "moos" / "pAcommsHandler"
    app.mkdir(parents=True)
    (tmp_path / "src" / "base.proto").write_text(
        "package goby.acomms.protobuf;\n"
        "message DriverConfig { optional int32 modem_id = 1; extensions 1000 to max; }\n"
        "enum DriverType { DRIVER_NONE = 1; DRIVER_UDP = 2; }\n"
    )
    (tmp_path / "src" / "udp.proto").write_text(
        "package goby.acomms;\n"
        "message UDPDriverConfig {\n"
        '  message EndPoint { optional string ip = 1 [default = "127.0.0.1"]; }\n'
        "  extend goby.acomms.protobuf.DriverConfig { optional EndPoint local = 1201; }\n"
        "}\n"
    )
    (app / "cfg.proto").write_text(
        'import "base.proto";\n'
        "message pAcommsHandlerConfig {\n"
        "  required int32 modem_id = 2; // a comment\n"
        "  optional goby.acomms.protobuf.DriverType driver_type = 3;\n"
        "  optional goby.acomms.protobuf.DriverConfig driver_cfg = 4;\n"
        "  /* block comment */ repeated string load_proto_file = 5;\n"
        "}\n"
    )
    data = goby.generate(str(tmp_path), commit="abc")
    assert data["apps"]["pAcommsHandler"]["message"] == "pAcommsHandlerConfig"
    root = data["messages"]["pAcommsHandlerConfig"]["fields"]
    assert root == {
        "modem_id": "int32",
        "driver_type": "goby.acomms.protobuf.DriverType",
        "driver_cfg": "goby.acomms.protobuf.DriverConfig",
        "load_proto_file": "string",
    }
    ext = data["messages"]["goby.acomms.protobuf.DriverConfig"]["extensions"]
    assert ext == {"goby.acomms.UDPDriverConfig.local": "goby.acomms.UDPDriverConfig.EndPoint"}
    assert data["enums"]["goby.acomms.protobuf.DriverType"]["values"] == [
        "DRIVER_NONE",
        "DRIVER_UDP",
    ]
    assert data["source"]["commit"] == "abc"


def _release(root: str, fields: dict, commit: str, repository: str) -> dict:
    driver = {"fields": {"modem_id": "int32"}, "extensions": {}, "source": "driver.proto"}
    if "driver_type" not in fields:  # the newer release moved it into driver_cfg
        driver["fields"]["driver_type"] = "DriverType"
    return {
        "source": {"commit": commit, "repository": repository},
        "apps": {"pAcommsHandler": {"message": root, "source": "src/apps", "proto": "a.proto"}},
        "messages": {
            root: {"fields": fields, "extensions": {}, "source": "a.proto"},
            "DriverConfig": driver,
        },
        "enums": {"DriverType": {"values": ["DRIVER_NONE", "DRIVER_UDP"], "source": "d.proto"}},
        "moos_globals": {},
    }


def test_merge_keeps_each_release_of_an_app_and_unites_shared_messages():
    old = _release(
        "pAcommsHandlerConfig",
        {"driver_type": "DriverType", "driver_cfg": "DriverConfig"},
        "aaa",
        "https://github.com/GobySoft/goby",
    )
    new = _release(
        "goby.apps.pAcommsHandlerConfig",
        {"driver_cfg": "DriverConfig"},
        "bbb",
        "https://github.com/GobySoft/goby3",
    )
    new["enums"]["DriverType"]["values"] = ["DRIVER_NONE", "DRIVER_POPOTO"]
    data = goby.merge([old, new])
    assert [s["commit"] for s in data["sources"]] == ["aaa", "bbb"]
    assert [(a["message"], a["from"]) for a in data["apps"]["pAcommsHandler"]] == [
        ("pAcommsHandlerConfig", 0),
        ("goby.apps.pAcommsHandlerConfig", 1),
    ]
    # one message of one name in both releases: the fields of either
    assert data["messages"]["DriverConfig"]["fields"] == {
        "modem_id": "int32",
        "driver_type": "DriverType",
    }
    assert data["messages"]["DriverConfig"]["from"] == 0
    assert data["enums"]["DriverType"]["values"] == ["DRIVER_NONE", "DRIVER_UDP", "DRIVER_POPOTO"]


def test_stock_goby_catalogue_knows_the_apps():
    app = text_format_app("pAcommsHandler")
    assert app is not None and app.message == "pAcommsHandlerConfig"
    # goby 3 builds the same app with its own message: the stock catalogue has both
    assert [r.message for r in app.all_releases] == [
        "pAcommsHandlerConfig",
        "goby.apps.moos.protobuf.pAcommsHandlerConfig",
    ]
    assert app.releases[0].provenance.startswith("goby3 ")
    assert app.provenance.startswith("goby ")
    assert (
        "frontseat_cfg"
        in text_format_schema().messages[text_format_app("iFrontSeat").releases[0].message]
    )
    assert text_format_app("iFrontSeat_bluefin").name == "iFrontSeat"
    assert text_format_app("pHelmIvP") is None
    assert "common" in text_format_schema().messages["pAcommsHandlerConfig"]


def test_read_block_nesting_lists_and_errors():
    fields, errors = read_block(
        _lines(
            "common { log: false }  # c\n"
            "slot < src: 1, rate: 0 >\n"
            "manipulator: [NO_QUEUE, LOOPBACK]\n"
            '[a.b.ext]: "x" "y"\n'
            "name = 3\n"
            "open {"
        )
    )
    assert [f.name for f in fields] == ["common", "slot", "manipulator", "a.b.ext", "open"]
    assert fields[0].children[0].value == "false"
    assert fields[3].extension
    assert [(e[0].lineno, e[3]) for e in errors] == [
        (5, "`name` needs `: value` or `{ ... }` after it"),
        (6, "`{` is never closed"),
    ]


def test_stray_closer_and_missing_value_do_not_stop_the_reader():
    fields, errors = read_block(_lines("}\na: \nb: 2\nc: $(MACRO)"))
    assert [f.name for f in fields] == ["b", "c"]
    assert [e[3] for e in errors] == ["`}` closes no `{`", "`a:` has no value"]


def test_the_text_format_hint():
    proto = _lines("a: 1\nb { c: 2 }\n}\nd: 3")
    moos = _lines("a = 1\nb = 2\nc: 3")
    assert looks_like_text_format(proto, known_app=False)
    assert not looks_like_text_format(moos, known_app=False)
    assert looks_like_text_format(_lines("a: 1\nb = 2"), known_app=True)
    assert not looks_like_text_format(_lines("a: 1\nb = 2"), known_app=False)


def test_a_moos_block_with_colons_is_not_text_format():
    """`POINT:NAME=x` lines (uGeodesy) hold an `=`: MOOS lines, whatever the colon."""
    block = _lines("AppTick = 5\nPOINT:NAME=Origin,North=0\nPOINT: NAME=Earth,Lat=47")
    assert not looks_like_text_format(block, known_app=False)
    assert looks_like_text_format(_lines('format: "%1%=x"\nname: "a=b"  # c=d'), False)
