"""Rule pages: rendered from each rule module's docstring.

``python scripts/docs.py rules`` writes one Markdown page per rule into the
``rules/`` folder; ``--check`` exits 1 when a page is stale or missing.
"""

from __future__ import annotations

import sys
from pathlib import Path

from moos_lint.commands.rule_page import render_rule_page
from moos_lint.core.registry import Rule, all_rules


def page_path(folder: Path, r: Rule) -> Path:
    return folder / f"{r.name}.md"


def index_page() -> str:
    lines = [
        "# moos-lint rules",
        "",
        "| Code | Name | Severity | Default | Summary |",
        "|---|---|---|---|---|",
    ]
    for r in all_rules():
        on = "on" if r.default_enabled else "off"
        lines.append(
            f"| {r.code} | [{r.name}]({r.name}.md) | {r.severity.value} | {on} | {r.summary} |"
        )
    return "\n".join(lines) + "\n"


README_START, README_END = "<!-- rules:start -->", "<!-- rules:end -->"


def readme_table() -> str:
    lines = ["| Code | Name | Default | Summary |", "|---|---|---|---|"]
    for r in all_rules():
        on = "on" if r.default_enabled else "off"
        lines.append(f"| {r.code} | [`{r.name}`](rules/{r.name}.md) | {on} | {r.summary} |")
    return "\n".join(lines)


def readme_with_table(text: str) -> str:
    """The README text with its rule table brought up to date."""
    start, end = text.find(README_START), text.find(README_END)
    if start < 0 or end < start:
        return text
    return text[: start + len(README_START)] + "\n" + readme_table() + "\n" + text[end:]


def expected_pages(folder: Path) -> dict[Path, str]:
    pages = {page_path(folder, r): render_rule_page(r) for r in all_rules()}
    pages[folder / "README.md"] = index_page()
    return pages


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    check = "--check" in argv
    folders = [a for a in argv if not a.startswith("--")]
    folder = Path(folders[0] if folders else "rules")
    stale = []
    for path, text in expected_pages(folder).items():
        current = path.read_text(encoding="utf-8") if path.exists() else None
        if current != text:
            stale.append(path)
            if not check:
                folder.mkdir(parents=True, exist_ok=True)
                path.write_text(text, encoding="utf-8")
    readme = folder.parent / "README.md"
    if readme.exists():
        current = readme.read_text(encoding="utf-8")
        wanted = readme_with_table(current)
        if current != wanted:
            stale.append(readme)
            if not check:
                readme.write_text(wanted, encoding="utf-8")
    known = set(expected_pages(folder))
    extra = [p for p in folder.glob("*.md") if p not in known] if folder.exists() else []
    if check:
        for p in stale:
            print(f"stale or missing: {p}")
        for p in extra:
            print(f"page for no rule: {p}")
        return 1 if stale or extra else 0
    for p in extra:
        p.unlink()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
