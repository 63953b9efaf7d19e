"""The C++ checks of moos-lint's rules: plain functions over an :class:`AppModel`.

Each yields ``(span, message)``; the rule modules turn them into findings.
Names that cannot be resolved statically are dynamic and never reported.
"""

from __future__ import annotations

import fnmatch
import re
from collections.abc import Callable, Iterator
from typing import Any

from moos_lint.files.diagnostics import Edit, Fix, Span
from moos_lint.frontends.cpp import angle_exprs as angles
from moos_lint.frontends.cpp import facts, values
from moos_lint.frontends.cpp.app import sibling_apps
from moos_lint.frontends.cpp.model import AppModel, GeodesyCall, Publication
from moos_lint.frontends.cpp.names import axis_of, words
from moos_lint.semantics.catalogue import COMMAND_KEY_SUFFIX, TEMPLATE_MAIL_KEYS, UNASKED_MAIL
from moos_lint.semantics.process_names import PREFIXED, placeholder, prefix_problem
from moos_lint.semantics.variables import STANDARD_ACTUATORS, scoped_to_app

Finding = tuple[Span, str]
UPPER_SNAKE = re.compile(r"^[A-Z][A-Z0-9_]*$")
#: apps whose network traffic carries MOOS itself
MOOS_NETWORK_APPS = ("pShare", "pMOOSBridge", "MOOSDB")


def _named(app: AppModel, pred) -> Iterator[Publication]:
    for p in app.publications:
        if p.name.text is not None and p.value is not None and pred(p.name.text):
            yield p


def _app_label(app: AppModel) -> str:
    return f"`{app.process_name}`" if app.process_name else "this app"


def process_name_prefix(app: AppModel, exempt: tuple[str, ...] = ()) -> Iterator[Finding]:
    """The process name of each program the folder builds (see :func:`sibling_apps`)."""
    for one in (app, *sibling_apps(app)):
        yield from _process_name_prefix(one, exempt)


def _process_name_prefix(app: AppModel, exempt: tuple[str, ...]) -> Iterator[Finding]:
    name = app.process_name
    if not app.is_app or not name or app.process_name_span is None:
        return
    if name.lower() in {e.lower() for e in exempt} or PREFIXED.match(name):
        return
    if app.process_name_source == "folder" and name.islower():
        return  # a generic folder (src, attic, test): the name is a guess
    if placeholder(name):
        return  # a template's `APP_NAME`: the generated app is named when it is made
    where = {
        "run": "as given to Run()",
        "cmake": "the CMake add_executable name",
        "folder": "from its folder, as no Run() literal or add_executable names it",
    }[app.process_name_source]
    yield (
        app.process_name_span,
        f"process name `{name}` ({where}) "
        + prefix_problem(name, "does not start with i, p or u (instrument, process, utility)"),
    )


def instrument_app_prefix(app: AppModel) -> Iterator[Finding]:
    """Each program of the folder whose app class derives from CMOOSInstrument."""
    for one in (app, *sibling_apps(app)):
        yield from _instrument_app_prefix(one)


def _instrument_app_prefix(app: AppModel) -> Iterator[Finding]:
    name = app.process_name
    if not app.is_instrument or not name or app.app_class is None:
        return
    if name.startswith("i") or placeholder(name):
        return
    yield (
        app.app_class.span,
        f"`{app.app_class.name}` derives from CMOOSInstrument but its process is `{name}`: "
        "instruments are named with an `i` prefix",
    )


def _header_stem(path: str) -> str:
    """``MOOSSerial`` of ``"src/MOOSSerial.h"``."""
    return path.rsplit("/", 1)[-1].rsplit(".", 1)[0]


def pure_app_does_io(app: AppModel, sockets: bool = True) -> Iterator[Finding]:
    name = app.process_name
    if not app.is_app or not name or not re.match(r"^[pu][A-Z0-9_]", name):
        return
    # a type named like a link (``UdpDecoder``) that is the app's own class is no evidence:
    # what it does shows in its calls, includes and strings
    # nor is the header of the app's own class (``pMOOSSerial``'s ``#include "MOOSSerial.h"``)
    own = {*app.base_chain, *(c.name for f in app.files for c in f.classes)}
    io = [
        u
        for u in app.io
        if not (u.kind in ("socket", "serial") and u.detail in own)
        and not (u.kind == "serial" and _header_stem(u.detail) in app.base_chain)
    ]
    uses = [u for u in io if u.device]
    termios = [u for u in io if u.kind == "termios"]
    if termios and any(u.kind == "serial" for u in uses):
        uses = [*uses, *termios]
    bridge = name.startswith(MOOS_NETWORK_APPS) or any(u.kind == "moos" for u in io)
    if sockets and name.startswith("p") and not bridge:
        # a GUI that fetches over HTTP (a viewer downloading its background map with
        # libcurl) talks to no vehicle or service of the mission
        gui = any(u.kind == "gui" for u in io)
        uses += [u for u in io if u.kind == "socket" and not (gui and "curl" in u.detail)]
    if not uses:
        return
    first = min(uses, key=lambda u: (u.span.path, u.span.line, u.span.col))
    kinds = sorted({u.detail for u in uses})
    kind = "a `p` app" if name.startswith("p") else "a `u` app"
    what = "device I/O" if all(u.kind != "socket" for u in uses) else "I/O outside the MOOSDB"
    yield (
        first.span,
        f"{_app_label(app)} is {kind} but does {what} ({', '.join(kinds[:4])}): "
        "an app that talks to a device, or to a vehicle or service in a protocol that is "
        "not MOOS, is an interface app, named with an `i` prefix",
    )


