"""nsplug preprocessing, as nsplug does it, with a source map.

nsplug (MOOS-IvP's mission preprocessor) handles ``#include``, ``#define``,
``#ifdef``/``#ifndef``/``#elseifdef``/``#else``/``#endif`` and ``$(NAME)`` /
``%(NAME)`` macros. This module reproduces it in two modes:

``lint``
    What the linter uses. A macro that is neither ``#define``-d in the files nor
    given by the user is *unknown* (the launch script usually sets it): ``$(X)``
    stays in the text, and a condition that depends on it is unknown, so every
    branch of that ``#ifdef`` is kept. Each kept line records the branches it
    sits in, so that two lines in mutually exclusive branches never conflict.

``nsplug``
    What ``moos-lint expand`` prints: an undefined macro is undefined, exactly
    one branch is taken, and a line with a macro left over is left unexpanded
    (as nsplug does without ``--lenient``).

Every output :class:`Line` maps back to its file and line, with the chain of
``#include`` lines that led to it. Problems (a missing include, an include
loop, an unknown directive, ...) are recorded as :class:`Problem` facts; the
rules decide what to report.
"""

from __future__ import annotations

import difflib
import itertools
import os
import re
import threading
from collections import OrderedDict
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from moos_lint.files.diagnostics import IncludeSite, Span
from moos_lint.files.nsplug_calls import DEFINED
from moos_lint.files.source import ReadProblem, SourceFile, read_source
from moos_lint.files.stamps import folder_mtime

DIRECTIVES = ("#ifdef", "#ifndef", "#elseifdef", "#else", "#endif", "#include", "#define")
#: directives of the C preprocessor that nsplug does not have: a file that uses them was
#: written for ``cpp`` (MOOS-IvP's behavior templates of 2011 and before were expanded with
#: it), not for nsplug, and only cpp's output reaches the helm
CPP_ONLY_DIRECTIVES = frozenset({"warning", "error", "pragma", "undef"})


def written_for_cpp(lines: Iterable[str]) -> bool:
    """Whether a file's lines use a directive only the C preprocessor knows
    (``#warning``, ``#error``, ``#pragma``, ``#undef``)."""
    for text in lines:
        if "#" in text:
            m = _DIRECTIVE_LIKE.match(text)
            if m is not None and m.group(2).lower() in CPP_ONLY_DIRECTIVES:
                return True
    return False


#: A macro whose value depends on the branch taken: its value is unknown.
UNKNOWN = object()
#: Real missions nest includes a few levels deep. Each linted file expands its
#: whole include tree, so a deeper chain costs every file above it time and memory.
MAX_INCLUDE_DEPTH = 100
MAX_SUBS_PER_LINE = 100
#: The budget of one file's expansion: the lines read (every included copy counted) and
#: the characters its macros expand to. An include bomb (a file included many times at
#: many levels) or a macro that doubles at each level stops there, with a finding at
#: the line that ran over, instead of growing without bound.
MAX_EXPANDED_LINES = 400_000
MAX_MACRO_CHARS = 16 * 2**20
MAX_LINE_CHARS = 2**20
#: ``#ifdef`` group numbers, unique in the process (expansions may be kept across runs)
_GROUPS = itertools.count(1)

_MACRO_DEFAULT = re.compile(r"([$%])\(([^()=:$%]+?)(:?=)([^()]*)\)")
_MACRO_REF = re.compile(r"[$%]\(([^()]*)\)")


def _has_tag(src: SourceFile, tag: str) -> bool:
    """Whether the file has a ``<tag><tag>`` section."""
    return any("<tag>" in ln and tag_of(ln) == tag for ln in src.lines)


def tag_of(raw: str) -> str | None:
    """The section a ``<tag>`` line opens (``<tag><iM300>`` and ``<tag> iM300`` alike), or
    None for any other line. nsplug reads every line that starts with ``<tag>`` so, and
    never writes it out (Expander.cpp ``strBegins(line_orig, "<tag>")``, then
    ``stripChevrons``)."""
    text = raw.strip()
    if not text.startswith("<tag>"):
        return None
    tag = text[5:].strip()
    if len(tag) >= 2 and tag[0] == "<" and tag[-1] == ">":
        tag = tag[1:-1]
    return tag


_INCLUDE_TAG = re.compile(r"^(.*?)\s*<([^<>]+)>\s*$")
_DIRECTIVE_LIKE = re.compile(r"^\s*(#+\s*)([A-Za-z]+)")


