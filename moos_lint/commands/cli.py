"""The ``moos-lint`` command line.

Exit status: 0 no findings, 1 findings, 2 usage, configuration or internal error.
Heavy modules are imported inside the commands that need them, so that
``moos-lint --version`` stays instant.
"""

from __future__ import annotations

import os
import sys

from moos_lint import __version__

TYPE_CHECKING = False  # typing itself is not imported at run time

if TYPE_CHECKING:
    import argparse
    from pathlib import Path

EXIT_CLEAN, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2


def _csv(values: list[str] | None) -> list[str]:
    out: list[str] = []
    for v in values or []:
        out.extend(x.strip() for x in v.split(",") if x.strip())
    return out


def _defines(values: list[str] | None) -> dict[str, str]:
    from moos_lint.files.nsplug_calls import DEFINED  # (the value nsplug gives a bare NAME)

    out = {}
    for v in values or []:
        name, eq, value = v.partition("=")
        if not name:
            raise SystemExit(_usage_error(f"--define needs NAME=VALUE, got {v!r}"))
        out[name] = value if eq else DEFINED
    return out


def _jobs(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        import argparse

        raise argparse.ArgumentTypeError(f"must be a whole number of at least 1, not {text!r}")
    return n


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


def _columns() -> int:
    """The terminal's width, as ``shutil.get_terminal_size`` gives it (without its import)."""
    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):
            columns = 0
    return columns or 80