#: what a value's type may be for the unit rules to judge it (None: not known)
NUMERIC = (None, "integer", "floating")


def _valued(app: AppModel, pred) -> Iterator[tuple[Publication, Any]]:
    """Publications of numbers whose name (or its known last word) ``pred`` accepts, with
    their values. A string or a bool (its type known with ``--cpp-backend clang``) carries
    no unit; a publication compiled out is not in ``app.publications``."""
    for p in app.publications:
        name = p.name.last
        if name and p.value is not None and p.value.type in NUMERIC and pred(name):
            yield p, p.value.abstract


def _shown(p: Publication) -> str:
    """The name as a message quotes it (with how it is built when only its end is known)."""
    if p.name.text is not None:
        return f"`{p.name.text}`"
    source = " ".join(p.name.source.split())
    if p.name.suffix in source:
        return f"`{p.name.suffix}` (named by `{source}`)"
    if "[" in source:
        return f"`{source}` (a {angles.last_word(p.name.suffix)} by its index)"
    return f"`{source}` (a name set to end in `{p.name.suffix}`)"


def _steps(why: list[str]) -> str:
    """The last three reasons of a chain, source first, as a parenthesis."""
    return f" ({'; '.join(why[-3:])})" if why else ""


def _because(v: Any) -> str:
    """The chain of reasons, source first, as a parenthesis."""
    return f" ({v.explanation})" if v is not None and v.why else ""


#: (published as, unit, sense of the value, a name's word enough, what it is, the rule)
_SIGN_SLIPS = (
    (
        angles.is_yaw_var,
        "rad",
        "heading",
        True,
        "a heading turned into radians",
        "yaw is −heading·π/180 (heading turns clockwise, yaw counter-clockwise)",
    ),
    (
        angles.is_heading_var,
        "deg",
        "yaw",
        False,  # a device's yaw may be about Z-down: only a yaw MOOS gives is one
        "a yaw turned into degrees",
        "heading is −yaw·180/π (yaw turns counter-clockwise, heading clockwise)",
    ),
)


def yaw_heading_sign(app: AppModel) -> Iterator[Finding]:
    said: set[Span] = set()
    for published_as, unit, sense, hint_ok, what, rule in _SIGN_SLIPS:
        for p, v in _valued(app, published_as):
            if v is None or v.unit != unit or v.sense != sense or (v.hint and not hint_ok):
                continue
            said.add(p.value.span)  # type: ignore[union-attr]
            yield (
                p.value.span,  # type: ignore[union-attr]
                f"{_shown(p)} is {what} without the minus sign{_because(v)}; {rule}",
            )
    for yaw, heading in _same_sign_pairs(app):
        if yaw.value.span in said or heading.value.span in said:  # type: ignore[union-attr]
            continue
        said.add(yaw.value.span)  # type: ignore[union-attr]
        at = values.place(heading.span.path, heading.span.line)
        yield (
            yaw.value.span,  # type: ignore[union-attr]
            f"{_shown(yaw)} and {_shown(heading)} ({at}) are one angle published with the "
            f"same sign (`{_flat(yaw.value.text)}`, `{_flat(heading.value.text)}`): "  # type: ignore[union-attr]
            "yaw is −heading·π/180, so one of them turns the wrong way (a device's yaw "
            "about Z-down turns clockwise, as a heading does: negate it for the yaw)",
        )


#: words of a name that say its angle is in another frame than MOOS's, on purpose
_FRAME_WORDS = frozenset({"NED", "ENU", "NWU", "FRD", "FLU", "BODY", "MATH"})