@dataclass(slots=True)
class Line:
    """One line of preprocessed text, mapped back to where it was written."""

    text: str  # after macro expansion
    raw: str  # as written in the file
    path: str
    lineno: int
    chain: tuple[IncludeSite, ...] = ()
    branches: tuple[tuple[int, int], ...] = ()
    #: what the conditions around the line say about macros whose value is not known:
    #: ``(name, version, "def" | "undef" | "eq" | "ne", value)`` (see :func:`branch_facts`)
    facts: frozenset[tuple[str, int, str, str]] = frozenset()

    def span(self, start: int = 0, end: int | None = None) -> Span:
        """The span of ``text[start:end]``, mapped to the written line."""
        if end is None:
            end = len(self.text.rstrip())
            if start == 0:
                start = len(self.text) - len(self.text.lstrip())
        if self.text == self.raw:
            return Span(self.path, self.lineno, start + 1, self.lineno, end + 1)
        piece = self.text[start:end].strip()
        idx = self.raw.find(piece) if piece else -1
        if idx >= 0:
            return Span(self.path, self.lineno, idx + 1, self.lineno, idx + len(piece) + 1)
        return Span(self.path, self.lineno, 1, self.lineno, len(self.raw) + 1)

    def excludes(self, other: Line) -> bool:
        """True when the two lines sit in different branches of one ``#ifdef``."""
        if not self.branches or not other.branches:
            return False
        mine = dict(self.branches)
        if any(g in mine and mine[g] != b for g, b in other.branches):
            return True
        return contradict(self.facts, other.facts)


def contradict(a: frozenset, b: frozenset) -> bool:
    """True when no macro values make both sets of facts hold (a macro cannot be
    both defined and undefined, nor hold two values)."""
    if not a or not b:
        return False
    index: dict[tuple[str, int], list[tuple[str, str]]] = {}
    for name, version, kind, value in a:
        index.setdefault((name, version), []).append((kind, value))
    for name, version, kind, value in b:
        for k2, v2 in index.get((name, version), ()):
            pair = {kind, k2}
            if pair == {"def", "undef"} or pair == {"eq", "undef"}:
                return True
            if kind == k2 == "eq" and value != v2:
                return True
            if pair == {"eq", "ne"} and value == v2:
                return True
    return False


@dataclass(slots=True)
class Problem:
    """Something nsplug gets wrong, rejects or silently lets through."""

    kind: str
    span: Span
    message: str
    chain: tuple[IncludeSite, ...] = ()


@dataclass(slots=True)
class Expansion:
    """The result of preprocessing one top-level file."""

    path: str
    lines: list[Line] = field(default_factory=list)
    problems: list[Problem] = field(default_factory=list)
    sources: dict[str, SourceFile] = field(default_factory=dict)
    #: an include could not be followed (unresolved macro in its path, or missing)
    incomplete: bool = False
    read_problem: ReadProblem | None = None
    #: the condition of each ``#ifdef`` branch, by ``(group, branch)`` as in ``Line.branches``:
    #: ``"ifdef A v"``, ``"ifndef A"`` or ``"else"``
    conditions: dict[tuple[int, int], str] = field(default_factory=dict)
    #: the facts each branch holds about macros of unknown value (see ``Line.facts``)
    facts: dict[tuple[int, int], frozenset] = field(default_factory=dict, repr=False)
    #: the branches whose condition could not be decided (a macro of unknown value)
    undecided: set[tuple[int, int]] = field(default_factory=set, repr=False)
    #: how many times each macro was ``#define``d so far: facts hold per version
    define_counts: dict[str, int] = field(default_factory=dict, repr=False)
    facts_memo: dict[tuple, frozenset] = field(default_factory=dict, repr=False, compare=False)
    #: the models parsed from this expansion, by parser name (see :func:`parsed`)
    models: dict[str, Any] = field(default_factory=dict, repr=False, compare=False)


def _line_facts(exp: Expansion, branches: tuple[tuple[int, int], ...]) -> frozenset:
    """The facts of every branch a line sits in (memoised per branch path)."""
    memo = exp.facts_memo
    found = memo.get(branches)
    if found is None:
        found = frozenset().union(*(exp.facts.get(b, frozenset()) for b in branches))
        memo[branches] = found
    return found


def derived(exp: Expansion, key: str, compute: Callable[[], Any]) -> Any:
    """``compute()``, once per expansion and ``key``: what is read from a file's lines
    (its model, its variables, ...) is only read once built."""
    value = exp.models.get(key)
    if value is None:
        value = exp.models[key] = compute()
    return value


def parsed(exp: Expansion, parse: Callable[[Expansion], Any]) -> Any:
    """``parse(exp)``, once per expansion."""
    return derived(exp, parse.__name__, lambda: parse(exp))


@dataclass(slots=True)
class _Frame:
    kind: str  # "ifdef" | "ifndef"
    group: int
    branch: int
    state: str  # "T" | "F" | "U": the current branch's truth
    matched: bool  # an earlier branch was certainly taken
    line: Line
    seen_else: bool = False
    any_unknown: bool = False  # some branch so far was unknown
    #: the negations of the earlier branches' conditions (facts every later branch holds)
    negated: frozenset = frozenset()


