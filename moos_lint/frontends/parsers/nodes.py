"""The model the rules look at: mission files, their blocks and launches, behavior files.

Parsers build these objects from preprocessed lines; rules only read them.
Every node keeps the :class:`~moos_lint.frontends.nsplug.Line` it came from, so any
finding maps back to the file and line the user edits.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from moos_lint.files.diagnostics import Span
from moos_lint.files.suffixes import script_stem
from moos_lint.frontends.nsplug import Expansion, Line

#: Keys every MOOS app reads from the top of a mission file (CMOOSApp, MOOSDB, pAntler).
GLOBAL_KEYS = {
    "serverhost": "ServerHost",
    "serverport": "ServerPort",
    "community": "Community",
    "moostimewarp": "MOOSTimeWarp",
    "latorigin": "LatOrigin",
    "longorigin": "LongOrigin",
}

#: Keys CMOOSApp::Run read in MOOS before v10 (``GetValue("SIMULATOR")`` set
#: IsSimulateMode(), ``GetValue("PLAYBACK")`` the playback mode), ignored since but still
#: set by MOOS-IvP's own missions (x1_alpha, m5_hunter, m8_hugo): harmless, and known.
LEGACY_GLOBALS = ("Simulator", "Playback")

#: Every key MOOS, pAntler and the MOOS apps read at the top of a mission file: the keys
#: above and those only some programs read.
MOOS_GLOBALS = [
    *GLOBAL_KEYS.values(),
    "UseMOOSComms",
    "NoNetwork",
    "WebServerPort",
    "ClientTimeout",
    "WarningLatency",
    "tcpnodelay",
    "TERM_REPORTING",
    "GlobalLogPath",
    "CircuitName",
    "MagneticOffset",
    *LEGACY_GLOBALS,
    "ProcessConfig",
]


#: the lines git writes around the two sides of a conflict (``<<<<<<< HEAD``, ``=======``,
#: ``>>>>>>> branch``; ``|||||||`` in diff3 style)
_CONFLICT = re.compile(r"(?:<{7}|>{7}|\|{7})(?:\s|$)|={7}\s*$")


def conflict_marker(text: str) -> bool:
    """True when ``text`` (stripped) is a merge-conflict marker left in the file."""
    return _CONFLICT.match(text) is not None


#: where a conflict left in a whole text opens (``<<<<<<< HEAD`` at a line's start), for
#: a search of the text at once
CONFLICT_OPENED = re.compile(r"^<{7}(?:[ \t]|$)", re.M)


def has_macro(text: str) -> bool:
    """True when ``text`` still holds an unexpanded nsplug macro, or a placeholder of
    another template generator (:func:`has_placeholder`)."""
    return "$(" in text or "%(" in text or has_placeholder(text)


#: a placeholder of a template generator other than nsplug: ``{{SPEED}}``, ``{{ cfg.speed }}``
#: (not uTimerScript's arithmetic, ``{{$[TCOUNT]+1}/2}``)
_PLACEHOLDER = re.compile(r"\{\{\s*[A-Za-z_][\w.]*\s*\}\}")


def has_placeholder(text: str) -> bool:
    """True when ``text`` holds a placeholder of a template generator other than nsplug
    (``speed = {{SPEED}}``, which a script fills in with ``str.replace`` or Jinja
    before the file is launched)."""
    return "{{" in text and _PLACEHOLDER.search(text) is not None


@dataclass(slots=True)
class Param:
    """A ``key = value`` line. Positions are indices into ``line.text``."""

    key: str
    value: str
    line: Line
    key_start: int
    value_start: int
    value_end: int
    block: Block | None = None
    _lkey: str | None = field(default=None, init=False, repr=False, compare=False)

    @property
    def lkey(self) -> str:
        """The key as MOOS compares it: spaces removed, case folded."""
        if self._lkey is None:
            self._lkey = "".join(self.key.split()).lower()
        return self._lkey

    @property
    def key_span(self) -> Span:
        return self.line.span(self.key_start, self.key_start + len(self.key))

    @property
    def value_span(self) -> Span:
        return self.line.span(self.value_start, self.value_end)

    @property
    def span(self) -> Span:
        return self.line.span(self.key_start, self.value_end)


@dataclass(slots=True)
class TextField:
    """A field of a block written in protobuf text format (``name: value`` or ``name { }``)."""

    name: str
    line: Line
    start: int
    end: int
    value: str | None  # the scalar value as written; None for a nested message
    children: list[TextField] | None  # the nested message's fields
    extension: bool = False  # ``[package.name]``

    @property
    def name_span(self) -> Span:
        width = len(self.name) + (2 if self.extension else 0)
        return self.line.span(self.start, self.start + width)


@dataclass(slots=True)
class Block:
    """``ProcessConfig = NAME`` followed by ``{ ... }``."""

    name: str
    header: Line | None  # None for an orphan ``{ ... }``
    name_start: int = 0
    open: Line | None = None
    close: Line | None = None
    params: list[Param] = field(default_factory=list)
    brace_on_header: bool = False
    #: the block is read with protobuf's text format (goby's MOOS apps): its
    #: fields are in ``text_fields``, its syntax errors in ``text_errors``
    text_format: bool = False
    text_fields: list[TextField] = field(default_factory=list)
    text_errors: list[tuple[Line, int, int, str]] = field(default_factory=list)
    #: lines that are one nsplug macro alone (``$(RUN)``), whose text a launch script
    #: gives: they may hold any parameter, a Run line among them
    macro_lines: list[Line] = field(default_factory=list)
    _lname: str | None = field(default=None, init=False, repr=False, compare=False)
    #: what readers work out from the block once (it never changes after parsing)
    memo: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    @property
    def lname(self) -> str:
        if self._lname is None:
            self._lname = self.name.lower()
        return self._lname

    @property
    def name_span(self) -> Span:
        line = self.header or self.open
        assert line is not None
        if self.header is None:
            return line.span()
        return line.span(self.name_start, self.name_start + len(self.name))

    def get(self, key: str) -> list[Param]:
        k = key.lower()
        return [p for p in self.params if p.lkey == k]


@dataclass(slots=True)
class RunLine:
    """An Antler ``Run = BINARY @ OPTIONS ~ ALIAS`` line."""

    param: Param
    binary: str
    has_at: bool
    options: dict[str, str]
    alias: str | None
    alias_from_params: str | None = None  # ``--alias=`` given through ExtraProcessParams
    #: as written: the options between the ``@`` and the ``~``, and all after the ``~``
    #: (the alias, and what pAntler never reads after its comma)
    options_text: str = ""
    alias_text: str = ""
    #: the program pAntler starts, without its folder
    program: str = field(init=False)
    #: the MOOS name the process connects as, and the block it reads
    name: str = field(init=False)

    def __post_init__(self) -> None:
        # (read at every turn by the rules and the models: worked out once)
        self.program = self.binary.replace("\\", "/").rsplit("/", 1)[-1]
        self.name = self.alias_from_params or self.alias or self.program

    @property
    def inhibits_moos_params(self) -> bool:
        """``InhibitMOOSParams = true``: pAntler passes neither the mission file nor the
        MOOS name, as for a program that is no MOOS client (``gdb``, an LCM program)."""
        return self.options.get("inhibitmoosparams", "").strip().lower() == "true"

    @property
    def script_block(self) -> str | None:
        """The block a script started without an alias reads besides its own name:
        ``Run = ./iSonar.py`` reads ``ProcessConfig = iSonar`` (the script, not pAntler,
        names its MOOS client). None for a compiled program or an aliased one."""
        if self.alias_from_params or self.alias:
            return None
        return script_stem(self.name)

    @property
    def block_names(self) -> tuple[str, ...]:
        """The names of the blocks the process may read (see :attr:`script_block`)."""
        stem = self.script_block
        return (self.name, stem) if stem else (self.name,)

    def _find(self, text: str, after: int = 0) -> Span:
        line = self.param.line
        idx = line.text.find(text, self.param.value_start + after) if text else -1
        if idx < 0:
            return self.param.value_span
        return line.span(idx, idx + len(text))

    @property
    def binary_span(self) -> Span:
        return self._find(self.binary.strip())

    @property
    def name_span(self) -> Span:
        if self.alias and not self.alias_from_params:
            tilde = self.param.line.text.find("~", self.param.value_start)
            return self._find(self.alias, max(0, tilde - self.param.value_start))
        return self.binary_span


@dataclass(slots=True)
class MoosFile:
    """A ``.moos`` file (or fragment) after nsplug, as MOOS would read it."""

    path: str
    expansion: Expansion
    lines: list[Line] = field(default_factory=list)
    globals: list[Param] = field(default_factory=list)
    blocks: list[Block] = field(default_factory=list)
    orphan_blocks: list[Block] = field(default_factory=list)
    unclosed_blocks: list[Block] = field(default_factory=list)
    headers_without_block: list[Line] = field(default_factory=list)
    stray_closers: list[Line] = field(default_factory=list)
    malformed: list[Line] = field(default_factory=list)
    # built on first use, again whenever blocks or Antler lines were added since
    _by_name: tuple[int, dict[str, list[Block]]] | None = field(
        default=None, init=False, repr=False, compare=False
    )
    _runs: tuple[tuple[int, ...], list[RunLine]] | None = field(
        default=None, init=False, repr=False, compare=False
    )
    # (sizes, line -> its index, lower-case key -> its params), for read_values
    _values: tuple[tuple[int, ...], dict[int, int], dict[str, list[Param]]] | None = field(
        default=None, init=False, repr=False, compare=False
    )

    def blocks_named(self, name: str) -> list[Block]:
        if self._by_name is None or self._by_name[0] != len(self.blocks):
            index: dict[str, list[Block]] = {}
            for b in self.blocks:
                index.setdefault(b.lname, []).append(b)
            self._by_name = (len(self.blocks), index)
        return list(self._by_name[1].get(name.lower(), ()))

    @property
    def antler_blocks(self) -> list[Block]:
        return self.blocks_named("ANTLER")

    @property
    def is_mission(self) -> bool:
        """A mission launches processes: it has an ANTLER block."""
        return bool(self.antler_blocks)

    @property
    def runs(self) -> list[RunLine]:
        blocks = self.antler_blocks
        key = (len(self.blocks), *(len(b.params) for b in blocks))
        if self._runs is None or self._runs[0] != key:
            self._runs = (key, [run for block in blocks for run in antler_runs(block)])
        return list(self._runs[1])

    def global_values(self, key: str) -> list[Param]:
        k = key.lower()
        return [p for p in self.globals if p.lkey == k]

    @property
    def all_params(self) -> list[Param]:
        out = list(self.globals)
        for b in self.blocks:
            out.extend(b.params)
        return out

    def read_values(self, key: str) -> list[Param]:
        """The ``key = value`` lines (any case, blocks included) CMOOSFileReader's
        ``GetValue`` may read: the first in the file, and each later one in an ``#ifdef``
        branch that excludes every earlier one (``LatOrigin``, ``MOOSTimeWarp``)."""
        sizes = (len(self.lines), len(self.globals), *(len(b.params) for b in self.blocks))
        if self._values is None or self._values[0] != sizes:
            index: dict[str, list[Param]] = {}
            for p in self.all_params:
                index.setdefault(p.lkey, []).append(p)
            lines = {id(line): i for i, line in enumerate(self.lines)}
            self._values = (sizes, lines, index)
        _sizes, order, by_key = self._values
        found = sorted(
            by_key.get(key.lower(), ()),
            key=lambda p: order.get(id(p.line), len(order)),
        )
        return [p for i, p in enumerate(found) if all(q.line.excludes(p.line) for q in found[:i])]


# ------------------------------------------------------------------ Antler
# How pAntler reads its Run lines: the parsed file derives them on first use.
def _squeeze(text: str) -> str:
    return "".join(text.split())


def parse_run(param: Param, block: Block) -> RunLine:
    """Read a Run line the way pAntler's CreateMOOSProcess does."""
    value = param.value
    if "@" in value:
        binary, _, rest = value.partition("@")
        has_at = True
    else:
        binary, rest, has_at = value, "", False
    opts_text, _, alias_text = rest.partition("~")
    options: dict[str, str] = {}
    for item in opts_text.split(","):
        k, _, v = item.partition("=")
        if k.strip():
            options[_squeeze(k).lower()] = _squeeze(v)
    alias = _squeeze(alias_text.split(",", 1)[0]) or None if has_at else None
    binary = _squeeze(binary)  # pAntler reads lines with every space removed
    alias_from_params = None
    extra = options.get("extraprocessparams")
    if extra:
        for p in block.params:
            if _squeeze(p.key).lower() == extra.lower():
                for token in p.value.split(","):
                    token = _squeeze(token)
                    if token.startswith("--alias="):
                        alias_from_params = token[len("--alias=") :] or None
    return RunLine(param, binary, has_at, options, alias, alias_from_params, opts_text, alias_text)


