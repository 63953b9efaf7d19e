"""Branches of an ``if`` / ``else if`` chain that an earlier branch of the chain shadows.

OnNewMail and OnStartUp are long chains of tests of one name
(``if(key == "NAV_X") ... else if(key == "NAV_Y") ...``). When a test repeats
one an earlier branch of the same chain already takes, its branch can never
run: the earlier branch takes every message (or parameter) it would.

A test is read only in three shapes, against a string literal:

- ``subject == "NAME"`` (either side), exact;
- ``msg.IsName("NAME")``, exact, of the message's own name (``msg.GetKey()``);
- ``MOOSStrCmp(subject, "NAME")``, case-insensitive.

A branch *takes* the tests its condition is made of by ``||`` (any one of them
true takes the branch); a condition with ``&&`` takes nothing. A later branch
is *shadowed* when its condition cannot be true without an earlier taken test
being true: a test the earlier branches took, a ``&&`` with one such operand,
or an ``||`` of only such alternatives. The subject must be a name
(``key``, ``m_mode``, ``msg.m_sKey``) or a read of a message's name
(``msg.GetKey()``): nothing that could change between the two tests. A test
that may change a name (an assignment, a call it is handed to) ends what is
known of the tests of that name.

Chains are found from the bytes (``else if``), and only in a file where an
``else if`` line tests a literal an earlier ``if`` line tests: most files are
never walked.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from moos_lint.frontends.cpp.names import callee_name, node_text, strip

#: calls whose result is the same on each call: a message's name and a string's case
_STABLE_CALLS = frozenset(
    {"GetKey", "GetName", "GetString", "GetSource", "GetCommunity", "c_str", "tolower", "toupper"}
)
#: case-insensitive equality, true when equal (``MOOSStrCmp(a, b)``)
_CASELESS = frozenset({"MOOSStrCmp"})
#: the calls a condition makes that change nothing: the stable ones and the tests
_HARMLESS_CALLS = _STABLE_CALLS | _CASELESS | {"IsName"}


@dataclass(frozen=True, slots=True)
class Test:
    """``subject == "NAME"``: exact, or ``caseless`` (the name upper-cased)."""

    subject: str
    name: str
    caseless: bool = False

    def covered_by(self, taken: dict[Test, Any]) -> tuple[Test, Any] | None:
        """The earlier test in ``taken`` that is true whenever this one is, with its
        literal, or None."""
        if self in taken:
            return self, taken[self]
        wider = Test(self.subject, self.name.upper(), True)
        if not self.caseless and wider in taken:
            return wider, taken[wider]
        return None


@dataclass(slots=True)
class Shadowed:
    """A test of a branch no message reaches, and the earlier test that takes its cases."""

    test: Test
    expr: Any  # the later test
    node: Any  # its literal
    earlier: Test
    earlier_node: Any  # the earlier test's literal
    branch: Any  # the later branch's if_statement


def shadowed(data: bytes, root: Any) -> list[Shadowed]:
    """The shadowed tests of the chains of a file (its bytes and its syntax tree), in
    source order."""
    if not _repeats_a_test(data):
        return []
    later: set[int] = set()
    outers: dict[int, Any] = {}
    for m in _ELSE_IF.finditer(data):
        clause = root.descendant_for_byte_range(m.start(), m.end())  # ``else if``: its clause
        if clause is None or clause.type != "else_clause":
            continue
        inner = _alternative_if(clause.parent)
        if inner is not None:
            later.add(inner.id)
            outers.setdefault(clause.parent.id, clause.parent)
    out: list[Shadowed] = []
    for head in sorted(outers.values(), key=lambda s: s.start_byte):
        if head.id not in later:
            out += _in_chain(head)
    return out


def _repeats_a_test(data: bytes) -> bool:
    """Whether an ``else if`` line tests a literal an earlier ``if`` line tests (in any
    case): the file is read further only then."""
    seen: set[bytes] = set()
    for m in _IF_LINE.finditer(data):
        lits = [lit.upper() for lit in _LITERAL.findall(m.group())]
        after_else = data[max(0, m.start() - 12) : m.start()].rstrip().endswith(b"else")
        if after_else and not seen.isdisjoint(lits):
            return True
        seen.update(lits)
    return False


def _in_chain(head: Any) -> list[Shadowed]:
    """The shadowed tests of the chain that starts at ``head``."""
    branches = []
    stmt = head
    while stmt is not None:
        branches.append((stmt, stmt.child_by_field_name("condition")))
        stmt = _alternative_if(stmt)
    # only a chain whose tests hold some literal twice (in any case) is read further
    literals = [
        lit.upper() for _s, c in branches if c is not None for lit in _LITERAL.findall(c.text)
    ]
    if len(set(literals)) == len(literals):
        return []
    taken: dict[Test, Any] = {}
    out: list[Shadowed] = []
    for stmt, cond in branches:
        expr = _condition_expr(cond)
        if expr is None or expr.has_error:
            return out  # a declaration in the condition, or a part we cannot read
        form = _form(expr)
        changed = _changed(expr)
        hit = _never(form, taken)
        if hit is not None and changed & _names_in(hit[0].subject):
            hit = None  # the test may see a new value: ``(key = next()) == "A"``
        if hit is not None:
            out.append(Shadowed(*hit, branch=stmt))
        else:
            for test, _expr, lit in _taken(form):
                taken.setdefault(test, lit)
            if changed:  # what this test may change is no longer known to later tests
                taken = {t: lit for t, lit in taken.items() if not changed & _names_in(t.subject)}
    return out


def _changed(expr: Any) -> set[str]:
    """The names a condition may change as it is evaluated: assigned (``(key = next())``),
    incremented, or handed to a call that may change them (``biteStringX(sval, '=')``,
    ``m_list.pop()``); the tests' own calls and the stable ones change nothing."""
    out: set[str] = set()
    if not _MAY_CHANGE.search(expr.text):
        return out
    stack = [expr]
    while stack:
        x = stack.pop()
        if x.type == "assignment_expression":
            out |= _names_under(x.child_by_field_name("left"))
        elif x.type == "update_expression":
            out |= _names_under(x.child_by_field_name("argument"))
        elif x.type == "call_expression":
            fn = x.child_by_field_name("function")
            if fn is not None and callee_name(fn) not in _HARMLESS_CALLS:
                out |= _names_under(x.child_by_field_name("arguments"))
                if fn.type == "field_expression":
                    out |= _names_under(fn.child_by_field_name("argument"))
        stack.extend(x.named_children)
    return out