def _same_sign_pairs(app: AppModel) -> Iterator[tuple[Publication, Publication]]:
    """A yaw and a heading one function publishes from the same angle, one of them
    converted from the other's unit, with the same sign: ``Notify("GP9_YAW", e)`` and
    ``Notify("GP9_HEADING", angle360(e*180/M_PI))``, or a yaw ``h*M_PI/180`` beside the
    heading ``h``. MOOS's yaw is −heading·π/180: one of the two has its sign wrong,
    whatever the angle is."""
    yaws: dict[str, list[tuple[Publication, tuple[int, str, str | None]]]] = {}
    headings: list[tuple[Publication, tuple[int, str, str | None]]] = []
    for p in app.publications:
        name = p.name.last
        if not name or p.value is None or p.value.type not in NUMERIC:
            continue
        is_yaw, is_heading = angles.is_yaw_var(name), angles.is_heading_var(name)
        if not (is_yaw or is_heading) or _FRAME_WORDS & {w.upper() for w in words(name)}:
            continue
        v = p.value.abstract
        if is_yaw and v is not None and v.unit == "deg":
            continue  # (a yaw in degrees: yaw-in-degrees says so)
        form = angles.angle_conversion(p.value.expanded)
        if p.value.number is not None or re.fullmatch(r"[-+\d.eE]+[fF]?", form[1]):
            continue
        if is_yaw:
            yaws.setdefault(p.function, []).append((p, form))
        else:
            headings.append((p, form))
    for heading, (h_sign, h_angle, h_conv) in headings:
        for yaw, (y_sign, y_angle, y_conv) in yaws.get(heading.function, ()):
            if y_angle != h_angle or y_sign != h_sign:
                continue
            if (y_conv, h_conv) in (("rad", None), (None, "deg")):
                yield yaw, heading


def heading_in_radians(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_heading_var):
        if v is None or v.unit != "rad":
            continue
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is published in radians{_because(v)}: "
            "headings are degrees, 0 = north, clockwise",
        )


def trig_of_degrees(app: AppModel) -> Iterator[Finding]:
    """``sin``, ``cos`` or ``tan`` of an angle known to be in degrees (not by its name
    alone): once per argument and function, the first use, with how many more."""
    uses: dict[tuple[str, str], list[Any]] = {}
    for f in app.files:
        for t in f.trig_uses:
            v = t.value.abstract
            if v is None or v.unit != "deg" or v.hint:
                continue
            uses.setdefault((t.within, " ".join(t.value.text.split())), []).append(t)
    for (within, arg), found in uses.items():
        t = found[0]
        v = t.value.abstract
        more = len(found) - 1
        also = f"; and {more} more use{'s' if more > 1 else ''} in `{within}`" if more else ""
        convert = (
            "a heading becomes the math angle with headingToRadians() (MOOS-IvP's "
            "AngleUtils: (90 − h)·π/180), or take `h·π/180` where the formula is written "
            "for a compass angle (x += d·sin(h·π/180))"
            if v.sense == "heading"
            else "multiply by π/180 (MOOSDeg2Rad(), degToRadians())"
        )
        yield (
            t.value.span,
            f"`{t.function}()` is given `{values.brief(arg)}` in degrees{_because(v)}: "
            f"C++'s sin, cos and tan take radians: {convert}{also}",
        )


def angle_argument_unit(app: AppModel) -> Iterator[Finding]:
    """One of MOOS's angle functions given an angle known, not by a name alone, to be in
    the other unit: ``angle360()`` of radians, ``MOOS_ANGLE_WRAP()`` of degrees,
    ``MOOSDeg2Rad()`` of radians."""
    for f in app.files:
        for t in f.angle_arguments:
            v = t.value.abstract
            takes = facts.HELPERS[t.function][0]
            if v is None or v.hint or v.pending is not None or v.unit not in ("deg", "rad"):
                continue
            if v.unit == takes:
                continue
            given = "degrees" if v.unit == "deg" else "radians"
            wanted = "degrees" if takes == "deg" else "radians"
            yield (
                t.value.span,
                f"`{t.function}()` takes {wanted} but is given `{values.brief(t.value.text)}` "
                f"in {given}{_because(v)}",
            )


def mixed_angle_units(app: AppModel) -> Iterator[Finding]:
    """Degrees and radians added, subtracted or compared, each side's unit known."""
    for f in app.files:
        for m in f.unit_mixes:
            units = [
                "degrees" if v.abstract.unit == "deg" else "radians" for v in (m.left, m.right)
            ]
            op = m.op[0] if m.op in ("+=", "-=") else m.op  # (``yaw += 360``, in place)
            if op == "+":
                doing = f"adds an angle in {units[1]} to one in {units[0]}"
            elif op == "-":
                doing = f"subtracts an angle in {units[1]} from one in {units[0]}"
            else:
                doing = f"compares an angle in {units[0]} with one in {units[1]}"
            sides = ", ".join(
                f"`{values.brief(v.text, 32)}` is in {unit}{_because(v.abstract)}"
                for v, unit in zip((m.left, m.right), units, strict=True)
            )
            yield (
                m.span,
                f"`{values.brief(m.left.text, 32)} {m.op} {values.brief(m.right.text, 32)}` "
                f"{doing}: {sides}: convert one side (× π/180 or × 180/π)",
            )


