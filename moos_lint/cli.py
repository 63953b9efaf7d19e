"""The ``moos-lint`` command line.

Exit status: 0 no findings, 1 findings, 2 usage, configuration or internal error.
Heavy modules are imported inside the commands that need them, so that
``moos-lint --version`` stays instant.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from moos_lint import __version__

EXIT_CLEAN, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2


def _csv(values: list[str] | None) -> list[str]:
    out: list[str] = []
    for v in values or []:
        out.extend(x.strip() for x in v.split(",") if x.strip())
    return out


def _defines(values: list[str] | None) -> dict[str, str]:
    out = {}
    for v in values or []:
        name, eq, value = v.partition("=")
        if not name:
            raise SystemExit(_usage_error(f"--define needs NAME=VALUE, got {v!r}"))
        out[name] = value if eq else "<defined>"
    return out


def _usage_error(msg: str) -> int:
    print(f"moos-lint: error: {msg}", file=sys.stderr)
    return EXIT_ERROR


def _add_preproc_args(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--define",
        "-D",
        action="append",
        metavar="NAME=VALUE",
        help="define an nsplug macro (repeatable)",
    )
    p.add_argument(
        "--include-path",
        "-I",
        action="append",
        metavar="DIR",
        help="a folder nsplug searches for #include files, like nsplug --path (repeatable)",
    )


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="moos-lint",
        description="Lint MOOS and MOOS-IvP mission (.moos) and behavior (.bhv) files.",
    )
    parser.add_argument("--version", action="version", version=f"moos-lint {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    check = sub.add_parser("check", help="lint files and folders (the default command)")
    check.add_argument("paths", nargs="*", type=Path, help="files or folders (default: .)")
    check.add_argument(
        "--select", action="append", help="rules to enable (codes, prefixes, names, ALL)"
    )
    check.add_argument(
        "--extend-select", action="append", help="rules to enable on top of the selection"
    )
    check.add_argument("--ignore", action="append", help="rules to disable")
    _add_preproc_args(check)
    check.add_argument("--config", type=Path, help="use this config file instead of searching")
    check.add_argument(
        "--output-format",
        choices=("text", "json"),
        default="text",
        help="output format (default: text)",
    )
    check.add_argument("--output-file", "-o", type=Path, help="write the report to this file")
    check.add_argument("--statistics", action="store_true", help="count findings per rule")
    check.add_argument("--show-settings", action="store_true", help="print the settings and exit")
    check.add_argument("--exit-zero", action="store_true", help="exit 0 even with findings")
    check.add_argument("--quiet", "-q", action="store_true", help="print findings only")

    expand = sub.add_parser("expand", help="print a file as nsplug would expand it")
    expand.add_argument("file", type=Path)
    _add_preproc_args(expand)
    expand.add_argument(
        "--lenient",
        action="store_true",
        help="expand the defined macros of a line that also holds undefined ones",
    )

    rule = sub.add_parser("rule", help="print the documentation of a rule")
    rule.add_argument("rule", metavar="CODE-or-NAME")

    rules = sub.add_parser("rules", help="list every rule")
    rules.add_argument("--output-format", choices=("text", "json"), default="text")
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    commands = {"check", "expand", "rule", "rules"}
    if not argv or (argv[0] not in commands and argv[0] not in ("-h", "--help", "--version")):
        argv.insert(0, "check")
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        if args.command == "check":
            return cmd_check(args)
        if args.command == "expand":
            return cmd_expand(args)
        if args.command == "rule":
            return cmd_rule(args)
        if args.command == "rules":
            return cmd_rules(args)
    except KeyboardInterrupt:
        return EXIT_ERROR
    except BrokenPipeError:
        return EXIT_ERROR
    parser.print_help()
    return EXIT_ERROR


def _settings(args: argparse.Namespace):
    from moos_lint.config import ConfigError, resolve_settings
    from moos_lint.registry import is_valid_selector

    settings = resolve_settings(list(args.paths), args.config)
    for opt in ("select", "extend_select", "ignore"):
        for sel in _csv(getattr(args, opt)):
            if not is_valid_selector(sel):
                raise ConfigError(f"--{opt.replace('_', '-')}: unknown rule or code `{sel}`")
    if args.select:
        settings.select = _csv(args.select)
    settings.extend_select += _csv(args.extend_select)
    settings.ignore += _csv(args.ignore)
    settings.defines.update(_defines(args.define))
    settings.include_paths += [os.path.abspath(p) for p in args.include_path or []]
    return settings


def cmd_check(args: argparse.Namespace) -> int:
    from moos_lint.config import ConfigError
    from moos_lint.diagnostics import Diagnostic, Severity, Span
    from moos_lint.engine import lint_paths
    from moos_lint.output import render

    try:
        settings = _settings(args)
    except ConfigError as exc:
        return _usage_error(str(exc))
    if args.show_settings:
        print(json.dumps(settings.as_dict(), indent=2))
        return EXIT_CLEAN
    result = lint_paths(args.paths, settings)
    for missing in result.missing:
        result.diagnostics.insert(
            0,
            Diagnostic(
                "R001",
                "unreadable-file",
                Severity.ERROR,
                Span(os.path.abspath(missing), 1, 1),
                "no such file or directory",
            ),
        )
    text = render(args.output_format, result, statistics=args.statistics, quiet=args.quiet)
    if args.output_file:
        try:
            args.output_file.write_text(text, encoding="utf-8")
        except OSError as exc:
            return _usage_error(f"cannot write {args.output_file}: {exc.strerror or exc}")
    else:
        sys.stdout.write(text)
    if result.internal_errors:
        print(
            f"moos-lint: {result.internal_errors} internal error(s); please report them",
            file=sys.stderr,
        )
        return EXIT_ERROR
    if result.diagnostics and not args.exit_zero:
        return EXIT_FINDINGS
    return EXIT_CLEAN


def cmd_expand(args: argparse.Namespace) -> int:
    from moos_lint.nsplug import Preprocessor, expand_text
    from moos_lint.output import display_path

    try:
        defines = _defines(args.define)
    except SystemExit as exc:
        return int(exc.code or EXIT_ERROR)
    pre = Preprocessor(
        defines=defines,
        include_paths=[os.path.abspath(p) for p in args.include_path or []],
        mode="nsplug",
    )
    pre.lenient = bool(args.lenient)
    exp = pre.expand(args.file)
    if exp.read_problem is not None:
        return _usage_error(f"{args.file}: {exp.read_problem.message}")
    sys.stdout.write(expand_text(exp))
    fatal = {"include-not-found", "include-cycle", "unbalanced-conditional", "malformed-directive"}
    status = EXIT_CLEAN
    for prob in exp.problems:
        s = prob.span
        print(f"{display_path(s.path)}:{s.line}:{s.col}: {prob.message}", file=sys.stderr)
        if prob.kind in fatal:
            status = EXIT_FINDINGS
    return status


def cmd_rule(args: argparse.Namespace) -> int:
    from moos_lint.docs import render_rule_page
    from moos_lint.registry import get_rule

    r = get_rule(args.rule)
    if r is None:
        return _usage_error(f"unknown rule `{args.rule}` (see `moos-lint rules`)")
    sys.stdout.write(render_rule_page(r))
    return EXIT_CLEAN


def cmd_rules(args: argparse.Namespace) -> int:
    from moos_lint.registry import all_rules

    rules = all_rules()
    if args.output_format == "json":
        data = [
            {
                "code": r.code,
                "name": r.name,
                "severity": r.severity.value,
                "default": r.default_enabled,
                "scope": r.scope.value,
                "summary": r.summary,
                "url": r.url,
            }
            for r in rules
        ]
        print(json.dumps(data, indent=2))
        return EXIT_CLEAN
    for r in rules:
        on = "on " if r.default_enabled else "off"
        print(f"{r.code}  {r.name:32s} {r.severity.value:8s} {on}  {r.summary}")
    return EXIT_CLEAN
