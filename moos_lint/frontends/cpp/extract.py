"""From one parsed C++ file to its part of the app model (:class:`CppFile`).

Two passes over the query's matches of every file of a folder: first the
tables that name resolution needs across the folder (``#define`` strings,
what each member or constant is assigned), then the facts themselves.
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from moos_lint.files.diagnostics import Span
from moos_lint.frontends.cpp import branches
from moos_lint.frontends.cpp.facts import (
    DEG2RAD_NAME,
    GEODESY_ARGUMENTS,
    HELPERS,
    INVERSE_TRIG,
)
from moos_lint.frontends.cpp.model import (
    Assignment,
    CaseMismatch,
    ConfigParam,
    CppClass,
    CppFile,
    DecimalComma,
    GeodesyCall,
    IOUse,
    MailKey,
    Name,
    OriginRead,
    Publication,
    ShadowedBranch,
    Subscription,
    TrigUse,
    UnitMix,
    Value,
)
from moos_lint.frontends.cpp.names import (
    MAIL_COMPARES,
    PEEK_MAIL,
    WORD_BYTES,
    callee_name,
    function_declarator,
    key_literal,
    mail_key_of,
    valued_name,
)

#: ``Notify``, and what a helm behavior posts through (IvPBehavior.h: ``postMessage(var,
#: value)``, ``postIntMessage`` of a number rounded, ``postRepeatableMessage``), name first
PUBLISH = {"Notify", "postMessage", "postIntMessage", "postRepeatableMessage"}
#: a message built to be posted: ``CMOOSMsg Msg(MOOS_NOTIFY, "DESIRED_RUDDER", dfRudder)``
#: (then ``m_Comms.Post(Msg)``, or handed back in a task's message list)
NOTIFY_MSG = "CMOOSMsg"
NOTIFY_KINDS = ("MOOS_NOTIFY", "'N'")
#: ``Register``, and pHelmIvP's wrapper round it (HelmIvP.cpp:1182-1190), through which
#: the helm registers for ``MOOS_MANUAL_OVERRIDE`` and its old spelling ``_OVERIDE``
SUBSCRIBE = {"Register", "registerSingleVariable"}
CONFIG_CALLS = {"GetConfigurationParam", "GetConfigurationParamNoCase", "GetConfiguration"}
#: ``m_MissionReader.GetValue("LatOrigin", lat)``: a top-of-file key of the mission
GLOBAL_VALUE = "GetValue"
#: the keys of the local grid's origin, as apps read them
ORIGIN_KEYS = {"latorigin", "longorigin"}
#: the words of names that may hold an angle: only a sum, difference or comparison of two
#: such operands is looked at for degrees mixed with radians (mixed-angle-units)
ANGLE_WORDS = (
    "[Hh]ead|HEAD|[Hh]dg|HDG|[Yy]aw|YAW|[Pp]itch|PITCH|[Rr]oll|ROLL|[Tt]heta|THETA|[Pp]hi|PHI"
    "|[Pp]si|PSI|[Aa]ng|ANG|[Bb]ear|BEAR|[Cc]ourse|COURSE|[Cc]og|COG|[Aa]zim|AZIM|[Dd]eg|DEG"
    "|[Rr]ad|RAD"
)
#: a number that is a quarter, half, three-quarter or whole turn in degrees (``90``,
#: ``180.0``, ``360.f``): added to or taken from an angle in radians, it can only be a turn
#: written in the wrong unit (mixed-angle-units)
DEGREE_TURNS = r"^(90|180|270|360)([.]0*)?[fFlL]?$"
#: what each of those numbers is, in degrees
TURN_NAMES = {
    90: ("a quarter turn", "π/2"),
    180: ("a half turn", "π"),
    270: ("three quarter turns", "3π/2"),
    360: ("a whole turn", "2π"),
}
#: C++'s sine, cosine and tangent (``std::`` or not; float and long double forms): radians in
TRIG = {f"{f}{s}" for f in ("sin", "cos", "tan") for s in ("", "f", "l")}
STRCMP = {"MOOSStrCmp", "MOOSStrCmpi", "strcmp", "strcasecmp", "strBegins", "strEnds"}
PREFIX_CALLS = {
    "strBegins",
    "find",
    "compare",
    "rfind",
    "starts_with",
    "MOOSStrCmpN",
    # C's comparison of the first n letters: ``strncmp(key.c_str(), "NAV_", 4)``
    "strncmp",
    "strncasecmp",
    "_strnicmp",
}
IO_TYPES = re.compile(
    r"^(?:CMOOSSerialPort|CMOOSLinuxSerialPort|CMOOSNTSerialPort|SerialPort|QSerialPort|Serial)$"
)
#: a MOOS client of another community: a bridge's sockets carry MOOS itself
MOOS_CLIENT_TYPES = re.compile(r"^(?:CMOOSCommClient|MOOSAsyncCommClient|CMOOSAsyncCommClient)$")
SOCKET_TYPES = re.compile(r"[Ss]ocket|TCP|UDP|Udp|Tcp|^gpsmm$")  # gpsmm: libgps's gpsd client
DEVICE_STRING = re.compile(
    r"^/dev/(?:tty|cu\.|serial|usb|can|i2c|spidev|hidraw|video|input/|js\d|gpiochip)"
)
BAUD_CALLS = {"cfsetispeed", "cfsetospeed", "cfsetspeed", "cfmakeraw"}
#: ``gps_open(host, port, &data)``: libgps's C client of the gpsd service;
#: ``curl_easy_perform(handle)``: libcurl's transfer (a web service over HTTP)
SOCKET_CALLS = {"socket", "connect", "bind", "sendto", "recvfrom", "gps_open", "curl_easy_perform"}
#: MAVSDK's ``Mavsdk::add_*_connection(url)``: a link to an autopilot over UDP, TCP or serial
VEHICLE_LINK_CALLS = {
    "add_any_connection",
    "add_udp_connection",
    "add_tcp_connection",
    "add_serial_connection",
}
#: conversions from degrees that tell what a variable read by mail carries
FROM_DEGREES = {"MOOSDeg2Rad", "degToRadians", "headingToRadians"}
#: MOOS's and MOOS-IvP's angle functions that take an angle in one unit (the wraps and
#: the conversions of :data:`HELPERS`, but the generic ``degrees``/``radians``): a call
#: given an angle known to be in the other is looked at (angle-argument-unit)
UNIT_ARGUMENT = {
    name
    for name, (unit_in, _out, _rng, _sense) in HELPERS.items()
    if unit_in is not None and name not in ("degrees", "radians")
}
#: every call :meth:`Extractor._call` looks at (the query captures no other)
#: ``Set`` on a table of published ``CMOOSVariable``s (published by ``PublishFreshMOOSVariables``)
VARIABLE_SET = {"Set"}
#: CMOOSApp's dynamic variables: ``AddMOOSVariable(name, subscribe_as, publish_as, period)``
#: declares one, ``SetMOOSVar(name, value, time)`` writes it, and
#: ``PublishFreshMOOSVariables()`` posts the fresh ones under their ``publish_as`` names
#: (core MOOS, App/MOOSApp.cpp); ``RegisterMOOSVariables()`` subscribes to ``subscribe_as``
ADD_MOOS_VAR = "AddMOOSVariable"
SET_MOOS_VAR = "SetMOOSVar"
CALLED = (
    PUBLISH
    | {NOTIFY_MSG}
    | SUBSCRIBE
    | {"Run"}
    | CONFIG_CALLS
    | {GLOBAL_VALUE}
    | TRIG
    | BAUD_CALLS
    | SOCKET_CALLS
    | VEHICLE_LINK_CALLS
    | STRCMP
    | FROM_DEGREES
    | UNIT_ARGUMENT
    | VARIABLE_SET
    | {ADD_MOOS_VAR, SET_MOOS_VAR}
    | set(GEODESY_ARGUMENTS)
)
WRAP_PI = {
    "MOOS_ANGLE_WRAP",
    "radAngleWrap",
    "angleWrap",
    "wrapToPi",
    "wrap_to_pi",
    "wrapAngle",
    "normalizeAngle",
    "normalize_angle",
    "angle_wrap",
    "__wrap_pi",
}
WRAP_2PI = {"wrapTo2Pi", "wrap_to_2pi", "__wrap_2pi"}
_PI = r"(?:M_PI|\bPI\b|3\.14\d*)"
_TWO_PI = re.compile(r"(?:2(?:\.0*)?\s*\*\s*" + _PI + r"|M_2PI|TWO_PI|2PI|6\.28\d*)")
_HALF_PI_BOUND = re.compile(r"[<>]=?\s*-?\s*" + _PI + r"(?!\s*/)")
_ZERO_BOUND = re.compile(r"<\s*0(?:\.0*)?\b")
_ANGLE_TARGET = re.compile(r"yaw|heading|hdg", re.I)
_NUMBER = re.compile(r"^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[fFlL]?$")


def text(n: Any) -> str:
    return n.text.decode("utf-8", "replace") if n is not None else ""


def callee(fn: Any) -> str:
    """The called function's own name: ``Notify`` for ``m_Comms.Notify`` or ``CMOOSApp::Notify``."""
    t = fn.type
    if t == "identifier":
        return text(fn)
    if t == "field_expression":
        return text(fn.child_by_field_name("field"))
    if t == "qualified_identifier":
        return callee(fn.child_by_field_name("name"))
    if t == "template_function":
        return text(fn.child_by_field_name("name"))
    return ""


def string_value(n: Any) -> str | None:
    """The value of a string literal (concatenations included), or None."""
    if n is None:
        return None
    if n.type == "string_literal":
        parts = []
        for c in n.named_children:
            if c.type == "string_content":
                parts.append(text(c))
            elif c.type == "escape_sequence":
                parts.append(_unescape(text(c)))
            else:
                return None
        return "".join(parts)
    if n.type == "concatenated_string":
        vals = [string_value(c) for c in n.named_children]
        return None if any(v is None for v in vals) else "".join(vals)  # type: ignore[arg-type]
    if n.type == "raw_string_literal":
        t = text(n)
        m = re.match(r'R"([^(]*)\((.*)\)\1"$', t, re.S)
        return m.group(2) if m else None
    return None


def _unescape(esc: str) -> str:
    return {"\\n": "\n", "\\t": "\t", "\\\\": "\\", '\\"': '"', "\\'": "'"}.get(esc, esc[1:])


def _braced(n: Any) -> Any:
    """The one value of a brace initialiser (``std::string m_var{"NAV_X"}``), else ``n``."""
    if n.type == "initializer_list":
        values = [c for c in n.named_children if c.type != "comment"]
        if len(values) == 1:
            return values[0]
    return n


def strip_parens(n: Any) -> Any:
    while n is not None and n.type == "parenthesized_expression" and n.named_child_count == 1:
        n = n.named_children[0]
    return n


def _in_place(call: Any, arg: Any) -> bool:
    """Whether ``call`` is what its own argument is set to (``x = MOOSDeg2Rad(x)``): a
    value converted where it is kept, whose value before is the one the author had."""
    parent = call.parent
    while parent is not None and parent.type == "parenthesized_expression":
        parent = parent.parent
    if parent is None or parent.type != "assignment_expression":
        return False
    left = parent.child_by_field_name("left")
    return arg is not None and left is not None and text(left) == text(arg)


def _radians_call(n: Any) -> bool:
    """Whether ``n`` is a call that gives radians whatever its argument: an inverse
    trigonometric function or a conversion to radians (``MOOSDeg2Rad(h)``)."""
    n = strip_parens(n)
    if n is None or n.type != "call_expression":
        return False
    name = re.sub(r"^std::", "", callee_name(n.child_by_field_name("function")))
    if name.rstrip("f") in INVERSE_TRIG:
        return True
    helper = HELPERS.get(name)
    return (helper is not None and helper[1] == "rad") or bool(re.match(DEG2RAD_NAME, name))