#: a published component's name: what comes before its axis, and the axis
_AXIS_NAME = re.compile(r"^(?P<vector>\w+?)_(?P<axis>[XYZ])$")
#: a component read from a vector: ``v.x``, ``p->y``, ``v.z()``, ``v[2]``, negated or not
_COMPONENT = re.compile(
    r"^(?P<neg>-?)\s*(?:(?P<obj>.+?)\s*(?:\.|->)\s*(?P<field>[xyzXYZ])(?:\(\))?"
    r"|(?P<arr>.+?)\[\s*(?P<index>[012])\s*\])$"
)


def _component(p: Publication) -> tuple[str, str, bool] | None:
    """(the vector, the axis read from it, negated) of a value that is one component of
    a vector, as written or as its local was set."""
    for written in (p.value.text, p.value.expanded) if p.value is not None else ():
        m = _COMPONENT.match(" ".join(written.split()))
        if m is None:
            continue
        if m.group("obj") is not None:
            return m.group("obj"), m.group("field").lower(), bool(m.group("neg"))
        return m.group("arr"), "xyz"[int(m.group("index"))], bool(m.group("neg"))
    return None


def mirrored_axes(app: AppModel) -> Iterator[Finding]:
    """A vector's three components published with the vertical and a horizontal axis
    swapped and the swap not undone by a sign: a mirror image, which no rotation of a
    sensor gives."""
    groups: dict[tuple[str, str], dict[str, tuple[str, bool, Publication]]] = {}
    for p in app.publications:
        m = _AXIS_NAME.match(p.name.text or "")
        found = _component(p) if m else None
        if m is None or found is None:
            continue
        obj, source, negated = found
        axes = groups.setdefault((m.group("vector"), obj), {})
        axes.setdefault(m.group("axis").lower(), (source, negated, p))
    for (vector, obj), axes in groups.items():
        if len(axes) < 3 or sorted(src for src, _, _ in axes.values()) != ["x", "y", "z"]:
            continue
        order = [axes[a][0] for a in "xyz"]
        if order[2] == "z":
            continue  # the vertical stays vertical (NED to ENU swaps x and y only)
        swaps = sum(1 for a, b in ((0, 1), (0, 2), (1, 2)) if order[a] > order[b])
        negations = sum(1 for _, neg, _ in axes.values() if neg)
        if (swaps + negations) % 2 == 0:
            continue  # a rotation: a sensor mounted on its side
        z_from = axes["z"][0]
        published = ", ".join(
            f"`{axes[a][2].name.text}` = `{'-' if axes[a][1] else ''}.{axes[a][0]}`" for a in "xyz"
        )
        where = axes["z"][2]
        yield (
            where.value.span,  # type: ignore[union-attr]
            f"`{vector}` is published from `{values.brief(obj, 40)}` with its axes exchanged "
            f"({published}): the vertical is taken from a horizontal axis, and the "
            "exchange with its signs is a mirror image (a left-handed frame, which no "
            f"mounting of the sensor gives): publish `.{z_from}` under its own axis, or "
            "change one sign if the sensor is turned on its side",
        )


#: a value that may stand for one quantity: no literal, no assignment or increment, no
#: call (``next()``, ``atof(field)``: each call may give another value; a cast may stay)
_LITERAL = re.compile(r'[-+]?[\d.][\w.+-]*|"[^"]*"|\'[^\']*\'|true|false|nullptr|NULL')
_CHANGES = re.compile(r"\+\+|--|(?<![=!<>])=(?!=)|\w\s*\(")


def _pasted_key(p: Publication) -> str | None:
    """The value of publication ``p`` as compared with its neighbours' (spaces aside);
    None for one that says nothing of a quantity (a constant) or may change between two
    calls."""
    v = p.value
    if v is None or not p.active or v.number is not None:
        return None
    written = "".join(v.text.split())
    if not written or _LITERAL.fullmatch(written) or _CHANGES.search(written):
        return None
    if v.abstract is not None and v.abstract.const is not None:
        return None
    return written


def pasted_publication(app: AppModel) -> Iterator[Finding]:
    """One value published under the names of two kinds of quantity (a position and a
    heading) by calls written one after the other in a block: a call copied and its
    value not changed."""
    blocks: dict[tuple[str, int], dict[int, list[Publication]]] = {}
    for p in app.publications:
        if p.statement is not None:
            block, place = p.statement
            blocks.setdefault((p.span.path, block), {}).setdefault(place, []).append(p)
    for places in blocks.values():
        run: list[Publication] = []
        last = None
        for place in sorted(places):
            if last is not None and place != last + 1:
                yield from _pasted(run)
                run = []
            run.extend(places[place])
            last = place
        yield from _pasted(run)


