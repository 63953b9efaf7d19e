"""The mission model: launched processes, their configuration, their interfaces and behaviors.

One :class:`MissionModel` per mission (a ``.moos`` file with an ANTLER block,
after nsplug expansion), built once and cached on the lint run
(:func:`mission_model`). It joins

- the Run lines of the ANTLER block (the launched processes, aliases followed
  to their ProcessConfig block);
- the app catalogue (:mod:`moos_lint.semantics.catalogue`: the linted C++, user
  catalogues, the stock catalogue) for what each app publishes and reads;
- the variables that configuration values name (:mod:`moos_lint.semantics.variables`:
  uTimerScript events, pMarineViewer buttons, pShare routes, ...);
- the behavior files of every launched pHelmIvP.

**Finding the behavior files.** ``behaviors = FILE`` is opened next to the
mission. A name holding an nsplug macro (``targ_$(VNAME).bhv``), or a
``targ_*.bhv`` that does not exist yet, is the output of the launch script:
it runs nsplug on a ``meta_*.bhv`` template beside the mission. The model
then uses the template: ``meta_`` + the rest of the name when that file
exists (``targ_shoreside.bhv`` -> ``meta_shoreside.bhv``), otherwise the only
``meta_*.bhv`` in the folder, or the only ``meta_*vehicle*.bhv``; for a
macro name with one template per vehicle (``meta_gilda.bhv``,
``meta_henry.bhv``), all of them but ``meta_shoreside*``: the model is then
the union of the vehicles, which can only hide findings, not make them.
Otherwise, when the name is a macro pattern, the only existing file the
pattern matches. With no candidate or no way to choose, no behavior file is
used and the model says so (:attr:`MissionModel.unresolved_behaviors`).

**Variables from outside the mission.** A mission that receives variables
from another community (pShare with an ``input`` route, uFldNodeBroker,
uFldShoreBroker, pMOOSBridge), or that launches no MOOSDB (its processes join
the database another mission file launches), may get any variable that the
other missions of its folder publish; the model adds those. It also counts
``VAR=value`` pairs that a ``uPokeDB`` command in a shell script beside the
mission posts.
"""

from __future__ import annotations

import functools
import glob
import os
import re
import threading
from collections import OrderedDict
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Protocol

from moos_lint.files.diagnostics import Span
from moos_lint.files.launch import launch_folders, notes, project_folder, shell_scripts
from moos_lint.frontends.nsplug import Expansion, Line, derived, parsed
from moos_lint.frontends.parsers.bhv import parse_bhv
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.frontends.parsers.nodes import (
    Behavior,
    BehaviorFile,
    Block,
    MoosFile,
    RunLine,
    has_macro,
)
from moos_lint.semantics.catalogue import (
    AppInfo,
    BehaviorInfo,
    Catalogue,
    PublishedKey,
    catalogue_for,
)
from moos_lint.semantics.run_state import RunView
from moos_lint.semantics.variables import (
    PUBLISH,
    SUBSCRIBE,
    VarRef,
    app_of,
    bare_name,
    bhv_variables,
    block_variables,
    flag_variables,
)

#: apps that bring variables in from other MOOS communities
INBOUND_APPS = {"pshare", "ufldnodebroker", "ufldshorebroker", "pmoosbridge", "imoosgateway"}
#: parameters whose value is a logic condition a process waits on
CONDITION_PARAMS = {
    "condition",
    "set-condition",
    "lead_condition",
    "pass_condition",
    "fail_condition",
}
#: the variables whose value is a message uFldMessageHandler posts on the receiving
#: vehicle: ``NODE_MESSAGE_LOCAL = src_node=alpha,dest_node=all,var_name=X,string_val=Y``
#: becomes ``X = Y`` there (MOOS-IvP's lib_ufld NodeMessage; uFldMessageHandler's
#: MessageHandler.cpp ``Notify(var_name, ...)``), relayed by uFldNodeComms
NODE_MESSAGE_VARS = {"NODE_MESSAGE", "NODE_MESSAGE_LOCAL"}
_VAR_NAME = re.compile(r"\bvar_name\s*=\s*([^,\s\"]+)", re.I)
_POKE = re.compile(r"\buPokeDB\b([^\n;|&]*)")
_PAIR = re.compile(r"(?:^|\s)['\"]?([A-Za-z_][A-Za-z0-9_]*)\s*:?=")
_MACRO = re.compile(r"[$%]\([^)]*\)")