def nodes_under(n: Any) -> Iterator[Any]:
    """``n`` and every named node under it (none for ``None``)."""
    stack = [n] if n is not None else []
    while stack:
        x = stack.pop()
        yield x
        stack.extend(x.named_children)


def target_name(n: Any) -> str:
    """``m_x`` for ``m_x``, ``this->m_x``, ``&m_x`` or ``m_x[3]`` declarators and left sides."""
    n = strip_parens(n)
    if n is None:
        return ""
    if n.type in ("identifier", "field_identifier"):
        return text(n)
    if n.type == "field_expression":
        obj = text(n.child_by_field_name("argument"))
        if obj == "this":
            return text(n.child_by_field_name("field"))
        return text(n)
    if n.type in ("reference_declarator", "pointer_declarator", "init_declarator"):
        for c in n.named_children:
            name = target_name(c)
            if name:
                return name
    if n.type == "qualified_identifier":
        return text(n.child_by_field_name("name"))
    return ""


def function_name(fn_def: Any) -> str:
    """``App::OnNewMail`` for a function definition node."""
    decl = function_declarator(fn_def)
    if decl is None:
        return ""
    return re.sub(r"\s+", "", text(decl.child_by_field_name("declarator")))


_PARAM_DECL = "parameter_declaration"


def _parameters(fn_def: Any) -> list[tuple[str, str]]:
    """(type, name) of each parameter of a function definition ("" for a missing name)."""
    decl = function_declarator(fn_def)
    params = decl.child_by_field_name("parameters") if decl is not None else None
    out = []
    for p in params.named_children if params else []:
        if p.type != _PARAM_DECL:
            continue
        inner = p.child_by_field_name("declarator")
        while inner is not None and inner.type != "identifier":
            inner = inner.child_by_field_name("declarator") or (
                inner.named_children[-1] if inner.named_children else None
            )
        kind = p.child_by_field_name("type")
        out.append((text(kind) if kind is not None else "", text(inner) if inner else ""))
    return out


def _notify_wrapper(pf: ParsedFile, call: Any, args: Any) -> tuple[str, tuple[int, int]] | None:
    """(function, (name index, value index)) when ``call`` is a ``Notify(a, b)`` whose
    name and value are two parameters of the function around it."""
    fn_def = pf.function_of(call)
    argv = [a for a in args.named_children if a.type != "comment"]
    if fn_def is None or len(argv) < 2:
        return None
    name = short(function_name(fn_def))
    if not name or name in PUBLISH:
        return None
    names = [n for _t, n in _parameters(fn_def)]
    a, b = strip_parens(argv[0]), strip_parens(argv[1])
    if a is None or b is None or a.type != "identifier" or b.type != "identifier":
        return None
    if text(a) in names and text(b) in names and text(a) != text(b):
        return name, (names.index(text(a)), names.index(text(b)))
    return None


def _returns_its_parameter(fn_def: Any) -> bool:
    """Whether a function of one string parameter returns that parameter (in one of its
    ``return`` statements): ``string postVar(string varname) { ... return(varname); }``."""
    params = _parameters(fn_def)
    if len(params) != 1 or "string" not in params[0][0] or not params[0][1]:
        return False
    name = params[0][1]
    for n in nodes_under(fn_def.child_by_field_name("body")):
        if n.type == "return_statement" and n.named_children:
            value = strip_parens(n.named_children[0])
            if value is not None and value.type == "identifier" and text(value) == name:
                return True
    return False


def short(fn_name: str) -> str:
    return fn_name.rsplit("::", 1)[-1]


def enclosing(n: Any, types: tuple[str, ...]) -> Any:
    p = n.parent
    while p is not None and p.type not in types:
        p = p.parent
    return p


@dataclass
class _Asg:
    target: str
    op: str
    rhs: Any
    node: Any
    fn: Any  # the function_definition, or None at file scope


@dataclass
class FolderTables:
    """What name resolution may use across the files of one folder."""

    defines: dict[str, str] = field(default_factory=dict)
    # member/global/constant name -> its assigned values (None: not a literal)
    assigns: dict[str, list[str | None]] = field(default_factory=dict)
    # member -> the configuration key read into it (``GetConfigurationParam("prefix", m_prefix)``)
    config_keys: dict[str, str] = field(default_factory=dict)
    # member/global -> the literal end of each value assigned to it, "" where it has none
    # (``namePitch = pre + "PITCH"`` gives "PITCH")
    suffixes: dict[str, list[str]] = field(default_factory=dict)
    # array -> the literal names it is initialised with (``const char* names[] = {"A", "B"}``)
    name_tables: dict[str, list[str]] = field(default_factory=dict)
    # a dynamic variable's name -> the name it is published as (``AddMOOSVariable``; None
    # when declared twice with different names)
    moos_vars: dict[str, str | None] = field(default_factory=dict)
    # the folder calls ``RegisterMOOSVariables()``: its dynamic variables are subscribed
    registers_moos_vars: bool = False
    # functions of one parameter that return it unless configured otherwise
    # (uProcessWatch's ``postVar(varname)``: a name, or the one the configuration maps it to)
    passthrough: set[str] = field(default_factory=set)
    # the folder's own functions that publish their arguments: name -> (index of the name
    # argument, index of the value argument) (``void post(string var, double v) {
    # Notify(var, v); }``)
    notify_wrappers: dict[str, tuple[int, int]] = field(default_factory=dict)
    # the folder's files, for :meth:`upper_cased` (worked out on first use)
    files: list[ParsedFile] = field(default_factory=list)
    _upper: set[str] | None = None

    def upper_cased(self, member: str) -> bool:
        """Whether the app upper-cases ``member`` (``m_var = toupper(value)``,
        ``MOOSToUpper(m_var)``): asked only of the members a published name is built from."""
        if self._upper is None:
            self._upper = set()
            for pf in self.files:
                self._upper |= _upper_cased(pf)
        return member in self._upper


class Spans:
    """Byte positions to 1-based line and character columns."""

    def __init__(self, path: str, data: bytes):
        self.path = path
        self.lines = data.split(b"\n")

    def col(self, row: int, bcol: int) -> int:
        if row >= len(self.lines):
            return bcol + 1
        return len(self.lines[row][:bcol].decode("utf-8", "replace")) + 1

    def of(self, n: Any) -> Span:
        (r1, c1), (r2, c2) = n.start_point, n.end_point
        if r2 != r1:  # findings stay on one line: the first
            line = self.lines[r1] if r1 < len(self.lines) else b""
            return Span(self.path, r1 + 1, self.col(r1, c1), r1 + 1, self.col(r1, len(line)))
        return Span(self.path, r1 + 1, self.col(r1, c1), r2 + 1, self.col(r2, c2))


class ParsedFile:
    """One file's tree and its query matches, sorted out by kind."""

    def __init__(self, path: str, data: bytes, tree: Any, matches: list[tuple[int, dict]]):
        self.path = path
        self.data = data
        self.tree = tree
        self.spans = Spans(path, data)
        self.calls: list[tuple[Any, Any, Any]] = []
        self.cmps: list[tuple[Any, Any, Any]] = []
        self.mixes: list[tuple[Any, Any, Any]] = []
        #: a sum or difference of a turn in degrees (``90``) and another value
        self.turns: list[tuple[Any, Any, Any]] = []
        self.asgs: list[_Asg] = []
        self.inits: list[tuple[str, Any]] = []
        self.defines: list[tuple[str, str]] = []
        self.strings: list[Any] = []
        self.includes: list[Any] = []
        self.types: list[Any] = []
        self.namespaces: list[Any] = []
        self.classes: list[tuple[Any, Any]] = []
        self.functions: list[Any] = []
        # the enclosing function of a node, by byte range (no walk up the tree)
        fns = sorted(
            (caps["fn"][0] for _idx, caps in matches if "fn" in caps), key=lambda n: n.start_byte
        )
        self._fn_starts = [f.start_byte for f in fns]
        self._fns = fns
        self._fn_names: dict[int, str] = {}
        #: what the file gives its folder's tables (:func:`_file_tables`)
        self.tables: FolderTables | None = None
        #: what the file gives its folder's look-ups (``values.FilePart``)
        self.folder_part: Any = None
        for _idx, caps in matches:
            if "call" in caps:
                self.calls.append((caps["call"][0], caps["call.fn"][0], caps["call.args"][0]))
            elif "cmp" in caps:
                self.cmps.append((caps["cmp"][0], caps["cmp.l"][0], caps["cmp.r"][0]))
            elif "mix" in caps:
                self.mixes.append((caps["mix"][0], caps["mix.l"][0], caps["mix.r"][0]))
            elif "turn" in caps:
                self.turns.append((caps["turn"][0], caps["turn.angle"][0], caps["turn.n"][0]))
            elif "asg" in caps:
                node = caps["asg"][0]
                op = "="
                if node.type == "assignment_expression":
                    op = text(node.child_by_field_name("operator")) or "="
                fn = self.function_of(node)
                name = target_name(caps["asg.l"][0])
                if name:
                    self.asgs.append(_Asg(name, op, _braced(caps["asg.r"][0]), node, fn))
            elif "fi" in caps:
                self.inits.append((text(caps["fi.name"][0]), caps["fi.args"][0]))
            elif "def.name" in caps:
                self.defines.append((text(caps["def.name"][0]), text(caps["def.val"][0]).strip()))
            elif "str" in caps:
                self.strings.append(caps["str"][0])
            elif "inc" in caps:
                self.includes.append(caps["inc"][0])
            elif "type" in caps:
                self.types.append(caps["type"][0])
            elif "ns" in caps:
                self.namespaces.append(caps["ns"][0])
            elif "cls" in caps:
                self.classes.append((caps["cls.name"][0], caps["cls.bases"][0]))
            elif "fn" in caps:
                self.functions.append(caps["fn"][0])
        # assignments per function, in source order, for local data flow
        self.local: dict[int, dict[str, list[_Asg]]] = {}
        for a in self.asgs:
            key = a.fn.id if a.fn is not None else 0
            self.local.setdefault(key, {}).setdefault(a.target, []).append(a)

    def function_of(self, n: Any) -> Any:
        """The innermost function definition holding ``n`` (an ancestor: it holds its bytes)."""
        start, end = n.start_byte, n.end_byte
        i = bisect.bisect_right(self._fn_starts, start) - 1
        while i >= 0:
            f = self._fns[i]
            if f.end_byte >= end and f.id != n.id:
                return f
            i -= 1
        return None

    def function_name_of(self, n: Any) -> str:
        """``App::OnNewMail`` for the function holding ``n``, or ``""``."""
        fn = self.function_of(n)
        if fn is None:
            return ""
        name = self._fn_names.get(fn.id)
        if name is None:
            name = self._fn_names[fn.id] = function_name(fn)
        return name