def _formatter_class():
    """argparse's help formatter, measuring the terminal once: argparse makes one for
    every argument it adds."""
    import argparse

    columns = _columns() - 2

    class Formatter(argparse.HelpFormatter):
        def __init__(self, prog, indent_increment=2, max_help_position=24, width=None):
            width = columns if width is None else width
            super().__init__(prog, indent_increment, max_help_position, width)

    return Formatter


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The command-line parser; ``only``: build just that command's arguments (a parser
    costs time to build, and a run needs one)."""
    import argparse
    from pathlib import Path

    from moos_lint.commands.output import FORMATS

    formatter = _formatter_class()
    parser = argparse.ArgumentParser(
        prog="moos-lint",
        formatter_class=formatter,
        description="Lint MOOS and MOOS-IvP mission (.moos) and behavior (.bhv) files "
        "and the C++ of MOOS apps.",
    )
    parser.add_argument("--version", action="version", version=f"moos-lint {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    if only in (None, "check"):
        check = sub.add_parser(
            "check", help="lint files and folders (the default command)", formatter_class=formatter
        )
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
            "--cpp-backend",
            choices=("tree-sitter", "clang"),
            help="how C++ apps are read: tree-sitter (fast, default) or clang (libclang deep mode)",
        )
        check.add_argument(
            "--compile-commands",
            type=Path,
            metavar="PATH",
            help="compile_commands.json (or its folder) for --cpp-backend clang",
        )
        check.add_argument(
            "--output-format",
            choices=FORMATS,
            default=None,
            help="output format (default: text; github when GITHUB_ACTIONS=true)",
        )
        check.add_argument("--output-file", "-o", type=Path, help="write the report to this file")
        check.add_argument(
            "--context",
            action="store_true",
            help="also lint the missions under the project root that include the given files; "
            "report findings in the given files and those missions only (pre-commit)",
        )
        check.add_argument(
            "--baseline",
            type=Path,
            metavar="FILE",
            help="report only findings not in this baseline",
        )
        check.add_argument(
            "--write-baseline",
            type=Path,
            metavar="FILE",
            help="record the current findings in FILE (per file and rule) and exit",
        )
        check.add_argument("--fix", action="store_true", help="apply the fixes findings offer")
        check.add_argument(
            "--diff", action="store_true", help="print the fixes as a unified diff; write nothing"
        )
        check.add_argument("--statistics", action="store_true", help="count findings per rule")
        check.add_argument(
            "--show-settings", action="store_true", help="print the settings and exit"
        )
        check.add_argument("--exit-zero", action="store_true", help="exit 0 even with findings")
        check.add_argument("--quiet", "-q", action="store_true", help="print findings only")
        check.add_argument(
            "--jobs",
            "-j",
            type=_jobs,
            metavar="N",
            help="worker processes (default: the CPU count; small inputs use one)",
        )
        check.add_argument(
            "--no-cache",
            action="store_true",
            help="neither read nor write the result cache (kept in the user's cache folder)",
        )
        check.add_argument(
            "--cache-dir",
            type=Path,
            metavar="DIR",
            help="keep the result cache in DIR (default: ~/.cache/moos-lint, see the README)",
        )
        check.add_argument(
            "--respect-gitignore",
            dest="respect_gitignore",
            action="store_true",
            default=None,
            help="leave out files git ignores (.gitignore, .ignore, global excludes; the default)",
        )
        check.add_argument(
            "--no-respect-gitignore",
            dest="respect_gitignore",
            action="store_false",
            help="also lint files git ignores (a file named on the command line always is)",
        )
        check.add_argument(
            "--color",
            choices=("auto", "always", "never"),
            default="auto",
            help="colour the text output: auto (on a terminal; NO_COLOR, FORCE_COLOR), "
            "always or never",
        )

    if only in (None, "expand"):
        expand = sub.add_parser(
            "expand", help="print a file as nsplug would expand it", formatter_class=formatter
        )
        expand.add_argument("file", type=Path)
        _add_preproc_args(expand)
        expand.add_argument(
            "--lenient",
            action="store_true",
            help="expand the defined macros of a line that also holds undefined ones",
        )

    if only in (None, "rule"):
        rule = sub.add_parser(
            "rule", help="print the documentation of a rule", formatter_class=formatter
        )
        rule.add_argument("rule", metavar="CODE-or-NAME")

    if only in (None, "rules"):
        rules = sub.add_parser("rules", help="list every rule", formatter_class=formatter)
        rules.add_argument("--output-format", choices=("text", "json"), default="text")

    if only in (None, "graph"):
        graph = sub.add_parser(
            "graph", help="draw a mission's processes and variables", formatter_class=formatter
        )
        graph.add_argument("mission", type=Path, help="a .moos mission file")
        graph.add_argument("--format", choices=("html", "dot", "json"), default="html")
        graph.add_argument("-o", "--output", type=Path, help="write to FILE (default: stdout)")
        graph.add_argument(
            "--all-variables", action="store_true", help="also draw variables no one else reads"
        )
        graph.add_argument("--config", type=Path, help="use this config file")
        graph.add_argument("--define", "-D", action="append", metavar="NAME=VALUE")

    if only in (None, "server"):
        server = sub.add_parser(
            "server", help="run the language server for editors (stdio)", formatter_class=formatter
        )
        server.add_argument(
            "--stdio", action="store_true", help="talk on stdin/stdout (the default)"
        )

    return parser


def run() -> None:
    """``moos-lint`` as a program (the console script and ``python -m moos_lint``):
    :func:`main`, then exit without tearing the interpreter down.

    A lint leaves hundreds of thousands of objects behind; freeing them one by
    one, module by module, and the garbage collection Python runs on the way
    out would only delay the exit after the report is written.
    Everything written goes through files that are closed, or through the
    standard streams, which are flushed first.
    """
    status = main()
    for stream in (sys.stdout, sys.stderr):
        try:
            if stream is not None and not stream.closed:  # (the server closes stdout)
                stream.flush()
        except OSError:  # the reader went away (``| head``)
            status = EXIT_ERROR
    os._exit(status)


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv == ["--version"]:  # the one answer that needs no parser
        print(f"moos-lint {__version__}")
        return EXIT_CLEAN
    commands = {"check", "expand", "rule", "rules", "server", "graph"}
    given = list(argv)
    if not argv or argv[0] not in commands - {"check"}:
        from moos_lint.speed.replay import replay  # an unchanged run: its report, before argparse

        status = replay(given)
        if status is not None:
            return status
    if not argv or (argv[0] not in commands and argv[0] not in ("-h", "--help", "--version")):
        argv.insert(0, "check")
    parser = build_parser(argv[0] if argv[0] in commands else None)
    args = parser.parse_args(argv)
    args.argv = given
    try:
        if args.command == "check":
            return cmd_check(args)
        if args.command == "expand":
            return cmd_expand(args)
        if args.command == "rule":
            return cmd_rule(args)
        if args.command == "rules":
            return cmd_rules(args)
        if args.command == "server":
            return cmd_server(args)
        if args.command == "graph":
            return cmd_graph(args)
    except KeyboardInterrupt:
        return EXIT_ERROR
    except BrokenPipeError:
        return EXIT_ERROR
    parser.print_help()
    return EXIT_ERROR


def _settings(args: argparse.Namespace):
    from moos_lint.core.config import ConfigError, resolve_settings
    from moos_lint.files.project import project_root

    settings = resolve_settings(list(args.paths), args.config)
    settings.project_root = project_root(args.paths, settings.config_path)
    for opt in ("select", "extend_select", "ignore"):
        for sel in _csv(getattr(args, opt)):
            from moos_lint.core.registry import is_valid_selector

            if not is_valid_selector(sel):
                raise ConfigError(f"--{opt.replace('_', '-')}: unknown rule or code `{sel}`")
    if args.select:
        settings.select = _csv(args.select)
    settings.extend_select += _csv(args.extend_select)
    settings.ignore += _csv(args.ignore)
    settings.defines.update(_defines(args.define))
    settings.include_paths += [os.path.abspath(p) for p in args.include_path or []]
    if getattr(args, "cpp_backend", None):
        settings.cpp_backend = args.cpp_backend
    if getattr(args, "compile_commands", None):
        settings.compile_commands = os.path.abspath(args.compile_commands)
    if getattr(args, "respect_gitignore", None) is not None:
        settings.respect_gitignore = args.respect_gitignore
    return settings


def cmd_check(args: argparse.Namespace) -> int:
    from moos_lint.core.config import ConfigError

    for p in args.paths:  # a typo lints nothing: an error even with --exit-zero
        if not os.path.lexists(p):
            return _usage_error(f"{p}: no such file or directory")
    try:
        settings = _settings(args)
    except ConfigError as exc:
        return _usage_error(str(exc))
    if args.show_settings:
        import json

        print(json.dumps(settings.as_dict(), indent=2))
        return EXIT_CLEAN
    if not (args.baseline or args.write_baseline):
        return _check(args, settings)
    from moos_lint.core.baseline import BaselineError

    try:
        return _check(args, settings)
    except BaselineError as exc:
        return _usage_error(str(exc))


def _check(args: argparse.Namespace, settings) -> int:
    from pathlib import Path

    from moos_lint.commands.output import render
    from moos_lint.core.context import project_root

    paths = list(args.paths) or [Path(".")]
    # A baseline outside any project (no config, no VCS) is relative to its own folder.
    baseline_file = args.write_baseline or args.baseline
    fallback = os.path.dirname(os.path.abspath(baseline_file)) if baseline_file else None
    root = project_root(settings, paths, fallback)
    base = None
    if args.baseline:
        from moos_lint.core import baseline as bl

        base = bl.load(str(args.baseline), root)

    # --fix/--diff re-lint edited text in memory, and a baseline is written from a fresh run
    use_cache = not (args.no_cache or args.fix or args.diff or args.write_baseline)
    folder = None
    if use_cache:
        from moos_lint.speed.cache import cache_folder

        given = str(args.cache_dir) if args.cache_dir else None
        folder = cache_folder(settings, paths, given)

    fmt = args.output_format or ("github" if os.environ.get("GITHUB_ACTIONS") == "true" else "text")
    # an unchanged run prints the report it printed before, rendered the same way
    replay = folder is not None and not args.baseline
    color = False
    if fmt in ("text", "concise"):
        from moos_lint.commands.output.color import wanted

        color = wanted(args.color, 1 if args.output_file is None else -1)
    render_key = repr((fmt, bool(args.statistics), bool(args.quiet), os.getcwd(), color))
    if replay and folder is not None:
        from moos_lint.speed.cache import cached_output

        shown = cached_output(
            paths, settings, context=args.context, folder=folder, render_key=render_key
        )
        if shown is not None:
            text, has_findings, watch = shown
            failed = _emit(args.output_file, text)
            if failed is not None:
                return failed
            status = EXIT_FINDINGS if has_findings and not args.exit_zero else EXIT_CLEAN
            _remember(args, watch, text, status)
            return status

    from moos_lint.commands.progress import for_terminal

    progress = for_terminal(sys.stderr, fmt, args.quiet, _outside_any_project(settings, root))

    def lint(cache=None, *, filtered: bool = True):
        with _CyclicGCPaused(), _Cleared(progress):
            if folder is not None and cache is None:
                from moos_lint.speed.cache import cached_lint  # the engine loads only on a miss

                result = cached_lint(
                    paths,
                    settings,
                    context=args.context,
                    jobs=args.jobs,
                    folder=folder,
                    progress=progress,
                )
            else:
                from moos_lint.core.engine import lint_paths
                from moos_lint.speed import parallel

                result = lint_paths(
                    paths,
                    settings,
                    context=args.context,
                    cache=cache,
                    jobs=args.jobs,
                    progress=progress,
                    parallel=parallel,
                )
        if base is not None and filtered:
            from moos_lint.core import baseline as bl

            result.diagnostics, result.baselined = bl.new_findings(
                result.diagnostics, base, result.sources
            )
        if not result.files:
            result.warnings.append(no_files_warning(paths))
        return result

    if args.write_baseline:
        result = lint(filtered=False)
        _warn(result)
        return _write_baseline(args, settings, root, result)
    result = lint()
    if args.fix or args.diff:
        from moos_lint.core.fix import fix_until_stable

        outcome = fix_until_stable(lint, first=result)
        _keep_inside(outcome, settings.project_root)
        if args.diff:
            return _show_diff(args, outcome)
        written = _write_fixes(outcome)
        if written is not None:
            return written
        result = outcome.result
    _warn(result)
    text = render(fmt, result, statistics=args.statistics, quiet=args.quiet, color=color)
    # (a run with a warning is not kept: the replay prints no warning)
    if replay and folder is not None and not result.warnings:  # (no cache with --fix or --diff)
        from moos_lint.speed.cache import store_output

        store_output(folder, result, render_key, text, bool(result.diagnostics))
    failed = _emit(args.output_file, text)
    if failed is not None:
        return failed
    if result.internal_errors:
        print(
            f"moos-lint: {result.internal_errors} internal error(s); please report them",
            file=sys.stderr,
        )
        return EXIT_ERROR
    status = EXIT_FINDINGS if result.diagnostics and not args.exit_zero else EXIT_CLEAN
    if replay and result.cache_watch is not None and not result.warnings:
        _remember(args, result.cache_watch, text, status)
    return status


def no_files_warning(paths) -> str:
    return f"warning: no MOOS or C++ files found under {', '.join(str(p) for p in paths)}"


def _warn(result) -> None:
    for warning in result.warnings:
        print(f"moos-lint: {warning}", file=sys.stderr)


def _remember(args: argparse.Namespace, watch: dict, text: str, status: int):
    """Keep a cached run's report for the same command line (:mod:`moos_lint.speed.replay`)."""
    if getattr(args, "argv", None) is None:
        return
    from moos_lint.speed.replay import remember

    paths = [str(p) for p in args.paths]
    config = str(args.config) if args.config else None
    remember(args.argv, paths, config, watch, text, status)


