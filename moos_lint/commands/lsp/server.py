"""``moos-lint server``: the language server, on stdio, built on pygls.

Diagnostics are computed on open, on save and, debounced, on change, from the
editor's in-memory text. Linting runs on worker threads (:data:`WORKERS`), so a
huge document never blocks the connection nor the other documents; a result
that is older than the document when it arrives is dropped, and at most one
lint per document runs at a time. A lint stops when its document is edited
again (the new text is linted instead) and when it runs past its time budget
(:data:`DEFAULT_BUDGET`; the document then shows one note saying so).
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

from lsprotocol import types as lsp
from pygls.exceptions import JsonRpcException, JsonRpcInvalidParams, JsonRpcMethodNotFound
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol

from moos_lint import __version__
from moos_lint.commands.lsp import features
from moos_lint.commands.lsp.analysis import COLLECTOR, Analysis, analyse, settle
from moos_lint.commands.lsp.catalogue import EMPTY, Catalogue, default_catalogue
from moos_lint.commands.lsp.documents import DocumentStore, uri_to_path
from moos_lint.core.config import CONFIG_FILES
from moos_lint.core.engine import LintStopped
from moos_lint.core.registry import all_rules
from moos_lint.files.source import SourceFile, read_source, split_lines

log = logging.getLogger("moos_lint.commands.lsp")

#: Seconds of quiet typing before a changed document is linted again.
DEFAULT_DEBOUNCE = 0.3
#: Dependent documents wait this long, so that a burst of saves lints them once.
DEPENDENT_DELAY = 0.05
#: Lints that may run at once (different documents): one large document occupies one.
WORKERS = 3
#: Seconds one lint of a document may take (``initializationOptions.budget``).
DEFAULT_BUDGET = 20.0


class _Dropped:
    """A message that could not be read: pygls logs it and moves on."""

    jsonrpc = "dropped"


class Protocol(LanguageServerProtocol):
    """pygls' protocol, answering a request it cannot read instead of ignoring it."""

    def structure_message(self, data: Any):
        if isinstance(data, dict) and "id" in data and "method" in data:
            method = data["method"]
            if not (isinstance(method, str) and self._handles(method)):
                # a request for a method this server does not have: -32601, whatever its params
                msg_id = data["id"]
                if isinstance(msg_id, (int, str)):
                    error = JsonRpcMethodNotFound.of(str(method))
                    self._send_response(msg_id, None, error.to_response_error())
                log.info("no such method: %r", method)
                return _Dropped()
        try:
            return super().structure_message(data)
        except JsonRpcException as exc:
            msg_id = data.get("id") if isinstance(data, dict) else None
            if isinstance(msg_id, (int, str)) and "method" in data:
                error = JsonRpcInvalidParams(f"invalid params for {data.get('method')!r}")
                self._send_response(msg_id, None, error.to_response_error())
            log.warning("dropped a malformed message: %s", exc.message)
            return _Dropped()

    def _handles(self, method: str) -> bool:
        return method in self.fm.builtin_features or method in self.fm.features