def _file_tables(pf: ParsedFile) -> FolderTables:
    """What one file gives its folder's tables; kept on the file, which the language
    server keeps while its bytes are unchanged (see :func:`collect_tables`)."""
    if pf.tables is not None:
        return pf.tables
    t = FolderTables()
    t.registers_moos_vars = b"RegisterMOOSVariables" in pf.data
    for fn in pf.functions:
        if _returns_its_parameter(fn):
            t.passthrough.add(short(function_name(fn)))
    for call, fn, args in pf.calls:
        if callee(fn) in PUBLISH:
            wrapper = _notify_wrapper(pf, call, args)
            if wrapper is not None:
                t.notify_wrappers.setdefault(*wrapper)
    for name, define in pf.defines:
        m = re.fullmatch(r'"((?:[^"\\]|\\.)*)"', define)
        if m:
            t.defines[name] = m.group(1)
    declared: dict[tuple, bool] = {}  # (function, target) -> a local of it
    for a in pf.asgs:
        # members, globals and constants; locals are followed per function
        if a.fn is not None:
            key = (a.fn.id, a.target)
            local = declared.get(key)
            if local is None:
                local = declared[key] = _declared_in(pf, a)
            if local:
                continue
        val = string_value(strip_parens(a.rhs)) if a.op == "=" else None
        if val is None and a.fn is not None:
            ckey = _config_branch_key(pf, a)
            if ckey is not None:  # the configuration may change it: the default stands
                t.config_keys.setdefault(a.target, ckey)
                continue
        t.assigns.setdefault(a.target, []).append(val)
        t.suffixes.setdefault(a.target, []).append(_literal_end(a.rhs) if a.op == "=" else "")
    for name, entries in _name_tables(pf):
        t.name_tables.setdefault(name, entries)
    for name, args in pf.inits:
        vals = args.named_children
        val = string_value(vals[0]) if len(vals) == 1 else None
        t.assigns.setdefault(name, []).append(val)
    for _call, fn, args in pf.calls:
        argv = args.named_children
        if callee(fn) == ADD_MOOS_VAR and len(argv) >= 3:
            var = string_value(strip_parens(argv[0]))
            pub = string_value(strip_parens(argv[2]))
            if var is not None and pub:
                known = t.moos_vars.setdefault(var, pub)
                if known != pub:
                    t.moos_vars[var] = None
        if callee(fn) in CONFIG_CALLS and len(argv) >= 2:
            ckey = string_value(strip_parens(argv[-2]))
            member = target_name(argv[-1])
            if ckey is not None and member:
                t.config_keys.setdefault(member, ckey.lower())
    pf.tables = t
    return t


def _literal_end(rhs: Any) -> str:
    """The literal a sum ends with (``pre + "PITCH"``, ``m_prefix + "_" + "ROLL"``), else ""."""
    n = strip_parens(rhs)
    if n is None or n.type != "binary_expression" or text(n.child_by_field_name("operator")) != "+":
        return ""
    return string_value(strip_parens(n.child_by_field_name("right"))) or ""


def collect_tables(files: list[ParsedFile]) -> FolderTables:
    """The folder's tables: each file's, merged in the files' order (a name a first file
    gives keeps its value, as if one pass read the files in turn)."""
    t = FolderTables()
    for pf in files:
        part = _file_tables(pf)
        t.registers_moos_vars = t.registers_moos_vars or part.registers_moos_vars
        t.passthrough |= part.passthrough
        for name, wrapper in part.notify_wrappers.items():
            t.notify_wrappers.setdefault(name, wrapper)
        t.defines.update(part.defines)
        for name, vals in part.assigns.items():
            t.assigns.setdefault(name, []).extend(vals)
        for name, ends in part.suffixes.items():
            t.suffixes.setdefault(name, []).extend(ends)
        for name, ckey in part.config_keys.items():
            t.config_keys.setdefault(name, ckey)
        for name, entries in part.name_tables.items():
            t.name_tables.setdefault(name, entries)
        for var, pub in part.moos_vars.items():
            known = t.moos_vars.setdefault(var, pub)
            if known != pub:
                t.moos_vars[var] = None
    t.files = files
    return t


_UPPER = re.compile(rb"(?i)upper")
_WORD_REST = re.compile(rb"\w*")


def upper_words(data: bytes) -> Iterator[tuple[int, int]]:
    """The spans of the words of ``data`` that hold ``upper`` in any case: what
    ``(?i)\\w*upper\\w*`` finds, without its search, which tries every byte and walks
    each word back and forth (10x slower over a repository's C++)."""
    end = 0
    for m in _UPPER.finditer(data):
        start = m.start()
        if start < end:  # a second ``upper`` in the same word
            continue
        while start > end and data[start - 1] in WORD_BYTES:
            start -= 1
        match = _WORD_REST.match(data, m.end())
        end = match.end() if match is not None else m.end()
        yield start, end


def _upper_calls(pf: ParsedFile) -> Iterator[Any]:
    """The calls in ``pf`` whose callee or an argument is an upper-casing word (found on
    the bytes first: most files have none)."""
    seen = set()
    root = pf.tree.root_node
    for start, end in upper_words(pf.data):
        n = root.descendant_for_byte_range(start, end)
        while n is not None and n.type != "call_expression":
            if n.type in ("expression_statement", "compound_statement", "function_definition"):
                n = None
                break
            n = n.parent
        if n is not None and n.id not in seen:
            seen.add(n.id)
            yield n


def _upper_cased(pf: ParsedFile) -> set[str]:
    """The variables ``pf`` upper-cases: the arguments of an upper-casing call
    (``MOOSToUpper(m_var)``, ``transform(v.begin(), v.end(), v.begin(), ::toupper)``), what is
    assigned its result (``m_var = toupper(value)``), and what is assigned a variable
    upper-cased before it in the same block (``value = toupper(value); m_var = value;``)."""
    from moos_lint.frontends.cpp.facts import UPPER_CASE_CALLS

    upper: dict[str, list[Any]] = {}  # variable -> the upper-casing calls of it
    for call in _upper_calls(pf):
        fn, args = call.child_by_field_name("function"), call.child_by_field_name("arguments")
        argv = args.named_children if args is not None else []
        if callee(fn) not in UPPER_CASE_CALLS and not any(
            short(text(a)) == "toupper" for a in argv
        ):
            continue
        words = set()
        in_place = callee(fn) in ("to_upper", "transform") or callee(fn) not in UPPER_CASE_CALLS
        for a in argv if in_place else ():  # ``MOOSToUpper(v)`` and ``toupper(v)`` copy
            a = strip_parens(a)
            if a is not None and a.type == "call_expression":  # ``v.begin()``
                inner = a.child_by_field_name("function")
                if inner.type == "field_expression":
                    a = inner.child_by_field_name("argument")
            words.add(target_name(a) if a is not None else "")
        if call.parent is not None and call.parent.type == "argument_list":
            # a setter given the upper-cased value: ``setNonWhiteVarOnString(m_var, toupper(v))``
            words.update(target_name(a) for a in call.parent.named_children)
        asg = enclosing(call, ("assignment_expression", "init_declarator"))
        if asg is not None and pf.function_of(asg) is pf.function_of(call):
            words.add(
                target_name(
                    asg.child_by_field_name("left") or asg.child_by_field_name("declarator")
                )
            )
        for w in words - {""}:
            upper.setdefault(w, []).append(call)
    out = set(upper)
    for a in pf.asgs:
        for call in upper.get(target_name(strip_parens(a.rhs)), ()):
            block = enclosing(call, ("compound_statement",))  # the call's block holds `a`
            if call.start_byte < a.node.start_byte and block is not None and _inside(a.node, block):
                out.add(a.target)
    return out


#: a file that may name a NED z (``ned``, ``NED``, ``down`` as words or parts of names).
#: One pattern per spelling, each starting with its literal and looking behind it only
#: then: a search skips ahead on a literal, not on an alternation (6x faster than one
#: pattern of alternatives, 25x faster than lookbehinds first).
_NED_BYTES = tuple(
    re.compile(p)
    for p in (
        rb"ned(?<![A-Za-z]ned)(?![a-z])",
        rb"Ned(?<![A-Za-z]Ned)(?![a-z])",
        rb"NED(?<![A-Z]NED)(?![a-z])",
        rb"down(?<![A-Za-z]down)\b",
        rb"_down\b",
        rb"Down\b",
    )
)


def may_name_ned(data: bytes) -> bool:
    """Whether ``data`` may name a NED z (:data:`_NED_BYTES`)."""
    return any(p.search(data) for p in _NED_BYTES)


_TABLE_HINT = re.compile(rb'\]\s*=\s*\{\s*"')


def _name_tables(pf: ParsedFile) -> Iterator[tuple[str, list[str]]]:
    """Arrays initialised with string literals only (the file is walked only when it has one)."""
    if not _TABLE_HINT.search(pf.data):
        return
    stack = [pf.tree.root_node]
    while stack:
        x = stack.pop()
        if x.type != "init_declarator":
            stack.extend(x.named_children)
            continue
        decl = x.child_by_field_name("declarator")
        value = x.child_by_field_name("value")
        while decl is not None and decl.type in ("pointer_declarator", "reference_declarator"):
            decl = decl.child_by_field_name("declarator")
        if decl is None or decl.type != "array_declarator" or value is None:
            continue
        if value.type != "initializer_list":
            continue
        items = [c for c in value.named_children if c.type != "comment"]
        lits = [string_value(c) for c in items]
        if items and all(v is not None for v in lits):
            yield text(decl.child_by_field_name("declarator")), [v for v in lits if v]


def _config_branch_key(pf: ParsedFile, a: _Asg) -> str | None:
    """The configuration key whose branch sets ``a`` (``if (param == "PREFIX") m_prefix = value;``)
    in a start-up or configuration function, else None."""
    fname = short(pf.function_name_of(a.node)).lower()
    if not (fname == "onstartup" or re.search(r"config|param|startup|setparam", fname)):
        return None
    p, child = a.node.parent, a.node
    while p is not None and p.type != "function_definition":
        if p.type == "if_statement" and child == p.child_by_field_name("consequence"):
            lit = key_literal(p.child_by_field_name("condition"))
            if lit is not None:
                return lit.lower()
        p, child = p.parent, p
    return None


def _declared_in(pf: ParsedFile, a: _Asg) -> bool:
    """Whether ``a``'s target is a local of its function (declared there)."""
    cands = pf.local.get(a.fn.id, {}).get(a.target, []) if a.fn is not None else []
    return any(c.node.type == "init_declarator" for c in cands)