def _outside_any_project(settings, root: str) -> str | None:
    """The folder a run lints when it has no moos-lint config and no version-control
    checkout (None when it has either): a large run there is announced."""
    if settings.config_path:
        return None
    from moos_lint.files.project import vcs_top

    if vcs_top(root) is not None:
        return None
    return os.path.abspath(root)


class _Cleared:
    """The progress line cleared when a lint ends, however it ends."""

    def __init__(self, progress) -> None:
        self.progress = progress

    def __enter__(self) -> None:
        return None

    def __exit__(self, *exc: object) -> None:
        if self.progress is not None:
            self.progress.close()


class _CyclicGCPaused:
    """The cyclic garbage collector paused for one command-line lint (and its forked
    workers).

    A run allocates millions of small objects (lines, parameters, syntax nodes) and
    keeps most of them to the end; almost none die in reference cycles. The
    collector still ran hundreds of times over that growing heap and freed nothing
    (the benchmark's peak memory is the same either way).
    Reference counting frees everything else as usual. The language server, which
    runs for hours, keeps the collector.
    """

    def __enter__(self) -> None:
        import gc

        self.was_enabled = gc.isenabled()
        gc.disable()

    def __exit__(self, *exc: object) -> None:
        import gc

        if self.was_enabled:
            # What the lint made stays alive to the end of the command: moved out of the
            # collector's sight, it is not walked by the collection that re-enabling would
            # start at the next allocation, over every object made since the pause
            # (about 25 ms after a run over the MOOS-IvP tree's missions).
            gc.freeze()
            gc.enable()


