"""A rule's documentation page, rendered from its module docstring.

``moos-lint rule NAME`` prints it, the language server shows it on hover, and
the docs generator writes it into the ``rules/`` folder.
"""

from __future__ import annotations

from moos_lint.core.registry import DOC_SECTIONS, Rule, doc_sections


def missing_sections(r: Rule) -> list[str]:
    sections = doc_sections(r.doc)
    return [s for s in DOC_SECTIONS if not sections.get(s)]


def render_rule_page(r: Rule) -> str:
    sections = doc_sections(r.doc)
    lines = [
        f"# {r.code} {r.name}",
        "",
        sections.get("summary", r.name),
        "",
        "| | |",
        "|---|---|",
        f"| Code | `{r.code}` |",
        f"| Name | `{r.name}` |",
        f"| Default severity | {r.severity.value} |",
        f"| Enabled by default | {'yes' if r.default_enabled else 'no'} |",
        f"| Scope | {r.scope.value} |",
        f"| Files | {', '.join('.' + k.value for k in r.kinds)} |",
        f"| Autofix | {'yes' if r.fixable else 'no'} |",
        "",
    ]
    for title in DOC_SECTIONS:
        lines += [f"## {title}", "", sections.get(title, "").strip() or "None.", ""]
    return "\n".join(lines).rstrip() + "\n"


__all__ = ["missing_sections", "render_rule_page"]