@dataclass
class Process:
    """One Run line: the process it starts and what the model knows of it."""

    name: str  # the MOOS name (alias) = the ProcessConfig block it reads
    binary: str  # the program, without folder
    run: RunLine
    block: Block | None = None
    app: AppInfo | None = None


@dataclass(slots=True)
class Publisher:
    """Where a variable comes from (models share them: never changed once made)."""

    var: str
    who: str  # process name, behavior, ``uPokeDB`` or ``<mission> (other community)``
    how: str  # "app" | "config" | "behavior" | "poke" | "external"
    line: Line | None = None
    process: str | None = None  # the launched process, when it is one of the mission's


@dataclass
class MissionModel:
    path: str
    moos: MoosFile
    catalogue: Catalogue
    processes: list[Process] = field(default_factory=list)
    behavior_files: list[tuple[str, BehaviorFile]] = field(default_factory=list)
    unresolved_behaviors: list[str] = field(default_factory=list)
    #: every variable reference of the mission's config and behavior files
    refs: list[VarRef] = field(default_factory=list)
    publishers: dict[str, list[Publisher]] = field(default_factory=dict)
    #: launched processes the catalogue does not know
    unknown_apps: list[Process] = field(default_factory=list)
    #: processes bringing variables in from other communities
    inbound: list[Process] = field(default_factory=list)
    #: the other missions of the folder, whose publications count as inbound
    sibling_missions: list[str] = field(default_factory=list)
    #: the mission launches processes but no MOOSDB: they join the database another
    #: mission file of their community launches (``Community = evader``, a second file
    #: that starts a helm beside the vehicle's own), so what that file's processes post
    #: is theirs
    joins: bool = False
    #: apps whose publications are not all known statically (name -> binary)
    dynamic_apps: list[Process] = field(default_factory=list)
    #: id(VarRef) -> the process whose configuration (or behavior file) holds it
    ref_process: dict[int, str] = field(default_factory=dict)

    # ------------------------------------------------------------ queries
    @property
    def receives(self) -> bool:
        """Whether variables reach the mission from processes other mission files
        launch: through its inbound processes, or by joining another file's database."""
        return bool(self.inbound) or self.joins

    def published_by(self, var: str) -> list[Publisher]:
        """Who publishes ``var`` (exact names, then prefixes and suffixes of dynamic names)."""
        found = self.publishers.get(var)
        return list(found) if found else list(self._dynamic_publishers(var))

    def is_published(self, var: str) -> bool:
        """Whether anything publishes ``var``: :meth:`published_by`, without listing who."""
        if self.publishers.get(var):
            return True
        return next(self._dynamic_publishers(var), None) is not None

    def _dynamic_publishers(self, var: str) -> Iterator[Publisher]:
        """The publishers of ``var`` by the prefixes and suffixes of dynamic names: the
        apps that may publish it, in the order the processes are launched, then the
        wildcard publications that match it."""
        by_app, globs = self._dynamic()
        for i in sorted(i for app, indexed in by_app if app.publishes_var(var) for i in indexed):
            name = self.processes[i].name
            yield Publisher(var, name, "app", process=name)
        for name, pubs in globs:
            if _glob_match(name, var):
                yield from pubs

    def built_from_config(self, var: str) -> Process | None:
        """The launched process that most likely posts ``var`` under a name built from a
        value of its block: pMarinePIDV22's ``output_suffix = _PID`` posts
        ``DESIRED_RUDDER_PID`` (``"DESIRED_RUDDER" + m_output_suffix``), a simulator the
        catalogue does not know with ``PREFIX = NAV`` posts ``NAV_DEPTH``. For an app the
        catalogue knows, the rest of the name must be one it publishes, and the app must
        build names at run time; for an unknown app, the value must be a whole word at
        either end of the name."""
        values, exact = self._config_values()
        if var in exact:
            return exact[var]
        if not values:
            return None
        for i, ch in enumerate(var):
            if ch != "_" or i == 0 or i == len(var) - 1:
                continue
            # the value at the end (`_PID` or `PID`) or at the start (`NAV` or `NAV_`)
            for value, rest in (
                (var[i:], var[:i]),
                (var[i + 1 :], var[:i]),
                (var[:i], var[i + 1 :]),
                (var[: i + 1], var[i + 1 :]),
            ):
                for proc in values.get(value, ()):
                    if proc.app is None or rest in proc.app.publishes:
                        return proc
        return None

    def _config_values(self) -> tuple[dict[str, list[Process]], dict[str, Process]]:
        """The word values of the blocks of the processes that may build names from them
        (unknown apps, and apps that build names at run time), and the names the apps'
        own C++ publishes under a key of their block (``PREFIX = NAV`` of
        ``Notify(m_sim_prefix + "_DEPTH", ...)``: ``NAV_DEPTH``), once per model."""
        kept = self.__dict__.get("_config_values_kept")
        if kept is not None and kept[0] == len(self.processes):
            return kept[1]
        found: dict[str, list[Process]] = {}
        exact: dict[str, Process] = {}
        for proc in self.processes:
            app = proc.app
            if proc.block is None:
                continue
            if app is not None and app.published_keys:
                for param in proc.block.params:
                    value = param.value.strip()
                    if _CONFIG_NAME.fullmatch(value):
                        for pub in app.published_keys.get(param.lkey, ()):
                            exact.setdefault(value + pub.suffix, proc)
            if app is not None and not app.publishes_dynamic:
                continue
            for param in proc.block.params:
                value = param.value.strip()
                if len(value.strip("_")) >= 2 and _CONFIG_WORD.fullmatch(value):
                    procs = found.setdefault(value, [])
                    if not procs or procs[-1] is not proc:  # (a value twice in one block)
                        procs.append(proc)
        self.__dict__["_config_values_kept"] = (len(self.processes), (found, exact))
        return found, exact

    def _dynamic(self) -> tuple[list[tuple[AppInfo, list[int]]], list[tuple[str, list]]]:
        """The processes grouped by app, and the wildcard publications: what a name no one
        publishes exactly is matched against (each app once, however many processes run
        it), kept while the processes and publications stay as many."""
        stamp = (len(self.processes), len(self.publishers))
        kept = self.__dict__.get("_dynamic_kept")
        if kept is not None and kept[0] == stamp:
            return kept[1]
        groups: dict[int, tuple[AppInfo, list[int]]] = {}
        for i, p in enumerate(self.processes):
            if p.app is not None:
                groups.setdefault(id(p.app), (p.app, []))[1].append(i)
        globs = [(name, pubs) for name, pubs in self.publishers.items() if "*" in name]
        value = (list(groups.values()), globs)
        self.__dict__["_dynamic_kept"] = (stamp, value)
        return value

    @property
    def waits(self) -> list[VarRef]:
        """Variables a launched app's or a behavior's condition waits for."""
        return [r for r in self.refs if r.role == SUBSCRIBE and r.param in CONDITION_PARAMS]

    @property
    def complete(self) -> bool:
        """Whether every launched process is known to the model."""
        return not self.unknown_apps and not self.unresolved_behaviors

    def consumers(self) -> dict[str, list[tuple[str, VarRef | None]]]:
        """Variable -> the processes (or behaviors) that read it."""
        out: dict[str, list[tuple[str, VarRef | None]]] = {}
        for r in self.refs:
            if r.role == SUBSCRIBE:
                for read in r.read_names:
                    name = bare_name(read)
                    if name:
                        out.setdefault(name, []).append((r.app, r))
        for p in self.processes:
            if p.app is None:
                continue
            for var in p.app.subscribes:
                out.setdefault(var, []).append((p.name, None))
        return out


