"""tree-sitter: the C++ parser and the one combined query run over each file.

tree-sitter is imported on first use only, so that linting mission files (and
``moos-lint --version``) never pays for it.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from moos_lint.frontends.cpp.extract import ANGLE_WORDS, CALLED, DEGREE_TURNS

QUERY_TEMPLATE = r"""
(class_specifier name: (_) @cls.name (base_class_clause) @cls.bases) @cls
(struct_specifier name: (_) @cls.name (base_class_clause) @cls.bases) @cls
(call_expression function: (_) @call.fn arguments: (argument_list) @call.args
  (#match? @call.fn "CALLEES")) @call
[(binary_expression left: (_) @cmp.l operator: ["==" "!="] right: (string_literal) @cmp.r)
 (binary_expression left: (string_literal) @cmp.r operator: ["==" "!="] right: (_) @cmp.l)] @cmp
(binary_expression
  left: [(identifier) (field_expression) (qualified_identifier) (subscript_expression)
         (call_expression)] @mix.l
  operator: ["<" ">" "<=" ">=" "==" "!=" "+" "-"]
  right: [(identifier) (field_expression) (qualified_identifier) (subscript_expression)
          (call_expression)] @mix.r
  (#match? @mix.l "ANGLE_WORDS") (#match? @mix.r "ANGLE_WORDS")) @mix
[(binary_expression left: (_) @turn.angle operator: ["+" "-"]
   right: (number_literal) @turn.n (#match? @turn.n "TURNS"))
 (binary_expression left: (number_literal) @turn.n operator: ["+" "-"]
   right: (_) @turn.angle (#match? @turn.n "TURNS"))] @turn
(init_declarator declarator: (_) @asg.l value: (_) @asg.r) @asg
(assignment_expression left: (_) @asg.l right: (_) @asg.r) @asg
(field_declaration declarator: (_) @asg.l default_value: (_) @asg.r) @asg
(field_initializer (field_identifier) @fi.name (argument_list) @fi.args) @fi
(preproc_def name: (identifier) @def.name value: (preproc_arg) @def.val)
((string_literal) @str (#match? @str "/dev/"))
(preproc_include path: (_) @inc)
((type_identifier) @type
  (#match? @type "Serial|[Ss]ocket|CAN|[Uu]sb|USB|termios|TCP|UDP|Udp|Tcp|CommClient|^gpsmm$"))
((namespace_identifier) @ns (#any-of? @ns "asio" "serial"))
(function_definition declarator: (_) @fn.decl) @fn
"""

#: Only calls whose function's text holds a name the extractor looks at are captured (the
#: name it takes, ``callee()``, is always part of that text): most calls never leave C.
QUERY = (
    QUERY_TEMPLATE.replace("CALLEES", "|".join(sorted(CALLED)))
    .replace("ANGLE_WORDS", ANGLE_WORDS)
    .replace("TURNS", DEGREE_TURNS)
)

#: Patterns are matched only on nodes at most this deep in the syntax tree.
MAX_QUERY_DEPTH = 400


class Backend:
    """The parser and the compiled query (built once per process)."""

    def __init__(self) -> None:
        import tree_sitter as ts
        import tree_sitter_cpp as tscpp

        self.ts = ts
        self.language = ts.Language(tscpp.language())
        self.parser = ts.Parser(self.language)
        self.query = ts.Query(self.language, QUERY)

    def parse(self, data: bytes, old_tree: Any = None) -> Any:
        if old_tree is not None:
            return self.parser.parse(data, old_tree)
        return self.parser.parse(data)

    def matches(self, tree: Any) -> list[tuple[int, dict[str, list[Any]]]]:
        cursor = self.ts.QueryCursor(self.query)
        # Query time grows with the square of the tree's depth: a generated expression of
        # thousands of terms would take minutes. Real code never nests this deep.
        cursor.set_max_start_depth(MAX_QUERY_DEPTH)
        return cursor.matches(tree.root_node)


@lru_cache(maxsize=1)
def backend() -> Backend:
    return Backend()