def _pasted(run: list[Publication]) -> Iterator[Finding]:
    """The findings of one run of consecutive publications."""
    by_value: dict[str, list[tuple[Publication, str]]] = {}
    for p in run:
        kind = angles.quantity(p.name.last)
        key = _pasted_key(p) if kind is not None else None
        if kind is not None and key is not None:
            by_value.setdefault(key, []).append((p, kind))
    for key, pubs in by_value.items():
        first, kind = pubs[0]
        for p, other in pubs[1:]:
            if other == kind:
                continue
            yield (
                p.value.span,  # type: ignore[union-attr]
                f"{_shown(p)} ({other}) is given `{values.brief(key, 40)}`, which line "
                f"{first.span.line} just above publishes as {_shown(first)} ({kind}): one "
                "value is not both; a call copied with its value left unchanged?",
            )


def angle_from_east(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_heading_var):
        if v is None or v.sense != "math":
            continue
        # the step that says so (a conversion on the same line would hide it in the chain)
        frame = next((w for w in v.why if "north over east" in w), None)
        turned = next((w for w in v.why if w.endswith(values.QUARTER_TURN)), None)
        because = (
            f" ({frame.replace(', north over east,', ': north over east,')}"
            + (f"; {turned}" if turned else "")
            + ")"
            if frame
            else _because(v)
        )
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is an angle from east, counter-clockwise{because}: a heading is "
            "clockwise from north: atan2(Δx, Δy), or 90° − the math angle",
        )


#: how to turn each speed unit into metres per second, as a message says it
_TO_MPS = {
    "kn": "multiply by 0.514444 (1852 m / 3600 s)",
    "km/h": "divide by 3.6",
    "mph": "multiply by 0.44704",
}


def speed_in_knots(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_speed_var):
        speed = values.speed_unit(v) if v is not None else None
        if speed is None:
            continue
        unit, why = speed
        because = _steps(why)
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is published in {values.speed_label(unit)}{because}: MOOS speeds "
            f"are metres per second; {_TO_MPS[unit]}",
        )


def decimal_comma(app: AppModel) -> Iterator[tuple[Span, str, Fix]]:
    for d in app.decimal_commas:
        number = d.written.replace(",", ".", 1)
        yield (
            d.span,
            f"`{d.written}` is not a number in C++: the comma operator evaluates "
            f"`{values.brief(d.kept, 60)}` and throws the digits after the comma away; "
            f"write `{number}`",
            Fix(f"write `{number}`", (Edit(d.span, number),)),
        )


def case_never_matches(app: AppModel) -> Iterator[tuple[Span, str, Fix]]:
    for c in app.case_mismatches:
        meant = c.literal.lower() if c.case == "lower" else c.literal.upper()
        always = "always true" if c.negated else "never true, and its branch never runs"
        yield (
            c.span,
            f"`{c.subject}` is made {c.case} case at line {c.converted_at} "
            f'(`{c.conversion}`), so comparing it with `"{c.literal}"` is {always}; '
            f'compare with `"{meant}"`',
            Fix(f'compare with `"{meant}"`', (Edit(c.span, f'"{meant}"'),)),
        )


def unreachable_branch(app: AppModel) -> Iterator[Finding]:
    for b in app.shadowed_branches:
        where = f" of `{b.function}`" if b.function else ""
        caseless = " (ignoring case)" if b.earlier_caseless else ""
        yield (
            b.span,
            f"this branch{where} never runs: the branch at line {b.earlier_line} of the same "
            f"if/else-if chain takes `{b.name}` first{caseless}, so `{b.test}` is never true here",
        )


def depth_z_sign(
    app: AppModel, own: Callable[[str], bool] = lambda var: False
) -> Iterator[Finding]:
    """``own``: whether a variable is the repository's own (its readers give its sense)."""
    for p, v in _valued(app, lambda n: angles.is_z_var(n) or angles.is_depth_var(n)):
        if v is None or v.sign is None:
            continue
        name = p.name.last
        if p.name.text is not None and own(p.name.text):
            continue
        if angles.is_z_var(name) and v.sign == "down":
            what, rule = "a depth (positive down)", "Z is up, so Z = −depth"
        elif angles.is_depth_var(name) and v.sign == "up" and not v.hint:
            what, rule = "a Z (positive up)", "depth is down, so depth = −Z"
        else:
            continue
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is published from {what} without negation{_because(v)}: {rule}",
        )
    for a in app.ned_writes:
        v = a.value.abstract
        if v is None or v.sign != "up" or v.hint:
            continue
        yield (
            a.span,
            f"`{a.target}`, a NED z (positive down), is set from a Z (positive up) without "
            f"negation{_because(v)}: NED down = −Z = depth",
        )