def _emit(path: Path | None, text: str) -> int | None:
    """Write a report to ``path`` (stdout when None); an exit status when that fails."""
    if path is None:
        from moos_lint.files.streams import write_stdout

        write_stdout(text)
        return None
    try:
        path.write_text(text, encoding="utf-8", errors="surrogateescape")
    except OSError as exc:
        return _usage_error(f"cannot write {path}: {exc.strerror or exc}")
    return None


def _write_baseline(args: argparse.Namespace, settings, root: str, result) -> int:
    from moos_lint.core import baseline as bl
    from moos_lint.core.registry import select_rules

    path = str(args.write_baseline)
    previous = bl.load(path, root) if os.path.exists(path) else None
    ran = {r.code for r in select_rules(settings.select, settings.extend_select, settings.ignore)}
    new = bl.build(
        result.diagnostics,
        root,
        result.sources,
        previous=previous,
        linted=result.files,
        ran_codes=ran,
    )
    try:
        bl.write(path, new)
    except OSError as exc:
        return _usage_error(f"cannot write {path}: {exc.strerror or exc}")
    if not args.quiet:
        print(
            f"moos-lint: wrote {new.total} finding(s) in {len(new.files)} file(s) to {path}",
            file=sys.stderr,
        )
    return EXIT_ERROR if result.internal_errors else EXIT_CLEAN