def _glob_match(pattern: str, var: str) -> bool:
    return _glob_regex(pattern).fullmatch(var) is not None


@functools.lru_cache(maxsize=1024)
def _glob_regex(pattern: str) -> re.Pattern[str]:
    """A published wildcard name (``RANGE_AVD_*``) as the expression it matches."""
    return re.compile(re.escape(pattern).replace(r"\*", ".*").replace(r"\?", "."))


def _norm(path: str) -> str:
    return os.path.normpath(os.path.abspath(path))


def behavior_paths(value: str, folder: str, *parents: str) -> tuple[list[str], bool]:
    """The behavior file(s) a ``behaviors = VALUE`` line names; and whether it was resolved.

    A plain name is looked up in the mission's folder, then in ``parents`` (the
    other folders it may be launched from, see :mod:`moos_lint.files.launch`). See the
    module docs for templates (``targ_$(VNAME).bhv`` -> ``meta_*.bhv``).
    """
    name = "".join(value.split())
    if len(name) >= 2 and name[0] == name[-1] == '"':
        name = name[1:-1]
    if not name:
        return [], True
    if not has_macro(name):
        for where in (folder, *parents):
            path = name if os.path.isabs(name) else os.path.join(where, name)
            if os.path.isfile(path):
                return [_norm(path)], True
    base = os.path.basename(name)
    where = os.path.join(folder, os.path.dirname(name))
    ext = os.path.splitext(base)[1] or ".bhv"
    if base.startswith("targ_"):
        meta = os.path.join(where, "meta_" + base[len("targ_") :])
        if not has_macro(meta) and os.path.isfile(meta):
            return [_norm(meta)], True
        metas = meta_templates(where, ext)
        if len(metas) == 1:
            return [_norm(metas[0])], True
        vehicle = [m for m in metas if "vehicle" in os.path.basename(m)]
        if len(vehicle) == 1 and has_macro(name):
            return [_norm(vehicle[0])], True
        if metas and has_macro(name):
            # one template per vehicle (meta_gilda.bhv, meta_henry.bhv): use them all
            return [_norm(m) for m in metas if "shoreside" not in os.path.basename(m)], True
        return [], False
    if has_macro(name):
        pattern = _MACRO.sub("*", name)
        path = pattern if os.path.isabs(pattern) else os.path.join(folder, pattern)
        hits = sorted(glob.glob(path))
        if len(hits) == 1:
            return [_norm(hits[0])], True
        return [], False
    return [], True  # a missing plain file: missing-behavior-file reports it