def latlong_in_radians(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_latlong_var):
        if v is None or v.unit != "rad":
            continue
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is published in radians{_because(v)}: "
            "latitude and longitude are decimal degrees",
        )


def latlong_not_decimal(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_latlong_var):
        found = values.nmea_position(v) if v is not None else None
        if found is None:
            continue
        sentence, why = found
        because = _steps(why)
        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} is published as NMEA's {sentence} sentence writes it, degrees and "
            f"minutes run together{because}: `4916.45` is 49°16.45′, not 4916.45°; "
            "latitude and longitude are decimal degrees: the degrees plus the minutes / 60",
        )


def yaw_in_degrees(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, angles.is_yaw_var):
        val = p.value
        if angles.literal_over_two_pi(val.number):  # type: ignore[union-attr]
            yield (
                val.span,  # type: ignore[union-attr]
                f"{_shown(p)} is published as {val.text}, more than 2π: "  # type: ignore[union-attr]
                "a yaw is in radians",
            )
        elif v is not None and v.unit == "deg":
            yield (
                val.span,  # type: ignore[union-attr]
                f"{_shown(p)} is published in degrees{_because(v)}: a yaw is in radians",
            )


def angle_not_wrapped(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, lambda n: angles.is_yaw_var(n) or angles.is_other_angle_var(n)):
        if v is None or v.unit != "rad" or v.range is None:
            continue
        if angles_within(v):
            continue
        from moos_lint.frontends.cpp.values import range_text

        yield (
            p.value.span,  # type: ignore[union-attr]
            f"{_shown(p)} lies in {range_text(v.range, v.unit)}{_because(v)}: "
            "angles are wrapped to ±π (MOOS_ANGLE_WRAP)",
        )


def angles_within(v: Any) -> bool:
    from moos_lint.frontends.cpp.values import within_pi

    return within_pi(v.range) is not False


def angle_in_degrees(app: AppModel) -> Iterator[Finding]:
    for p, v in _valued(app, lambda n: angles.is_other_angle_var(n) or angles.is_rate_var(n)):
        val = p.value
        if angles.is_other_angle_var(p.name.last) and angles.literal_over_two_pi(val.number):  # type: ignore[union-attr]
            why = f" ({val.text} is more than 2π)"  # type: ignore[union-attr]
            unit = "degrees"
        elif v is not None and v.unit in ("deg", "deg/s"):
            rate_only = angles.is_rate_var(p.name.last) and not angles.is_other_angle_var(
                p.name.last
            )
            if rate_only and v.unit == "deg" and v.hint:
                continue
            why = _because(v)
            unit = "degrees per second" if angles.is_rate_var(p.name.last) else "degrees"
        else:
            continue
        rule = (
            "angular rates are radians per second"
            if unit == "degrees per second"
            else "angles other than heading are radians"
        )
        yield (val.span, f"{_shown(p)} is published in {unit}{why}: {rule}")  # type: ignore[union-attr]


def geodesy_argument_order(app: AppModel) -> Iterator[Finding]:
    """Arguments of CMOOSGeodesy's conversions whose names say the opposite of the
    parameter they are given to: one finding per pair (latitude and longitude, north and
    east)."""
    for call in app.geodesy_calls:
        if call.own_signature is None:  # (else the repository's own function: its order)
            yield from geodesy_call_findings(call)


def geodesy_call_findings(call: GeodesyCall) -> Iterator[Finding]:
    """What :func:`geodesy_argument_order` says of one call, by CMOOSGeodesy's order."""
    from moos_lint.frontends.cpp.facts import GEODESY_ARGUMENTS

    words = {"lat": "latitude", "lon": "longitude", "north": "north", "east": "east"}
    roles = GEODESY_ARGUMENTS[call.function]
    said = [axis_of(text) for text, _ in call.arguments]
    signature = f"`{call.function}({', '.join(words[r] for r in roles)})`"
    for pair in (("lat", "lon"), ("north", "east")):
        i, j = sorted(roles.index(r) for r in pair)
        if said[i] == said[j]:
            continue  # named alike, or neither named: not a swap we can read
        wrong = [k for k in (i, j) if said[k] == roles[i + j - k]]
        if len(wrong) == 2:
            a, b = call.arguments[i][1], call.arguments[j][1]
            yield (
                Span(a.path, a.line, a.col, b.end_line, b.end_col),
                f"`{_flat(call.arguments[i][0])}` and `{_flat(call.arguments[j][0])}` are "
                f"swapped: {signature} takes the {words[roles[i]]} before the "
                f"{words[roles[j]]}",
            )
        elif wrong:
            k = wrong[0]
            text, span = call.arguments[k]
            meant = roles[i + j - k]  # what its name says, the other argument's role
            yield (
                span,
                f"`{_flat(text)}` is given as the {words[roles[k]]} of {signature}, but "
                f"its name says {words[meant]}, which goes in argument {i + j - k + 1}",
            )


