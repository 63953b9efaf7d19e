"""Configuration: ``[tool.moos-lint]`` in pyproject.toml, or moos-lint.toml / .moos-lint.toml.

The first of those found walking up from the linted paths wins. Unknown keys,
unknown rules and options of the wrong type are errors that name the file and
the key: a typo in a config must never silently turn a check off.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from moos_lint.files.discovery import DEFAULT_EXCLUDE
from moos_lint.files.markers import CONFIG_FILES

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from typing import Any


def _toml():
    """The TOML reader, imported when a config file is read (not on every run)."""
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib
    return tomllib


LIST_KEYS = ("select", "ignore", "extend-select", "exclude", "include-paths")
KNOWN_KEYS = {
    *LIST_KEYS,
    "per-file-ignores",
    "defines",
    "rules",
    "cpp-backend",
    "compile-commands",
    "catalogues",
    "cache-dir",
    "respect-gitignore",
}
CPP_BACKENDS = ("tree-sitter", "clang")


class ConfigError(Exception):
    """A configuration problem; the CLI exits with status 2."""


class Settings:
    """What a run lints with: the selection, the options, nsplug defines, paths.

    A plain class (not a dataclass): loading the settings is on the path of
    every run, the fastest ones (a cached report) included.
    """

    def __init__(
        self,
        select: list[str] | None = None,
        extend_select: list[str] | None = None,
        ignore: list[str] | None = None,
        per_file_ignores: dict[str, list[str]] | None = None,
        exclude: list[str] | None = None,
        defines: dict[str, str] | None = None,
        include_paths: list[str] | None = None,
        rule_options: dict[str, dict[str, Any]] | None = None,
        config_path: str | None = None,
        root: str = ".",
        cpp_backend: str = "tree-sitter",
        compile_commands: str | None = None,
        catalogues: list[str] | None = None,
        cache_dir: str | None = None,
        respect_gitignore: bool = True,
    ) -> None:
        self.select = select
        self.extend_select = [] if extend_select is None else extend_select
        self.ignore = [] if ignore is None else ignore
        self.per_file_ignores = {} if per_file_ignores is None else per_file_ignores
        self.exclude = [] if exclude is None else exclude
        self.defines = {} if defines is None else defines
        self.include_paths = [] if include_paths is None else include_paths
        self.rule_options = {} if rule_options is None else rule_options
        self.config_path = config_path
        self.root = root
        #: how C++ is read: "tree-sitter" (fast) or "clang" (libclang deep mode)
        self.cpp_backend = cpp_backend
        self.compile_commands = compile_commands  # a compile_commands.json, or its folder
        #: app/behavior catalogue files (JSON or TOML) for apps whose C++ is elsewhere
        self.catalogues = [] if catalogues is None else catalogues
        #: where the result cache lives, inside the project (None: the user's cache folder)
        self.cache_dir = cache_dir
        #: leave out what git ignores (``.gitignore``, ``.ignore``, global excludes)
        self.respect_gitignore = respect_gitignore
        #: the run's project root (:mod:`moos_lint.files.project`), set by the command line and
        #: the language server: no text of a file outside it is shown
        #: (:mod:`moos_lint.files.boundary`)
        self.project_root: str | None = None

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={v!r}" for k, v in vars(self).items())
        return f"Settings({fields})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Settings) and vars(self) == vars(other)

    __hash__ = None  # type: ignore[assignment]  # mutable, as the dataclass was

    def options_for(self, name: str) -> dict[str, Any]:
        """A rule's options: its defaults, overridden by the config."""
        from moos_lint.core.registry import get_rule

        r = get_rule(name)
        out = dict(r.options) if r else {}
        out.update(self.rule_options.get(name, {}))
        return out

    def as_dict(self) -> dict[str, Any]:
        from moos_lint.core.registry import all_rules

        return {
            "config": self.config_path,
            "root": self.root,
            "select": self.select,
            "extend-select": self.extend_select,
            "ignore": self.ignore,
            "per-file-ignores": self.per_file_ignores,
            "exclude": [*DEFAULT_EXCLUDE, *self.exclude],
            "defines": self.defines,
            "include-paths": self.include_paths,
            "cpp-backend": self.cpp_backend,
            "compile-commands": self.compile_commands,
            "catalogues": self.catalogues,
            "cache-dir": self.cache_dir,
            "respect-gitignore": self.respect_gitignore,
            "rules": {r.name: self.options_for(r.name) for r in all_rules() if r.options},
        }


def find_config(start: Path) -> Path | None:
    """The nearest config file at or above ``start``."""
    here = start if start.is_dir() else start.parent
    here = Path(os.path.abspath(here))
    for folder in (here, *here.parents):
        for name in CONFIG_FILES:
            candidate = folder / name
            if not candidate.is_file():
                continue
            if name == "pyproject.toml":
                tomllib = _toml()
                try:
                    data = tomllib.loads(candidate.read_text(encoding="utf-8"))
                except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
                    continue
                if "moos-lint" not in data.get("tool", {}):
                    continue
            return candidate
    return None


def _check_list(path: Path, key: str, value: Any) -> list[str]:
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{path}: `{key}` must be a list of strings")
    return value


def _check_selectors(path: Path, key: str, values: list[str]) -> None:
    from moos_lint.core.registry import is_valid_selector

    for v in values:
        if not is_valid_selector(v):
            raise ConfigError(f"{path}: `{key}` names an unknown rule or code `{v}`")


