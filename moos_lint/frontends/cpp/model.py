"""The app interface model: what one MOOS app publishes, subscribes to, handles and reads.

An app is the C++ files of one folder. Everything carries a :class:`Span` so
that rules, and a later join with missions, can point at the code.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from moos_lint.files.diagnostics import Span

#: The MOOS base classes an app derives from.
APP_BASES = ("CMOOSApp", "AppCastingMOOSApp", "CMOOSInstrument", "AppCastingMOOSInstrument")


@dataclass(slots=True)
class Name:
    """A MOOS variable name as the code writes it.

    ``text`` is the whole name when it is known statically; otherwise the name
    is dynamic and ``prefix`` holds what is known of its beginning.
    """

    source: str  # the expression as written
    text: str | None = None
    prefix: str = ""
    #: what is known of the name's end when the whole is not (``m_prefix + "_PITCH"``,
    #: ``varName("NAV_YAW")``, a table indexed by ``Yaw``): enough for its last word
    suffix: str = ""
    #: the app's configuration key that may change the name (``prefix`` for ``m_prefix``)
    config_key: str | None = None
    #: the app upper-cases the key's value before it publishes under it
    config_upper: bool = False

    @property
    def last(self) -> str:
        """The name as far as rules keyed on its last word need it."""
        return self.text if self.text is not None else self.suffix

    @property
    def dynamic(self) -> bool:
        return self.text is None

    @property
    def wildcard(self) -> bool:
        return self.text is not None and ("*" in self.text or "?" in self.text)


@dataclass(slots=True)
class Value:
    """A value expression: as written, and with the function's local assignments substituted.

    ``expanded`` marks angle wraps found between an assignment and the use as
    ``__wrap_pi(...)`` (to ±π) or ``__wrap_2pi(...)`` (to [0, 2π)).
    """

    text: str
    expanded: str
    span: Span
    number: float | None = None  # a numeric constant, when the value is one
    #: "integer" | "floating" | "string" | "bool", as written before the call converts it
    #: (libclang deep mode; None: not known)
    type: str | None = None
    #: unit, sense, range and sign (:mod:`moos_lint.frontends.cpp.values`), for published angles,
    #: headings, positions and depths
    abstract: Any = None


@dataclass(slots=True)
class Publication:
    name: Name
    value: Value | None
    span: Span  # the call
    name_span: Span
    function: str  # the enclosing function, e.g. ``Sim::OnNewMail``
    active: bool = True  # False when libclang sees the call compiled out
    #: for a call that is a whole statement of a block: (the block's first byte, the
    #: statement's place among the block's statements); calls in consecutive places
    #: are written one after the other
    statement: tuple[int, int] | None = None


@dataclass(slots=True)
class Subscription:
    name: Name
    span: Span
    name_span: Span
    function: str
    active: bool = True


@dataclass(slots=True)
class Assignment:
    """``target = value`` (also declarations with an initialiser)."""

    target: str
    value: Value
    span: Span
    function: str


@dataclass(slots=True)
class MailKey:
    """A mail key OnNewMail (or a function it calls) compares against."""

    text: str
    span: Span
    prefix: bool = False  # matched as a prefix (``strBegins(key, "X_")``, ``key.find("X_")``)
    suffix: bool = False  # matched as a suffix (``strEnds(key, "_X")``)
    #: compared with the message's own name (``msg.GetKey()``, a local set from it,
    #: ``msg.IsName("X")``, ``PeekMail(mail, "X", msg)``), not with a string that only
    #: holds a key (a ``key=value`` pair parsed from a message's text)
    direct: bool = False
    #: where the ``||`` chain the test is one alternative of begins (byte offset), -1 when
    #: the test stands alone: ``key == "OLD_NAME" || key == "NEW_NAME"`` runs on either
    either_at: int = -1
    #: the branch the test guards does nothing (``else if(key == "X") {}``: mail ignored)
    empty_branch: bool = False
    #: tested with ``!=``: the branch runs on every other name (the template's catch-all
    #: ``else if(key != "APPCAST_REQ") reportRunWarning(...)``); the name itself passes
    negated: bool = False
    #: the name's expression when it is not a literal (``m_moosvar_saturation``, a ``#define``)
    held_in: str = ""
    #: how the branch the test guards reads the message's value: "number" when only as a
    #: number (``msg.GetDouble()``, a local set from it), "text" when as text or by asking
    #: its type, "" when it does not read it or hands the message on
    reads: str = ""


@dataclass(slots=True)
class ConfigParam:
    text: str
    span: Span
    #: the app reads every key that starts with ``text`` (``param.find("IMAGE_") == 0``,
    #: ``strBegins(param, "IMAGE_")``)
    prefix: bool = False


@dataclass(slots=True)
class TrigUse:
    """``sin(x)``, ``cos(x)`` or ``tan(x)`` (C++'s, which take radians): the function and
    its argument, with the argument's value (:mod:`moos_lint.frontends.cpp.values`)."""

    function: str
    value: Value
    span: Span  # the call
    within: str  # the enclosing function


@dataclass(slots=True)
class UnitMix:
    """A sum, difference or comparison of an angle in degrees with one in radians: the
    operator, each side as written with its value, and where."""

    op: str
    left: Value
    right: Value
    span: Span
    within: str  # the enclosing function


@dataclass(slots=True)
class OriginRead:
    """``m_MissionReader.GetValue("LatOrigin", lat)``: a read of the local grid's origin.
    ``optional``: the read is the test of an ``if`` with no ``else`` (the app goes on
    without an origin and says nothing: it makes its own, or does without)."""

    key: str
    span: Span
    optional: bool


@dataclass(slots=True)
class IOUse:
    """External I/O: ``kind`` is serial, device, termios, can, usb, socket or network
    (``moos``: a client of another MOOS community, the I/O of a bridge; ``gui``: a
    window toolkit, FLTK or Qt)."""

    kind: str
    detail: str
    span: Span

    @property
    def device(self) -> bool:
        return self.kind in ("serial", "device", "can", "usb")


@dataclass(slots=True)
class CaseMismatch:
    """A string compared with a literal that its case conversion rules out: after
    ``param = tolower(...)``, ``param == "TSS_FILE"`` is never true."""

    subject: str  # the variable compared (``param``)
    literal: str  # the literal as written (``TSS_FILE``)
    conversion: str  # the call that made its case (``tolower``)
    case: str  # "lower" or "upper"
    converted_at: int  # the line of that call
    span: Span  # the literal, quotes included
    negated: bool = False  # ``!=``: always true


@dataclass(slots=True)
class DecimalComma:
    """A number written with a decimal comma (``0,514444``), which C++ reads as the comma
    operator: the expression up to the comma, then the digits after it, thrown away."""

    written: str  # ``0,514444``
    span: Span  # the number as written
    #: the expression the comma operator evaluates and keeps
    kept: str


@dataclass(slots=True)
class ShadowedBranch:
    """A branch of an ``if`` / ``else if`` chain that never runs: its test repeats one an
    earlier branch of the chain takes (``else if(key == "NAV_X")`` after
    ``if(key == "NAV_X")``)."""

    test: str  # the later test as written: ``key == "NAV_X"``
    name: str  # the name it tests for
    span: Span  # the later test's literal
    earlier_line: int  # the line of the earlier test that takes the name
    #: the earlier test ignores case (``MOOSStrCmp``) and this one does not
    earlier_caseless: bool
    function: str  # the enclosing function: ``App::OnNewMail``


@dataclass(slots=True)
class GeodesyCall:
    """A call of one of CMOOSGeodesy's conversions (``facts.GEODESY_ARGUMENTS``), with its
    arguments as written."""

    function: str
    arguments: list[tuple[str, Span]]
    span: Span
    #: the parameter names of a function of the same name that the repository declares
    #: itself, when they differ from CMOOSGeodesy's (its own order, which the call follows)
    own_signature: tuple[str, ...] | None = None
    #: the object the call is made on, as written (``geod`` in ``geod.LatLong2LocalUTM``),
    #: for a member call
    receiver: str | None = None


@dataclass(slots=True)
class CppClass:
    name: str
    bases: list[str]
    span: Span


@dataclass(slots=True)
class CppFile:
    path: str
    classes: list[CppClass] = field(default_factory=list)
    publications: list[Publication] = field(default_factory=list)
    subscriptions: list[Subscription] = field(default_factory=list)
    assignments: list[Assignment] = field(default_factory=list)
    #: writes to a NED z (positive down), with the value's abstract value
    ned_writes: list[Assignment] = field(default_factory=list)
    mail_keys: list[MailKey] = field(default_factory=list)
    config_params: list[ConfigParam] = field(default_factory=list)
    origin_reads: list[OriginRead] = field(default_factory=list)
    io: list[IOUse] = field(default_factory=list)
    #: MOOS variables this file converts from degrees on arrival: (name, span, helper)
    consumed_degrees: list[tuple[str, Span, str]] = field(default_factory=list)
    run_names: list[tuple[str, Span]] = field(default_factory=list)  # literal App.Run("x", ...)
    geodesy_calls: list[GeodesyCall] = field(default_factory=list)
    decimal_commas: list[DecimalComma] = field(default_factory=list)
    shadowed_branches: list[ShadowedBranch] = field(default_factory=list)
    case_mismatches: list[CaseMismatch] = field(default_factory=list)
    trig_uses: list[TrigUse] = field(default_factory=list)
    #: calls of MOOS's angle functions (``angle360(h)``, ``MOOSDeg2Rad(h)``) with their
    #: argument's value
    angle_arguments: list[TrigUse] = field(default_factory=list)
    unit_mixes: list[UnitMix] = field(default_factory=list)
    has_main: bool = False
    has_on_new_mail: bool = False
    #: OnNewMail passes whole messages to code we cannot follow (generic handling)
    mail_generic: bool = False
    #: names of registrations taken out on purpose (``//Register("X", 0);``, under ``#if 0``)
    commented_registrations: list[str] = field(default_factory=list)
    #: the file hands the app's comms client, or the app itself, to other code
    #: (``m_helper.subscribe(m_Comms)``, ``new Worker(this)``), which may register for it
    comms_shared: bool = False
    parse_errors: bool = False


@dataclass(slots=True)
class AppModel:
    """One folder of C++: a MOOS app when one of its classes derives from a MOOS app base."""

    folder: str
    files: list[CppFile] = field(default_factory=list)
    app_class: CppClass | None = None
    base_chain: list[str] = field(default_factory=list)  # app class first, MOOS base last
    process_name: str | None = None
    process_name_source: str = ""  # "run" | "cmake" | "folder"
    process_name_span: Span | None = None
    #: the executable CMake builds from the folder (what a Run line names), when clear
    executable: str | None = None
    backend: str = "tree-sitter"

    @property
    def is_app(self) -> bool:
        return self.app_class is not None

    @property
    def is_instrument(self) -> bool:
        return any(b in ("CMOOSInstrument", "AppCastingMOOSInstrument") for b in self.base_chain)

    @property
    def publications(self) -> list[Publication]:
        return [p for f in self.files for p in f.publications if p.active]

    @property
    def subscriptions(self) -> list[Subscription]:
        return [s for f in self.files for s in f.subscriptions if s.active]

    @property
    def assignments(self) -> list[Assignment]:
        return [a for f in self.files for a in f.assignments]

    @property
    def ned_writes(self) -> list[Assignment]:
        return [a for f in self.files for a in f.ned_writes]

    @property
    def geodesy_calls(self) -> list[GeodesyCall]:
        return [g for f in self.files for g in f.geodesy_calls]

    @property
    def decimal_commas(self) -> list[DecimalComma]:
        return [d for f in self.files for d in f.decimal_commas]

    @property
    def shadowed_branches(self) -> list[ShadowedBranch]:
        return [b for f in self.files for b in f.shadowed_branches]

    @property
    def case_mismatches(self) -> list[CaseMismatch]:
        return [c for f in self.files for c in f.case_mismatches]

    @property
    def mail_keys(self) -> list[MailKey]:
        return [k for f in self.files for k in f.mail_keys]

    @property
    def config_params(self) -> list[ConfigParam]:
        return [c for f in self.files for c in f.config_params]

    @property
    def io(self) -> list[IOUse]:
        return [u for f in self.files for u in f.io]
