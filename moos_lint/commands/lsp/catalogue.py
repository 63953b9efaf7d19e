"""What the server knows about MOOS apps and helm behaviors, for completion and hover.

The server asks a :class:`Catalogue` for the app names it completes on ``Run =``
lines, the parameters it completes inside a ``ProcessConfig`` or ``Behavior``
block, and the text it shows when hovering a parameter. :func:`default_catalogue`
adapts the app catalogue that the rules use (:mod:`moos_lint.semantics.catalogue`, when
it is there); without one the server offers no completion. Another catalogue is
plugged in with ``create_server(catalogue=...)``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field


@dataclass(frozen=True, slots=True)
class ParamInfo:
    """One configuration parameter of an app or a behavior."""

    name: str
    doc: str = ""


@dataclass(frozen=True, slots=True)
class Component:
    """A MOOS app (``pHelmIvP``) or a helm behavior (``BHV_Waypoint``)."""

    name: str
    doc: str = ""
    params: Mapping[str, ParamInfo] = field(default_factory=dict)

    def param(self, key: str) -> ParamInfo | None:
        """A parameter by name, compared as MOOS does: case-insensitively."""
        want = key.strip().lower()
        for name, info in self.params.items():
            if name.lower() == want:
                return info
        return None


class Catalogue:
    """Apps and behaviors, looked up by name (case-insensitively, as MOOS does)."""

    def __init__(self, apps: Iterable[Component] = (), behaviors: Iterable[Component] = ()):
        self._apps = {c.name.lower(): c for c in apps}
        self._behaviors = {c.name.lower(): c for c in behaviors}

    @property
    def empty(self) -> bool:
        return not self._apps and not self._behaviors

    def apps(self) -> list[Component]:
        return sorted(self._apps.values(), key=lambda c: c.name.lower())

    def behaviors(self) -> list[Component]:
        return sorted(self._behaviors.values(), key=lambda c: c.name.lower())

    def app(self, name: str) -> Component | None:
        return self._apps.get(name.strip().lower())

    def behavior(self, name: str) -> Component | None:
        return self._behaviors.get(name.strip().lower())


#: The catalogue the server uses until moos-lint ships one.
EMPTY = Catalogue()


#: How the value forms the catalogue records read in a hover.
FORM_TEXT = {
    "bool": "a boolean: true/false, on/off, yes/no",
    "number": "a number",
    "nonneg": "a number, 0 or more",
    "positive": "a number greater than 0",
    "uint": "a whole number, 0 or more",
    "posuint": "a whole number, 1 or more",
    "int": "a whole number",
    "moos_double": "a number starting with a digit or `-` (`0.5`, not `.5`)",
    "moos_int": "a whole number (read with atoi: `2.5` is 2, a word is 0)",
    "true_word": "`true` or `false`: any other word is taken as false",
    "fields:src": "`key=value` fields, `src=` required",
    "convex_polygon": "a convex polygon of 3 or more vertices (`x,y : x,y : x,y`)",
    "waypoints": "a point list (`x,y : x,y`), a polygon, `empty` or `start`",
    "point": "a point: `x,y`, `x:y` or `x=..,y=..`",
    "point|start|empty": "a point (`x,y`), `start` or `empty`",
    "timer_event": "`var=`, `val=` and optional `time=` (seconds or `min:max`) and `amt=`, "
    "or `quit`",
}


def form_text(kind: str) -> str:
    """A value form in words: ``enum:a|b`` and ``enum_or_uint:a|b`` are spelt out."""
    if kind in FORM_TEXT:
        return FORM_TEXT[kind]
    head, _, words = kind.partition(":")
    if head == "range" and "," in words:
        return f"a number in {words.replace(',', ', ')}"
    if head == "clip" and "," in words:
        low, _, high = words.partition(",")
        parts = [f"one below {low} is taken as {low}"] if low else []
        parts += (
            [f"one above {high} as {high}" if low else f"one above {high} is taken as {high}"]
            if high
            else []
        )
        return "a number; " + ", ".join(parts)
    listed = " or ".join(f"`{w}`" for w in words.split("|") if w)
    if head == "enum" and listed:
        return f"one of {listed}"
    if head.startswith("enum_or_") and listed:
        number = head[len("enum_or_") :]
        return f"{listed}, or {FORM_TEXT.get(number, number)}"
    return kind


def from_app_catalogue(cat: object) -> Catalogue:
    """Adapt the rules' app catalogue (``moos_lint.semantics.catalogue.Catalogue``).

    It knows which keys each app and behavior reads (in lower case, as MOOS
    compares them) and where that was learnt, not what a key means: the help
    text says just that.
    """

    def component(info: object, what: str) -> Component:
        name = str(getattr(info, "name", ""))
        where = str(getattr(info, "provenance", "") or "")
        doc = f"{what} `{name}`" + (f" (from {where})" if where else "")
        forms = dict(getattr(info, "forms", {}) or {})
        params = {}
        for p in sorted(getattr(info, "params", ()) or ()):
            text = f"a configuration key that `{name}` reads"
            form = forms.get(str(p).lower())
            if form:
                kind, at = form
                text += f"; its value is {form_text(kind)}"
                if at:
                    text += f" (parsed at {at})"
            params[str(p)] = ParamInfo(str(p), text)
        return Component(name, doc, params)

    apps = [component(i, "MOOS app") for i in dict(getattr(cat, "apps", {}) or {}).values()]
    bhvs = [
        component(i, "helm behavior") for i in dict(getattr(cat, "behaviors", {}) or {}).values()
    ]
    return Catalogue(apps, bhvs)


def default_catalogue() -> Catalogue:
    """The stock app catalogue, or :data:`EMPTY` when moos-lint has none."""
    try:
        from moos_lint.semantics.catalogue import stock

        return from_app_catalogue(stock())
    except Exception:  # no catalogue, or one this adapter cannot read
        return EMPTY