def _names_under(n: Any) -> set[str]:
    """The identifiers (and member names) in ``n``."""
    out: set[str] = set()
    stack = [n] if n is not None else []
    while stack:
        x = stack.pop()
        if x.type in ("identifier", "field_identifier"):
            out.add(node_text(x))
        stack.extend(x.named_children)
    return out


def _names_in(subject: str) -> set[str]:
    return set(_WORD.findall(subject))


_WORD = re.compile(r"[A-Za-z_]\w*")
#: ``else if``, where a chain goes on
_ELSE_IF = re.compile(rb"else(?<=\belse)\s+if\b")
#: a line with an ``if`` and a string literal after it
_IF_LINE = re.compile(rb"if(?<=\bif)\s*\([^\n]*\"[^\n]*")
#: a string literal's bytes
_LITERAL = re.compile(rb'"(?:[^"\\\n]|\\.)*"')
#: a call, an assignment or an increment in a condition's bytes
_MAY_CHANGE = re.compile(rb"\w\s*\(|[^=!<>]=[^=]|\+\+|--")


def _alternative_if(stmt: Any) -> Any:
    """The ``if`` of ``stmt``'s ``else if``, or None."""
    if stmt is None or stmt.type != "if_statement":
        return None
    alt = stmt.child_by_field_name("alternative")
    if alt is None or alt.type != "else_clause":
        return None
    inner = [c for c in alt.named_children if c.type != "comment"]
    if len(inner) == 1 and inner[0].type == "if_statement":
        return inner[0]
    return None


def _condition_expr(cond: Any) -> Any:
    if cond is None or cond.type != "condition_clause":
        return None
    if cond.child_by_field_name("initializer") is not None:
        return None
    value = cond.child_by_field_name("value")
    if value is None or value.type in ("declaration", "init_declarator", "comma_expression"):
        return None
    return value


