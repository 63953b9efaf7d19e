"""Fields of C and C++ structs and classes, for the value analysis.

Whose field an expression reads (``m_roll`` in a method of ``XsEuler``, ``att.yaw``
for ``Attitude att``), which fields share its storage (the members at the same place
of the anonymous structs of a union: ``m_roll`` and ``m_x``), and where a file writes
a field of that type (``thisPtr->m_x = ...`` for ``XsEuler* thisPtr``, ``m_x = ...``
in a method of ``XsEuler``). Every check is on the tree, never on text alone.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from moos_lint.frontends.cpp.names import callee_name, function_declarator, strip
from moos_lint.frontends.cpp.names import node_text as text

_CLASS_TYPES = ("struct_specifier", "class_specifier", "union_specifier")
#: words of a declared type that are not its name
_TYPE_NOISE = {"const", "struct", "class", "union", "volatile", "mutable", "static", "std"}


def _qualified_class(fn: Any) -> str | None:
    """``S`` for an out-of-line method ``T S::f(...)``."""
    decl = function_declarator(fn)
    name = decl.child_by_field_name("declarator") if decl is not None else None
    if name is None or name.type != "qualified_identifier":
        return None
    parts = re.split(r"::", re.sub(r"\s+", "", text(name)))
    return parts[-2] if len(parts) >= 2 and parts[-2] else None


def enclosing_class(n: Any) -> str | None:
    """The struct or class whose method (or body) holds ``n``, by name."""
    p = n.parent
    while p is not None:
        if p.type in _CLASS_TYPES and p.child_by_field_name("body") is not None:
            name = p.child_by_field_name("name")
            if name is not None:
                return text(name).split("::")[-1]
        if p.type == "function_definition":
            cls = _qualified_class(p)
            if cls is not None:
                return cls
        p = p.parent
    return None


#: ``std::unique_ptr<T>``, ``boost::shared_ptr<const T>``: what ``->`` reaches is a ``T``
_SMART_POINTER = re.compile(
    r"(?:const\s+)?(?:(?:std|boost)\s*::\s*)?(?:unique_ptr|shared_ptr)\s*<\s*([^<>,]+?)\s*>\s*[&*]?"
)


def type_name(type_text: str) -> str | None:
    """The class a declared type names: ``XsEuler`` for ``const struct XsEuler*``,
    ``Attitude`` for ``nav::Attitude&``, ``Ais1_2_3`` for the smart pointer
    ``std::unique_ptr<libais::Ais1_2_3>`` (read with ``->`` as a raw pointer is); None for
    other templates and built-in types."""
    smart = _SMART_POINTER.fullmatch(type_text.strip())
    if smart is not None:
        type_text = smart.group(1)
    if "<" in type_text:
        return None
    words = [w for w in re.findall(r"\w+", type_text) if w not in _TYPE_NOISE]
    if not words:
        return None
    last = words[-1]
    if last in ("double", "float", "int", "long", "short", "char", "bool", "auto", "void"):
        return None
    return last


def _declarator_name(d: Any) -> str:
    while d is not None and d.type not in ("identifier", "field_identifier"):
        nxt = d.child_by_field_name("declarator")
        if nxt is None:
            nxt = next(
                (c for c in d.named_children if c.type in ("identifier", "field_identifier")), None
            )
        d = nxt
    return text(d) if d is not None else ""


def declarations(root: Any) -> Iterator[tuple[str, str]]:
    """(name, type text) of every variable, parameter and field ``root`` declares."""
    for name, type_text, _node in _declaring(root):
        yield name, type_text


def _declaring(root: Any) -> Iterator[tuple[str, str, Any]]:
    """(name, type text, declaration node) of every variable, parameter and field."""
    stack = [root]
    while stack:
        x = stack.pop()
        if x.type in ("parameter_declaration", "declaration", "field_declaration"):
            t = x.child_by_field_name("type")
            if t is not None:
                for d in x.children_by_field_name("declarator"):
                    name = _declarator_name(d)
                    if name:
                        yield name, text(t), x
        stack.extend(x.named_children)


def declared_type(fn: Any, name: str, use: Any) -> str | None:
    """The class of ``name`` as a parameter or local of function ``fn``, of the declaration
    in scope at node ``use``: the last before it in a block that holds it (each ``if``
    branch of a message handler may declare its own ``msg`` of another type). None when no
    declaration of ``name`` is in scope there (a member of that name)."""
    if fn is None:
        return None
    best: tuple[int, str] | None = None
    for n, t, node in _declaring(fn):
        if n != name or node.start_byte > use.start_byte:
            continue
        scope = node.parent
        if node.type == "parameter_declaration":
            scope = fn
        elif scope is not None and scope.type == "condition_clause":
            scope = scope.parent  # ``if (Foo* m = ...)``: the whole if statement
        if scope is None or not (scope.start_byte <= use.start_byte < scope.end_byte):
            continue
        if best is None or node.start_byte > best[0]:
            best = (node.start_byte, t)
    return type_name(best[1]) if best is not None else None


def auto_getter(fn: Any, name: str) -> str | None:
    """The function whose return initialises ``name`` when function ``fn`` declares it
    ``auto`` (``getUniHeadingA`` for ``const auto &hdg = m_parser->getUniHeadingA();``);
    None for any other declaration, or when ``fn`` declares ``name`` more than once."""
    value = auto_value(fn, name)
    return _callee(value) if value is not None else None


def auto_value(fn: Any, name: str) -> Any:
    """The expression that initialises ``name`` when function ``fn`` declares it ``auto``
    (``m_parser->getUniHeadingA()`` of ``const auto &hdg = m_parser->getUniHeadingA();``),
    parentheses stripped; None for any other declaration, or when ``fn`` declares ``name``
    more than once."""
    if fn is None:
        return None
    found: list[Any] = []
    stack = [fn]
    while stack:
        x = stack.pop()
        stack.extend(x.named_children)
        if x.type not in ("declaration", "parameter_declaration"):
            continue
        for d in x.children_by_field_name("declarator"):
            if _declarator_name(d) != name:
                continue
            t = x.child_by_field_name("type")
            value = d.child_by_field_name("value") if d.type == "init_declarator" else None
            if t is None or t.type != "placeholder_type_specifier" or value is None:
                found.append(None)
            else:
                found.append(strip(value))
    return found[0] if len(found) == 1 else None


def _callee(call: Any) -> str | None:
    """The short name of the function a call expression calls (``getX`` for ``p->getX()``)."""
    if call is None or call.type != "call_expression":
        return None
    return callee_name(call.child_by_field_name("function")) or None


def _field_names(body: Any) -> list[str]:
    out: list[str] = []
    for c in body.named_children:
        if c.type == "field_declaration":
            out.extend(_declarator_name(d) for d in c.children_by_field_name("declarator"))
    return [n for n in out if n]


def union_aliases(root: Any, cls: str, field: str) -> list[str]:
    """The fields sharing ``field``'s storage in class ``cls``: the members at the same
    place of the other anonymous structs of an anonymous union
    (``union { struct { x, y, z }; struct { roll, pitch, yaw }; }``)."""
    stack = [root]
    while stack:
        x = stack.pop()
        stack.extend(x.named_children)
        if x.type != "union_specifier" or enclosing_class(x) != cls:
            continue
        body = x.child_by_field_name("body")
        if body is None:
            continue
        groups = []
        for c in body.named_children:
            spec = c if c.type == "struct_specifier" else c.child_by_field_name("type")
            if spec is None or spec.type != "struct_specifier":
                continue
            inner = spec.child_by_field_name("body")
            if inner is not None and spec.child_by_field_name("name") is None:
                groups.append(_field_names(inner))
        for g in groups:
            if field in g:
                i = g.index(field)
                return [h[i] for h in groups if h is not g and i < len(h)]
    return []


def field_writes(pf: Any, cls: str, names: set[str]) -> Iterator[tuple[Any, Any]]:
    """(assignment node, right side) of each plain write in ``pf`` of a field in ``names``
    of class ``cls``: through an object or pointer declared of that class, through
    ``this``, or by name in a method of the class."""
    for a in pf.asgs:
        if a.op != "=" or a.node.type != "assignment_expression":
            continue
        left = strip(a.node.child_by_field_name("left"))
        if left is None:
            continue
        if left.type == "field_expression":
            if text(left.child_by_field_name("field")) not in names:
                continue
            obj = strip(left.child_by_field_name("argument"))
            if obj is None:
                continue
            if text(obj) == "this":
                owner = enclosing_class(a.node)
            elif obj.type == "identifier":
                owner = declared_type(a.fn, text(obj), obj)
            else:
                continue
        elif left.type == "identifier" and text(left) in names:
            if a.fn is not None and any(n == text(left) for n, _t in declarations(a.fn)):
                continue  # a local or parameter of the same name
            owner = enclosing_class(a.node)
        else:
            continue
        if owner == cls:
            yield a.node, a.rhs