def _pokes(folder: str) -> dict[str, str]:
    """``VAR`` -> file, for ``uPokeDB ... VAR=value`` in the shell scripts of ``folder``
    and in its notes (a README's ``$ uPokeDB WPT_REQUEST=true``: a step run by hand)."""
    return _poked(shell_scripts(folder) + notes(folder))


@functools.lru_cache(maxsize=256)
def _poked(scripts: tuple[tuple[str, str], ...]) -> dict[str, str]:
    out: dict[str, str] = {}
    for script, text in scripts:
        text = text.replace("\\\n", " ")  # a command continued over a line break
        for m in _POKE.finditer(text):
            for pair in _PAIR.finditer(m.group(1)):
                out.setdefault(pair.group(1), os.path.basename(script))
    return out


_CONFIG_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_CONFIG_WORD = re.compile(r"[A-Za-z0-9_]+")


@dataclass(frozen=True, slots=True)
class ConfiguredPublication:
    """``KEY = NAME`` in an app's block, where ``KEY`` renames a variable the app publishes
    (the catalogue knows it from the app's C++: :attr:`AppInfo.published_keys`)."""

    name: str
    span: Span
    line: Line
    block: str
    app: AppInfo
    key: str
    published: PublishedKey

    def says(self) -> str:
        """``pMixer publishes `SERVO_3` under `servo_var` (default `SERVO_2`, Mixer.cpp:42)``."""
        pub = self.published
        value = f", {pub.value}" if pub.value else ""
        under = f"`{self.key}` + `{pub.suffix}`" if pub.suffix else f"`{self.key}`"
        return (
            f"{self.app.name} publishes `{self.name}` under {under} (default "
            f"`{pub.default}`{value}, {pub.where})"
        )


def configured_publications(run: RunView, moos: MoosFile) -> list[ConfiguredPublication]:
    """The variables a mission's blocks name through keys that rename an app's publication."""
    cat = catalogue_for(run)
    programs = {r.name.lower(): r.program for r in moos.runs}
    found: list[ConfiguredPublication] = []
    for block in moos.blocks:
        app = cat.app(programs.get(block.lname, block.name))
        if app is None or not app.published_keys:
            continue
        for p in block.params:
            pubs = app.published_keys.get("".join(p.key.split()).lower(), ())
            value = p.value.strip()
            if not pubs or not _CONFIG_NAME.fullmatch(value) or has_macro(p.value):
                continue
            found.extend(
                ConfiguredPublication(
                    value + pub.suffix, p.value_span, p.line, block.name, app, p.key.strip(), pub
                )
                for pub in pubs
            )
    return found


def node_message_vars(ref: VarRef) -> list[str]:
    """The variable a posted node message names (``var_name=X``), for a publication of
    ``NODE_MESSAGE`` or ``NODE_MESSAGE_LOCAL``; none for any other reference."""
    if ref.role != PUBLISH or ref.name not in NODE_MESSAGE_VARS:
        return []
    value = ref.line.text[ref.start + len(ref.name) :]
    return [v for v in _VAR_NAME.findall(value) if not has_macro(v)]