class MoosLintServer(LanguageServer):
    def __init__(self, catalogue: Catalogue = EMPTY, debounce: float = DEFAULT_DEBOUNCE):
        super().__init__(
            "moos-lint",
            __version__,
            text_document_sync_kind=lsp.TextDocumentSyncKind.Incremental,
            protocol_cls=Protocol,
        )
        self.catalogue = catalogue
        self.debounce = debounce
        self.store = DocumentStore()
        self.analyses: dict[str, Analysis] = {}
        self.budget = DEFAULT_BUDGET
        self.executor = ThreadPoolExecutor(max_workers=WORKERS, thread_name_prefix="moos-lint")
        #: set once the client asked to shut down: nothing more is scheduled
        self.closing = False
        #: per document being linted: set to stop that lint (a newer text came)
        self._stops: dict[str, threading.Event] = {}
        self._timers: dict[str, asyncio.TimerHandle] = {}
        self._cascade: dict[str, bool] = {}
        self._running: set[str] = set()
        self._tasks: set[asyncio.Future] = set()
        self._again: dict[str, bool] = {}
        self._config_errors: set[str] = set()
        all_rules()  # load the registry now, not first in the lint thread

    def report_server_error(self, error: Exception, source: Any) -> None:
        """Log a problem with a message or a handler; never pop up a dialog for it."""
        log.warning("%s: %s", getattr(source, "__name__", source), error)
        with contextlib.suppress(Exception):  # no connection left to log on
            self.window_log_message(
                lsp.LogMessageParams(type=lsp.MessageType.Warning, message=f"moos-lint: {error}")
            )

    # ------------------------------------------------------------ helpers
    @property
    def encoding(self) -> str:
        try:
            enc = self.workspace.position_encoding
        except RuntimeError:
            return "utf-16"
        value = getattr(enc, "value", enc)
        return value if value in ("utf-8", "utf-16", "utf-32") else "utf-16"

    def lines_of(self, path: str) -> list[str]:
        doc = self.store.get(path)
        if doc is not None:
            return split_lines(doc.text)
        src = read_source(Path(path))
        return src.lines if isinstance(src, SourceFile) else []

    def text_of(self, uri: str) -> str | None:
        doc = self.store.by_uri(uri)
        return doc.text if doc is not None else None

    # ----------------------------------------------------------- schedule
    def schedule(self, path: str, delay: float, cascade: bool) -> None:
        """Lint ``path`` after ``delay`` seconds; a later call replaces an earlier one."""
        if self.closing:
            return
        old = self._timers.pop(path, None)
        if old is not None:
            old.cancel()
        self._cascade[path] = self._cascade.get(path, False) or cascade
        loop = asyncio.get_running_loop()
        self._timers[path] = loop.call_later(max(0.0, delay), self._start, path)

    def cancel(self, path: str) -> None:
        """Stop the lint of ``path`` that is running (its text is no longer the editor's)."""
        stop = self._stops.get(path)
        if stop is not None:
            stop.set()

    def close(self) -> None:
        """Schedule nothing more, stop what runs (the client is shutting down)."""
        self.closing = True
        for timer in self._timers.values():
            timer.cancel()
        self._timers.clear()
        self._again.clear()
        for stop in self._stops.values():
            stop.set()
        self.executor.shutdown(wait=False, cancel_futures=True)

    def _start(self, path: str) -> None:
        if self.closing:
            return
        self._timers.pop(path, None)
        cascade = self._cascade.pop(path, False)
        if path in self._running:
            self._again[path] = self._again.get(path, False) or cascade
            return
        self._running.add(path)
        task = asyncio.ensure_future(self._lint(path, cascade))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    async def _lint(self, path: str, cascade: bool) -> None:
        try:
            doc = self.store.get(path)
            if doc is None:
                return
            version, text = doc.version, doc.text
            texts = self.store.texts()
            includers = self.store.includers(path)
            loop = asyncio.get_running_loop()
            stopped = self._stops[path] = threading.Event()
            deadline = time.monotonic() + self.budget

            def stop() -> bool:
                return stopped.is_set() or time.monotonic() > deadline

            def work() -> Analysis:
                with COLLECTOR.linting():
                    return analyse(path, texts, includers, stop=stop)

            try:
                result = await loop.run_in_executor(self.executor, work)
            except LintStopped:
                if not stopped.is_set():  # over budget (a newer text is linted anyway)
                    self._over_budget(path, version)
                return
            except RuntimeError:  # the executor shut down under this lint
                if self.closing:
                    return
                log.exception("linting %s failed", path)
                return
            except Exception:  # the engine never raises; this is a last guard
                log.exception("linting %s failed", path)
                return
            doc = self.store.get(path)
            if doc is None or doc.version != version or doc.text != text:
                return  # stale: the newer text is already scheduled
            self.analyses[path] = result
            self.store.record(path, result.reads, result.includes)
            self._report_config_error(result.config_error)
            self.publish(doc.uri, result, text, version)
            if cascade:
                for other in self.store.dependents(path):
                    self.schedule(other.path, DEPENDENT_DELAY, cascade=False)
        finally:
            self._running.discard(path)
            self._stops.pop(path, None)
            if path in self._again:
                self.schedule(path, 0.0, self._again.pop(path))
            elif not self._running:
                COLLECTOR.idle()  # (the diagnostics are out: see Collector)

    def _over_budget(self, path: str, version: int | None) -> None:
        """Tell the editor the document was not linted: it took longer than the budget."""
        doc = self.store.get(path)
        if doc is None or doc.version != version or self.closing:
            return
        log.warning("linting %s took more than %g s: stopped", path, self.budget)
        note = lsp.Diagnostic(
            range=lsp.Range(lsp.Position(0, 0), lsp.Position(0, 0)),
            message=f"moos-lint stopped: linting this document took more than {self.budget:g} s",
            severity=lsp.DiagnosticSeverity.Information,
            source=features.SOURCE,
        )
        self.text_document_publish_diagnostics(
            lsp.PublishDiagnosticsParams(uri=doc.uri, diagnostics=[note], version=version)
        )

    def publish(self, uri: str, result: Analysis, text: str, version: int | None) -> None:
        diags = features.diagnostics(result, text, self.encoding, self.lines_of)
        self.text_document_publish_diagnostics(
            lsp.PublishDiagnosticsParams(uri=uri, diagnostics=diags, version=version)
        )

    def _report_config_error(self, error: str | None) -> None:
        if error and error not in self._config_errors:
            self._config_errors.add(error)
            self.window_show_message(
                lsp.ShowMessageParams(
                    type=lsp.MessageType.Warning,
                    message=f"moos-lint: {error}; linting with the default settings",
                )
            )


