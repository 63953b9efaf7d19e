"""Where a mission or behavior file names a MOOS variable, and in what syntax.

MOOS itself never says which configuration values are variable names: each
app decides for its own parameters. This module holds that knowledge for the
stock MOOS and MOOS-IvP apps and for the IvP helm, so that every rule (and a
publish/subscribe graph) reads variable names the same way:

- :func:`moos_variables` yields the variables a ``.moos`` file names, per
  ProcessConfig block, for the apps in :data:`APP_PARAMS`;
- :func:`bhv_variables` yields the variables a ``.bhv`` file names: behavior
  conditions and flags, ``updates``, ``initialize`` and ``set`` blocks;
- :func:`unit_variables` does either for a linted unit.

Each :class:`VarRef` carries the name as written, where it is (a
:class:`~moos_lint.files.diagnostics.Span` via its :class:`~moos_lint.frontends.nsplug.Line`),
whether the app publishes or subscribes to it, and whether the app accepts
``*``/``?`` wildcards there. Names are returned as written: callers decide
what to do with placeholders (``$[X]``, ``$V``) and nsplug macros (``$(X)``).
The syntaxes follow the app sources (for example the helm's flags follow
``setVarDataPairOnString``: ``[@tag] [#dest] VAR = value [[if] condition]``;
logic conditions follow lib_logic: the left side of each relation is a
variable, the right side a literal).
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from moos_lint.files.diagnostics import Span
from moos_lint.frontends.nsplug import Line, derived
from moos_lint.frontends.parsers.nodes import BehaviorFile, Block, MoosFile, has_macro

PUBLISH = "publish"
SUBSCRIBE = "subscribe"
#: the actuators of the MOOS Conventions (section 4.3): a command to one is
#: ``DESIRED_<ACTUATOR>`` (pMarinePID posts them, uSimMarine and the drivers read them)
STANDARD_ACTUATORS = ("THRUST", "RUDDER", "ELEVATOR")

#: A piece of a line: its text and the index of its first character in ``line.text``.
Piece = tuple[str, int]


@dataclass(frozen=True, slots=True)
class VarRef:
    """One place where a configuration value names a MOOS variable."""

    name: str
    line: Line
    start: int  # index of the name in ``line.text``
    role: str  # PUBLISH or SUBSCRIBE
    app: str  # the ProcessConfig block (or behavior kind, or ``helm``) that reads the value
    param: str  # the parameter key, lower case
    wildcard: bool = False  # the app accepts ``*`` and ``?`` here
    #: what the app subscribes to for this name, when not the name itself (see
    #: :data:`SUBSCRIBED_AS`); ``*`` stands for any text
    reads: tuple[str, ...] = ()

    @property
    def span(self) -> Span:
        return self.line.span(self.start, self.start + len(self.name))

    @property
    def read_names(self) -> tuple[str, ...]:
        """The variables the app reads for this reference (a subscription's)."""
        return self.reads or (self.name,)


# ------------------------------------------------------------------ text pieces
def _trim(piece: Piece) -> Piece:
    text, at = piece
    lead = len(text) - len(text.lstrip())
    return text.strip(), at + lead


def _split(piece: Piece, sep: str, quotes: bool = True, braces: bool = False) -> list[Piece]:
    """Split on ``sep`` outside double quotes (and ``{}`` when asked); pieces trimmed."""
    text, at = piece
    out: list[Piece] = []
    if '"' not in text and not (braces and "{" in text):
        # nothing to skip over (the common case): plain splitting, same pieces
        start = 0
        while True:
            i = text.find(sep, start)
            if i < 0:
                out.append(_trim((text[start:], at + start)))
                return out
            out.append(_trim((text[start:i], at + start)))
            start = i + len(sep)
    start, quoted, depth = 0, False, 0
    i = 0
    while i < len(text):
        ch = text[i]
        if quotes and ch == '"':
            quoted = not quoted
        elif braces and ch == "{" and not quoted:
            depth += 1
        elif braces and ch == "}" and not quoted and depth:
            depth -= 1
        elif not quoted and depth == 0 and text.startswith(sep, i):
            out.append(_trim((text[start:i], at + start)))
            i += len(sep)
            start = i
            continue
        i += 1
    out.append(_trim((text[start:], at + start)))
    return out


def _bite(piece: Piece, sep: str) -> tuple[Piece, Piece] | None:
    """(left, right) of the first ``sep``, both trimmed; None without ``sep``."""
    text, at = piece
    idx = text.find(sep)
    if idx < 0:
        return None
    return _trim((text[:idx], at)), _trim((text[idx + len(sep) :], at + idx + len(sep)))


_SPACE = re.compile(r"\s")


def _is_name(text: str) -> bool:
    return bool(text) and _SPACE.search(text) is None


# ------------------------------------------------------------------ syntaxes
#: A syntax reads a value piece and yields (name piece, role).
Syntax = Callable[[Piece], Iterator[tuple[Piece, str]]]


def plain(role: str) -> Syntax:
    """The whole value is one variable name."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        piece = _trim(piece)
        if _is_name(piece[0]):
            yield piece, role

    return read


def comma_list(role: str) -> Syntax:
    """``A, B, C``."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        for item in _split(piece, ","):
            if _is_name(item[0]):
                yield item, role

    return read


def before(sep: str, role: str) -> Syntax:
    """The name is the text before ``sep`` (pLogger ``Log = VAR @ 0 NOSYNC``)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _bite(piece, sep)
        name = parts[0] if parts else _trim(piece)
        if _is_name(name[0]):
            yield name, role

    return read


def flag(role: str = PUBLISH) -> Syntax:
    """An IvP var-data pair: ``[@tag] [#dest] VAR = value [[if] condition]``."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        text, at = _trim(piece)
        cond: Piece | None = None
        idx = text.find("[if]")
        if idx >= 0:
            cond = (text[idx + 4 :], at + idx + 4)
            text = text[:idx]
        text, at = _trim((text, at))
        if text[:1] in ("@", "<", ">"):
            sp = re.search(r"\s", text)
            if sp is None:
                return
            text, at = _trim((text[sp.start() :], at + sp.start()))
        if text[:1] == "#":
            sp = re.search(r"\s", text)
            if sp is None:
                return
            text, at = _trim((text[sp.start() :], at + sp.start()))
        parts = _bite((text, at), "=")
        if parts and parts[1][0] and _is_name(parts[0][0]):
            yield parts[0], role
        if cond is not None:
            yield from condition()(cond)

    return read


def mail_flag() -> Syntax:
    """A ``MailFlagSet`` flag, ``@KEY # VAR = value``: mail of ``KEY`` (``ANY``: any mail the
    app reads) posts ``VAR`` (lib_mbutil/MailFlagSet.cpp ``addFlag``)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _bite(piece, "#")
        if parts is None or not parts[0][0].startswith("@"):
            return
        (key, at), pair = parts
        key_piece = _trim((key[1:], at + 1))
        if _is_name(key_piece[0]) and key_piece[0].lower() != "any":
            yield key_piece, SUBSCRIBE
        var = _bite(pair, "=")
        if var and var[1][0] and _is_name(var[0][0]):
            yield var[0], PUBLISH

    return read


def keyed(roles: dict[str, str], sep: str = ",") -> Syntax:
    """``key=value`` pairs; the values of the given keys are variable names."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        for item in _split(piece, sep, braces=True):
            parts = _bite(item, "=")
            if parts is None:
                continue
            role = roles.get(parts[0][0].lower())
            if role and _is_name(parts[1][0]):
                yield parts[1], role

    return read


def keyed_colon_list(key: str, role: str) -> Syntax:
    """``key=..., vars=A:B:C`` (pMarineViewer/uMACView ``watch_cluster``, pRealm ``scope_set``)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        for item in _split(piece, ","):
            parts = _bite(item, "=")
            if parts is None or parts[0][0].lower() != key:
                continue
            for name in _split(parts[1], ":"):
                if _is_name(name[0]):
                    yield name, role

    return read


def hash_pairs(skip: tuple[str, ...], label_ok: bool) -> Syntax:
    """pMarineViewer buttons and actions: ``#``-separated ``VAR=value`` (quotes protect)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        for item in _split(piece, "#"):
            parts = _bite(item, "=")
            if parts is None:
                continue  # a button label (or a bad action)
            key, value = parts
            if key[0].lower() in skip or (label_ok and not value[0]):
                continue
            if _is_name(key[0]):
                yield key, PUBLISH

    return read


def arrow(sep: str) -> Syntax:
    """pEchoVar ``echo = SRC -> DEST``: reads SRC, posts DEST."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _bite(piece, sep)
        if parts is None:
            return
        for name, role in ((parts[0], SUBSCRIBE), (parts[1], PUBLISH)):
            if _is_name(name[0]):
                yield name, role

    return read


def custom_key() -> Syntax:
    """iRemote / iRemoteLite ``CustomKey = 9 : VAR @ "value"``: the key posts VAR
    (MOOSRemoteLite.cpp:789-807, ``MOOSChomp(sVal, ":")`` then ``MOOSChomp(sVal, "@")``)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _bite(piece, ":")
        if parts is None:
            return
        name = parts[1]
        at = name[0].find("@")
        if at >= 0:
            name = _trim((name[0][:at], name[1]))
        if _is_name(name[0]):
            yield name, PUBLISH

    return read


def term_command() -> Syntax:
    """uTermCommand ``cmd = KEY --> VAR --> value``."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _split(piece, "-->", quotes=False)
        if len(parts) >= 3 and _is_name(parts[1][0]):
            yield parts[1], PUBLISH

    return read


def pshare_output() -> Syntax:
    """pShare ``output = src_name=X, dest_name=Y, route=...`` or ``X->[Y:]host:port``."""

    keyed_form = keyed({"src_name": SUBSCRIBE, "dest_name": PUBLISH})

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        text = piece[0]
        if "->" not in text:
            for name, role in keyed_form(piece):
                if role == SUBSCRIBE and ":" in name[0]:  # var_pattern:app_pattern
                    name = _trim((name[0].split(":", 1)[0], name[1]))
                yield name, role
            return
        for share in _split(piece, ","):
            parts = _bite(share, "->")
            if parts is None:
                continue
            src, routes = parts
            if ":" in src[0]:  # var_pattern:app_pattern
                src = _trim((src[0].split(":", 1)[0], src[1]))
            if _is_name(src[0]):
                yield src, SUBSCRIBE
            first = _split(routes, "&")[0]
            fields = first[0].split(":")
            if len(fields) == 3 and _is_name(fields[0]):
                yield _trim((fields[0], first[1])), PUBLISH

    return read


def bridge_share() -> Syntax:
    """pMOOSBridge ``SHARE = [A,B] -> COMMUNITY@HOST:PORT [X,Y]``."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        parts = _bite(piece, "->")
        if parts is None:
            return
        for side, role in ((parts[0], SUBSCRIBE), (parts[1], PUBLISH)):
            text, at = side
            lo, hi = text.find("["), text.find("]")
            if lo < 0 or hi < lo:
                continue
            for name in _split((text[lo + 1 : hi], at + lo + 1), ","):
                if _is_name(name[0]):
                    yield name, role

    return read


_LOGIC_OPS = ("==", "=", "!=", ">=", "<=", ">", "<")
_CONNECTIVE = re.compile(r"(?<=[\s)])(or|and)(?=[\s(!])", re.IGNORECASE)


def _depths(text: str) -> list[int]:
    out, depth = [], 0
    for ch in text:
        if ch == "(":
            depth += 1
        out.append(depth)
        if ch == ")":
            depth -= 1
    return out


def _global_parens(text: str) -> bool:
    if len(text) < 2 or text[0] != "(" or text[-1] != ")":
        return False
    depth = 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if depth == 0 and i < len(text) - 1:
            return False
    return depth == 0


def _condition_vars(piece: Piece, alternatives: set[int] | None = None) -> Iterator[Piece]:
    """The left side of every relation in a lib_logic condition; the start of each that
    is one side of an ``or`` (the condition may hold without it) goes in
    ``alternatives`` when given."""
    text, at = _trim(piece)
    while _global_parens(text):
        text, at = _trim((text[1:-1], at + 1))
    if not text:
        return
    if text[0] == "!" and _global_parens(text[1:].strip()):
        yield from _condition_vars((text[1:], at + 1), alternatives)
        return
    depths = _depths(text)
    for i in range(len(text)):
        if depths[i] != 0 and text[i] != ")":
            continue
        m = _CONNECTIVE.match(text, i)
        if m and depths[i] == 0:
            sides = [(text[:i], at), (text[m.end() :], at + m.end())]
            for side in sides:
                names = list(_condition_vars(side, alternatives))
                if alternatives is not None and m.group(1).lower() == "or":
                    alternatives.update(n[1] for n in names)
                yield from names
            return
        if depths[i] != 0:
            continue
        for op in _LOGIC_OPS:
            if text.startswith(op, i):
                left = _trim((text[:i], at))
                if left[0] and not any(c in left[0] for c in '"<>=!()'):
                    yield left
                return


def alternative_starts(text: str, at: int = 0) -> set[int]:
    """Where the variables of a lib_logic condition that sit on one side of an ``or``
    start (``(DEPLOY = true) or (ALPHA = one)``: both): the condition can hold without
    any one of them."""
    found: set[int] = set()
    for _ in _condition_vars((text, at), found):
        pass
    return found


def one_alternative(ref: VarRef) -> bool:
    """Whether the condition of ``ref`` names it only on one side of an ``or``."""
    # (the helm reads `,` as `=`: same offsets; both readers cut a line at its `//`)
    text = ref.line.text.split("//", 1)[0].replace(",", "=")
    start = text.find("=") + 1
    return start > 0 and ref.start in alternative_starts(text[start:], start)


def condition(commas_are_equals: bool = False) -> Syntax:
    """A lib_logic condition (the helm turns ``,`` into ``=`` before parsing)."""

    def read(piece: Piece) -> Iterator[tuple[Piece, str]]:
        text, at = piece
        if commas_are_equals:
            text = text.replace(",", "=")
        for name in _condition_vars((text, at)):
            if _is_name(name[0]):
                yield name, SUBSCRIBE

    return read


# ------------------------------------------------------------------ the app table
_FLAG = flag()
_COND = condition()

#: app (lower case) -> parameter (lower case) -> (syntax, wildcards accepted)
APP_PARAMS: dict[str, dict[str, tuple[Syntax, bool]]] = {
    "plogger": {
        "log": (before("@", SUBSCRIBE), False),
        # both are split with MOOSChomp(sVal, ",") (MOOSLogger.cpp:417-428)
        "wildcardpattern": (comma_list(SUBSCRIBE), True),
        "wildcardomitpattern": (comma_list(SUBSCRIBE), True),
    },
    "imatlab": {"subscribe": (before("@", SUBSCRIBE), False)},
    "utimerscript": {
        "event": (keyed({"var": PUBLISH}), False),
        "condition": (_COND, False),
        "forward_var": (plain(SUBSCRIBE), False),
        "pause_var": (plain(SUBSCRIBE), False),
        "reset_var": (plain(SUBSCRIBE), False),
        "status_var": (plain(PUBLISH), False),
    },
    "pshare": {"output": (pshare_output(), True)},
    "pmoosbridge": {"share": (bridge_share(), False), "udpshare": (bridge_share(), False)},
    # the route goes to pShare unchanged as a PSHARE_CMD (NodeBroker.cpp
    # postPShareCommand), and pShare routes a `*`/`?` source as a wildcard (Share.cpp AddRoute)
    "ufldnodebroker": {"bridge": (keyed({"src": SUBSCRIBE, "alias": PUBLISH}), True)},
    "ufldshorebroker": {
        "bridge": (keyed({"src": SUBSCRIBE, "alias": PUBLISH}), False),
        "qbridge": (comma_list(SUBSCRIBE), False),
    },
    "pechovar": {"echo": (arrow("->"), False), "condition": (_COND, False)},
    "pnodereporter": {"rider": (keyed({"var": SUBSCRIBE}), False)},
    "uprocesswatch": {"post_mapping": (comma_list(PUBLISH), False)},
    "uxms": {"var": (comma_list(SUBSCRIBE), False), "history_var": (plain(SUBSCRIBE), False)},
    "uhelmscope": {"var": (comma_list(SUBSCRIBE), False)},
    "pmarineviewer": {
        "scope": (comma_list(SUBSCRIBE), False),
        "action": (hash_pairs(("menu_key",), False), False),
        "action+": (hash_pairs(("menu_key",), False), False),
        "cmd": (keyed({"var": PUBLISH}), False),
        "watch_cluster": (keyed_colon_list("vars", SUBSCRIBE), False),
        "node_report_variable": (plain(SUBSCRIBE), False),
        "connection_posting": (_FLAG, False),
        "mission_hash_var": (plain(SUBSCRIBE), False),
        "mhash_short_var": (plain(SUBSCRIBE), False),
        # button_*, left_context[*] and right_context[*]: see _prefixed()
    },
    "umacview": {"watch_cluster": (keyed_colon_list("vars", SUBSCRIBE), False)},
    "prealm": {
        "hist_var": (plain(SUBSCRIBE), False),
        "scope_set": (keyed_colon_list("vars", SUBSCRIBE), False),
    },
    "ucommand": {"cmd": (keyed({"var": PUBLISH}), False)},
    "utermcommand": {"cmd": (term_command(), False)},
    "iremote": {"customkey": (custom_key(), False)},
    "iremotelite": {"customkey": (custom_key(), False)},
    "upokedb": {"poke": (_FLAG, False)},
    "uplotviewer": {"plot_var": (keyed({"var": SUBSCRIBE}), False)},
    "ufldscope": {"scope": (keyed({"var": SUBSCRIBE}), False)},
    "pbasiccontactmgr": {"alert": (keyed({"var": PUBLISH}), False)},
    "pcontactmgrv20": {
        "alert": (keyed({"var": PUBLISH}), False),
        "disable_var": (plain(SUBSCRIBE), False),
        "enable_var": (plain(SUBSCRIBE), False),
        "early_warning_flag": (_FLAG, False),
        "cease_warning_flag": (_FLAG, False),
    },
    "pdeadmanpost": {"deadflag": (_FLAG, False), "heartbeat_var": (plain(SUBSCRIBE), False)},
    "psafetyretreat": {
        "retreat_cue_var": (plain(SUBSCRIBE), False),
        "retreat_message_var": (plain(PUBLISH), False),
        "retreat_notify_var": (plain(PUBLISH), False),
    },
    "pxrelay": {"incoming_var": (plain(SUBSCRIBE), False), "outgoing_var": (plain(PUBLISH), False)},
    "pobstaclemgr": {
        "point_var": (plain(SUBSCRIBE), False),
        "general_alert": (keyed({"update_var": PUBLISH}), False),
    },
    "pposekeep": {
        "activeflag": (_FLAG, False),
        "inactiveflag": (_FLAG, False),
        "endflag": (_FLAG, False),
    },
    "ufldcollobdetect": {
        "collision_flag": (_FLAG, False),
        "near_miss_flag": (_FLAG, False),
        "encounter_flag": (_FLAG, False),
    },
    "ufldcollisiondetect": {
        "collision_flag": (_FLAG, False),
        "near_miss_flag": (_FLAG, False),
        "encounter_flag": (_FLAG, False),
        "condition": (_COND, False),
    },
    "uquerydb": {
        "condition": (_COND, False),
        "pass_condition": (_COND, False),
        "fail_condition": (_COND, False),
    },
    # MissionEval.cpp:158-163 (the conditions), 306-313 (it registers their variables)
    "pmissioneval": {
        "lead_condition": (_COND, False),
        "pass_condition": (_COND, False),
        "fail_condition": (_COND, False),
        # addVarDataPairOnString (MissionEval.cpp:175-180), MailFlagSet::addFlag (:190)
        "result_flag": (_FLAG, False),
        "pass_flag": (_FLAG, False),
        "fail_flag": (_FLAG, False),
        "mailflag": (mail_flag(), False),
    },
    # addVarDataPairOnString (AutoPoke.cpp:102-103): posted once the required nodes report
    "pautopoke": {"flag": (_FLAG, False)},
    "pevalloiter": {"condition": (_COND, False)},
}

_BUTTON = hash_pairs(("color",), True)

#: (app, key) -> what the app subscribes to for a name ``X`` the key gives, when not
#: ``X`` itself. uFldShoreBroker ``qbridge = X`` is shorthand for
#: ``bridge = src=X_ALL, alias=X`` and ``bridge = src=X_$V, alias=X``
#: (ShoreBroker.cpp:626-647): the shoreside reads X_ALL and X_<VNAME>.
SUBSCRIBED_AS: dict[tuple[str, str], tuple[str, ...]] = {
    ("ufldshorebroker", "qbridge"): ("{}_ALL", "{}_*"),
}


#: ``bridge = src=X_$V, alias=X``: the ``$V`` of a uFldShoreBroker bridge
_SHORE_BRIDGE_V = re.compile(r"src\s*=\s*([A-Za-z0-9_]+_)\$V\b")


def upper_vehicle_prefixes(mf: MoosFile) -> frozenset[str]:
    """The prefixes ``X_`` of the mission's uFldShoreBroker bridges that it reads with the
    vehicle's name upper-cased: ``qbridge = X`` bridges ``X_$V``, and the broker replaces
    ``$V`` with ``toupper(community)`` (``$v`` keeps the name as it is) (ShoreBroker.cpp:
    546-547, 644-646). A name ``X_abe`` of such a mission is never bridged: the broker
    reads ``X_ABE``."""
    out: set[str] = set()
    for block in mf.blocks:
        if app_of(block.name) != "ufldshorebroker":
            continue
        for p in block.params:
            if p.lkey == "qbridge":
                out.update(f"{v.strip()}_" for v in p.value.split(",") if v.strip())
            elif p.lkey == "bridge":
                out.update(m.group(1) for m in _SHORE_BRIDGE_V.finditer(p.value))
    return frozenset(out)


#: pEchoVar ``flip:N = source_variable = X`` / ``flip:N = dest_variable = Y``: a flipper
#: reads X and posts Y (EchoVar.cpp:300-342)
_FLIP = keyed({"source_variable": SUBSCRIBE, "dest_variable": PUBLISH})


def _prefixed(app: str, key: str) -> tuple[Syntax, bool] | None:
    if app == "pechovar" and key.startswith("flip"):
        return _FLIP, False
    if app == "pmarineviewer":
        if key.startswith("button_"):
            return _BUTTON, False
        if key.startswith(("left_context", "right_context")):
            return _FLAG, False
    return None


def app_of(block_name: str, aliases: dict[str, str] | None = None) -> str | None:
    """The stock app (lower case) a ProcessConfig block configures, if known.

    ``aliases`` maps a launched name (lower case) to its binary, from the Run
    lines; otherwise ``uTimerScript_PING`` is read as uTimerScript.
    """
    low = block_name.lower()
    if aliases and low in aliases:
        low = aliases[low].replace("\\", "/").rsplit("/", 1)[-1].lower()
    if low in APP_PARAMS:
        return low
    head = low.split("_", 1)[0]
    return head if head in APP_PARAMS else None


def _params_for(app: str, key: str) -> tuple[Syntax, bool] | None:
    return APP_PARAMS.get(app, {}).get(key) or _prefixed(app, key)


def flag_variables(block: Block, reads: Callable[[str], bool], app: str) -> Iterator[VarRef]:
    """The flags of a block of an app this module has no table for: MOOS-IvP apps post a
    VarDataPair for each ``*_flag`` parameter they read (pObstacleMgr ``new_obs_flag =
    OBM_NEW_GIVEN=true``, uFldCollisionDetect ``collision_flag``), as behaviors do;
    ``reads`` says which keys the app reads (the catalogue)."""
    for param in block.params:
        if not _app_flag(param.lkey) or not reads(param.lkey):
            continue
        text = param.line.text[param.value_start : param.value_end]
        for (name, start), role in _ANY_FLAG((text, param.value_start)):
            yield VarRef(name, param.line, start, role, app, param.lkey)


def _app_flag(lkey: str) -> bool:
    """An app's flag parameter (``mailflag``, ``new_obs_flag``), not a bare ``flag``:
    uFldFlagManager's ``flag = x=-58, y=-71, label=red`` places a game flag."""
    return lkey != "flag" and is_flag_param(lkey)


def block_variables(block: Block, app: str) -> Iterator[VarRef]:
    """The variables one block of a known app names (worked out once per block and app)."""
    refs = block.memo.get(("variables", app))
    if refs is None:
        refs = block.memo[("variables", app)] = tuple(_block_variables(block, app))
    return iter(refs)


def _block_variables(block: Block, app: str) -> Iterator[VarRef]:
    for param in block.params:
        key = param.lkey
        spec = _params_for(app, key)
        if spec is None and _app_flag(key):
            spec = (_ANY_FLAG, False)  # MOOS-IvP apps post their ``*_flag`` VarDataPairs
        if spec is None:
            continue
        syntax, wildcard = spec
        text = param.line.text[param.value_start : param.value_end]
        reads = SUBSCRIBED_AS.get((app, key), ())
        for (name, start), role in syntax((text, param.value_start)):
            as_read = tuple(r.format(name) for r in reads) if role == SUBSCRIBE else ()
            yield VarRef(name, param.line, start, role, block.name, key, wildcard, as_read)


def moos_variables(mf: MoosFile) -> Iterator[VarRef]:
    """Every variable a ``.moos`` file names, block by block (worked out once per parsed
    file: the rules of its own unit and those that gather the run's names all ask)."""
    kept = mf.expansion.models.get("moos_variables")
    if kept is None or kept[0] is not mf:
        kept = mf.expansion.models["moos_variables"] = (mf, tuple(_moos_variables(mf)))
    return iter(kept[1])


def _moos_variables(mf: MoosFile) -> Iterator[VarRef]:
    aliases = {run.name.lower(): run.binary for run in mf.runs if run.name}
    for block in mf.blocks:
        app = app_of(block.name, aliases)
        if app is not None:
            yield from block_variables(block, app)


# ------------------------------------------------------------------ behaviors
#: any behavior parameter whose key ends in ``flag``
_ANY_FLAG = flag()
#: the other behavior parameters (lower case, leading ``_`` dropped) -> syntax
BHV_PARAMS: dict[str, Syntax] = {
    "condition": condition(commas_are_equals=True),
    "lead_condition": condition(),
    "updates": plain(SUBSCRIBE),
    "duration_status": plain(PUBLISH),
    "duration_reset": before("=", SUBSCRIBE),
    "post_mapping": comma_list(PUBLISH),
    "depth_mismatch_var": plain(PUBLISH),
    "heading_mismatch_var": plain(PUBLISH),
    "wpt_status_var": plain(PUBLISH),
    "wpt_index_var": plain(PUBLISH),
    "wpt_dist_to_next": plain(PUBLISH),
    "wpt_dist_to_prev": plain(PUBLISH),
}


def is_flag_param(lkey: str) -> bool:
    """Whether a behavior parameter (lower case) is a flag, a var-data pair the helm
    posts: every ``*flag`` is, IvPBehavior's (``endflag``, ``runflag``, ...), BHV_ZigZag's
    ``zigflag``, the task behaviors' ``bidwonflag``, a project's own behavior's flags."""
    return lkey.endswith("flag")


def bhv_variables(bf: BehaviorFile) -> Iterator[VarRef]:
    """Every variable a ``.bhv`` file names (worked out once per parsed file)."""
    return iter(derived(bf.expansion, "bhv_variables", lambda: tuple(_bhv_variables(bf))))


def _bhv_variables(bf: BehaviorFile) -> Iterator[VarRef]:
    for init in bf.initializes:
        yield VarRef(init.var, init.line, init.var_start, PUBLISH, "helm", "initialize")
    cond = condition()
    for sb in bf.sets:
        low = sb.header.text.lower()
        start = sb.header.text.find(sb.mode_var, low.find("set") + 3)
        if start >= 0:
            yield VarRef(sb.mode_var, sb.header, start, PUBLISH, "helm", "set")
        for text, line in sb.conditions:
            at = line.text.find(text)
            if at < 0:
                continue
            for (name, s), role in cond((text, at)):
                yield VarRef(name, line, s, role, "helm", "set-condition")
    for bhv in bf.behaviors:
        for param in bhv.params:
            syntax = BHV_PARAMS.get(param.lkey)
            if syntax is None and is_flag_param(param.lkey):
                syntax = _ANY_FLAG
            if syntax is None:
                continue
            text = param.line.text[param.value_start : param.value_end]
            for (name, start), role in syntax((text, param.value_start)):
                yield VarRef(name, param.line, start, role, bhv.kind, param.lkey)


_PLACEHOLDER = re.compile(r"\$\[[^\]]*\]|\$\{[^}]*\}|\$[A-Za-z_][A-Za-z0-9_]*")


@functools.lru_cache(maxsize=8192)
def bare_name(name: str) -> str | None:
    """``name`` with run-time placeholders removed, or None when it holds an nsplug macro.

    Placeholders are expanded by the app when it posts: ``$[OWNSHIP]`` (helm
    flags, pMarineViewer, uTimerScript), ``$V`` / ``$UP_V1`` (uFld apps) and
    ``${X}`` (the MOOS file reader). Only the text around them is written by
    the user.
    """
    if has_macro(name):
        return None
    return _PLACEHOLDER.sub("", name)


_last_unit: tuple = (None, None, ())


def unit_variables(moos: MoosFile | None = None, bhv: BehaviorFile | None = None):
    """The variables of one linted unit (a ``.moos`` or a ``.bhv`` file).

    The engine runs every rule on a unit before the next, and several rules ask
    for the same unit's variables: the last unit's are kept (refs are frozen).
    """
    global _last_unit
    last_moos, last_bhv, refs = _last_unit
    if last_moos is not moos or last_bhv is not bhv or (moos is None and bhv is None):
        found: list[VarRef] = []
        if moos is not None:
            found.extend(moos_variables(moos))
        if bhv is not None:
            found.extend(bhv_variables(bhv))
        refs = tuple(found)
        _last_unit = (moos, bhv, refs)
    return iter(refs)


_UPPER_WORDS = re.compile(r"[A-Z0-9_]+")


def scoped_to_app(name: str, apps: frozenset[str]) -> bool:
    """Whether ``name`` is an upper-case name joined to the name of one of ``apps``
    (the repository's own apps) as that app is named (``iWhoiMicroModem_CMD``): such
    a name is most often built from the app's name (``GetAppName() + "_CMD"``), so its
    publishers and subscribers must write it in the app's case. (Core MOOS's apps
    upper-case theirs, ``PHELMIVP_CMD``: a stock app's name is not one of ``apps``.)"""
    head, _, tail = name.partition("_")
    return head in apps and _UPPER_WORDS.fullmatch(tail) is not None


__all__ = [
    "APP_PARAMS",
    "BHV_PARAMS",
    "PUBLISH",
    "SUBSCRIBE",
    "VarRef",
    "app_of",
    "bare_name",
    "bhv_variables",
    "block_variables",
    "moos_variables",
    "unit_variables",
]