def _block_for(moos: MoosFile, name: str) -> Block | None:
    """The first block of that name (the one MOOS takes)."""
    return _first_blocks(moos).get(name.lower())


def _first_blocks(moos: MoosFile) -> dict[str, Block]:
    """The first block of each (lower-case) name, worked out once per expansion."""

    def compute() -> dict[str, Block]:
        first: dict[str, Block] = {}
        for b in moos.blocks:
            first.setdefault(b.lname, b)
        return first

    return derived(moos.expansion, "first-blocks", compute)


def _publisher(
    var: str, who: str, how: str, line: Line | None = None, process: str | None = None
) -> tuple[str, Publisher] | None:
    """The key a model files ``var``'s publisher under, and the publisher (None: no name)."""
    name = bare_name(var)
    if not name:
        return None
    return (var if "*" in var else name), Publisher(name, who, how, line, process)


class _Builder:
    def __init__(self, run: RunView, path: str, moos: MoosFile):
        self.run = run
        self.cat = catalogue_for(run)
        self.m = MissionModel(path=path, moos=moos, catalogue=self.cat)
        #: what the model read besides its own file: each ``behaviors =`` value resolved
        #: (value, folder, paths found, ok) and each behavior file's expansion
        self.behavior_lookups: list[tuple[str, tuple[str, ...], tuple[list[str], bool]]] = []
        self.behavior_expansions: list[tuple[str, Expansion]] = []
        #: in a whole model, the publisher lists it made itself (by id); every other list
        #: is shared (with its core, or with what a sibling publishes) and copied before
        #: it is added to. None while the core is built: it owns every list.
        self._owned: set[int] | None = None

    def add(
        self, var: str, who: str, how: str, line: Line | None = None, process: str | None = None
    ) -> None:
        found = _publisher(var, who, how, line, process)
        if found is not None:
            self._put(*found)

    def _put(self, key: str, pub: Publisher) -> None:
        """Add a publisher of ``key``; a shared list is copied first (a model copies
        only the lists it adds to)."""
        self._put_all(key, [pub])

    def _put_all(self, key: str, pubs: list[Publisher], share: bool = False) -> None:
        """Add publishers of ``key``, in order; ``share``: ``pubs`` itself may become the
        model's list (it is never changed: a later addition copies it)."""
        publishers = self.m.publishers
        owned = self._owned
        found = publishers.get(key)
        if found is None:
            publishers[key] = found = pubs if share else list(pubs)
            if owned is not None and not share:
                owned.add(id(found))
        elif owned is None or id(found) in owned:
            found.extend(pubs)
        else:
            publishers[key] = found = [*found, *pubs]
            owned.add(id(found))

    def build(self) -> MissionModel:
        """The whole model: the mission's own part (:func:`_core`, shared with the
        missions beside it), then what ``uPokeDB`` scripts and sibling missions post."""
        core = _core(self.run, self.m.path, self.m.moos).m
        self.m = m = MissionModel(
            path=core.path,
            moos=core.moos,
            catalogue=core.catalogue,
            processes=core.processes,
            behavior_files=core.behavior_files,
            unresolved_behaviors=core.unresolved_behaviors,
            refs=core.refs,
            publishers=dict(core.publishers),
            unknown_apps=core.unknown_apps,
            inbound=core.inbound,
            joins=core.joins,
            dynamic_apps=core.dynamic_apps,
            ref_process=core.ref_process,
        )
        self._owned = set()
        folder = os.path.dirname(_norm(m.path))
        pokes = self.run.memos.pokes
        if folder not in pokes:
            pokes[folder] = _pokes(folder)
        for var, script in pokes[folder].items():
            self.add(var, f"uPokeDB ({script})", "poke")
        if m.receives:
            self._siblings(folder)
        return m

    def build_core(self) -> MissionModel:
        """The mission's own part: its processes, what their apps and configuration
        blocks publish and read, and its behavior files."""
        m = self.m
        seen: set[str] = set()
        for run in m.moos.runs:
            if run.name and has_macro(run.name) and not has_macro(run.binary):
                # `Run = pMOOSBridge ~ pMOOSBridge_$(VNAME)`: whatever its name, the process
                # brings in what other communities send
                binary = run.program.strip()
                if binary.lower() in INBOUND_APPS:
                    m.inbound.append(Process(run.name, binary, run, None, self.cat.app(binary)))
            if not run.name or has_macro(run.name) or has_macro(run.binary):
                continue
            binary = run.program.strip()
            if run.name.lower() in seen:
                continue
            seen.add(run.name.lower())
            reads = self.cat.block_names(run)  # (an app's main may hard-code its name)
            block = _block_for(m.moos, run.name if reads == run.block_names else reads[0])
            proc = Process(run.name, binary, run, block, self.cat.app(binary))
            m.processes.append(proc)
            low = binary.lower()
            if low in ("moosdb", "pantler"):
                continue
            if proc.app is None:
                m.unknown_apps.append(proc)
            elif proc.app.publishes_dynamic:
                m.dynamic_apps.append(proc)
            if low in INBOUND_APPS:
                m.inbound.append(proc)
        m.joins = bool(m.processes) and not any(
            has_macro(run.binary) or run.program.strip().lower() == "moosdb" for run in m.moos.runs
        )
        for proc in m.processes:
            self._process(proc)
        for proc in m.processes:
            if proc.binary.lower() == "phelmivp" and proc.block is not None:
                self._helm(proc)
        if any(p.binary.lower() == "ufldmessagehandler" for p in m.processes):
            for ref in m.refs:
                for var in node_message_vars(ref):
                    self.add(var, f"uFldMessageHandler ({ref.app}: {ref.name})", "app", ref.line)
        db = self.cat.programs.get("moosdb")
        for var in sorted(db.publishes) if db is not None else ():
            self.add(var, "MOOSDB", "app", process="MOOSDB")  # every mission has its database
        return m

    def _process(self, proc: Process) -> None:
        if proc.app is not None:
            publishers = self.m.publishers
            for key, pub in _app_publishers(self.run, proc.app, proc.name):
                publishers.setdefault(key, []).append(pub)
        if proc.block is None:
            return
        app = app_of(proc.block.name, {proc.name.lower(): proc.binary})
        if app is not None:
            refs: Iterable[VarRef] = block_variables(proc.block, app)
        elif proc.app is not None:
            refs = flag_variables(proc.block, proc.app.reads, proc.binary)
        else:
            return
        for ref in refs:
            self.m.refs.append(ref)
            self.m.ref_process[id(ref)] = proc.name
            if ref.role == PUBLISH:
                self.add(ref.name, proc.name, "config", ref.line, proc.name)

    def _helm(self, proc: Process) -> None:
        if proc.block is None:
            return
        settings = getattr(self.run, "settings", None)
        folders = tuple(launch_folders(self.m.path, project_folder(settings, self.m.path)))
        for param in proc.block.get("behaviors"):
            paths, ok = behavior_paths(param.value, *folders)
            self.behavior_lookups.append((param.value, folders, (paths, ok)))
            if not ok:
                self.m.unresolved_behaviors.append(param.value.strip())
            for path in paths:
                if any(p == path for p, _ in self.m.behavior_files):
                    continue
                bf = self._parse_bhv(path)
                if bf is None:
                    continue
                self.m.behavior_files.append((path, bf))
                for ref in bhv_variables(bf):
                    self.m.refs.append(ref)
                    self.m.ref_process[id(ref)] = proc.name
                    if ref.role == PUBLISH:
                        who = f"{proc.name}: {ref.app}"
                        self.add(ref.name, who, "behavior", ref.line, proc.name)
                for bhv in bf.behaviors:
                    info = self.cat.behavior(bhv.kind)
                    if info is not None:
                        who = f"{proc.name}: {bhv.kind}"
                        for var in info.posts:
                            self.add(var, who, "behavior", process=proc.name)
                        for pre in info.post_prefixes:  # "RANGE_AVD_" + the contact's name
                            self.add(pre + "*", who, "behavior", process=proc.name)
                        for var, line in _configured_posts(bhv, info):
                            self.add(var, who, "behavior", line, proc.name)

    def _parse_bhv(self, path: str) -> BehaviorFile | None:
        exp = self.run.preprocessor.expand(path)
        self.behavior_expansions.append((path, exp))
        if exp.read_problem is not None:
            return None
        return parsed(exp, parse_bhv)  # once per expansion: rules only read models

    def _siblings(self, folder: str) -> None:
        pre = self.run.preprocessor
        me = _norm(self.m.path)
        generated = os.path.basename(me).startswith("targ_")
        for cand in missions_beside(self.run, folder, generated):
            if cand == me:
                continue
            exp = pre.expand(cand)
            if exp.read_problem is not None:
                continue
            moos = parsed(exp, parse_moos)
            if not moos.is_mission:
                continue
            self.m.sibling_missions.append(cand)
            for key, pubs in _external_publishers(self.run, cand, moos).items():
                self._put_all(key, pubs, share=True)