def differs_from_geodesy(function: str, parameters: list[str]) -> bool:
    """Whether parameters named so say another order than CMOOSGeodesy's ``function``."""
    from moos_lint.frontends.cpp.facts import GEODESY_ARGUMENTS

    roles = GEODESY_ARGUMENTS[function]
    return len(parameters) != len(roles) or any(
        axis_of(p) not in (None, r) for p, r in zip(parameters, roles, strict=True)
    )


def _flat(text: str) -> str:
    return " ".join(text.split())


def variable_name_case(
    app: AppModel, allow: tuple[str, ...] = (), own_apps: frozenset[str] = frozenset()
) -> Iterator[Finding]:
    """Each name once per app, at its first place (published before subscribed to), with
    the number of other places that use it; a name joined to the name of one of
    ``own_apps`` (the repository's apps) takes that app's case (:func:`scoped_to_app`)."""
    places: dict[str, list[tuple[Span, str]]] = {}
    items: list[tuple[Any, str]] = [(p, "published") for p in app.publications]
    items += [(s, "subscribed to") for s in app.subscriptions]
    for item, verb in items:
        name = item.name.text
        if name is None or not name or item.name.config_key is not None:
            continue  # (a member the configuration sets: its literal is only a default)
        check = name.replace("*", "").replace("?", "")
        if not check or UPPER_SNAKE.match(check) or re.fullmatch(r"[A-Z0-9_]+", check):
            continue
        if re.search(r"\s", name) or any(fnmatch.fnmatchcase(name, a) for a in allow):
            continue  # not a variable name (a message or a format), or allowed
        if scoped_to_app(name, own_apps):
            continue  # `iWhoiMicroModem_CMD`: the app's name decides its case
        spans = places.setdefault(name, [])
        if all((s.path, s.line) != (item.name_span.path, item.name_span.line) for s, _ in spans):
            spans.append((item.name_span, verb))
    for name, spans in places.items():
        span, verb = spans[0]
        more = len(spans) - 1
        also = f"; the app uses it in {more} more place{'s' if more > 1 else ''}" if more else ""
        yield span, f"variable `{name}` ({verb}) is not UPPER_SNAKE_CASE{also}"


def unhandled_mail(app: AppModel) -> Iterator[Finding]:
    if not any(f.has_on_new_mail for f in app.files) or any(f.mail_generic for f in app.files):
        return
    keys = app.mail_keys
    exact = {k.text for k in keys if not (k.prefix or k.suffix)}
    prefixes = [k.text for k in keys if k.prefix and k.text]
    suffixes = [k.text for k in keys if k.suffix and k.text]
    if not exact and not prefixes:
        return  # no dispatch on literal keys: handling we cannot read
    # a name the app posts itself comes back as its own echo (a debugging aid): not lost;
    # so is one a name it builds may be (``ss << "VISIT_POINT_" << m_vname; Notify(ss.str()``)
    seen = {p.name.text for p in app.publications if p.name.text and not p.name.wildcard}
    built = {
        p.name.prefix
        for p in app.publications
        if p.name.text is None and p.name.prefix.endswith("_") and len(p.name.prefix) > 3
    }
    for s in app.subscriptions:
        name = s.name.text
        if name is None or s.name.wildcard or name in seen or name in UNASKED_MAIL:
            continue
        if any(name.startswith(b) for b in built):
            continue
        seen.add(name)
        if name in exact or name.upper() in {e.upper() for e in exact}:
            continue
        if any(name.startswith(p) for p in prefixes) or any(name.endswith(x) for x in suffixes):
            continue
        if s.name.source.strip().startswith('"') is False:
            continue  # a name built in code may be matched in code too
        yield (
            s.name_span,
            f"{_app_label(app)} registers for `{name}` but its OnNewMail never handles it",
        )


