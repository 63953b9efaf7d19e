"""A process name that does not start with `i`, `p` or `u`.

## What it does
Reports a MOOS process name that does not start with `i`, `p` or `u`
followed by an upper-case letter or a digit (`iGPS`, `pHelmIvP`, `uXMS`,
`p2BTracker`). It looks at every name a process runs under:

- the program of an Antler `Run` line (`Run = Logger @ ...`);
- the `~` alias of a `Run` line (`Run = pShare @ NewConsole = false ~ ShareA`);
- an alias given through `ExtraProcessParams` as `--alias=NAME`;
- in a file without `Run` lines (a plug that missions include), a
  `ProcessConfig = NAME` header, unless a mission of the run launches the
  name (it is reported there once, on its `Run` line) or the linted C++
  builds it (an app's sample block: reported once, on the app). In a mission, a block
  that no `Run` line launches runs under no name: unlaunched-process-config
  reports it (or keeps quiet when its `Run` line is commented out on purpose).
  A header with its `{` on the same line (`ProcessConfig = MyApp {`) names no
  process either: MOOS never finds that block, which brace-on-header reports.
  Nor does an empty block (`ProcessConfig = somethingElse {}` after an app's
  sample block, a sentinel for a parser that reads up to the next header): it
  configures nothing.

`Run` lines with `InhibitMOOSParams = true` are skipped: pAntler passes that
program neither the mission file nor a MOOS name, as it does for a program that
is no MOOS client (`gdb`, an LCM program). The name of a script
(`Run = ./inhouse-dp.sh`, `Run = shoreside.py`) is not judged either: a shell script
is no MOOS client but a wrapper, and what it starts connects under a name of its own;
a Python (or Perl, Ruby, ...) client connects under the name its code gives
(pymoos's `comms.run(host, port, "name")`), not its file's. Its `~` alias, when it
has one, is still judged: pAntler passes it on as the MOOS name.
An alias equal to its program's name is judged once, as the program.

The MOOS infrastructure is exempt, in any case: `MOOSDB`, `ANTLER` /
`pAntler`, and the command-line tools MOOS core ships beside the MOOSDB
(`umm`, `mtm`, `gtm`, `ktm`, `atm`, `mqos`: monitors and timing tools named
like Unix utilities). Names that hold an nsplug macro (`$(X)`) are skipped.


In C++ (a folder of a MOOS app's sources), it checks the app's process name:
the literal first argument of `App.Run("pName", ...)` in `main` (or a name set
to a literal before the call, `const char* sMOOSName = "iGPS";`, unless the
command line may set it first), else the
CMake `add_executable(pName ...)` of the folder (read as text; of a folder
that builds several programs, the one whose source list holds the app class's
files), else the folder name (never for a folder that builds several programs
and none clearly this app). It reports on the `Run` literal, or on the app class when the
name comes from CMake or the folder. A folder that builds several programs
(`add_executable(source_node source_node.cpp)`, `add_executable(sink_node
sink_node.cpp)`) has each of them judged. A program the linted C++ builds is reported
there once, not again on each Run line that launches it nor on its sample block.
Only folders with a class derived from CMOOSApp, AppCastingMOOSApp or
CMOOSInstrument are apps. A name in capitals with an underscore
(`add_executable(MOOSAPPFACTORY_NAME ...)`) is the placeholder of a template an
app generator copies, not judged: the app is named when it is generated.

## Why is this bad?
The MOOS Conventions (section 4.1) name every application by what it does:
`i` for interface apps that talk to hardware or the outside world, `p` for
pure apps that only talk to the MOOSDB, `u` for utilities. The prefix is how a
reader of a mission file, of `uProcessWatch` or of the MOOSDB's client list
tells one kind from another. MOOS-IvP follows it everywhere: every program
launched in its missions has a prefix except `MOOSDB`, and its aliases keep
the program's prefix (`uTimerScript_PING`, `pXRelay_APPLES`,
`--alias=pHelmIvP_Standby`). The only names without one are the aliases
`ShareA` / `ShareB` of a pShare test script in MOOS core and the MOOSDB test
program `app_test`: test code, which the rule leaves alone (`check-tests`).

MOOS-IvP departs from the 2007 document in *what* the prefixes mean
(`u` apps such as uSimMarine run during missions, `p` apps such as pLogger and
pMarineViewer do I/O), so this rule checks only that a prefix is there, not
that it is the right one.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB  @ NewConsole = false
  Run = Logger  @ NewConsole = false
  Run = pShare  @ NewConsole = false ~ ShareA
}
```

## How to fix
Rename the program, or choose an alias that keeps the program's prefix
(`~ pShare_A`), and rename its `ProcessConfig` block to match.

## Options
- `exempt` (list of strings, default `["MOOSDB", "ANTLER", "pAntler", "umm", "mtm",
  "gtm", "ktm", "atm", "mqos"]`):
  names that need no prefix, compared without regard to case; nor do the
  aliases of these programs (`Run = MOOSDB @ NewConsole = false ~ MOOSDB_ALPHA`).
- `check-aliases` (bool, default `true`): also check `~` aliases,
  `--alias=` names and the `ProcessConfig` blocks of aliases. With `false`,
  only program names and blocks that are not an alias are checked.
- `check-tests` (bool, default `false`): also check test programs and test
  missions: files in a `test`, `tests` or `testing` folder (or `testcases`,
  `unittests`, a `*_test_scripts` folder). Their names are picked to exercise code:
  core MOOS builds a MOOSDB test as `app_test` and its pShare test mission
  launches `pShare ~ ShareA`. A file named for a test outside such a folder
  (`sonar_test.moos`) is most often a mission run in the field, and is checked.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Severity
from moos_lint.files.suffixes import script_stem
from moos_lint.files.test_code import is_test_code
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.per_run import per_run
from moos_lint.semantics.catalogue import catalogue_for
from moos_lint.semantics.process_names import PREFIXED, prefix_problem

#: MOOS's own programs: the database, the launcher, and MOOS core's command-line tools
#: (``MOOSCore/Core/tools``: umm, mtm, gtm, ktm, atm, mqos)
INFRASTRUCTURE = ("MOOSDB", "ANTLER", "pAntler", "umm", "mtm", "gtm", "ktm", "atm", "mqos")


def conforms(name: str, exempt: set[str]) -> bool:
    return bool(PREFIXED.match(name)) or name.lower() in exempt


@rule(
    code="N001",
    name="process-name-prefix",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.CPP),
    options={"exempt": list(INFRASTRUCTURE), "check-aliases": True, "check-tests": False},
)
def check(ctx):
    if not ctx.options.get("check-tests", False) and is_test_code(
        ctx.path, ctx.settings.project_root
    ):
        return
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx)
        return
    exempt = {str(n).lower() for n in ctx.options.get("exempt", [])}
    check_aliases = bool(ctx.options.get("check-aliases", True))
    launched: set[str] = set()
    aliases: set[str] = set()
    cat = catalogue_for(ctx.run)
    for run in ctx.moos.runs:
        program = run.program
        launched.add(run.name.lower())
        if run.inhibits_moos_params:
            continue  # no MOOS client (`gdb`, an LCM program): pAntler passes it no MOOS name
        # a wrapper (what it starts connects, not it), or a script that connects under a
        # name its own code gives (pymoos's `comms.run(host, port, "name")`)
        script = script_stem(program) is not None
        info = cat.app(program) if program else None
        if info is not None and info.own:
            pass  # an app of the linted C++: reported once, where it is defined
        elif program and not script and not has_macro(program) and not conforms(program, exempt):
            yield ctx.report(
                run.binary_span,
                f"process `{program}` {prefix_problem(program)}",
                line=run.param.line,
            )
        for alias, span, line in _aliases(run):
            aliases.add(alias.lower())
            if program and program.lower() in exempt:
                continue  # an alias of MOOS's own programs (`MOOSDB ~ MOOSDB_ALPHA`)
            if program and alias.lower() == program.lower():
                continue  # the program's own name, judged above
            if check_aliases and not has_macro(alias) and not conforms(alias, exempt):
                yield ctx.report(
                    span,
                    f"alias `{alias}` of `{program}` {prefix_problem(alias)}",
                    line=line,
                )
    if ctx.moos.runs and not ctx.expansion.incomplete:
        return  # a mission: a block none of its Run lines launches runs under no name
    elsewhere_launched, elsewhere_aliases = _launched_in_run(ctx.run)
    for block in ctx.moos.blocks:
        name = block.name
        low = name.lower()
        if not name or has_macro(name) or low in launched or low in elsewhere_launched:
            continue  # judged on its Run line
        if block.brace_on_header:
            continue  # MOOS never finds the block: it names no process (brace-on-header)
        if not block.params:
            continue  # configures nothing: a sentinel that ends the block before it
        info = cat.app(name)
        if info is not None and info.own:
            continue  # an app of the linted C++ (its sample block): reported where defined
        if not check_aliases and (low in aliases or low in elsewhere_aliases):
            continue
        if not conforms(name, exempt):
            yield ctx.report(
                block.name_span,
                f"ProcessConfig name `{name}` {prefix_problem(name)}",
                line=block.header,
            )


def _aliases(run):
    """(alias, span, line) for the `~` alias and a `--alias=` given through ExtraProcessParams."""
    if run.alias:
        tilde = run.param.line.text.find("~", run.param.value_start)
        if tilde >= 0:
            idx = run.param.line.text.find(run.alias, tilde)
            span = run.param.line.span(idx, idx + len(run.alias)) if idx >= 0 else run.name_span
        else:
            span = run.name_span
        yield run.alias, span, run.param.line
    if run.alias_from_params:
        extra = run.options.get("extraprocessparams", "").lower()
        block = run.param.block
        for p in block.params if block is not None else ():
            if "".join(p.key.split()).lower() != extra:
                continue
            text = p.line.text
            idx = text.find("--alias=", p.value_start)
            if idx >= 0:
                start = idx + len("--alias=")
                end = start + len(run.alias_from_params)
                yield run.alias_from_params, p.line.span(start, end), p.line
                return
        yield run.alias_from_params, run.binary_span, run.param.line


def _launched_in_run(run) -> tuple[set[str], set[str]]:
    """Names (lower case) launched by any file of this lint run, and those that are aliases."""
    return per_run(run, "launched-names", _launched)


def _launched(units) -> tuple[set[str], set[str]]:
    names: set[str] = set()
    aliases: set[str] = set()
    for unit in units:
        for r in unit.moos.runs if unit.moos is not None else ():
            names.add(r.name.lower())
            aliases.update(a.lower() for a, _, _ in _aliases(r))
    return names, aliases


def cpp_check(ctx):
    """The C++ check, on the app model (see :mod:`moos_lint.semantics.cpp_checks`)."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import process_name_prefix

    yield from cpp_findings(
        ctx, process_name_prefix, exempt=tuple(str(n) for n in ctx.options.get("exempt", []))
    )