def _configured_posts(bhv: Behavior, info: BehaviorInfo) -> list[tuple[str, Line | None]]:
    """The names a behavior posts under that its parameters make: BHV_Timer's
    ``var_status_idle = TIMER_IDLE_SECONDS`` with ``status_suffix = base`` posts
    ``TIMER_IDLE_SECONDS_base``."""
    if not info.post_params:
        return []
    suffix = ""
    for p in bhv.get(info.post_suffix) if info.post_suffix else ():
        value = p.value.strip()
        suffix = value if not value or value.startswith("_") else "_" + value
    found: list[tuple[str, Line | None]] = []
    for key, default in info.post_params.items():
        given = bhv.get(key)
        if given:
            found.extend((p.value.strip() + suffix, p.line) for p in given if p.value.strip())
        else:
            found.append((default + suffix, None))
    return found


def meta_templates(folder: str, ext: str) -> list[str]:
    """The nsplug templates ``meta_*`` of ``folder`` ending in ``ext`` (``.bhv``), sorted:
    those a ``targ_$(VNAME)`` name may be made from."""
    return sorted(glob.glob(os.path.join(glob.escape(folder), "meta_*" + ext)))


def missions_beside(run: RunView, folder: str, generated: bool = False) -> list[str]:
    """The ``.moos`` files of ``folder`` that may be missions (normalised, sorted), once
    per run: the missions of a folder all look at the same ones. nsplug's outputs
    (``targ_*.moos``) are left out, being copies of the templates beside them, unless
    ``generated``: a ``targ_`` mission (a repository that keeps only nsplug's outputs)
    runs beside the other ``targ_`` missions of its folder."""
    memo = run.memos.mission_files
    found = memo.get(folder)
    if found is None:
        found = memo[folder] = [
            _norm(cand) for cand in sorted(glob.glob(os.path.join(glob.escape(folder), "*.moos")))
        ]
    if generated:
        return found
    return [cand for cand in found if not os.path.basename(cand).startswith("targ_")]