class Extractor:
    """Turns one parsed file into a :class:`CppFile`, given the folder's tables."""

    def __init__(self, pf: ParsedFile, tables: FolderTables, evaluator: Any = None):
        self.pf = pf
        self.tables = tables
        self.out = CppFile(path=pf.path)
        self.evaluator = evaluator
        self._ned_file: bool | None = None  # whether the file may name a NED z
        #: a block's first byte -> its statements' first bytes -> their places in it
        self._places: dict[int, dict[int, int]] = {}
        #: a function's first byte -> how its locals hold a message's value (_value_read)
        self._reads_in: dict[int, tuple[dict[str, str], set[str]]] = {}
        #: a function's first byte -> the variables it sets from a case conversion, and
        #: the cases they are set to
        self._case_set: dict[int, dict[bytes, set[str]]] = {}

    # -- names --------------------------------------------------------------
    def name(self, n: Any, depth: int = 0) -> Name:
        src = text(n)
        val, prefix = self._resolve(n, depth)
        name = Name(source=src, text=val, prefix=prefix if val is None else val)
        if val is None:
            name.suffix = self._suffix(strip_parens(n))
        name.config_key = self._config_key(strip_parens(n))
        if name.config_key is not None:
            name.config_upper = self.tables.upper_cased(self._config_member(strip_parens(n)))
        return name

    def _suffix(self, n: Any) -> str:
        """The known end of a name built at run time (see :attr:`Name.suffix`)."""
        if n is None:
            return ""
        if n.type == "binary_expression" and text(n.child_by_field_name("operator")) == "+":
            right = strip_parens(n.child_by_field_name("right"))
            val, _ = self._resolve(right, 1)
            return val if val is not None else self._suffix(right)
        if n.type == "call_expression":
            fn = n.child_by_field_name("function")
            args = n.child_by_field_name("arguments").named_children
            if fn.type == "field_expression" and callee(fn) in ("c_str", "str") and not args:
                return self._suffix(strip_parens(fn.child_by_field_name("argument")))
            # a helper that builds a name from a literal: ``varName("NAV_YAW")``
            lits = [string_value(strip_parens(a)) for a in args]
            if len(args) == 1 and lits[0] is not None:
                return lits[0]
            return ""
        if n.type == "subscript_expression":
            # a table of names indexed by an enumerator: ``m_names[Pitch]``
            idx = n.child_by_field_name("indices") or n.child_by_field_name("index")
            inner = [c for c in (idx.named_children if idx is not None else ())]
            key = strip_parens(inner[0]) if inner else None
            table = text(n.child_by_field_name("argument"))
            if (
                key is not None
                and key.type in ("identifier", "qualified_identifier")
                and re.search(r"name|var", table, re.I)
            ):
                enum = text(key).split("::")[-1]
                return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", enum).upper()
        if n.type in ("identifier", "field_expression"):
            # a member every assignment of which ends with one literal: ``namePitch`` of
            # ``namePitch = pre + "PITCH"``
            ends = self.tables.suffixes.get(target_name(n))
            if (
                ends
                and ends[0]
                and len(set(ends)) == 1
                and self._local_before(n, target_name(n)) is None
            ):
                return ends[0]
        return ""

    def _table_names(self, n: Any) -> list[Name]:
        """``names[i]`` (or ``names[i].c_str()``) of a table of literal names: each name the
        table holds, or the one a literal index picks."""
        n = strip_parens(n)
        if n is not None and n.type == "call_expression":
            fn = n.child_by_field_name("function")
            if fn.type == "field_expression" and callee(fn) in ("c_str", "str"):
                n = strip_parens(fn.child_by_field_name("argument"))
        if n is None or n.type != "subscript_expression":
            return []
        entries = self.tables.name_tables.get(target_name(n.child_by_field_name("argument")))
        if not entries:
            return []
        idx = n.child_by_field_name("indices") or n.child_by_field_name("index")
        inner = [c for c in idx.named_children] if idx is not None else []
        if len(inner) == 1 and inner[0].type == "number_literal":
            try:
                entries = [entries[int(text(inner[0]), 0)]]
            except (ValueError, IndexError):
                return []
        src = text(n)
        return [Name(source=src, text=e, prefix=e) for e in dict.fromkeys(entries)]

    def _config_key(self, n: Any) -> str | None:
        """The configuration key that sets the member a name is built from."""
        return self.tables.config_keys.get(self._config_member(n))

    def _config_member(self, n: Any, depth: int = 0) -> str:
        """The member a name is built from (``m_prefix`` of ``m_prefix + "_PITCH"``, and
        of a local set to it: ``string var = m_prefix + "_PITCH"; Notify(var, ...)``)."""
        while n is not None and n.type == "binary_expression":
            n = strip_parens(n.child_by_field_name("left"))
        if n is None or n.type not in ("identifier", "field_expression"):
            return ""
        key = target_name(n)
        if n.type == "identifier" and depth < 4:
            local = self._local_before(n, key)
            if local is not None and local.op == "=" and local.rhs is not None:
                return self._config_member(strip_parens(local.rhs), depth + 1)
        return key

    def _resolve(self, n: Any, depth: int) -> tuple[str | None, str]:
        n = strip_parens(n)
        if n is None or depth > 6:
            return None, ""
        lit = string_value(n)
        if lit is not None:
            return lit, lit
        t = n.type
        if t == "binary_expression" and text(n.child_by_field_name("operator")) == "+":
            lv, lp = self._resolve(n.child_by_field_name("left"), depth + 1)
            if lv is None:
                return None, lp
            rv, rp = self._resolve(n.child_by_field_name("right"), depth + 1)
            return (lv + rv if rv is not None else None), lv + rp
        if t == "call_expression":
            fn = n.child_by_field_name("function")
            args = n.child_by_field_name("arguments").named_children
            if fn.type == "field_expression" and callee(fn) in ("c_str", "str") and not args:
                inner = strip_parens(fn.child_by_field_name("argument"))
                if callee(fn) == "str" and inner is not None and inner.type == "identifier":
                    parts = self._stream_parts(n, text(inner))
                    if parts is not None:
                        return self._resolve_parts(parts, depth + 1)
                return self._resolve(inner, depth + 1)
            if text(fn) in ("string", "std::string") and len(args) == 1:
                return self._resolve(args[0], depth + 1)
            if fn.type == "identifier" and text(fn) in self.tables.passthrough and len(args) == 1:
                return self._resolve(args[0], depth + 1)  # ``postVar("PROC_WATCH_SUMMARY")``
            return None, ""
        if t in ("identifier", "field_expression", "qualified_identifier"):
            key = target_name(n)
            if not key:
                return None, ""
            local = self._local_before(n, key)
            if local is not None:
                if local.op != "=":
                    return None, ""
                return self._resolve(local.rhs, depth + 1)
            if key in self.tables.defines:
                v = self.tables.defines[key]
                return v, v
            vals = self.tables.assigns.get(key)
            if vals and len(set(vals)) == 1 and vals[0] is not None:
                return vals[0], vals[0]
        return None, ""

    def _resolve_parts(self, parts: list[Any], depth: int) -> tuple[str | None, str]:
        """The text of ``parts`` joined, as ``_resolve`` gives a sum: (the whole text or
        None, the known text it starts with)."""
        done = ""
        for part in parts:
            value, prefix = self._resolve(part, depth)
            if value is None:
                return None, done + prefix
            done += value
        return done, done

    def _stream_parts(self, use: Any, key: str) -> list[Any] | None:
        """What was written into the local string stream ``key`` before ``use`` (its
        ``key.str()``), in order: ``ostringstream ss; ss << "DONE_" << vname;`` gives the
        two operands. None unless the stream is declared without a value in the block of
        ``use``'s statement and only written by ``<<`` statements of that same block."""
        block = enclosing(use, ("compound_statement",))  # (a function's body, or in one)
        if block is None:
            return None
        declared = False
        written: list[Any] = []
        for stmt in block.named_children:
            if stmt.end_byte > use.start_byte:  # the statement of ``use``, or after it
                break
            if stmt.type == "declaration":
                kind = text(stmt.child_by_field_name("type"))
                names = [target_name(d) for d in stmt.children_by_field_name("declarator")]
                if key in names:
                    if not kind.endswith("stringstream") or any(
                        d.type == "init_declarator"
                        for d in stmt.children_by_field_name("declarator")
                    ):
                        return None
                    declared = True
                continue
            if key.encode() not in stmt.text:
                continue
            chain = (
                strip_parens(stmt.named_children[0])
                if stmt.type == "expression_statement"
                else None
            )
            operands: list[Any] = []
            while (
                chain is not None
                and chain.type == "binary_expression"
                and text(chain.child_by_field_name("operator")) == "<<"
            ):
                operands.append(chain.child_by_field_name("right"))
                chain = strip_parens(chain.child_by_field_name("left"))
            if chain is None or chain.type != "identifier" or text(chain) != key or not operands:
                return None  # any other use of the stream (a reset, a read, a nested write)
            if any(key.encode() in (o.text or b"") for o in operands):
                return None
            written += operands[::-1]
        if not declared or not written:
            return None
        return written

    def _local_before(self, n: Any, key: str) -> _Asg | None:
        """The last assignment to ``key`` before ``n`` in n's function (locals only)."""
        fn = self.pf.function_of(n)
        if fn is None:
            return None
        cands = self.pf.local.get(fn.id, {}).get(key, [])
        if not any(a.node.type == "init_declarator" for a in cands) and not key.isidentifier():
            return None
        if not any(a.node.type == "init_declarator" for a in cands) and self._is_param(fn, key):
            return None
        best = None
        for a in cands:
            if a.node.start_byte < n.start_byte and not _inside(n, a.node):
                best = a
        declared = any(a.node.type == "init_declarator" for a in cands)
        # an assignment to a member or a parameter: only trust it in straight-line code
        if best is not None and not declared and enclosing(best.node, ("for_statement",)):
            return None
        return best

    def _is_param(self, fn: Any, key: str) -> bool:
        decl = function_declarator(fn)
        if decl is None:
            return False
        params = decl.child_by_field_name("parameters")
        return any(
            target_name(p.child_by_field_name("declarator")) == key
            for p in (params.named_children if params else ())
        )

    # -- values -------------------------------------------------------------
    def value(self, n: Any) -> Value:
        raw = text(n)
        try:
            expanded = self._expand(n, 0)
        except RecursionError:  # an expression nested thousands deep: keep it as written
            expanded = raw
        number = None
        s = strip_parens(n)
        if s is not None and s.type == "number_literal" and _NUMBER.match(text(s)):
            number = float(re.sub(r"[fFlL]$", "", text(s)))
        elif (
            s is not None
            and s.type == "unary_expression"
            and _NUMBER.match(text(s).replace(" ", ""))
        ):
            number = float(re.sub(r"[fFlL]$", "", text(s).replace(" ", "")))
        return Value(text=raw, expanded=expanded, span=self.pf.spans.of(n), number=number)

    def _expand(self, n: Any, depth: int, level: int = 0) -> str:
        """The expression's text with local variables replaced by what they were assigned."""
        if n is None:
            return ""
        if depth > 5 or level > 100:  # deep or huge expressions stay as written
            return text(n)
        if n.type == "identifier":
            key = text(n)
            a = self._local_before(n, key)
            if a is None:
                return key
            return self._expand_asg(a, depth)
        if n.type == "field_expression" and text(n.child_by_field_name("argument")) == "this":
            return text(n.child_by_field_name("field"))
        if n.child_count == 0:
            return text(n)
        parts: list[str] = []
        prev_end = None
        for c in n.children:
            if prev_end is not None and c.start_byte > prev_end:
                parts.append(" ")
            if c.type in ("call_expression",) or c.named_child_count or c.type == "identifier":
                parts.append(self._expand(c, depth, level + 1))
            else:
                parts.append(text(c))
            prev_end = c.end_byte
        return "".join(parts)

    def _expand_asg(self, a: _Asg, depth: int) -> str:
        rhs = self._expand(a.rhs, depth + 1)
        if a.op == "=":
            inner = rhs if strip_parens(a.rhs).type in _ATOMS else f"({rhs})"
        else:
            prev = self._local_before(a.node, a.target)
            before = self._expand_asg(prev, depth + 1) if prev is not None else a.target
            inner = f"({before} {a.op[:-1]} {rhs})"
        wrap = self._loop_wrap(a)
        if wrap:
            prev = self._local_before(_top_of(a.node, wrap[1]), a.target)
            before = self._expand_asg(prev, depth + 1) if prev is not None else a.target
            return f"{wrap[0]}({before})"
        return inner

    def _loop_wrap(self, a: _Asg) -> tuple[str, Any] | None:
        """A ``while (x > M_PI) x -= 2*M_PI;`` style normalisation: the wrap it makes."""
        if a.op not in ("-=", "+=") or not _TWO_PI.search(text(a.rhs)):
            return None
        stmt = enclosing(a.node, ("while_statement", "if_statement", "for_statement"))
        if stmt is None or a.fn is None:
            return None
        # a normalisation sequence: the loops/ifs on this variable side by side
        block = stmt.parent
        conds = []
        for sib in block.named_children if block is not None else ():
            if sib.type in ("while_statement", "if_statement"):
                cond = text(sib.child_by_field_name("condition"))
                if re.search(r"\b" + re.escape(a.target) + r"\b", cond):
                    conds.append((sib, cond))
        if not conds:
            return None
        last = max(s.end_byte for s, _ in conds)
        first = min(s.start_byte for s, _ in conds)
        if not (first <= a.node.start_byte <= last):
            return None
        all_cond = " ".join(c for _, c in conds)
        if _ZERO_BOUND.search(all_cond) and not _HALF_PI_BOUND.search(all_cond):
            return "__wrap_2pi", first
        return "__wrap_pi", first

    # -- the facts ----------------------------------------------------------
    def run(self) -> CppFile:
        pf, out = self.pf, self.out
        out.parse_errors = pf.tree.root_node.has_error
        for name_node, bases in pf.classes:
            names = []
            for c in bases.named_children:
                if c.type in ("type_identifier", "qualified_identifier", "template_type"):
                    names.append(re.sub(r"<.*", "", text(c)).split("::")[-1])
            out.classes.append(CppClass(text(name_node), names, pf.spans.of(name_node)))
        for fn in pf.functions:
            fname = function_name(fn)
            if fname == "main":
                out.has_main = True
            if short(fname) == "OnNewMail" and "::" in fname:
                out.has_on_new_mail = True
            if re.search(r"mail", short(fname), re.I):
                self._mail_handling(fn)
            elif short(fname) == "OnStartUp" or _CONFIG_FN.search(short(fname)):
                self._config_handling(fn)
        for call, fn, args in pf.calls:
            self._call(call, fn, args)
        self._decimal_commas()
        self._shadowed_branches()
        if self.tables.notify_wrappers:
            self._wrapper_calls()
        for cmp, left, right in pf.cmps:
            self._comparison(cmp, left, right)
        for node, left, right in pf.mixes:
            self._unit_mix(node, left, right)
        for node, angle, number in pf.turns:
            self._turn_mix(node, angle, number)
        for a in pf.asgs:
            # ``if (hdg < 0) hdg += 360``: a turn in degrees added to a variable in place
            turn = a.rhs.type == "number_literal" and re.match(DEGREE_TURNS, text(a.rhs))
            if turn and a.op in ("+=", "-="):
                self._turn_mix(a.node, a.node.child_by_field_name("left"), a.rhs)
            if a.rhs.type == "argument_list" and a.node.type == "init_declarator":
                decl = a.node.parent
                kind = decl.child_by_field_name("type") if decl is not None else None
                if kind is not None and text(kind) == NOTIFY_MSG:
                    self._notify_msg(a.node, a.rhs)
            if (
                a.op in ("=", "+=", "-=", "*=", "/=")
                and a.fn is not None
                and _ANGLE_TARGET.search(a.target)
            ):
                out.assignments.append(
                    Assignment(
                        a.target,
                        self.value(a.rhs),
                        pf.spans.of(a.node),
                        function_name(a.fn),
                    )
                )
            elif a.op == "=" and a.fn is not None and self._ned_down(a):
                value = self.value(a.rhs)
                value.abstract = self.evaluator.of(pf, a.rhs)
                out.ned_writes.append(
                    Assignment(a.target, value, pf.spans.of(a.node), function_name(a.fn))
                )
        for s in pf.strings:  # the literals that mention /dev/
            v = string_value(s)
            if v is not None and DEVICE_STRING.match(v):
                out.io.append(IOUse("device", v, pf.spans.of(s)))
        for inc in pf.includes:
            path = text(inc).strip('<>"')
            kind = include_io(path)
            if kind:
                out.io.append(IOUse(kind, path, pf.spans.of(inc)))
        for t in pf.types:
            name = text(t)
            if IO_TYPES.match(name):
                out.io.append(IOUse("serial", name, pf.spans.of(t)))
            elif MOOS_CLIENT_TYPES.match(name):
                out.io.append(IOUse("moos", name, pf.spans.of(t)))
            elif name in ("termios",):
                out.io.append(IOUse("termios", name, pf.spans.of(t)))
            elif SOCKET_TYPES.search(name):
                out.io.append(IOUse("socket", name, pf.spans.of(t)))
        for ns in pf.namespaces:
            parent = ns.parent
            full = text(parent) if parent is not None else text(ns)
            if "serial_port" in full or text(ns) == "serial":
                out.io.append(IOUse("serial", full, pf.spans.of(ns)))
            elif "asio" in full:
                out.io.append(IOUse("network", full, pf.spans.of(ns)))
        self._registration_context(out)
        return out

    def _registration_context(self, out: CppFile) -> None:
        """What tells a missing registration from one made where we cannot see it:
        registrations commented out, and the comms client (or the app) handed to other code."""
        data = self.pf.data
        if b"Register" not in data and b"OnNewMail" not in data and b"m_Comms" not in data:
            return  # not the app class's: its own objects are what it hands over
        if b"Register" in data:
            blocks = b"/*" in data
            for m in _REGISTER_LITERAL.finditer(data):
                at = m.start()
                line_comment = b"//" in data[data.rfind(b"\n", 0, at) + 1 : at]
                in_block = blocks and data.rfind(b"/*", 0, at) > data.rfind(b"*/", 0, at)
                if line_comment or in_block:
                    out.commented_registrations.append(m.group(1).decode("utf-8", "replace"))
        for pattern in _HANDED:
            for m in pattern.finditer(data):
                at = m.start()
                if at and (data[at - 1 : at].isalnum() or data[at - 1 : at] == b"_"):
                    continue  # ``m_this)``: another name
                before = data[max(0, at - 80) : at].rstrip(b" \t\r\n&*")
                if not before.endswith((b"(", b",", b"{")):
                    continue
                call = re.search(rb"([A-Za-z_]\w*)\s*[(<{][^()<>{}]*$", before)
                if call is None or call.group(1) not in _THREAD_STARTS:
                    out.comms_shared = True
                    return

    def _ned_down(self, a: _Asg) -> bool:
        """Whether ``a`` sets a NED z (:meth:`Evaluator.ned_down`)."""
        if self.evaluator is None or a.node.type != "assignment_expression":
            return False
        if self._ned_file is None:
            self._ned_file = may_name_ned(self.pf.data)
        if not self._ned_file:
            return False
        return bool(self.evaluator.ned_down(self.pf, a.node.child_by_field_name("left")))

    def _fn_of(self, n: Any) -> str:
        return self.pf.function_name_of(n)

    def _publish(
        self,
        node: Any,
        args: Any,
        name_arg: Any,
        value_arg: Any,
        index: int,
        named: Name | None = None,
    ) -> None:
        """A publication at ``node`` of the name ``name_arg`` (or ``named``, the name it
        stands for) with the value ``value_arg``, the ``index``-th argument of ``args``."""
        spans = self.pf.spans
        pub_name = named if named is not None else self.name(name_arg)
        names = [pub_name] if pub_name.text is not None else self._table_names(name_arg)
        names = names or [pub_name]
        value = self.value(value_arg) if value_arg is not None else None
        valued = any(valued_name(n.last) for n in names)
        if value is not None and self._compiled_argument(args, index, value) in ("string", "bool"):
            valued = False  # not a number: no unit, sense or range to know
        if value is not None and self.evaluator is not None and valued:
            value.abstract = self.evaluator.of(self.pf, value_arg)
        statement = self._statement(node)
        for each in names:
            self.out.publications.append(
                Publication(
                    name=each,
                    value=value,
                    span=spans.of(node),
                    name_span=spans.of(name_arg),
                    function=self._fn_of(node),
                    statement=statement,
                )
            )

    def _statement(self, call: Any) -> tuple[int, int] | None:
        """Where the statement that is ``call`` alone sits in its block: (the block's first
        byte, the statement's place among the block's statements, comments aside); None
        for a call that is part of a larger statement or not in a block."""
        stmt = call.parent
        block = stmt.parent if stmt is not None and stmt.type == "expression_statement" else None
        if block is None or block.type != "compound_statement":
            return None
        places = self._places.get(block.start_byte)
        if places is None:
            statements = (c for c in block.named_children if c.type != "comment")
            places = {c.start_byte: i for i, c in enumerate(statements)}
            self._places[block.start_byte] = places
        place = places.get(stmt.start_byte)
        return (block.start_byte, place) if place is not None else None

    def _argument_use(self, call: Any, name: str, arg: Any) -> TrigUse | None:
        """A call of a function that takes an angle in one unit, with its argument's value:
        None outside a function, under ``#if 0``, or for a number written out."""
        if self.evaluator is None or in_if0(call) or self._fn_of(call) == "":
            return None
        s = strip_parens(arg)
        if s is None or s.type == "number_literal":
            return None
        value = self.value(arg)
        value.abstract = self.evaluator.of(self.pf, arg)
        return TrigUse(name, value, self.pf.spans.of(call), self._fn_of(call))

    def _angle_argument(self, call: Any, name: str, arg: Any) -> None:
        """A call of one of MOOS's angle functions (:data:`UNIT_ARGUMENT`), for the unit
        its argument is in (angle-argument-unit); not the app's own function of that name
        (it takes what it takes), nor a value converted where it is kept."""
        if self.evaluator is None or name in self.evaluator.folder.functions:
            return
        if _in_place(call, strip_parens(arg)):
            return
        use = self._argument_use(call, name, arg)
        if use is not None:
            self.out.angle_arguments.append(use)

    def _trig(self, call: Any, name: str, arg: Any) -> None:
        """A sine, cosine or tangent of a value that is not a number written out, for the
        unit it is in (trig-of-degrees)."""
        use = self._argument_use(call, name, arg)
        if use is None:
            return
        v = use.value.abstract
        if v is not None and v.unit is None and v.pending is None:
            use.value.abstract = self.evaluator.degree_term(self.pf, arg) or v
        self.out.trig_uses.append(use)

    def _unit_mix(self, node: Any, left: Any, right: Any) -> None:
        """Degrees and radians added, subtracted or compared (mixed-angle-units): each side's
        unit known, not by a name alone, one in degrees and the other in radians."""
        if self.evaluator is None or self.pf.function_of(node) is None:
            return
        lv = self.evaluator.of(self.pf, left)
        if lv.unit not in ("deg", "rad") or lv.hint:
            return  # (the other side is looked at only when this one has an angle's unit)
        rv = self.evaluator.of(self.pf, right)
        if {lv.unit, rv.unit} != {"deg", "rad"} or rv.hint or in_if0(node):
            return
        a, b = self.value(left), self.value(right)
        a.abstract, b.abstract = lv, rv
        op = text(node.child_by_field_name("operator"))
        self.out.unit_mixes.append(UnitMix(op, a, b, self.pf.spans.of(node), self._fn_of(node)))

    def _turn_mix(self, node: Any, angle: Any, number: Any) -> None:
        """``atan2(dy, dx) + 90``: a turn written in degrees added to or taken from an angle
        known to be in radians (mixed-angle-units). 90 radians is no turn at all: the sum
        is meant as degrees, and the conversion of the other side was forgotten."""
        if self.evaluator is None or self.pf.function_of(node) is None or in_if0(node):
            return
        av = self.evaluator.of(self.pf, angle)
        if av.unit != "rad" or av.hint or av.pending is not None:
            return
        if av.range is None and not _radians_call(angle):
            # (a sum with a value of unknown unit keeps the unit of its known side, with
            # no range: ``m_heading + m_away`` is no certain radian angle)
            return
        turn = round(float(text(number).rstrip("fFlL")))
        deg = self.evaluator.in_degrees(
            turn, f"{TURN_NAMES[turn][0]} in degrees, {TURN_NAMES[turn][1]} in radians"
        )
        a, b = self.value(angle), self.value(number)
        a.abstract, b.abstract = av, deg
        if number.start_byte < angle.start_byte:  # `90 - atan2(...)`: as written
            a, b = b, a
        op = text(node.child_by_field_name("operator"))
        self.out.unit_mixes.append(UnitMix(op, a, b, self.pf.spans.of(node), self._fn_of(node)))

    def _notify_msg(self, node: Any, args: Any) -> None:
        """``CMOOSMsg(MOOS_NOTIFY, NAME, VALUE[, time])``: a notification built to be posted."""
        argv = [a for a in args.named_children if a.type != "comment"]
        if len(argv) >= 3 and text(argv[0]).strip() in NOTIFY_KINDS and not in_if0(node):
            self._publish(node, args, argv[1], argv[2], 2)

    def _decimal_commas(self) -> None:
        """``x = y * 0,514444;``: a comma expression whose left side ends in a number and
        whose right side is digits, written together: a decimal comma."""
        pf = self.pf
        root = pf.tree.root_node
        for m in _DECIMAL_COMMA.finditer(pf.data):
            # the comma's own node: only a comma expression's is looked at (arrays and
            # arguments, most digit-comma-digit in C++, are not)
            comma = root.descendant_for_byte_range(m.start() + 1, m.start() + 2)
            n = comma.parent if comma is not None else None
            if n is None or n.type != "comma_expression":
                continue
            left, right = n.child_by_field_name("left"), n.child_by_field_name("right")
            if left is None or right is None or right.type != "number_literal":
                continue
            if left.type == "comma_expression" or (n.parent and n.parent.type == n.type):
                continue  # a list of values (a decimal comma makes one comma)
            if (
                left.type == "binary_expression"
                and text(left.child_by_field_name("operator")) == "<<"
            ):
                continue  # Eigen's comma initialiser: `m << 0,0;`
            last = _last_leaf(left)
            if last.type != "number_literal" or pf.data[last.end_byte : right.start_byte] != b",":
                continue
            if not (text(right).isdigit() and text(last).replace(".", "").isdigit()):
                continue
            if in_if0(n):
                continue
            span = pf.spans.of(last)
            end = pf.spans.of(right)
            self.out.decimal_commas.append(
                DecimalComma(
                    f"{text(last)},{text(right)}",
                    Span(span.path, span.line, span.col, end.end_line, end.end_col),
                    " ".join(text(left).split()),
                )
            )

    def _shadowed_branches(self) -> None:
        """Branches of an ``if`` / ``else if`` chain whose test an earlier branch takes
        (:mod:`moos_lint.frontends.cpp.branches`)."""
        pf = self.pf
        for s in branches.shadowed(pf.data, pf.tree.root_node):
            if in_if0(s.branch):
                continue
            self.out.shadowed_branches.append(
                ShadowedBranch(
                    test=" ".join(text(s.expr).split()),
                    name=string_value(s.node) or s.test.name,
                    span=pf.spans.of(s.node),
                    earlier_line=s.earlier_node.start_point[0] + 1,
                    earlier_caseless=s.earlier.caseless and not s.test.caseless,
                    function=self._fn_of(s.branch),
                )
            )

    def _call(self, call: Any, fn: Any, args: Any) -> None:
        name = callee(fn)
        if name in PUBLISH | SUBSCRIBE and in_if0(call):
            if name in SUBSCRIBE and args.named_children:  # taken out on purpose
                lit = string_value(strip_parens(args.named_children[0]))
                if lit is not None:
                    self.out.commented_registrations.append(lit)
            return
        argv = args.named_children
        spans = self.pf.spans
        out = self.out
        if name in UNIT_ARGUMENT and fn.type in ("identifier", "qualified_identifier"):
            real = [a for a in argv if a.type != "comment"]
            if len(real) == 1:
                self._angle_argument(call, name, real[0])
        if name in PUBLISH and argv and _is_moos_call(fn):
            self._publish(call, args, argv[0], argv[1] if len(argv) > 1 else None, 1)
        elif name == NOTIFY_MSG and fn.type == "identifier":
            self._notify_msg(call, args)
        elif name in VARIABLE_SET and argv and fn.type == "field_expression":
            self._variable_set(call, fn, argv)
        elif name == SET_MOOS_VAR and len(argv) >= 2 and _is_moos_call(fn):
            var = string_value(strip_parens(argv[0]))
            pub = self.tables.moos_vars.get(var) if var is not None else None
            if pub:
                named = Name(source=text(argv[0]), text=pub, prefix=pub)
                self._publish(call, args, argv[0], argv[1], 1, named=named)
        elif name == ADD_MOOS_VAR and len(argv) >= 3 and _is_moos_call(fn):
            # subscribed to its second name by RegisterMOOSVariables(), when the app calls it
            if self.tables.registers_moos_vars and string_value(strip_parens(argv[1])):
                out.subscriptions.append(
                    Subscription(
                        self.name(argv[1]), spans.of(call), spans.of(argv[1]), self._fn_of(call)
                    )
                )
        elif name in FROM_DEGREES and argv:
            var = mail_key_of(call)
            if var is not None and _reads_mail(argv[0]):
                out.consumed_degrees.append((var, spans.of(call), name))
        elif name in SUBSCRIBE and argv and _is_moos_call(fn):
            out.subscriptions.append(
                Subscription(
                    self.name(argv[0]), spans.of(call), spans.of(argv[0]), self._fn_of(call)
                )
            )
        elif name == "Run" and fn.type == "field_expression" and argv:
            # CMOOSApp::Run(name, mission[, argc, argv]); not CMOOSCommClient::Run(host, port, ...)
            second = strip_parens(argv[1]) if len(argv) > 1 else None
            app_run = len(argv) in (2, 4) and second is not None and second.type != "number_literal"
            if self._fn_of(call) == "main" and app_run:
                # a literal, or a name set to one before the call (``const char* sMOOSName =
                # "iGPS";``, a ``#define``); one the command line may set (``sMOOSName =
                # argv[2]``, ``run_command = argv[0]``) is not known
                lit, _ = self._resolve(argv[0], 0)
                if lit:
                    out.run_names.append((lit, spans.of(argv[0])))
        elif name in CONFIG_CALLS:
            for a in argv:
                lit = string_value(strip_parens(a))
                if lit is not None:
                    out.config_params.append(ConfigParam(lit.lower(), spans.of(a)))
                    break
        elif name in TRIG and len(argv) == 1 and fn.type in ("identifier", "qualified_identifier"):
            self._trig(call, name, argv[0])
        elif name == GLOBAL_VALUE and argv and fn.type == "field_expression":
            key = string_value(strip_parens(argv[0]))
            if key is not None and key.lower() in ORIGIN_KEYS:
                out.origin_reads.append(OriginRead(key, spans.of(call), _optional_read(call)))
        elif name in GEODESY_ARGUMENTS and not in_if0(call):
            given = [a for a in argv if a.type != "comment"]
            if len(given) == 4:
                arguments = [(text(a), spans.of(a)) for a in given]
                obj = fn.child_by_field_name("argument") if fn.type == "field_expression" else None
                receiver = text(obj).removeprefix("this->") if obj is not None else None
                out.geodesy_calls.append(
                    GeodesyCall(name, arguments, spans.of(call), None, receiver)
                )
        elif name in BAUD_CALLS:
            out.io.append(IOUse("serial", name, spans.of(call)))
        elif (name in SOCKET_CALLS and fn.type == "identifier") or name in VEHICLE_LINK_CALLS:
            out.io.append(IOUse("socket", name, spans.of(call)))
        elif name in STRCMP and len(argv) >= 2:
            lit = string_value(strip_parens(argv[1]))
            if lit is not None:
                self._compared(
                    call,
                    argv[0],
                    lit,
                    argv[1],
                    prefix=name == "strBegins",
                    suffix=name == "strEnds",
                )

    def _variable_set(self, call: Any, fn: Any, argv: list[Any]) -> None:
        """``m_PublishedVars[NAV_YAW]->Set(v, t)`` (or through a local pointer to it): a
        published ``CMOOSVariable`` named, as far as we know, by its table index."""
        obj = strip_parens(fn.child_by_field_name("argument"))
        if obj is not None and obj.type == "identifier":
            local = self._local_before(call, text(obj))
            obj = strip_parens(local.rhs) if local is not None and local.op == "=" else None
        if obj is None or obj.type != "subscript_expression":
            return
        if not re.search(r"publish", text(obj.child_by_field_name("argument")), re.I):
            return
        suffix = self._suffix(obj)
        if not suffix or not valued_name(suffix):
            return
        value = self.value(argv[0])
        numeric = self._compiled_argument(call.child_by_field_name("arguments"), 0, value) not in (
            "string",
            "bool",
        )
        if self.evaluator is not None and numeric:
            value.abstract = self.evaluator.of(self.pf, argv[0])
        self.out.publications.append(
            Publication(
                name=Name(source=text(obj), suffix=suffix),
                value=value,
                span=self.pf.spans.of(call),
                name_span=self.pf.spans.of(obj),
                function=self._fn_of(call),
            )
        )

    def _compiled_argument(self, args: Any, index: int, value: Value) -> str | None:
        """With libclang's facts: the type of the call's ``index``-th argument (integer,
        floating, string, bool) set on ``value``, with its folded number."""
        compiled = self.evaluator.compiled if self.evaluator is not None else None
        if compiled is None or args is None:
            return None
        row, col = args.start_point  # the call's ``(``
        kind, number = compiled.argument(self.pf.path, row, col, index)
        value.type = kind
        if value.number is None and kind in ("integer", "floating"):
            value.number = number
        return kind

    def _comparison(self, cmp: Any, left: Any, right: Any) -> None:
        lit = string_value(right)
        if lit is None:
            return
        op = cmp.child_by_field_name("operator")
        negated = op is not None and op.type == "!="
        self._compared(cmp, left, lit, right, prefix=False, negated=negated)
        if left.type == "identifier" and re.search(r"[A-Za-z]", lit):
            self._case_mismatch(cmp, text(left), lit, right, negated)

    def _case_mismatch(self, cmp: Any, var: str, lit: str, lit_node: Any, negated: bool) -> None:
        """``param == "TSS_FILE"`` after ``param = tolower(...)``: the last change of
        ``param`` before the comparison, in its function, made its case one the literal
        cannot have (:data:`_CASE_CHANGES`); any other assignment leaves it unknown."""
        fn = self.pf.function_of(cmp)
        if fn is None:
            return
        converted = self._case_set.get(fn.start_byte)
        if converted is None:  # (one search of the function for all its comparisons)
            converted = {}
            for m in _CASE_SET.finditer(self.pf.data[fn.start_byte : fn.end_byte]):
                converted.setdefault(m.group(1), set()).add(_CASE_CHANGES[m.group(2).decode()])
            self._case_set[fn.start_byte] = converted
        cases = converted.get(var.encode(), ())
        if not any(lit != (lit.lower() if c == "lower" else lit.upper()) for c in cases):
            return  # (most often: `param == "speed"` after a tolower)
        if in_if0(cmp):
            return
        before = self.pf.data[fn.start_byte : cmp.start_byte]
        name = re.escape(var).encode()
        last = None
        for m in re.finditer(rb"\b" + name + rb"\s*=(?!=)\s*([\w:]+)?\s*(\()?", before):
            last = m
        if last is None or last.group(1) is None or last.group(2) is None:
            return  # (not assigned in the function, or from no call: ``param = (x)``)
        call = last.group(1).decode()
        if call in _CASE_KEEPERS:  # ``stripBlankEnds(toupper(...))``
            inner = re.match(rb"\s*([\w:]+)\s*\(", before[last.end() :])
            call = inner.group(1).decode() if inner else call
        change = _CASE_CHANGES.get(call)
        if change is None:
            return
        # after the conversion: the variable changed in place, or handed to code that may
        after = before[last.end() :]
        if re.search(
            rb"\b" + name + rb"\b\s*(?:[-+]?=(?!=)|\.(?!c_str|size|length|find)\w+\s*\()", after
        ):
            return
        if re.search(rb"[(,]\s*&?\s*" + name + rb"\s*[,)]", after):
            return
        wrong = lit != (lit.lower() if change == "lower" else lit.upper())
        if not wrong:
            return
        meant = lit.lower() if change == "lower" else lit.upper()
        condition = _condition_of(cmp)
        if f'"{meant}"'.encode() in self.pf.data[condition.start_byte : condition.end_byte]:
            return  # ``param == "NAME" || param == "name"``: the other side holds
        if _empty_branch(condition):
            return  # ``if(param == "foo") { // handled }``: a template's placeholder
        line = self.pf.data[: fn.start_byte + last.start()].count(b"\n") + 1
        self.out.case_mismatches.append(
            CaseMismatch(var, lit, call, change, line, self.pf.spans.of(lit_node), negated)
        )

    def _compared(
        self,
        node: Any,
        subject: Any,
        lit: str,
        lit_node: Any,
        prefix: bool,
        suffix: bool = False,
        negated: bool = False,
    ) -> None:
        fname = short(self._fn_of(node))
        subject_text = text(subject)
        span = self.pf.spans.of(lit_node)
        low = fname.lower()
        mail_fn = fname == "OnNewMail" or re.search(r"mail", low)
        if not mail_fn and (fname == "OnStartUp" or _CONFIG_FN.search(fname)):
            if re.search(r"param|key|line|name|sVar|arg", subject_text, re.I):
                head = _head_of(subject)  # ``param.substr(0, 6) == "IMAGE_"``
                self.out.config_params.append(
                    ConfigParam(lit.lower(), span, prefix=prefix or head is not None)
                )
        elif mail_fn or re.search(r"\bkey\b|GetKey|GetName", subject_text):
            direct = not (prefix or suffix) and self._message_key(node, subject)
            key = MailKey(lit, span, prefix, suffix, direct, negated=negated)
            self.out.mail_keys.append(_branch(key, node, self._reads_in))

    def _message_key(self, at: Any, subject: Any) -> bool:
        """Whether ``subject`` is a message's own name: ``msg.GetKey()``, ``p->GetName()``,
        ``rMsg.m_sKey``, or a local set from one of them (``string key = msg.GetKey();``).
        A ``key`` parsed from a message's text (``biteStringX(pair, '=')``) is not."""
        subject = strip_parens(subject)
        if subject is None:
            return False
        if subject.type == "call_expression":
            return callee(subject.child_by_field_name("function")) in ("GetKey", "GetName")
        if subject.type == "field_expression":
            return text(subject).endswith("m_sKey")
        if subject.type != "identifier":
            return False
        local = self._local_before(at, text(subject))
        if local is None or local.op != "=":
            return False
        return local.rhs is not None and _KEY_READ.match(text(local.rhs)) is not None

    def _mail_handling(self, fn: Any) -> None:
        """Prefix matches on the key, and whether messages go to code we cannot follow."""
        for n in nodes_under(fn.child_by_field_name("body")):
            if n.type == "call_expression":
                f = n.child_by_field_name("function")
                args = n.child_by_field_name("arguments").named_children
                name = callee(f)
                if name in PREFIX_CALLS and args:
                    # the literal the key is compared with: ``key.find("X_")``,
                    # ``strBegins(key, "X_")``, ``strncmp(key.c_str(), "X_", 2)``,
                    # ``key.compare(0, 2, "X_")``
                    lit = next(
                        (v for a in args[:3] if (v := string_value(strip_parens(a))) is not None),
                        None,
                    )
                    if lit is not None:
                        self.out.mail_keys.append(MailKey(lit, self.pf.spans.of(n), prefix=True))
                if (
                    name not in _TESTS
                    and name not in _NOT_HANDLERS
                    and not _in_condition(n)
                    and not _under_literal_branch(n)
                    and any(_GENERIC_ARG.match(text(strip_parens(a))) for a in args)
                ):
                    self.out.mail_generic = True
                if name == "IsName" and args:
                    lit = string_value(strip_parens(args[0]))
                    if lit is not None:
                        span = self.pf.spans.of(args[0])
                        key = MailKey(lit, span, direct=True)
                        self.out.mail_keys.append(_branch(key, n, self._reads_in))
                if name in MAIL_COMPARES and len(args) > 1:
                    self._key_against(strip_parens(args[0]), strip_parens(args[1]))
                if name in PEEK_MAIL and len(args) > 1:  # PeekMail(NewMail, "KEY", Msg)
                    val, _ = self._resolve(args[1], 0)
                    if val is not None:
                        span = self.pf.spans.of(args[1])
                        self.out.mail_keys.append(MailKey(val, span, direct=True))
            elif n.type == "binary_expression":
                op = n.child_by_field_name("operator")
                if op is not None and op.type in ("==", "!="):
                    left = strip_parens(n.child_by_field_name("left"))
                    right = strip_parens(n.child_by_field_name("right"))
                    if left is not None and right is not None:
                        self._key_against(left, right)

    def _wrapper_calls(self) -> None:
        """Calls of the folder's own functions that publish their arguments
        (``post("NAV_YAW", yaw)`` with ``void post(string var, double v) { Notify(var, v); }``):
        publications at the call, of its name and value."""
        wrappers = self.tables.notify_wrappers
        data = self.pf.data
        if not any(name.encode() + b"(" in data for name in wrappers):
            return
        found = []
        for n in nodes_under(self.pf.tree.root_node):
            if n.type == "call_expression":
                fn = n.child_by_field_name("function")
                spec = wrappers.get(callee(fn)) if fn is not None else None
                args = n.child_by_field_name("arguments")
                if spec is not None and args is not None and _is_moos_call(fn):
                    argv = [a for a in args.named_children if a.type != "comment"]
                    if len(argv) > max(spec) and not in_if0(n):
                        found.append((n.start_byte, n, args, argv[spec[0]], argv[spec[1]], spec[1]))
        for _at, n, args, name_arg, value_arg, index in sorted(found, key=lambda f: f[0]):
            self._publish(n, args, name_arg, value_arg, index)

    def _config_handling(self, fn: Any) -> None:
        """Configuration keys compared with a name held elsewhere (``param == m_x_key`` of
        a member set to a literal in the constructor, ``MOOSStrCmp(param, KEY_X)`` of a
        ``#define``): the key, when it can be read."""
        for n in nodes_under(fn.child_by_field_name("body")):
            pair = None
            if n.type == "binary_expression":
                op = n.child_by_field_name("operator")
                if op is not None and op.type == "==":
                    pair = n.child_by_field_name("left"), n.child_by_field_name("right")
            elif n.type == "call_expression" and callee(n.child_by_field_name("function")) in (
                MAIL_COMPARES
            ):
                args = n.child_by_field_name("arguments").named_children
                if len(args) > 1:
                    pair = args[0], args[1]
            if pair is not None:
                a, b = strip_parens(pair[0]), strip_parens(pair[1])
                if a is not None and b is not None:
                    self._config_against(a, b)
            if n.type == "call_expression":
                lit_node = _prefix_test(n)
                if lit_node is not None:
                    lit = string_value(lit_node)
                    if lit and (lit[0].isalpha() or lit[0] == "_"):  # not `line.find("//") == 0`
                        span = self.pf.spans.of(lit_node)
                        self.out.config_params.append(ConfigParam(lit.lower(), span, prefix=True))

    def _config_against(self, a: Any, b: Any) -> None:
        for subject, other in ((a, b), (b, a)):
            if other.type not in _NAME_NODES or subject.type != "identifier":
                continue
            if not _CONFIG_SUBJECT.search(text(subject)) or _CONFIG_SUBJECT.search(text(other)):
                continue
            val, _ = self._resolve(other, 0)
            if val:
                self.out.config_params.append(ConfigParam(val.lower(), self.pf.spans.of(other)))
            return

    def _key_against(self, a: Any, b: Any) -> None:
        """The key compared with a name held elsewhere (``key == SLAVE_ORDERS`` of a
        ``#define``, ``key == m_var`` of a member set to a literal): the name, when it can
        be read. A name that cannot be read (a collaborator's, given at run time) handles
        no literal registration: ``Register("COLLABORATOR_NAV_X")`` beside
        ``key == m_collab + "_NAV_X"`` is the mistake the rule is for."""
        for subject, other in ((a, b), (b, a)):
            if other.type not in _NAME_NODES or string_value(other) is not None:
                continue
            if not _is_key(subject) or _KEY_SUBJECT.search(text(other)):
                continue
            val, _ = self._resolve(other, 0)
            if val is not None:
                direct = self._message_key(other, subject)
                key = MailKey(val, self.pf.spans.of(other), direct=direct, held_in=text(other))
                self.out.mail_keys.append(_branch(key, other, self._reads_in))
            return