@dataclass(slots=True)
class _Work:
    """A file being expanded, on the include stack."""

    src: SourceFile
    tag: str | None
    chain: tuple[IncludeSite, ...]
    outer: tuple[tuple[int, int], ...]
    uncertain: bool
    idx: int = 0
    in_tag: bool = False
    frames: list[_Frame] = field(default_factory=list)
    # Kept up to date at each conditional, so that a line costs O(1) however deep the
    # nesting: the branches of the current lines, and how many frames are false/unknown.
    branches: tuple[tuple[int, int], ...] = ()
    n_false: int = 0
    n_unknown: int = 0
    path: str = ""
    lines: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.branches = self.outer
        self.path = str(self.src.path)
        self.lines = self.src.lines

    def count(self, state: str | None, delta: int) -> None:
        if state == "F":
            self.n_false += delta
        elif state == "U":
            self.n_unknown += delta

    def frames_changed(self, depth_before: int, top_state_before: str | None) -> None:
        """Update the cached state after a conditional pushed, popped or moved a frame."""
        frames = self.frames
        if len(frames) < depth_before:  # #endif
            self.count(top_state_before, -1)
            self.branches = self.branches[:-1]
        elif len(frames) > depth_before:  # #ifdef / #ifndef
            top = frames[-1]
            self.count(top.state, 1)
            self.branches = (*self.branches, (top.group, top.branch))
        elif frames:  # #else / #elseifdef
            top = frames[-1]
            self.count(top_state_before, -1)
            self.count(top.state, 1)
            self.branches = (*self.branches[:-1], (top.group, top.branch))


class ExpansionStore:
    """Expansions kept from one lint run to the next (the language server re-lints one
    document at a time while its neighbours stay as they were).

    A stored expansion is reused while every file it read reads the same text
    and no folder it read from (nor an include path) has had a file added or
    removed; an expansion that could not follow an include is never stored.
    """

    def __init__(self, size: int = 256) -> None:
        self.size = size
        self._lock = threading.Lock()
        self._entries: OrderedDict[tuple, tuple[Expansion, dict[str, str], dict]] = OrderedDict()

    @staticmethod
    def _key(pre: Preprocessor, path: str) -> tuple:
        defines = tuple(sorted(pre.defines.items()))
        return (path, pre.mode, pre.lenient, defines, tuple(pre.include_paths))

    def get(self, pre: Preprocessor, path: str) -> Expansion | None:
        with self._lock:
            return self._get(pre, path)

    def _get(self, pre: Preprocessor, path: str) -> Expansion | None:
        key = self._key(pre, path)
        hit = self._entries.get(key)
        if hit is None:
            return None
        exp, texts, folders = hit
        for src, text in texts.items():
            now = pre.cache.get(src)
            if not isinstance(now, SourceFile) or now.text != text:
                return None
        if any(folder_mtime(d) != m for d, m in folders.items()):
            return None
        self._entries.move_to_end(key)
        return exp

    def put(self, pre: Preprocessor, path: str, exp: Expansion) -> None:
        if exp.read_problem is not None or exp.incomplete:
            return
        texts = {src: sf.text for src, sf in exp.sources.items()}
        read_from = {os.path.dirname(p) for p in texts} | {*pre.include_paths}
        folders = {d: folder_mtime(d) for d in read_from}
        if any(m is None for m in folders.values()):
            return
        with self._lock:
            self._entries[self._key(pre, path)] = (exp, texts, folders)
            while len(self._entries) > self.size:
                self._entries.popitem(last=False)


class FileCache:
    """Reads each file at most once per run."""

    def __init__(
        self,
        reader: Callable[[Path], SourceFile | ReadProblem] = read_source,
        store: ExpansionStore | None = None,
    ):
        self._reader = reader
        #: expansions kept across runs (None: every run expands afresh)
        self.store = store
        self._cache: dict[str, SourceFile | ReadProblem] = {}
        #: the folders searched for an ``#include`` (a file created there changes the result)
        self.probed: set[str] = set()
        #: files read for this run by worker processes
        self.read_elsewhere: set[str] = set()

    def get(self, path: str) -> SourceFile | ReadProblem:
        hit = self._cache.get(path)
        if hit is None:
            hit = self._reader(Path(path))
            self._cache[path] = hit
        return hit

    def paths(self) -> set[str]:
        """Every file this cache was asked for (read or not), here or in worker processes."""
        return {*self._cache, *self.read_elsewhere}

    def in_memory(self, path: str) -> SourceFile | ReadProblem | None:
        """The text of ``path`` when the reader holds it in memory (a file being fixed),
        which differs from the file on disk; None for a file read from disk."""
        held = getattr(self._reader, "in_memory", None)
        return held(Path(path)) if held is not None else None


