"""libclang deep mode over a small app of the project's own, with its compile_commands.json."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("tree_sitter")

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files

APP = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "clang_app"
FILES = [str(APP / n) for n in ("Compass.cpp", "Compass.h", "MOOSStub.h", "main.cpp")]


def _db(tmp_path: Path) -> Path:
    entries = [
        {
            "directory": str(APP),
            "file": str(APP / name),
            "arguments": ["c++", "-std=c++17", f"-I{APP}", "-c", name, "-o", f"/tmp/{name}.o"],
        }
        for name in ("Compass.cpp", "main.cpp")
    ]
    (tmp_path / "compile_commands.json").write_text(json.dumps(entries))
    return tmp_path


def _lint(backend: str, db: Path | None, select: list[str]):
    settings = Settings(root=str(APP), cpp_backend=backend)
    settings.compile_commands = str(db) if db else None
    settings.select = select
    return lint_files(FILES, settings)


def require_libclang() -> None:
    """Skip where libclang or the system compiler's include folder is missing."""
    ci = pytest.importorskip("clang.cindex")
    from moos_lint.frontends.cpp.clang import system_include

    try:
        ci.conf.lib  # noqa: B018
    except Exception:
        pytest.skip("libclang cannot be loaded")
    if system_include() is None:
        pytest.skip("no system compiler include folder")


def _clang_app(tmp_path):
    require_libclang()
    result = _lint("clang", _db(tmp_path), ["yaw-in-degrees"])
    app = next(u.cpp for u in result.units if u.cpp is not None and u.cpp.is_app)
    if app.backend != "clang":
        pytest.skip("no system C++ headers for libclang")
    return result, app


def test_clang_adds_types_folds_constants_and_follows_ifdef(tmp_path):
    result, app = _clang_app(tmp_path)
    pubs = {p.name.text: p for f in app.files for p in f.publications}
    assert pubs["COMPASS_YAW"].value.type == "floating"
    assert pubs["COMPASS_YAW"].value.number == pytest.approx(400 * 3.141592653589793 / 180)
    assert pubs["COMPASS_STATUS"].value.type == "string"
    assert pubs["COMPASS_debug"].active is False  # COMPASS_DEBUG is not defined
    assert "COMPASS_debug" not in {p.name.text for p in app.publications}
    # the folded constant is over 2π: a yaw in degrees
    assert [(Path(d.span.path).name, d.span.line) for d in result.diagnostics] == [
        ("Compass.cpp", 8)
    ]


def test_tree_sitter_alone_sees_neither(tmp_path):
    result = _lint("tree-sitter", None, ["yaw-in-degrees", "variable-name-case"])
    got = [(Path(d.span.path).name, d.span.line, d.code) for d in result.diagnostics]
    # both #ifdef branches are read, and the constant is not folded
    assert got == [("Compass.cpp", 11, "N003")]


def test_missing_compile_commands_warns_once_and_falls_back(tmp_path, capsys):
    pytest.importorskip("clang.cindex")
    import moos_lint.frontends.cpp.clang as clang_mod

    clang_mod._warned.clear()
    missing = tmp_path / "nowhere"
    missing.mkdir()
    settings = Settings(root=str(missing), cpp_backend="clang")
    settings.compile_commands = str(missing)
    settings.select = ["variable-name-case"]
    first = lint_files(FILES, settings)
    lint_files(FILES, settings)
    err = capsys.readouterr().err
    assert err.count("compile_commands.json") == 1
    assert [d.span.line for d in first.diagnostics] == [11]  # tree-sitter results kept


def test_missing_libclang_says_so(monkeypatch, capsys):
    import builtins

    import moos_lint.frontends.cpp.clang as clang_mod

    real_import = builtins.__import__

    def no_clang(name, *args, **kw):
        if name.startswith("clang"):
            raise ImportError("no libclang")
        return real_import(name, *args, **kw)

    clang_mod._warned.clear()
    monkeypatch.setattr(builtins, "__import__", no_clang)
    assert clang_mod.load_cindex() is None
    assert "needs libclang" in capsys.readouterr().err


def test_config_key_and_cli_flag(tmp_path):
    from moos_lint.core.config import ConfigError, load_config

    cfg = tmp_path / "moos-lint.toml"
    cfg.write_text('cpp-backend = "clang"\ncompile-commands = "build"\n')
    s = load_config(cfg)
    assert s.cpp_backend == "clang" and s.compile_commands == str((tmp_path / "build").resolve())
    cfg.write_text('cpp-backend = "gcc"\n')
    with pytest.raises(ConfigError):
        load_config(cfg)


# ------------------------------------------------------- a repository's compile database


def test_only_parse_shaping_flags_reach_libclang():
    from moos_lint.frontends.cpp.clang import parse_flags

    crafted = [
        *("-include", "/etc/passwd", "-include/etc/shadow"),
        *("-fplugin=/tmp/evil.so", "-Xclang", "-load", "-Xclang", "/tmp/evil.so"),
        *("-fmodules-cache-path=/tmp/m", "-fmodules", "-o", "/tmp/out.o", "-MF", "/tmp/d"),
        *("-MD", "-c", "x.cpp", "--serialize-diagnostics", "/tmp/s", "-stdlib=libc++"),
        *("-Iinc", "-I", "/abs/inc", "-isystem", "sys", "-isystem/abs/sys"),
        *("-DA=1", "-D", "B", "-UC", "-U", "D", "-std=c++17", "-std", "c++20"),
    ]
    assert parse_flags(crafted, "/build") == [
        "-I/build/inc",
        "-I/abs/inc",
        *("-isystem", "/build/sys", "-isystem", "/abs/sys"),
        *("-DA=1", "-DB", "-UC", "-UD", "-std=c++17", "-std=c++20"),
    ]


def test_compile_database_search_stops_at_the_project_root(tmp_path):
    from moos_lint.frontends.cpp.clang import find_compile_commands

    project = tmp_path / "project"
    app = project / "src" / "pApp"
    app.mkdir(parents=True)
    (tmp_path / "compile_commands.json").write_text("[]")  # above the project: never used
    settings = Settings(root=str(project))
    settings.project_root = str(project)
    assert find_compile_commands(settings, [str(app)]) is None
    (project / "build").mkdir()
    (project / "build" / "compile_commands.json").write_text("[]")
    assert find_compile_commands(settings, [str(app)]) == str(project / "build")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "compile_commands.json").write_text("[]")
    (project / "build" / "compile_commands.json").unlink()
    assert find_compile_commands(settings, [str(elsewhere)]) is None