_ATOMS = (
    "identifier",
    "field_expression",
    "call_expression",
    "number_literal",
    "qualified_identifier",
    "subscript_expression",
)


def _branch(
    key: MailKey, test: Any, reads_in: dict[int, tuple[dict[str, str], set[str]]]
) -> MailKey:
    """``key`` with what the ``if`` its test guards says of it: the ``||`` chain the test
    is one alternative of, whether the branch does nothing, and how it reads the message's
    value (``reads_in``: what :func:`_value_read` found of each function, kept per file)."""
    n = test
    while n.parent is not None and n.parent.type in _TEST_PARTS:
        n = n.parent
        op = n.child_by_field_name("operator") if n.type == "binary_expression" else None
        if op is not None and op.type == "||":
            key.either_at = n.start_byte
    clause = n.parent
    stmt = clause.parent if clause is not None and clause.type == "condition_clause" else None
    if stmt is not None and stmt.type == "if_statement":
        body = stmt.child_by_field_name("consequence")
        if body is not None and body.type == "compound_statement":
            key.empty_branch = not any(c.type != "comment" for c in body.named_children)
        elif body is not None and body.type == "expression_statement":
            key.empty_branch = body.named_child_count == 0
        if body is not None and key.direct:
            key.reads = _value_read(body, stmt, reads_in)
    return key