def _case_twin(name: str, folders: Sequence[str]) -> str | None:
    """The file name, as it is written on disk, that ``name`` names in one of ``folders``
    but for its case (``plug_V1_x.moos`` for ``plug_v1_x.moos``); None if none."""
    if os.path.isabs(name):
        folders, name = (os.path.dirname(name),), os.path.basename(name)
    head, base = os.path.split(name)
    for folder in folders:
        where = os.path.join(folder, head)
        try:
            entries = os.listdir(where)
        except OSError:
            continue
        for entry in entries:
            if entry != base and entry.lower() == base.lower():
                return os.path.join(head, entry) if head else entry
    return None


def _elsewhere(target: str, top_dir: str) -> bool:
    """Whether a missing include is an absolute path outside the mission's folder: a file
    of the machine the mission runs on (``/home/student/VehicleConfig/plug_iGPS.moos`` on a
    vehicle's computer), which this machine need not have."""
    if not os.path.isabs(target):
        return False
    top = _norm(top_dir)
    try:
        return os.path.commonpath([top, _norm(target)]) != top
    except ValueError:  # another drive
        return True


def _norm(path: str | Path) -> str:
    return os.path.normpath(os.path.abspath(path))


class Preprocessor:
    """Expands a file with nsplug's semantics. One instance may expand many files."""

    def __init__(
        self,
        defines: dict[str, str] | None = None,
        include_paths: Sequence[str | Path] | None = None,
        mode: str = "lint",
        cache: FileCache | None = None,
    ) -> None:
        if mode not in ("lint", "nsplug"):
            raise ValueError(f"unknown mode {mode!r}")
        self.defines = dict(defines or {})
        self.include_paths = [_norm(p) for p in include_paths or []]
        self.mode = mode
        self.lenient = False  # nsplug --lenient: partial expansion in nsplug mode
        self.cache = cache or FileCache()
        self._groups = _GROUPS
        #: when a dict, ``expand(path)`` (default macros) is computed once per path and shared:
        #: a lint run expands a behavior file or a sibling mission for each mission that uses it
        self.memo: dict[str, Expansion] | None = None

    # ------------------------------------------------------------------ macros
    def expand_macros(self, text: str, macros: dict) -> str:
        """Apply macros to one line, as ``applyMacrosToLine`` does."""
        if "(" not in text:
            return text
        original = text
        subs = 0
        while subs <= MAX_SUBS_PER_LINE:
            changed = False
            for ref in _MACRO_REF.finditer(text):
                name = ref.group(1)
                value = macros.get(name)
                if value is None or value is UNKNOWN:
                    continue
                value = "" if value == DEFINED else value
                if ref.group(0)[0] == "%":
                    value = value.upper()
                text = text[: ref.start()] + value + text[ref.end() :]
                changed = True
                subs += 1
                break
            if not changed or len(text) > MAX_LINE_CHARS:
                break
        text = _MACRO_DEFAULT.sub(lambda m: self._default(m, macros), text)
        if self.mode == "nsplug" and not self.lenient and ("$(" in text or "%(" in text):
            return original
        return text

    def _default(self, m: re.Match, macros: dict) -> str:
        sigil, name, op, default = m.groups()
        value = macros.get(name)
        if value is UNKNOWN:
            return m.group(0)
        if value is None or (op == ":=" and value in ("", DEFINED)):
            value = default
        value = "" if value == DEFINED else value
        return value.upper() if sigil == "%" else value

    # -------------------------------------------------------------- conditions
    def _value_state(self, name: str, macros: dict) -> object:
        """The macro's value, ``None`` when undefined, UNKNOWN when unknown."""
        if name in macros:
            return macros[name]
        return UNKNOWN if self.mode == "lint" else None

    def _eval_term(self, term: str, macros: dict, conj: bool) -> str:
        term = term.strip()
        name, _, want = term.partition(" ")
        want = want.strip()
        value = self._value_state(name, macros)
        if value is UNKNOWN:
            return "U"
        if not want:
            if conj:
                return "T" if value is not None else "F"
            return "T" if value not in (None, "") else "F"
        # nsplug reads ``macros[name]`` from a copy of its map: an undefined name reads
        # as "". A value test holds when the value equals the word, or the value of the
        # macro the word names (so an empty value matches a word naming no macro); in an
        # ``||`` list the name must also be defined.
        if value is None and not conj:
            return "F"
        value = "" if value is None else value
        if value == want:
            return "T"
        other = macros.get(want)
        if other is UNKNOWN:
            return "U"
        return "T" if value == ("" if other is None else other) else "F"

    def eval_ifdef(self, rest: str, macros: dict) -> str:
        disj, conj = "||" in rest, "&&" in rest
        if disj and conj:
            return "F"
        if conj:
            states = [self._eval_term(t, macros, True) for t in rest.split("&&")]
            if "F" in states:
                return "F"
            return "T" if all(s == "T" for s in states) else "U"
        states = [self._eval_term(t, macros, False) for t in rest.split("||")]
        if "T" in states:
            return "T"
        return "F" if all(s == "F" for s in states) else "U"

    def eval_ifndef(self, rest: str, macros: dict) -> str:
        states = []
        for name in rest.split():
            value = self._value_state(name, macros)
            if value is UNKNOWN:
                states.append("U")
            else:
                states.append("T" if value in (None, "") else "F")
        if "F" in states:
            return "F"
        return "T" if all(s == "T" for s in states) else "U"

    # ---------------------------------------------------------------- includes
    def resolve_include(self, name: str, top_dir: str, including_dir: str) -> str | None:
        """nsplug's search: its working folder, then ``--path`` folders, then the includer's."""
        if os.path.isabs(name):
            self.cache.probed.add(os.path.dirname(_norm(name)))
            return _norm(name) if os.path.exists(name) else None
        for folder in (top_dir, *self.include_paths, including_dir):
            candidate = os.path.join(folder, name)
            self.cache.probed.add(os.path.dirname(_norm(candidate)))
            if os.path.exists(candidate):
                return _norm(candidate)
        if self.mode != "lint":
            return None
        # the --path folders the mission's launch scripts give nsplug, and the folder a
        # script above runs nsplug in on this template (read only when all else fails)
        from moos_lint.files.launch import nsplug_working_folders, script_include_paths

        for folder in (*script_include_paths(top_dir), *nsplug_working_folders(top_dir)):
            candidate = os.path.join(folder, name)
            self.cache.probed.add(os.path.dirname(_norm(candidate)))
            if os.path.exists(candidate):
                return _norm(candidate)
        return None

    def _made_at_launch(self, target: str, top_dir: str) -> bool:
        """Whether a launch script beside the top-level file writes the missing include
        before nsplug runs (``cat > plug_pShare.moos <<EOF``) or a clean script deletes it,
        or the repository's ``.gitignore`` keeps it out (``plug_UUV*``: a build step, in
        any language, writes it): a file the launch makes, absent at rest."""
        if self.mode != "lint" or os.path.isabs(target):
            return False
        from moos_lint.files.gitignore import ignored_file
        from moos_lint.files.launch import made_by_scripts
        from moos_lint.files.project import is_within, vcs_top

        if "/" not in target.replace("\\", "/") and target in made_by_scripts(top_dir):
            return True
        top = vcs_top(top_dir)
        path = os.path.normpath(os.path.join(top_dir, target))
        return top is not None and is_within(path, top) and ignored_file(path, top)

    # ------------------------------------------------------------------ expand
    def expand(self, path: str | Path, macros: dict | None = None) -> Expansion:
        path = _norm(path)
        if macros is None and self.memo is not None:
            hit = self.memo.get(path)
            if hit is None:
                store = self.cache.store
                hit = store.get(self, path) if store is not None else None
                if hit is None:
                    hit = self._expand(path, None)
                    if store is not None:
                        store.put(self, path, hit)
                self.memo[path] = hit
            return hit
        return self._expand(path, macros)

    def _expand(self, path: str, macros: dict | None) -> Expansion:
        exp = Expansion(path=path)
        src = self.cache.get(path)
        if isinstance(src, ReadProblem):
            exp.read_problem = src
            return exp
        env: dict = dict(self.defines) if macros is None else macros
        top_dir = os.path.dirname(path)
        self._expand_file(exp, src, env, top_dir, chain=(), tag=None, uncertain=False)
        return exp

    def _expand_file(
        self,
        exp: Expansion,
        src: SourceFile,
        macros: dict,
        top_dir: str,
        chain: tuple[IncludeSite, ...],
        tag: str | None,
        uncertain: bool,
    ) -> None:
        """Expand one file. Includes are followed with an explicit work stack."""
        stack = [_Work(src, tag, chain, (), uncertain)]
        # The files on the include stack, for an include-loop check in O(1).
        active = {site.path for site in chain}
        active.add(str(src.path))
        lines_left = MAX_EXPANDED_LINES
        chars_left = MAX_MACRO_CHARS
        while stack:
            work = stack[-1]
            src = work.src
            path = work.path
            if work.idx == 0:
                exp.sources.setdefault(path, src)
            lines = work.lines
            if work.idx >= len(lines):
                self._close_file(exp, work.frames)
                stack.pop()
                active.discard(path)
                continue
            raw = lines[work.idx]
            work.idx += 1
            here = Line(raw, raw, path, work.idx, work.chain)
            frames = work.frames
            lines_left -= 1
            if lines_left < 0:
                self._over_budget(exp, here, f"more than {MAX_EXPANDED_LINES:,} lines")
                return

            opened = tag_of(raw) if "<tag>" in raw else None
            if opened is not None:  # <tag> lines are never written out
                work.in_tag = opened == work.tag
                continue
            if work.tag is not None:
                # Inside a tagged section nsplug skips lines starting with '#'.
                if work.in_tag and not raw.lstrip().startswith("#"):
                    exp.lines.append(self._out_line(exp, here, macros, frames, work.outer))
                    chars_left -= len(here.text)
                    if chars_left < 0 or len(here.text) > MAX_LINE_CHARS:
                        self._over_budget(exp, here, "macros that grow without bound")
                        return
                continue

            if not raw.lstrip().startswith("#"):  # not a directive: the common line
                if not work.n_false:  # (``_out_line``, inlined: most lines come here)
                    if "(" in raw:
                        here.text = self.expand_macros(raw, macros)
                        chars_left -= len(here.text)
                        if chars_left < 0 or len(here.text) > MAX_LINE_CHARS:
                            self._over_budget(exp, here, "macros that grow without bound")
                            return
                    here.branches = work.branches
                    if work.branches:
                        here.facts = _line_facts(exp, work.branches)
                    exp.lines.append(here)
                continue
            squeezed = raw.replace("\t", " ").strip()
            left, _, rest = squeezed.partition(" ")
            rest = rest.strip()

            if left in ("#ifdef", "#ifndef", "#elseifdef", "#else", "#endif"):
                before = len(frames), (frames[-1].state if frames else None)
                self._conditional(exp, here, left, rest, frames, macros)
                work.frames_changed(*before)
                continue
            if work.n_false:  # inside a branch that is not taken
                continue
            branch_uncertain = work.uncertain or work.n_unknown > 0
            branches = work.branches
            if left == "#define":
                self._define(exp, here, rest, macros, branch_uncertain)
                continue
            if left == "#include":
                child = self._include(exp, here, rest, macros, top_dir, active)
                if child is not None:
                    csrc, ctag = child
                    cchain = (*work.chain, IncludeSite(path, here.lineno))
                    if len(cchain) > MAX_INCLUDE_DEPTH:
                        self._problem(
                            exp,
                            "include-cycle",
                            here,
                            f"includes are nested more than {MAX_INCLUDE_DEPTH} deep",
                        )
                        continue
                    stack.append(_Work(csrc, ctag, cchain, branches, branch_uncertain))
                    active.add(str(csrc.path))
                continue
            self._unknown_directive(exp, here)  # a line starting with '#', not a directive
            exp.lines.append(self._out_line(exp, here, macros, frames, work.outer, branches))
            chars_left -= len(here.text)
            if chars_left < 0 or len(here.text) > MAX_LINE_CHARS:
                self._over_budget(exp, here, "macros that grow without bound")
                return

    def _over_budget(self, exp: Expansion, here: Line, what: str) -> None:
        """Stop expanding a file that grows past its budget (see MAX_EXPANDED_LINES)."""
        exp.incomplete = True
        self._problem(
            exp,
            "include-cycle",
            here,
            f"this file's includes and macros expand to {what}: moos-lint stops reading "
            "it here (nsplug would take as long, or run out of memory)",
        )

    def _conditional(
        self,
        exp: Expansion,
        here: Line,
        left: str,
        rest: str,
        frames: list[_Frame],
        macros: dict,
    ) -> None:
        if left in ("#ifdef", "#ifndef"):
            if not rest:
                self._problem(exp, "malformed-directive", here, f"`{left}` needs a macro name")
            self._check_condition(exp, here, left, rest)
            if left == "#ifdef":
                state = self.eval_ifdef(rest, macros)
            else:
                state = self.eval_ifndef(rest, macros)
            frame = _Frame(left[1:], next(self._groups), 0, state, state == "T", here)
            frame.any_unknown = state == "U"
            if state == "U":
                exp.undecided.add((frame.group, 0))
            frames.append(frame)
            exp.conditions[(frame.group, 0)] = f"{left[1:]} {rest}"
            pos, neg = self._facts(left[1:], rest, macros, exp)
            exp.facts[(frame.group, 0)] = pos
            frame.negated = neg
            return
        if not frames:
            what = "`#endif` without an open `#ifdef` or `#ifndef`"
            if left != "#endif":
                what = f"`{left}` without an open `#ifdef`"
            self._problem(exp, "unbalanced-conditional", here, what + ": nsplug stops here")
            return
        top = frames[-1]
        if left == "#endif":
            frames.pop()
            return
        if top.seen_else:
            self._problem(exp, "unbalanced-conditional", here, f"`{left}` after `#else`")
        if left == "#elseifdef":
            if top.kind == "ifndef":
                self._problem(
                    exp,
                    "unbalanced-conditional",
                    here,
                    "`#elseifdef` after `#ifndef`: nsplug stops with 'Dangling #elseifdef'",
                )
            self._check_condition(exp, here, left, rest)
            top.branch += 1
            exp.conditions[(top.group, top.branch)] = f"ifdef {rest}"
            pos, neg = self._facts("ifdef", rest, macros, exp)
            exp.facts[(top.group, top.branch)] = pos | top.negated
            top.negated = top.negated | neg
            if top.matched:
                top.state = "F"
            else:
                top.state = self.eval_ifdef(rest, macros)
                top.matched = top.state == "T"
                top.any_unknown = top.any_unknown or top.state == "U"
            if top.state != "F" and top.any_unknown:  # this branch, or one before, may hold
                exp.undecided.add((top.group, top.branch))
            return
        # #else
        top.seen_else = True
        top.branch += 1
        exp.conditions[(top.group, top.branch)] = "else"
        exp.facts[(top.group, top.branch)] = top.negated
        if top.matched:
            top.state = "F"
        elif top.any_unknown:
            top.state = "U"
            exp.undecided.add((top.group, top.branch))
        else:
            top.state = "T"
            top.matched = True

    def _facts(
        self, kind: str, rest: str, macros: dict, exp: Expansion
    ) -> tuple[frozenset, frozenset]:
        """What a condition says about macros of unknown value, and what its negation says.

        Only conditions that pin each name down give facts: ``#ifdef A``, ``#ifdef A v``
        and ``#ifndef A B``; an ``||`` or ``&&`` list gives none (the negation of an
        ``||`` list of names excepted), nor does a value that is itself the name of a
        known macro (nsplug compares with its value). A macro set to the empty string
        passes every value test whose word names no macro; launch scripts give the
        macros they test a value, so ``#ifdef VNAME abe`` and ``#ifdef VNAME ben``
        count as exclusive.
        """
        rest = rest.strip()
        if not rest or "//" in rest or ("||" in rest and "&&" in rest):
            return frozenset(), frozenset()
        counts = exp.define_counts

        def unknown(name: str) -> bool:
            return self._value_state(name, macros) is UNKNOWN

        pos: set = set()
        neg: set = set()
        if kind == "ifndef":
            names = rest.split()
            if all(unknown(n) for n in names):
                pos = {(n, counts.get(n, 0), "undef", "") for n in names}
                if len(names) == 1:
                    neg = {(names[0], counts.get(names[0], 0), "def", "")}
            return frozenset(pos), frozenset(neg)
        if "||" in rest:
            terms = [t.strip() for t in rest.split("||")]
            if all(" " not in t for t in terms) and all(unknown(t) for t in terms):
                # not (A or B): every name is undefined or empty
                neg = {(t, counts.get(t, 0), "undef", "") for t in terms}
            return frozenset(), frozenset(neg)
        if "&&" in rest:
            # in an ``&&`` list an undefined name reads as "" and may pass a value test
            return frozenset(), frozenset()
        name, _, want = rest.partition(" ")
        want = " ".join(want.split())
        if not unknown(name) or (want and want in macros):
            return frozenset(), frozenset()
        version = counts.get(name, 0)
        if want:
            return frozenset({(name, version, "eq", want)}), frozenset(
                {(name, version, "ne", want)}
            )
        return frozenset({(name, version, "def", "")}), frozenset({(name, version, "undef", "")})
        return frozenset(pos), frozenset(neg)

    # ---------------------------------------------------------------- helpers
    @staticmethod
    def _active(frames: list[_Frame]) -> bool:
        return all(f.state != "F" for f in frames)

    @staticmethod
    def _branches(frames: list[_Frame], outer: tuple) -> tuple[tuple[int, int], ...]:
        return (*outer, *((f.group, f.branch) for f in frames))

    def _out_line(
        self,
        exp: Expansion,
        here: Line,
        macros: dict,
        frames: list[_Frame],
        outer: tuple,
        branches: tuple[tuple[int, int], ...] | None = None,
    ) -> Line:
        here.text = self.expand_macros(here.raw, macros)
        here.branches = self._branches(frames, outer) if branches is None else branches
        if here.branches:
            here.facts = _line_facts(exp, here.branches)
        return here

    @staticmethod
    def _problem(exp: Expansion, kind: str, line: Line, message: str) -> None:
        exp.problems.append(Problem(kind, line.span(), message, line.chain))

    def _check_condition(self, exp: Expansion, here: Line, left: str, rest: str) -> None:
        if "//" in rest:
            self._problem(
                exp,
                "comment-in-condition",
                here,
                f"`{left}` reads the `//` comment as part of its condition: `{rest}`",
            )
        if left != "#ifndef" and "||" in rest and "&&" in rest:
            self._problem(
                exp,
                "mixed-and-or",
                here,
                f"`{left}` mixes `||` and `&&`: nsplug evaluates it as false",
            )

    def _define(self, exp: Expansion, here: Line, rest: str, macros: dict, uncertain: bool):
        rest = " ".join(rest.split())
        name, _, value = rest.partition(" ")
        if len(name) > 3 and name.startswith("$(") and name.endswith(")"):
            name = name[2:-1]
        if not name:
            self._problem(exp, "malformed-directive", here, "`#define` needs a macro name")
            return
        exp.define_counts[name] = exp.define_counts.get(name, 0) + 1
        macros[name] = UNKNOWN if uncertain else (value or DEFINED)

    def _include(
        self,
        exp: Expansion,
        here: Line,
        rest: str,
        macros: dict,
        top_dir: str,
        active: set[str],
    ) -> tuple[SourceFile, str | None] | None:
        target = self.expand_macros(rest, macros).strip()
        tag = None
        m = _INCLUDE_TAG.match(target)
        if m:
            target, tag = m.group(1).strip(), m.group(2).strip()
        if len(target) >= 2 and target[0] == target[-1] and target[0] in "\"'":
            target = target[1:-1]
        if not target:
            self._problem(exp, "malformed-directive", here, "`#include` needs a file name")
            return None
        if "$(" in target or "%(" in target:
            exp.incomplete = True
            return None
        including_dir = os.path.dirname(here.path)
        found = self.resolve_include(target, top_dir, including_dir)
        if found is None:
            exp.incomplete = True
            if self._made_at_launch(target, top_dir) or _elsewhere(target, top_dir):
                return None
            message = f"included file `{target}` not found"
            if "//" in target:
                message += (
                    ": nsplug takes the rest of the line as the path, the `//` comment "
                    "included (put the comment on a line of its own)"
                )
            twin = _case_twin(target, (top_dir, *self.include_paths, including_dir))
            if twin is not None:
                message += (
                    f"; `{twin}` differs from it only in case (found on a case-insensitive "
                    "file system such as macOS's, not on Linux)"
                )
            self._problem(exp, "include-not-found", here, message)
            return None
        if found == here.path or found in active:
            self._problem(
                exp,
                "include-cycle",
                here,
                f"`{target}` includes itself through this line (nsplug crashes on include loops)",
            )
            return None
        src = self.cache.get(found)
        if isinstance(src, ReadProblem):
            exp.incomplete = True
            self._problem(exp, "include-not-found", here, f"included file `{target}` {src.message}")
            return None
        if tag is not None and not _has_tag(src, tag):
            own = self.cache.get(exp.path) if here.path == exp.path else None
            if isinstance(own, SourceFile) and _has_tag(own, tag):
                # the top file holds that section itself, and nsplug writes every section
                # of the top file in every mode: the block is there, the include is idle
                return None
            self._problem(
                exp,
                "unknown-include-tag",
                here,
                f"`{target}` has no `<tag><{tag}>` section: nothing is included",
            )
            return None
        return src, tag

    def _unknown_directive(self, exp: Expansion, here: Line) -> bool:
        """Report a line meant as a directive that nsplug does not recognise."""
        m = _DIRECTIVE_LIKE.match(here.raw)
        if m is None:
            return False
        word = m.group(2).lower()
        if word == "elseifndef":
            hint = "nsplug has no `#elseifndef`"
        else:
            known = [d for d in DIRECTIVES if d[1:] == word]
            if not known:
                close = difflib.get_close_matches("#" + word, DIRECTIVES, n=1, cutoff=0.75)
                if not close:
                    return False  # a '#' line, not a directive: the not-a-comment rule's job
                known = close
            hint = f"did you mean `{known[0]}`?"
        self._problem(
            exp,
            "unknown-directive",
            here,
            f"`{m.group(0).strip()}` is not an nsplug directive (nsplug passes the line on "
            f"as text): {hint}",
        )
        return True

    def _close_file(self, exp: Expansion, frames: list[_Frame]) -> None:
        for frame in frames:
            self._problem(
                exp,
                "unclosed-conditional",
                frame.line,
                f"`#{frame.kind}` is never closed by `#endif`: nsplug silently drops "
                "every line after it",
            )
        frames.clear()


def expand_text(exp: Expansion) -> str:
    """The expanded text, one output line per kept line."""
    return "".join(line.text + "\n" for line in exp.lines)
