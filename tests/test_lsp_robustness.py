"""The language server survives garbage on the wire, huge documents and edit storms."""

from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("pygls")

from moos_lint.commands.lsp.documents import path_to_uri

BAD_MISSION = "ServerHost = localhost\nProcessConfig = pHelmIvP {\n  AppTick = 4\n}\n"


class Wire:
    """A bare JSON-RPC connection to ``moos-lint server``, able to send anything."""

    def __init__(self, stderr=subprocess.DEVNULL) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "moos_lint", "server"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=stderr,
        )
        self.inbox: queue.Queue = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        out = self.proc.stdout
        while True:
            length = None
            while True:
                header = out.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                name, _, value = header.decode("ascii").partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            self.inbox.put(json.loads(out.read(length)))

    def raw(self, body: bytes, header: bytes | None = None) -> None:
        if header is None:
            header = b"Content-Length: %d\r\n\r\n" % len(body)
        self.proc.stdin.write(header + body)
        self.proc.stdin.flush()

    def send(self, message: dict) -> None:
        self.raw(json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8"))

    def expect(self, predicate, timeout: float = 10.0) -> dict:
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError("no matching message from the server")
            try:
                msg = self.inbox.get(timeout=left)
            except queue.Empty:
                continue
            if predicate(msg):
                return msg

    def response(self, msg_id: int, timeout: float = 10.0) -> dict:
        return self.expect(lambda m: m.get("id") == msg_id and "method" not in m, timeout)

    def diagnostics(self, uri: str, timeout: float = 10.0) -> dict:
        return self.expect(
            lambda m: (
                m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri
            ),
            timeout,
        )

    def close(self) -> int:
        try:
            self.send({"id": 999, "method": "shutdown"})
            self.response(999)
            self.send({"method": "exit"})
            return self.proc.wait(timeout=10)
        finally:
            if self.proc.poll() is None:
                self.proc.kill()
                self.proc.wait()


@pytest.fixture
def wire(tmp_path):
    # Only brace-on-header, so that the assertions hold whatever rules are added.
    (tmp_path / "moos-lint.toml").write_text('select = ["R003"]\n')
    w = Wire()
    try:
        yield w
    finally:
        if w.proc.poll() is None:
            w.proc.kill()
            w.proc.wait()


def _open(wire: Wire, path: Path, text: str, version: int = 1) -> str:
    uri = path_to_uri(str(path))
    wire.send(
        {
            "method": "textDocument/didOpen",
            "params": {
                "textDocument": {"uri": uri, "languageId": "moos", "version": version, "text": text}
            },
        }
    )
    return uri


def test_malformed_messages_do_not_kill_the_server(wire, tmp_path):
    wire.raw(b"{this is not json")
    wire.raw(b"[1, 2, 3]")
    wire.raw(b'"a string"')
    wire.raw(b"\xff\xfe\x00 not utf-8")
    wire.raw(b"", header=b"Content-Length: many\r\n\r\n")
    wire.raw(b"", header=b"X-Nonsense: 1\r\n\r\n")
    wire.send({"id": 1, "method": "initialize", "params": {"capabilities": {}}})
    assert "capabilities" in wire.response(1)["result"]
    wire.send({"method": "initialized", "params": {}})
    # Notifications with missing or wrong params, and for documents never opened.
    wire.send({"method": "textDocument/didOpen", "params": {"foo": 1}})
    wire.send({"method": "textDocument/didOpen", "params": None})
    wire.send(
        {
            "method": "textDocument/didChange",
            "params": {
                "textDocument": {"uri": "file:///nowhere/x.moos", "version": 3},
                "contentChanges": [{"text": "x"}],
            },
        }
    )
    wire.send({"method": "textDocument/didClose", "params": {"textDocument": {"uri": "bogus"}}})
    _open(wire, Path("/untitled"), "x", 1)  # a path with no lintable suffix
    wire.send(
        {
            "method": "textDocument/didOpen",
            "params": {
                "textDocument": {
                    "uri": "untitled:Untitled-1",
                    "languageId": "moos",
                    "version": 1,
                    "text": BAD_MISSION,
                }
            },
        }
    )
    # Requests with bad params get an error or an empty answer, never silence.
    wire.send({"id": 2, "method": "textDocument/hover", "params": {"position": "here"}})
    assert "error" in wire.response(2)
    wire.send({"id": 3, "method": "moos/unknownMethod", "params": {}})
    assert wire.response(3)["error"]["code"] == -32601
    wire.send(
        {
            "id": 4,
            "method": "textDocument/hover",
            "params": {
                "textDocument": {"uri": "file:///nowhere/x.moos"},
                "position": {"line": 99, "character": 99},
            },
        }
    )
    assert wire.response(4).get("result") is None
    # And it still lints.
    path = tmp_path / "bad.moos"
    path.write_text(BAD_MISSION)
    uri = _open(wire, path, BAD_MISSION)
    diags = wire.diagnostics(uri)["params"]["diagnostics"]
    assert [(d["code"], d["range"]["start"]["line"]) for d in diags] == [("R003", 1)]
    # Positions far outside the document are answered, not crashed on.
    wire.send(
        {
            "id": 5,
            "method": "textDocument/codeAction",
            "params": {
                "textDocument": {"uri": uri},
                "range": {
                    "start": {"line": 5000, "character": 0},
                    "end": {"line": 5000, "character": 9},
                },
                "context": {"diagnostics": []},
            },
        }
    )
    assert wire.response(5)["result"] == []
    assert wire.close() == 0


def test_huge_document_and_edit_storm(wire, tmp_path):
    wire.send(
        {
            "id": 1,
            "method": "initialize",
            "params": {"capabilities": {}, "initializationOptions": {"debounce": 0.05}},
        }
    )
    wire.response(1)
    wire.send({"method": "initialized", "params": {}})
    path = tmp_path / "huge.moos"
    block = "ProcessConfig = uApp{n}\n{{\n  AppTick = 4\n  value = {n}\n}}\n\n"
    text = "".join(block.format(n=n) for n in range(10000)) + BAD_MISSION
    assert len(text) > 500_000
    uri = _open(wire, path, text)
    # While the huge document is linted, the server keeps answering.
    wire.send(
        {
            "id": 2,
            "method": "textDocument/hover",
            "params": {"textDocument": {"uri": uri}, "position": {"line": 0, "character": 0}},
        }
    )
    wire.response(2, timeout=5)
    diags = wire.diagnostics(uri, timeout=30)["params"]["diagnostics"]
    last_line = text.count("\n") - 3
    assert ("R003", last_line) in [(d["code"], d["range"]["start"]["line"]) for d in diags]
    # A storm of edits on a small document: the last version wins.
    small = tmp_path / "small.moos"
    small_uri = _open(wire, small, BAD_MISSION)
    good = BAD_MISSION.replace("pHelmIvP {", "pHelmIvP\n{")
    for version in range(2, 202):
        body = good if version < 201 else BAD_MISSION
        wire.send(
            {
                "method": "textDocument/didChange",
                "params": {
                    "textDocument": {"uri": small_uri, "version": version},
                    "contentChanges": [{"text": body}],
                },
            }
        )
    msg = wire.expect(
        lambda m: (
            m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"] == small_uri
            and m["params"].get("version") == 201
        ),
        timeout=30,
    )
    assert [d["code"] for d in msg["params"]["diagnostics"]] == ["R003"]
    assert wire.close() == 0


def _initialize(wire: Wire, **options) -> None:
    wire.send(
        {
            "id": 1,
            "method": "initialize",
            "params": {"capabilities": {}, "initializationOptions": {"debounce": 0.05, **options}},
        }
    )
    wire.response(1)
    wire.send({"method": "initialized", "params": {}})


def _huge_mission(size: int) -> str:
    block = "ProcessConfig = uApp{n}\n{{\n  AppTick = 4\n  value = {n}\n}}\n\n"
    parts, n, total = [], 0, 0
    while total < size:
        parts.append(block.format(n=n))
        total += len(parts[-1])
        n += 1
    return "".join(parts) + BAD_MISSION


def test_a_5_mb_document_does_not_starve_another(wire, tmp_path):
    _initialize(wire)
    huge = _huge_mission(5 * 2**20)
    huge_uri = _open(wire, tmp_path / "huge.moos", huge)
    time.sleep(0.3)  # the huge document is being linted
    other = tmp_path / "other" / "small.moos"
    other.parent.mkdir()
    started = time.monotonic()
    small_uri = _open(wire, other, BAD_MISSION)
    diags = wire.diagnostics(small_uri, timeout=15)["params"]["diagnostics"]
    assert [d["code"] for d in diags] == ["R003"]
    # (about 0.05 s; behind the huge document on a single worker, about 9 s)
    assert time.monotonic() - started < 3
    # and the huge one still gets its own diagnostics
    assert wire.diagnostics(huge_uri, timeout=120)["params"]["uri"] == huge_uri
    assert wire.close() == 0


def test_a_document_past_its_budget_is_stopped_and_says_so(wire, tmp_path):
    _initialize(wire, budget=0.2)
    uri = _open(wire, tmp_path / "huge.moos", _huge_mission(2 * 2**20))
    [note] = wire.diagnostics(uri, timeout=60)["params"]["diagnostics"]
    assert note["message"].startswith("moos-lint stopped: linting this document took more")
    small_uri = _open(wire, tmp_path / "small.moos", BAD_MISSION)
    assert wire.diagnostics(small_uri, timeout=15)["params"]["diagnostics"]
    assert wire.close() == 0


def test_shutdown_during_lints_prints_no_traceback(tmp_path):
    log = tmp_path / "stderr.txt"
    with log.open("wb") as err:
        wire = Wire(stderr=err)
        try:
            _initialize(wire)
            path = tmp_path / "huge.moos"
            text = _huge_mission(2**20)
            uri = _open(wire, path, text)
            time.sleep(0.3)
            for version in range(2, 6):  # newer texts while it is linted
                wire.send(
                    {
                        "method": "textDocument/didChange",
                        "params": {
                            "textDocument": {"uri": uri, "version": version},
                            "contentChanges": [{"text": text + "\n" * version}],
                        },
                    }
                )
                time.sleep(0.1)
            assert wire.close() == 0
        finally:
            if wire.proc.poll() is None:
                wire.proc.kill()
                wire.proc.wait()
    assert "Traceback" not in log.read_text(), log.read_text()


def test_json_rpc_error_codes(wire):
    _initialize(wire)
    wire.send({"id": 2, "method": "moos/noSuchMethod"})  # no params
    assert wire.response(2)["error"]["code"] == -32601
    wire.send({"id": 3, "method": "moos/noSuchMethod", "params": [1, 2]})
    assert wire.response(3)["error"]["code"] == -32601
    wire.send({"id": 4, "method": "textDocument/hover", "params": {"position": "here"}})
    assert wire.response(4)["error"]["code"] == -32602  # a known method, bad params
    wire.send({"method": "moos/noSuchNotification"})  # a notification gets no answer
    wire.send({"id": 5, "method": "shutdown"})
    assert wire.response(5)["result"] is None