def _app_publishers(run: RunView, app: AppInfo, process: str) -> list[tuple[str, Publisher]]:
    """The (key, publisher) of each variable ``app`` publishes, launched as ``process``;
    once per run (many missions launch the same apps under the same names)."""
    memo = run.memos.app_publishers
    key = (id(app), process)  # (the run's catalogue holds the app: its id stays its own)
    found = memo.get(key)
    if found is None:
        pubs = (_publisher(var, process, "app", process=process) for var in app.publishes)
        found = memo[key] = [p for p in pubs if p is not None]
    return found


def _external_publishers(run: RunView, path: str, moos: MoosFile) -> dict[str, list[Publisher]]:
    """What another mission of the folder publishes, by key, in the order a mission's
    model takes them; once per run (models are only read, so they share them), and
    kept across runs while all it was made from is unchanged (see :class:`_Kept`)."""
    memo = run.memos.external_publishers
    if path in memo:
        return memo[path]
    cat = catalogue_for(run)
    with _KEPT_LOCK:
        kept = _KEPT.get(path)
    if kept is not None and kept.holds(run, moos, cat):
        memo[path] = kept.publishers
        return kept.publishers
    builder = _core(run, path, moos)
    memo[path] = out = _publishers_of(path, builder.m)
    if cat.inputs is not None:
        with _KEPT_LOCK:
            _KEPT[path] = _Kept(moos, cat.inputs, builder, out)
            _KEPT.move_to_end(path)
            while len(_KEPT) > _KEPT_SIZE:
                _KEPT.popitem(last=False)
    return out