def _check_catalogues(path: Path, key: str, value: Any, root: Path) -> list[str]:
    """Catalogue files, relative to the config's folder; each must exist and be valid."""
    from moos_lint.semantics.catalogue import Catalogue, CatalogueError, load_user_catalogue

    out = []
    for name in _check_list(path, key, value):
        full = str((root / name).resolve())
        if not os.path.isfile(full):
            raise ConfigError(f"{path}: `{key}`: catalogue file `{name}` not found")
        try:
            load_user_catalogue(full, Catalogue())
        except CatalogueError as exc:
            raise ConfigError(f"{path}: `{key}`: {exc}") from exc
        out.append(full)
    return out


def load_config(path: Path) -> Settings:
    tomllib = _toml()
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as exc:
        raise ConfigError(f"{path}: cannot read config: {exc}") from exc
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: invalid TOML: {exc}") from exc
    if path.name == "pyproject.toml":
        data = data.get("tool", {}).get("moos-lint", {})
        prefix = "tool.moos-lint."
    else:
        prefix = ""
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: `{prefix}` must be a table")
    return settings_from_dict(data, path, prefix)


def settings_from_dict(data: dict[str, Any], path: Path, prefix: str = "") -> Settings:
    root = path.parent
    s = Settings(config_path=str(path), root=str(root))
    for key, value in data.items():
        if key not in KNOWN_KEYS:
            raise ConfigError(f"{path}: unknown key `{prefix}{key}`")
        if key in LIST_KEYS:
            _check_list(path, prefix + key, value)
    if "select" in data:
        s.select = _check_list(path, prefix + "select", data["select"])
        _check_selectors(path, prefix + "select", s.select)
    s.extend_select = list(data.get("extend-select", []))
    _check_selectors(path, prefix + "extend-select", s.extend_select)
    s.ignore = list(data.get("ignore", []))
    _check_selectors(path, prefix + "ignore", s.ignore)
    s.exclude = list(data.get("exclude", []))
    s.include_paths = [str((root / p).resolve()) for p in data.get("include-paths", [])]
    pfi = data.get("per-file-ignores", {})
    if not isinstance(pfi, dict):
        raise ConfigError(f"{path}: `{prefix}per-file-ignores` must be a table")
    for glob, codes in pfi.items():
        s.per_file_ignores[glob] = _check_list(path, f"{prefix}per-file-ignores.{glob}", codes)
        _check_selectors(path, f"{prefix}per-file-ignores.{glob}", codes)
    backend = data.get("cpp-backend", "tree-sitter")
    if backend not in CPP_BACKENDS:
        raise ConfigError(f"{path}: `{prefix}cpp-backend` must be one of {', '.join(CPP_BACKENDS)}")
    s.cpp_backend = backend
    if "compile-commands" in data:
        cc = data["compile-commands"]
        if not isinstance(cc, str):
            raise ConfigError(f"{path}: `{prefix}compile-commands` must be a path")
        s.compile_commands = str((root / cc).resolve())
    if "cache-dir" in data:
        cd = data["cache-dir"]
        if not isinstance(cd, str) or not cd:
            raise ConfigError(f"{path}: `{prefix}cache-dir` must be a path")
        full = str((root / cd).resolve())
        from moos_lint.files.project import real_within

        if not real_within(full, str(root)):  # a repository never writes outside itself
            raise ConfigError(
                f"{path}: `{prefix}cache-dir` must be a folder inside the project "
                f"({root}), not `{cd}`; --cache-dir or MOOS_LINT_CACHE_DIR may name any folder"
            )
        s.cache_dir = full
    if "respect-gitignore" in data:
        if not isinstance(data["respect-gitignore"], bool):
            raise ConfigError(f"{path}: `{prefix}respect-gitignore` must be true or false")
        s.respect_gitignore = data["respect-gitignore"]
    if "catalogues" in data:
        s.catalogues = _check_catalogues(path, prefix + "catalogues", data["catalogues"], root)
    defines = data.get("defines", {})
    if not isinstance(defines, dict):
        raise ConfigError(f"{path}: `{prefix}defines` must be a table of NAME = value")
    s.defines = {str(k): str(v) for k, v in defines.items()}
    rules = data.get("rules", {})
    if not isinstance(rules, dict):
        raise ConfigError(f"{path}: `{prefix}rules` must be a table")
    from moos_lint.core.registry import get_rule

    for name, opts in rules.items():
        r = get_rule(name)
        if r is None:
            raise ConfigError(f"{path}: unknown rule `{prefix}rules.{name}`")
        if not isinstance(opts, dict):
            raise ConfigError(f"{path}: `{prefix}rules.{name}` must be a table")
        for okey, oval in opts.items():
            if okey not in r.options:
                known = ", ".join(sorted(r.options)) or "none"
                raise ConfigError(
                    f"{path}: unknown option `{prefix}rules.{name}.{okey}` (options: {known})"
                )
            default = r.options[okey]
            int_for_float = isinstance(default, float) and isinstance(oval, int)
            if default is not None and type(oval) is not type(default) and not int_for_float:
                raise ConfigError(
                    f"{path}: `{prefix}rules.{name}.{okey}` must be "
                    f"{type(default).__name__}, not {type(oval).__name__}"
                )
        s.rule_options[r.name] = dict(opts)
    return s


def resolve_settings(paths: list[Path], config: Path | None) -> Settings:
    """Settings from ``--config`` or from the nearest config file."""
    if config is not None:
        if not config.is_file():
            raise ConfigError(f"{config}: config file not found")
        return load_config(config)
    start = paths[0] if paths else Path(".")
    found = find_config(start)
    if found is None:
        from moos_lint.files.project import project_root

        return Settings(root=project_root(paths))
    return load_config(found)