#: a message's value read as a number, as text, or its type asked
_AS_NUMBER = re.compile(r"\bGetDouble\s*\(")
_AS_TEXT = re.compile(
    r"\b(?:GetString|GetAsString|IsString|IsDouble|IsDataType|IsBinary|GetBinaryData\w*)\s*\("
)
#: ``double dval = msg.GetDouble();`` / ``string sval = p->GetString();``: a local declared
#: with the value as it is (not ``sval = doubleToStringX(msg.GetDouble())``, nor a member
#: another branch sets from its own message)
_LOCAL_OF = re.compile(
    r"\b(?:double|float|int|long|bool|auto|string|std::string)\s*&?\s+(\w+)\s*=\s*"
    r"\(?\s*\*?\s*\w+\s*\)?\s*(?:\.|->)\s*(GetDouble|GetString)\s*\(\s*\)"
)
#: the message object a key is read from (``msg`` of ``msg.GetKey()``)
_MESSAGE_OF = re.compile(r"\b(\w+)\s*(?:\.|->)\s*Get(?:Key|Name)\s*\(")


def _value_read(body: Any, stmt: Any, reads_in: dict[int, tuple[dict[str, str], set[str]]]) -> str:
    """How ``body``, the branch of ``stmt`` that one mail key guards, reads the message's
    value (see :attr:`MailKey.reads`), with the locals its function declares from it (read
    once per function: an OnNewMail of many keys is read once, not once per key)."""
    fn = stmt
    while fn is not None and fn.type != "function_definition":
        fn = fn.parent
    at = fn.start_byte if fn is not None else -1 - body.start_byte
    found = reads_in.get(at)
    if found is None:
        scope = text(fn) if fn is not None else text(body)
        locals_of: dict[str, str] = {}
        for m in _LOCAL_OF.finditer(scope):  # a local that ever holds the text is text
            if locals_of.get(m.group(1)) != "GetString":
                locals_of[m.group(1)] = m.group(2)
        found = reads_in[at] = (locals_of, set(_MESSAGE_OF.findall(scope)))
    locals_of, objects = found
    said = text(body)
    words = set(re.findall(r"\b\w+\b", said))
    for obj in objects:  # the message handed on whole
        if re.search(r"[(,]\s*\*?\s*" + re.escape(obj) + r"\s*[,)]", said):
            return ""
    text_read = bool(_AS_TEXT.search(said)) or any(locals_of.get(w) == "GetString" for w in words)
    if text_read:
        return "text"
    number_read = bool(_AS_NUMBER.search(said)) or any(
        locals_of.get(w) == "GetDouble" for w in words
    )
    return "number" if number_read else ""


