"""No import cycles among moos-lint's modules, function-level imports included.

The graph is read from the source (every ``import`` statement, wherever it
is), so an import hidden in a function counts like one at the top. Imports
under ``if TYPE_CHECKING:`` are left out: they are never executed. The
registry loads every module of ``moos_lint.rules`` by name
(``importlib.import_module``): that counts as importing each of them.
"""

from __future__ import annotations

import ast
from pathlib import Path

import moos_lint

PACKAGE = Path(moos_lint.__file__).parent

#: cycles that are known and being removed, each named by its sorted modules.
#: Empty this list as they go; a cycle not listed here fails the test.
ALLOWED: set[tuple[str, ...]] = set()


def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


def _type_checking_only(node: ast.AST) -> bool:
    test = node.test if isinstance(node, ast.If) else None
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(tree: ast.AST) -> list[ast.Import | ast.ImportFrom]:
    found: list[ast.Import | ast.ImportFrom] = []

    def visit(node: ast.AST) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _type_checking_only(child):
                for other in child.orelse:
                    visit(other)
                continue
            if isinstance(child, ast.Import | ast.ImportFrom):
                found.append(child)
            visit(child)

    visit(tree)
    return found


def _targets(module: str, is_package: bool, node: ast.Import | ast.ImportFrom) -> list[str]:
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    base = node.module or ""
    if node.level:
        parts = module.split(".")
        if not is_package:
            parts = parts[:-1]
        parts = parts[: len(parts) - node.level + 1]
        base = ".".join([*parts, base] if base else parts)
    return [base, *(f"{base}.{a.name}" for a in node.names)]


def import_graph() -> dict[str, set[str]]:
    modules = _modules()
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        deps: set[str] = set()
        for node in _imports(tree):
            for target in _targets(name, path.name == "__init__.py", node):
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target and target != name:
                    deps.add(target)
        graph[name] = deps
    rule_modules = {m for m in modules if m.startswith("moos_lint.rules.")}
    graph["moos_lint.core.registry"] |= rule_modules  # load_rules imports each by name
    return graph


def cycles(graph: dict[str, set[str]]) -> list[tuple[str, ...]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out: list[tuple[str, ...]] = []

    def connect(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(tuple(sorted(component)))

    for v in sorted(graph):
        if v not in index:
            connect(v)
    return out


def test_no_import_cycles_but_the_listed_ones():
    found = set(cycles(import_graph()))
    assert found - ALLOWED == set()


def test_the_allow_list_holds_only_live_cycles():
    assert set(cycles(import_graph())) >= ALLOWED


def test_the_graph_sees_function_level_imports_and_skips_type_checking_ones():
    tree = ast.parse(
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n    import moos_lint.core.engine\n"
        "def f():\n    from moos_lint.speed import cache\n"
    )
    names = [t for n in _imports(tree) for t in _targets("moos_lint.x", False, n)]
    assert "moos_lint.speed.cache" in names and "moos_lint.core.engine" not in names
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [("a", "b", "c")]