def create_server(
    catalogue: Catalogue = EMPTY, debounce: float = DEFAULT_DEBOUNCE
) -> MoosLintServer:
    """A server with every feature registered; ``catalogue`` feeds completion and help."""
    server = MoosLintServer(catalogue, debounce)

    @server.feature(lsp.INITIALIZE)
    def initialize(ls: MoosLintServer, params: lsp.InitializeParams) -> None:
        opts = params.initialization_options
        if isinstance(opts, dict):
            value = opts.get("debounce")
            if isinstance(value, (int, float)) and not isinstance(value, bool) and value >= 0:
                ls.debounce = float(value)
            value = opts.get("budget")
            if isinstance(value, (int, float)) and not isinstance(value, bool) and value > 0:
                ls.budget = float(value)

    @server.feature(lsp.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: MoosLintServer, params: lsp.DidOpenTextDocumentParams) -> None:
        item = params.text_document
        doc = ls.store.open(item.uri, item.text, item.version)
        if doc is not None:
            ls.schedule(doc.path, 0.0, cascade=True)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: MoosLintServer, params: lsp.DidChangeTextDocumentParams) -> None:
        uri = params.text_document.uri
        if ls.store.by_uri(uri) is None:
            return
        text = ls.workspace.get_text_document(uri).source
        doc = ls.store.update(uri, text, params.text_document.version)
        if doc is not None:
            ls.cancel(doc.path)  # a lint of the older text is wasted work
            ls.schedule(doc.path, ls.debounce, cascade=True)

    @server.feature(lsp.TEXT_DOCUMENT_DID_SAVE, lsp.SaveOptions(include_text=False))
    def did_save(ls: MoosLintServer, params: lsp.DidSaveTextDocumentParams) -> None:
        doc = ls.store.by_uri(params.text_document.uri)
        if doc is not None:
            if params.text is not None:
                ls.store.update(doc.uri, params.text, doc.version)
            ls.schedule(doc.path, 0.0, cascade=True)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: MoosLintServer, params: lsp.DidCloseTextDocumentParams) -> None:
        uri = params.text_document.uri
        path = uri_to_path(uri)
        if path is None:
            return
        dependents = ls.store.dependents(path)
        ls.store.close(uri)
        ls.analyses.pop(path, None)
        ls.cancel(path)
        timer = ls._timers.pop(path, None)
        if timer is not None:
            timer.cancel()
        ls.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        for other in dependents:  # they read the editor's text; now they read the disk
            ls.schedule(other.path, DEPENDENT_DELAY, cascade=False)

    @server.feature(lsp.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def watched(ls: MoosLintServer, params: lsp.DidChangeWatchedFilesParams) -> None:
        for change in params.changes:
            path = uri_to_path(change.uri)
            if path is None:
                continue
            if os.path.basename(path) in CONFIG_FILES:
                targets = ls.store.documents()
            else:
                targets = ls.store.dependents(path)
            for doc in targets:
                ls.schedule(doc.path, DEPENDENT_DELAY, cascade=False)

    @server.feature(lsp.TEXT_DOCUMENT_HOVER)
    def hover(ls: MoosLintServer, params: lsp.HoverParams) -> lsp.Hover | None:
        text = ls.text_of(params.text_document.uri)
        if text is None:
            return None
        path = uri_to_path(params.text_document.uri)
        return features.hover(
            ls.analyses.get(path or ""), text, params.position, ls.encoding, ls.catalogue
        )

    @server.feature(
        lsp.TEXT_DOCUMENT_CODE_ACTION,
        lsp.CodeActionOptions(code_action_kinds=[lsp.CodeActionKind.QuickFix]),
    )
    def code_action(ls: MoosLintServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
        uri = params.text_document.uri
        text = ls.text_of(uri)
        path = uri_to_path(uri)
        if text is None or path is None:
            return []
        return features.code_actions(
            uri, ls.analyses.get(path), text, params, ls.encoding, ls.lines_of
        )

    @server.feature(lsp.TEXT_DOCUMENT_DEFINITION)
    def definition(ls: MoosLintServer, params: lsp.DefinitionParams) -> lsp.Location | None:
        uri = params.text_document.uri
        text = ls.text_of(uri)
        path = uri_to_path(uri)
        if text is None or path is None:
            return None
        tops = [os.path.dirname(p) for p in ls.store.includers(path)]
        return features.definition(
            path, text, params.position, ls.encoding, ls.analyses.get(path), tops, ls.lines_of
        )

    if not catalogue.empty:  # nothing to complete without a catalogue

        @server.feature(
            lsp.TEXT_DOCUMENT_COMPLETION, lsp.CompletionOptions(trigger_characters=["=", " "])
        )
        def completion(ls: MoosLintServer, params: lsp.CompletionParams) -> lsp.CompletionList:
            text = ls.text_of(params.text_document.uri)
            items = []
            if text is not None:
                items = features.completion(text, params.position, ls.encoding, ls.catalogue)
            return lsp.CompletionList(is_incomplete=False, items=items)

    @server.feature(lsp.SHUTDOWN)
    def shutdown(ls: MoosLintServer, *_: Any) -> None:
        ls.close()

    return server


def serve(catalogue: Catalogue | None = None) -> int:
    """Run the server on stdin/stdout until the client says ``exit``."""
    logging.basicConfig(level=logging.WARNING, format="moos-lint server: %(message)s")
    server = create_server(default_catalogue() if catalogue is None else catalogue)
    settle()  # (after the server's own objects are made)
    server.start_io()
    return 0