#: what lies between a key's test and its ``if``: ``(key == "A") || (key == "B")``
_TEST_PARTS = ("parenthesized_expression", "binary_expression")


def _is_key(n: Any) -> bool:
    """The message's key itself (``key``, ``sKey``, ``msg.GetKey()``), not a use of it
    (``key.find("X")``)."""
    if n.type in _NAME_NODES:
        return bool(_KEY_SUBJECT.search(text(n)))
    return n.type == "call_expression" and callee(n.child_by_field_name("function")) in (
        "GetKey",
        "GetName",
    )


#: a message's name read (``msg.GetKey()``, ``p->GetName()``), maybe case-folded
#: (``toupper(msg.GetKey())``)
_KEY_READ = re.compile(r"^(?:\w+\(\s*)?[\w.>*-]+(?:\.|->)Get(?:Key|Name)\(\)\s*\)?$")
#: ``Register("X"``: taken out on purpose in a comment (``// Register("X", 0);``, ``/* */``)
_REGISTER_LITERAL = re.compile(rb'Register\s*\(\s*"([^"\n]+)"')
#: the comms client or the app passed to other code (``f(m_Comms)``, ``new Worker(this)``);
#: two patterns, each led by its literal (an alternation first is tried at every byte)
_HANDED = (re.compile(rb"m_Comms\s*[,)}]"), re.compile(rb"this\s*[,)}]"))
#: calls that hand the app to a thread of its own, which registers nothing elsewhere
_THREAD_STARTS = {b"Initialise", b"pthread_create", b"thread", b"Start", b"CMOOSThread"}
#: what a mail handler compares a key with when it holds the name elsewhere
_NAME_NODES = ("identifier", "field_expression", "qualified_identifier")
#: the functions that read an app's configuration, and the key they compare
_CONFIG_FN = re.compile(r"config|startup|param", re.I)