def antler_runs(block: Block) -> list[RunLine]:
    return [parse_run(p, block) for p in block.params if p.lkey == "run"]


# --------------------------------------------------------------------- behaviors
@dataclass(slots=True)
class BhvParam:
    key: str
    value: str
    line: Line
    key_start: int
    value_start: int
    value_end: int

    @property
    def lkey(self) -> str:
        """As the helm compares it: lower case, a leading ``_`` ignored."""
        return self.key.lower().lstrip("_")

    @property
    def key_span(self) -> Span:
        return self.line.span(self.key_start, self.key_start + len(self.key))

    @property
    def value_span(self) -> Span:
        return self.line.span(self.value_start, self.value_end)


@dataclass(slots=True)
class Behavior:
    kind: str
    header: Line
    kind_start: int
    params: list[BhvParam] = field(default_factory=list)
    closed: bool = False

    @property
    def kind_span(self) -> Span:
        return self.header.span(self.kind_start, self.kind_start + len(self.kind))

    def get(self, key: str) -> list[BhvParam]:
        k = key.lower()
        return [p for p in self.params if p.lkey == k]

    @property
    def name(self) -> BhvParam | None:
        for p in self.params:
            if p.lkey in ("name", "descriptor"):
                return p
        return None


@dataclass(slots=True)
class Initialize:
    var: str
    value: str
    line: Line
    deferred: bool
    var_start: int

    @property
    def var_span(self) -> Span:
        return self.line.span(self.var_start, self.var_start + len(self.var))


@dataclass(slots=True)
class SetBlock:
    mode_var: str
    value: str
    header: Line
    conditions: list[tuple[str, Line]] = field(default_factory=list)
    else_value: str | None = None


@dataclass(slots=True)
class BehaviorFile:
    path: str
    expansion: Expansion
    lines: list[Line] = field(default_factory=list)
    behaviors: list[Behavior] = field(default_factory=list)
    initializes: list[Initialize] = field(default_factory=list)
    sets: list[SetBlock] = field(default_factory=list)
    #: lines the helm rejects (the whole behavior set then fails), with the reason
    invalid: list[tuple[Line, str]] = field(default_factory=list)
    unclosed: list[Line] = field(default_factory=list)