def unregistered_mail(
    app: AppModel, near: Callable[[str, list[str]], str | None] | None = None
) -> Iterator[Finding]:
    """Names OnNewMail tests a message's own name against that the app never registers for.

    Only apps whose registrations can all be read: none with a name made at run time
    (a wildcard is matched as the pattern it is), none through a base class of another
    folder, none that hands its comms client (or itself) to other code. A registration
    commented out or under ``#if 0`` was taken out on purpose; its handler is left alone,
    and so is a test that is one alternative of an ``||`` whose other name is registered
    (the branch runs on it), and a branch that does nothing. Beside a registration the
    configuration may rename, only names the app itself holds in a member or constant are
    judged. ``near`` names the registered name a handled one is a misspelling of, if any.
    A ``!=`` test (the template's catch-all) is reported only when its name is a
    misspelling of one the app receives and no ``==`` test takes: that name then runs
    the branch.
    """
    if not app.is_app or not any(f.has_on_new_mail for f in app.files):
        return
    subs = [s for f in app.files for s in f.subscriptions]
    if not any(s.active for s in subs) or any(f.comms_shared for f in app.files):
        return
    if any(s.active and s.name.text is None for s in subs):
        return
    own = {c.name for f in app.files for c in f.classes}
    if any(b not in own for b in app.base_chain[:-1]):
        return  # a base class of another folder may register for the app
    renamed = any(s.active and s.name.config_key for s in subs)
    patterns = [s.name.text.upper() for s in subs if s.name.text and s.name.wildcard]
    registered = sorted({s.name.text for s in subs if s.name.text and s.active})
    handled = {k.text for k in app.mail_keys if k.direct and not k.negated}
    # what a misspelt ``!=`` meant to pass over: mail that arrives and no ``==`` takes first
    passed_over = (set(registered) | {n for n in UNASKED_MAIL if n.isupper()}) - handled
    known = {s.name.text.upper() for s in subs if s.name.text}  # inactive ones: on purpose
    known |= {n.upper() for f in app.files for n in f.commented_registrations}
    known |= {n.upper() for n in UNASKED_MAIL | TEMPLATE_MAIL_KEYS}
    keys = sorted(
        (k for k in app.mail_keys if k.direct),
        key=lambda k: (k.span.path, k.span.line, k.span.col),
    )
    runs_on_other = {
        (k.span.path, k.either_at) for k in keys if k.either_at >= 0 and k.text.upper() in known
    }
    for k in keys:
        name = k.text.upper()
        if not name or name in known or name.endswith(COMMAND_KEY_SUFFIX) or k.empty_branch:
            continue
        if (k.span.path, k.either_at) in runs_on_other or (renamed and not k.held_in):
            continue
        if any(fnmatch.fnmatchcase(name, p) for p in patterns):
            continue  # ``Register("POWER_*", "*", 0)``
        if k.negated:  # ``key != "X"``: the branch runs on every other name
            meant = near(k.text, sorted(passed_over)) if near is not None else None
            if meant:  # ``key != "APPCASE_REQ"``: the name it meant to pass over runs it
                known.add(name)
                yield (
                    k.span,
                    f"{_app_label(app)} passes over mail `{k.text}` (`!=`), which it never "
                    f"registers for: `{meant}`, a near spelling it does receive, is not "
                    f"passed over, so this branch runs on it",
                )
            continue
        known.add(name)
        held = f" (held in `{k.held_in}`)" if k.held_in and k.held_in != k.text else ""
        meant = near(k.text, registered) if near is not None else None
        hint = f"; it registers `{meant}`, a near spelling" if meant else ""
        yield (
            k.span,
            f"{_app_label(app)} handles mail `{k.text}`{held} but never registers for it: "
            f"the MOOSDB sends an app only what it registered for, so this branch never "
            f"runs{hint}",
        )


def published_names(app: AppModel) -> Iterator[tuple[str, Span]]:
    """The names an app publishes that are known statically, each once per place."""
    seen = set()
    for p in app.publications:
        name = p.name.text
        if not name or p.name.wildcard or (name, p.name_span.path, p.name_span.line) in seen:
            continue
        seen.add((name, p.name_span.path, p.name_span.line))
        yield name, p.name_span


#: the commands a driver of a standard actuator listens for
_STANDARD_COMMANDS = tuple("DESIRED_" + a for a in STANDARD_ACTUATORS)


def actuator_name(app: AppModel, word_of: Callable[[str], str | None]) -> Iterator[Finding]:
    """Published command variables naming an actuator outside THRUST / RUDDER / ELEVATOR.

    An app that subscribes to a standard command (``DESIRED_THRUST``) is the actuator's
    driver: what it publishes under an actuator word (``ZBOAT_PWM``, the sentence it sends
    to the motors) is its own output, downstream of the convention, and is not judged."""
    if any((s.name.text or "").startswith(_STANDARD_COMMANDS) for s in app.subscriptions):
        return
    for p in app.publications:
        name = p.name.text
        if name is None:
            continue
        word = word_of(name)
        if word:
            key = p.name.config_key
            where = f" (its default; the configuration key `{key}` may rename it)" if key else ""
            yield (
                p.name_span,
                f"`{name}`{where} names the actuator `{word}`: MOOS actuators are "
                "THRUST, RUDDER and ELEVATOR (`DESIRED_THRUST`, `DESIRED_RUDDER`, ...)",
            )