def _head_of(subject: Any) -> Any:
    """The string ``subject`` takes the head of (``param`` of ``param.substr(0, 6)``), or None."""
    subject = strip_parens(subject)
    if subject is None or subject.type != "call_expression":
        return None
    fn = subject.child_by_field_name("function")
    args = subject.child_by_field_name("arguments")
    if fn is None or fn.type != "field_expression" or callee(fn) != "substr" or args is None:
        return None
    argv = [a for a in args.named_children if a.type != "comment"]
    if len(argv) != 2 or text(argv[0]).strip() != "0":
        return None
    return fn.child_by_field_name("argument")


#: a method that tests how a string starts, by its arguments: ``s.find("X") == 0``,
#: ``s.rfind("X", 0) == 0``, ``s.compare(0, 6, "IMAGE_") == 0``, ``s.starts_with("X")``
#: (the index of the literal, and the arguments that must be 0)
_PREFIX_METHODS = {
    "find": (0, (1,)),
    "rfind": (0, (1,)),
    "compare": (2, (0,)),
    "starts_with": (0, ()),
}


def _prefix_test(call: Any) -> Any:
    """The literal of a test of how a configuration key starts (see :data:`_PREFIX_METHODS`),
    on a subject named like one (``param``, ``sKey``, ``line``), or None."""
    fn = call.child_by_field_name("function")
    if fn is None or fn.type != "field_expression":
        return None
    spec = _PREFIX_METHODS.get(callee(fn))
    subject = strip_parens(fn.child_by_field_name("argument"))
    args = call.child_by_field_name("arguments")
    if spec is None or subject is None or subject.type != "identifier" or args is None:
        return None
    if not _CONFIG_SUBJECT.search(text(subject)):
        return None
    argv = [a for a in args.named_children if a.type != "comment"]
    at, zeros = spec
    if len(argv) <= at or string_value(strip_parens(argv[at])) is None:
        return None
    if callee(fn) == "find" and len(argv) == 1:
        zeros = ()
    if any(len(argv) <= z or text(argv[z]).strip() != "0" for z in zeros):
        return None
    if callee(fn) != "starts_with":  # the result must be compared with 0
        parent = call.parent
        while parent is not None and parent.type == "parenthesized_expression":
            parent = parent.parent
        if parent is None or parent.type != "binary_expression":
            return None
        op = parent.child_by_field_name("operator")
        sides = [strip_parens(parent.child_by_field_name(k)) for k in ("left", "right")]
        others = [s for s in sides if s is not None and s.id != call.id]
        if op is None or op.type != "==" or len(others) != 1 or text(others[0]).strip() != "0":
            return None
    return strip_parens(argv[at])


_CONFIG_SUBJECT = re.compile(r"^(?:s|str)?(?:param|key|line|name|var|arg)\w*$", re.I)
#: the message's key (``msg.GetKey()``, ``key``, ``sKey``, ``rMsg.m_sKey``)
_KEY_SUBJECT = re.compile(r"key|GetName", re.I)
_GENERIC_ARG = re.compile(r"^(?:\*?p|\w*[Mm]sg|\w*[Kk]ey|\w*[Mm]ail\w*|message|e|rMsg)$")


#: calls in a mail handler that read a message or report, and do not handle it
_NOT_HANDLERS = {
    "OnNewMail",
    "GetKey",
    "GetString",
    "GetDouble",
    "IsDouble",
    "IsString",
    "GetTime",
    "GetSource",
    "GetCommunity",
    "GetSourceAux",
    "IsName",
    "begin",
    "end",
    "push_back",
    "handleMailAppCastRequest",
    "reportRunWarning",
    "reportEvent",
    "c_str",
}
_TESTS = STRCMP | PREFIX_CALLS | {"strEnds", "strContains", "tolower", "toupper", "MOOSToUpper"}


def _optional_read(call: Any) -> bool:
    """The call is the test of an ``if`` that has no ``else``, alone or joined by
    ``&&`` (``if (GetValue("LatOrigin", a) && GetValue("LongOrigin", b)) { ... }``): the
    code goes on the same way when the value is missing. Negated (``if (!GetValue(...))``),
    kept in a flag (``bool ok = GetValue(...)``) or followed by an ``else``, the app
    reacts to the value's absence."""
    p = call.parent
    while p is not None and (
        p.type == "parenthesized_expression"
        or (p.type == "binary_expression" and text(p.child_by_field_name("operator")) == "&&")
    ):
        p = p.parent
    if p is None or p.type != "condition_clause":
        return False
    stmt = p.parent
    return (
        stmt is not None
        and stmt.type == "if_statement"
        and stmt.child_by_field_name("alternative") is None
    )


def _in_condition(n: Any) -> bool:
    """Part of an ``if``/``while`` condition (a test of the key, not handling)."""
    p = n.parent
    while p is not None and p.type not in ("expression_statement", "compound_statement"):
        if p.type == "condition_clause":
            return True
        p = p.parent
    return False


#: a digit, a comma and a digit with no space between: where a decimal comma may be
_DECIMAL_COMMA = re.compile(rb"[0-9],[0-9]")


def _last_leaf(n: Any) -> Any:
    while n.child_count:
        n = n.children[-1]
    return n


def in_if0(n: Any) -> bool:
    """Inside the live branch of ``#if 0`` (code the compiler never sees)."""
    p, child = n.parent, n
    while p is not None:
        if p.type == "preproc_if":
            cond = p.child_by_field_name("condition")
            alt = p.child_by_field_name("alternative")
            if cond is not None and text(cond).strip() == "0" and child != alt:
                return True
        p, child = p.parent, p
    return False


def _under_literal_branch(n: Any) -> bool:
    """Inside an ``if`` whose condition compares with a string literal."""
    p, child = n.parent, n
    while p is not None and p.type != "function_definition":
        if p.type == "if_statement" and child == p.child_by_field_name("consequence"):
            cond = p.child_by_field_name("condition")
            if cond is not None and '"' in text(cond):
                return True
        p, child = p.parent, p
    return False


def _inside(n: Any, outer: Any) -> bool:
    return outer.start_byte <= n.start_byte and n.end_byte <= outer.end_byte


def _top_of(n: Any, start_byte: int) -> Any:
    """A node at ``start_byte`` to look up what came before a normalisation sequence."""
    p = n
    while p.parent is not None and p.parent.start_byte >= start_byte:
        p = p.parent
    return p


def _reads_mail(arg: Any) -> bool:
    """The argument is what a message carries (``msg.GetDouble()``, ``dval``)."""
    t = text(arg)
    return bool(re.search(r"GetDouble|GetString|dval|dfVal|dValue|atof|stod", t))


def _is_moos_call(fn: Any) -> bool:
    """``Notify(...)``, ``m_Comms.Notify(...)``, ``CMOOSApp::Notify(...)``; not ``cv.notify``."""
    return fn.type in ("identifier", "field_expression", "qualified_identifier")


def include_io(path: str) -> str:
    """The kind of I/O an included header gives (``sys/socket.h``: socket), or ''."""
    low = path.lower()
    if low in ("termios.h", "sys/termios.h"):
        return "termios"
    if low.startswith("linux/can") or "socketcan" in low:
        return "can"
    if "libusb" in low or "hidapi" in low or low.startswith("linux/usb"):
        return "usb"
    if "serialport" in low.replace("_", "") or low.endswith("serial.h"):
        return "serial"
    if low in _DEVICE_HEADERS or low.startswith(("modbus/", "linux/spi/")) or _RC_MODULE.match(low):
        return "device"
    if low in ("sys/socket.h", "netinet/in.h", "arpa/inet.h", "winsock2.h", "curl/curl.h"):
        return "socket"
    if low.startswith(("fl/", "qtwidgets/", "qtgui/")) or low in _QT_WINDOWS:
        return "gui"  # FLTK (pMarineViewer's `FL/Fl.H`) or Qt: a window of its own
    return ""


#: libraries that reach hardware: a Raspberry Pi's GPIO (pigpio, wiringPi, libgpiod), the
#: kernel's I2C, SPI and GPIO interfaces, libmodbus (``modbus/modbus.h``, RTU or TCP), the
#: BeagleBone's librobotcontrol (``robotcontrol.h``, ``rc/mpu.h``)
_DEVICE_HEADERS = frozenset(
    {
        "pigpio.h",
        "pigpiod_if2.h",
        "wiringpi.h",
        "wiringpii2c.h",
        "wiringpispi.h",
        "gpiod.h",
        "gpiod.hpp",
        "linux/i2c-dev.h",
        "linux/i2c.h",
        "linux/gpio.h",
        "modbus.h",
        "robotcontrol.h",
    }
)

_RC_MODULE = re.compile(r"rc/(?:mpu|servo|motor|adc|encoder\w*|i2c|spi|uart|pwm|gpio|bmp|dsm)\.h$")

#: Qt headers included by class name that only a program with windows includes
_QT_WINDOWS = frozenset({"qapplication", "qmainwindow", "qwidget", "qguiapplication"})


#: calls that return a string in one case: MOOS-IvP's MBUtils, core MOOS's
#: MOOSUtilityFunctions (its in-place overloads return nothing), boost
_CASE_CHANGES = {
    "tolower": "lower",
    "toupper": "upper",
    "MOOSToLower": "lower",
    "MOOSToUpper": "upper",
    "boost::to_lower_copy": "lower",
    "boost::to_upper_copy": "upper",
    "boost::algorithm::to_lower_copy": "lower",
    "boost::algorithm::to_upper_copy": "upper",
}


#: calls that keep the case of the string they are given (MBUtils)
_CASE_KEEPERS = ("stripBlankEnds", "stripBlanks", "stripQuotes")
#: a variable set from one of those calls, maybe inside one that keeps its case
_CASE_SET = re.compile(
    rb"\b(\w+)\s*=\s*(?:(?:"
    + "|".join(_CASE_KEEPERS).encode()
    + rb")\s*\(\s*)?("
    + "|".join(map(re.escape, _CASE_CHANGES)).encode()
    + rb")\s*\("
)


def _empty_branch(condition: Any) -> bool:
    """Whether the ``if`` that ``condition`` tests has a branch with no statement in it
    (comments only): whether it runs changes nothing."""
    clause = condition.parent
    stmt = clause.parent if clause is not None and clause.type == "condition_clause" else None
    if stmt is None or stmt.type != "if_statement":
        return False
    body = stmt.child_by_field_name("consequence")
    if body is None or body.type != "compound_statement":
        return False
    return all(c.type == "comment" for c in body.named_children)


def _condition_of(n: Any) -> Any:
    """The whole condition a comparison is part of: the outermost ``||``, ``&&``, ``!``
    or parentheses around it (what an ``if``, a loop or a statement holds)."""
    while n.parent is not None and n.parent.type in (
        "binary_expression",
        "parenthesized_expression",
        "unary_expression",
    ):
        n = n.parent
    return n