class _Kept:
    """What a sibling mission publishes, kept from one run to the next (the language
    server re-lints a mission at every edit, and its siblings rarely change).

    It holds while the sibling's parsed file is the very same object (the
    kept expansion of an unchanged file), the catalogue was made from the same
    inputs, each ``behaviors =`` value resolves to the same files, and each
    behavior file read is the same kept expansion.
    """

    __slots__ = ("catalogue", "core", "expansions", "lookups", "moos", "publishers")

    def __init__(
        self,
        moos: MoosFile,
        catalogue: tuple[object, ...],
        builder: _Builder,
        publishers: dict[str, list[Publisher]],
    ):
        self.moos = moos
        self.catalogue = catalogue
        self.core = builder.m
        self.lookups = list(builder.behavior_lookups)
        self.expansions = list(builder.behavior_expansions)
        self.publishers = publishers

    def holds(self, run: RunView, moos: MoosFile, cat: Catalogue) -> bool:
        if moos is not self.moos or cat.inputs is None or cat.inputs != self.catalogue:
            return False
        if any(behavior_paths(v, *folders) != found for v, folders, found in self.lookups):
            return False
        pre = run.preprocessor
        return all(pre.expand(p) is exp for p, exp in self.expansions)


_KEPT: OrderedDict[str, _Kept] = OrderedDict()
_KEPT_SIZE = 64
_KEPT_LOCK = threading.Lock()


def _publishers_of(path: str, sub: MissionModel) -> dict[str, list[Publisher]]:
    """A sibling's model's publishers, as the missions beside it see them, by key."""
    who = f"{os.path.basename(path)} (another community)"
    found: list[tuple[str, Publisher] | None] = []
    for var, pubs in sub.publishers.items():
        found.extend(_publisher(var, who, "external", p.line) for p in pubs)
    for ref in sub.refs:
        # uFldShoreBroker ``qbridge = X`` posts X_ALL and X_<VNAME> to the vehicles as X
        if ref.param == "qbridge":
            found.append(_publisher(ref.name, who, "external", ref.line))
        # a node message it sends, which uFldMessageHandler posts on the vehicles
        found.extend(_publisher(var, who, "external", ref.line) for var in node_message_vars(ref))
    for proc in sub.processes:
        if proc.app is not None:
            found.extend(_publisher(var, who, "external") for var in proc.app.publishes)
            found.extend(
                _publisher(pre_ + "*", who, "external") for pre_ in proc.app.publish_prefixes
            )
            found.extend(
                _publisher("*" + suf, who, "external") for suf in proc.app.publish_suffixes
            )
    grouped: dict[str, list[Publisher]] = {}
    for f in found:
        if f is not None:
            grouped.setdefault(f[0], []).append(f[1])
    return grouped


class _RuleContext(Protocol):
    """The part of a rule's context (:class:`moos_lint.core.engine.Context`) read here."""

    @property
    def run(self) -> RunView: ...
    @property
    def path(self) -> str: ...
    @property
    def moos(self) -> MoosFile | None: ...


def mission_model(ctx: _RuleContext) -> MissionModel:
    """The model of the mission a rule checks, built once per lint run."""
    if ctx.moos is None:
        raise ValueError(f"{ctx.path}: a mission rule runs on a parsed .moos file")
    return model_of(ctx.run, ctx.path, ctx.moos)


def _core(run: RunView, path: str, moos: MoosFile) -> _Builder:
    """The builder of the mission's own part (:meth:`_Builder.build_core`), once per run:
    its whole model and the models of the missions beside it start from it."""
    cores = run.memos.mission_cores
    key = _norm(path)
    found = cores.get(key)
    if found is None or found.m.moos is not moos:
        found = cores[key] = _Builder(run, path, moos)
        found.build_core()
    return found


def sibling_model(run: RunView, path: str) -> MissionModel | None:
    """The mission's own part (:func:`_core`) of the mission at ``path`` beside another
    (one of its ``sibling_missions``): what the language server keeps of it from one run
    to the next while it is unchanged, as for what it publishes; None when its expansion
    is not whole (a macro or an include left unread: what it reads is not all known)."""
    exp = run.preprocessor.expand(path)
    if exp.read_problem is not None or exp.incomplete:
        return None
    moos = parsed(exp, parse_moos)
    with _KEPT_LOCK:
        kept = _KEPT.get(path)
    if kept is not None and kept.holds(run, moos, catalogue_for(run)):
        return kept.core
    return _core(run, path, moos).m


def model_of(run: RunView, path: str, moos: MoosFile) -> MissionModel:
    """The model of the mission at ``path`` (parsed as ``moos``), built once per lint run."""
    cache = run.memos.mission_models
    key = _norm(path)
    found = cache.get(key)
    if found is None:
        found = cache[key] = _Builder(run, path, moos).build()
    return found


__all__ = [
    "MissionModel",
    "Process",
    "Publisher",
    "behavior_paths",
    "meta_templates",
    "mission_model",
    "missions_beside",
    "model_of",
    "sibling_model",
]