def _logical(n: Any) -> str | None:
    if n.type != "binary_expression":
        return None
    op = n.child_by_field_name("operator")
    return op.type if op is not None and op.type in ("||", "&&") else None


#: a test, the expression it is read from and its literal
_Atom = tuple[Test, Any, Any]
#: a condition as read once: ``("||", left, right)``, ``("&&", left, right)``, a test, or
#: None (anything else)
_Form = Any


def _form(n: Any) -> _Form:
    n = strip(n)
    op = _logical(n)
    if op is not None:
        return op, _form(n.child_by_field_name("left")), _form(n.child_by_field_name("right"))
    return _atom(n)


def _taken(f: _Form) -> list[_Atom]:
    """The tests any one of which, true, makes the condition true."""
    if f is None or f[0] == "&&":
        return []
    if f[0] == "||":
        return _taken(f[1]) + _taken(f[2])
    return [f]


def _never(f: _Form, taken: dict[Test, Any]) -> tuple[Test, Any, Any, Test, Any] | None:
    """Why the condition is never true after the ``taken`` tests were false: the first of
    its tests that one of them covers (its expression and literal), with that earlier test
    and its literal, or None."""
    if f is None:
        return None
    if f[0] == "&&":
        return _never(f[1], taken) or _never(f[2], taken)
    if f[0] == "||":
        left = _never(f[1], taken)
        return left if left is not None and _never(f[2], taken) is not None else None
    earlier = f[0].covered_by(taken)
    return (*f, *earlier) if earlier is not None else None


def _atom(n: Any) -> _Atom | None:
    """``n`` as a test of a stable subject against a string literal, with the literal."""
    if n is None:
        return None
    if n.type == "binary_expression":
        op = n.child_by_field_name("operator")
        if op is None or op.type != "==":
            return None
        left = strip(n.child_by_field_name("left"))
        right = strip(n.child_by_field_name("right"))
        for subject, lit in ((left, right), (right, left)):
            name = _literal(lit)
            if name is not None and _stable(subject):
                return Test(_squeezed(subject), name), n, lit
        return None
    if n.type != "call_expression":
        return None
    fn = n.child_by_field_name("function")
    args = n.child_by_field_name("arguments")
    if fn is None or args is None:
        return None
    argv = [strip(a) for a in args.named_children if a.type != "comment"]
    if fn.type == "field_expression" and callee_name(fn) == "IsName" and len(argv) == 1:
        obj = fn.child_by_field_name("argument")
        name = _literal(argv[0])
        if name is not None and _stable(obj):
            return Test(_squeezed(obj) + _arrow(fn) + "GetKey()", name), n, argv[0]
        return None
    if callee_name(fn) in _CASELESS and len(argv) == 2:
        for subject, lit in ((argv[0], argv[1]), (argv[1], argv[0])):
            name = _literal(lit)
            if name is not None and _stable(subject):
                return Test(_squeezed(subject), name.upper(), True), n, lit
    return None


def _literal(n: Any) -> str | None:
    """A plain string literal's text (no escapes, no concatenation), or None."""
    if n is None or n.type != "string_literal":
        return None
    parts = n.named_children
    if any(c.type != "string_content" for c in parts):
        return None
    return "".join(node_text(c) for c in parts)


def _stable(n: Any) -> bool:
    """A name, a member, or a stable call on one (``msg.GetKey()``, ``tolower(key)``)."""
    n = strip(n)
    if n is None:
        return False
    if n.type in ("identifier", "qualified_identifier", "this"):
        return True
    if n.type == "field_expression":
        return _stable(n.child_by_field_name("argument"))
    if n.type == "pointer_expression":
        return _stable(n.child_by_field_name("argument"))
    if n.type == "call_expression":
        fn = n.child_by_field_name("function")
        args = n.child_by_field_name("arguments")
        if fn is None or args is None or callee_name(fn) not in _STABLE_CALLS:
            return False
        argv = [a for a in args.named_children if a.type != "comment"]
        if fn.type == "field_expression":
            return not argv and _stable(fn.child_by_field_name("argument"))
        return len(argv) == 1 and _stable(argv[0])
    return False


def _arrow(fn: Any) -> str:
    return node_text(fn.child_by_field_name("operator")) or "."


def _squeezed(n: Any) -> str:
    return "".join(node_text(n).split())