def _show_diff(args: argparse.Namespace, outcome) -> int:
    from moos_lint.commands.output import display_path
    from moos_lint.core.fix import unified_diff

    text = "".join(unified_diff(doc, display_path(doc.path)) for doc in outcome.changed)
    failed = _emit(args.output_file, text)
    if failed is not None:
        return failed
    if not args.quiet:
        n, files = outcome.fixed, len(outcome.changed)
        print(f"moos-lint: would fix {n} finding(s) in {files} file(s)", file=sys.stderr)
    return EXIT_FINDINGS if outcome.changed else EXIT_CLEAN


def _keep_inside(outcome, root: str | None) -> None:
    """Never write (nor show the text of) a file whose real path lies outside the
    project, a link inside the project to a file outside included; say so."""
    if root is None:
        return
    from moos_lint.commands.output import shown_path
    from moos_lint.files.project import real_within

    for doc in outcome.changed:
        if not real_within(doc.path, root):
            del outcome.docs[doc.path]
            print(
                f"moos-lint: not fixing {shown_path(doc.path)}: "
                "its real path lies outside the project",
                file=sys.stderr,
            )


def _write_fixes(outcome) -> int | None:
    from moos_lint.commands.output import display_path
    from moos_lint.core.fix import write_atomic

    for doc in outcome.changed:
        try:
            write_atomic(doc)
        except OSError as exc:
            return _usage_error(f"cannot write {display_path(doc.path)}: {exc.strerror or exc}")
    if outcome.changed:
        print(
            f"moos-lint: fixed {outcome.fixed} finding(s) in {len(outcome.changed)} file(s)",
            file=sys.stderr,
        )
    return None


def cmd_expand(args: argparse.Namespace) -> int:
    from moos_lint.commands.output import display_path
    from moos_lint.frontends.nsplug import Preprocessor, expand_text

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


def cmd_graph(args: argparse.Namespace) -> int:
    from moos_lint.commands.graph import GraphError, build_graph, render
    from moos_lint.core.config import ConfigError, resolve_settings

    try:
        settings = resolve_settings([args.mission], args.config)
        settings.defines.update(_defines(args.define))
        g = build_graph(str(args.mission), settings, all_variables=args.all_variables)
    except (ConfigError, GraphError) as exc:
        return _usage_error(str(exc))
    return _emit(args.output, render(g, args.format)) or EXIT_CLEAN


def cmd_rule(args: argparse.Namespace) -> int:
    from moos_lint.commands.rule_page import render_rule_page
    from moos_lint.core.registry import get_rule

    r = get_rule(args.rule)
    if r is None:
        return _usage_error(f"unknown rule `{args.rule}` (see `moos-lint rules`)")
    sys.stdout.write(render_rule_page(r))
    return EXIT_CLEAN


def cmd_rules(args: argparse.Namespace) -> int:
    from moos_lint.core.registry import all_rules

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
        import json

        print(json.dumps(data, indent=2))
        return EXIT_CLEAN
    for r in rules:
        on = "on " if r.default_enabled else "off"
        print(f"{r.code}  {r.name:32s} {r.severity.value:8s} {on}  {r.summary}")
    return EXIT_CLEAN


def cmd_server(args: argparse.Namespace) -> int:
    try:
        from moos_lint.commands.lsp.server import serve
    except ImportError as exc:
        return _usage_error(
            f"the language server needs pygls ({exc}); install it with "
            "`pip install 'moos-lint[lsp]'`"
        )
    return serve()
