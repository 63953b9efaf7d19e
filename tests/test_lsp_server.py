"""The language server, driven over stdio by a pytest-lsp client."""

from __future__ import annotations

import asyncio
import shutil
import sys
import time
from pathlib import Path

import pytest

pytest.importorskip("pygls")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types as lsp  # noqa: E402
from pytest_lsp import ClientServerConfig, LanguageClient  # noqa: E402

from moos_lint.commands.lsp.catalogue import default_catalogue  # noqa: E402
from moos_lint.commands.lsp.documents import path_to_uri  # noqa: E402
from moos_lint.core.registry import get_rule  # noqa: E402

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "lsp"
SERVER = ClientServerConfig(server_command=[sys.executable, "-m", "moos_lint", "server"])
# One server for the module (starting one costs an import of lsprotocol); every
# test works on its own copy of the fixtures, so they never see each other's files.
pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(scope="module", config=SERVER)
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):
    root = tmp_path_factory.mktemp("workspace")
    result = await lsp_client.initialize_session(
        lsp.InitializeParams(
            capabilities=lsp.ClientCapabilities(),
            root_uri=path_to_uri(str(root)),
            initialization_options={"debounce": 0.05},
        )
    )
    lsp_client.server_capabilities = result.capabilities
    yield
    await lsp_client.shutdown_session()


@pytest.fixture
def mission(tmp_path: Path) -> Path:
    for f in FIXTURES.iterdir():
        shutil.copy(f, tmp_path / f.name)
    return tmp_path / "mission.moos"


async def wait_for(predicate, timeout: float = 5.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        await asyncio.sleep(0.02)
    raise AssertionError("timed out waiting for the server")


def codes(client: LanguageClient, uri: str) -> list[tuple[int, str]]:
    return sorted((d.range.start.line, str(d.code)) for d in client.diagnostics.get(uri, []))


def open_doc(client: LanguageClient, path: Path, text: str | None = None, version: int = 1):
    uri = path_to_uri(str(path))
    client.text_document_did_open(
        lsp.DidOpenTextDocumentParams(
            lsp.TextDocumentItem(
                uri=uri,
                language_id="moos",
                version=version,
                text=path.read_text() if text is None else text,
            )
        )
    )
    return uri


def change(client: LanguageClient, uri: str, version: int, text: str) -> None:
    client.text_document_did_change(
        lsp.DidChangeTextDocumentParams(
            text_document=lsp.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[lsp.TextDocumentContentChangeWholeDocument(text=text)],
        )
    )


async def test_diagnostics_on_open_carry_code_link_and_source(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: client.diagnostics.get(uri))
    diags = client.diagnostics[uri]
    found = codes(client, uri)
    # R007 on `#output`, R003 on the header with `{`, L001 on the unused suppression,
    # and the fragment's R003 shown on the `#include` line that pulls it in.
    assert found == [(12, "R007"), (15, "R003"), (20, "R003"), (24, "L001")]
    r003 = next(d for d in diags if d.code == "R003" and d.range.start.line == 15)
    assert r003.source == "moos-lint"
    assert r003.code_description.href == get_rule("R003").url
    assert r003.severity == lsp.DiagnosticSeverity.Error
    assert (r003.range.start.character, r003.range.end.character) == (0, 26)
    via = next(d for d in diags if d.range.start.line == 20)
    assert "plug_vehicle.moos" in via.message
    assert via.related_information[0].location.uri.endswith("plug_vehicle.moos")


async def test_change_lints_the_unsaved_text_not_the_disk(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: client.diagnostics.get(uri))
    fixed = mission.read_text().replace("pHelmIvP {", "pHelmIvP\n{")
    change(client, uri, 2, fixed)
    await wait_for(lambda: (15, "R003") not in codes(client, uri))
    assert (12, "R007") in codes(client, uri)
    assert "pHelmIvP {" in mission.read_text()  # the disk was never touched


async def test_rapid_edits_end_on_the_last_version(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: client.diagnostics.get(uri))
    good = mission.read_text().replace("pHelmIvP {", "pHelmIvP\n{")
    bad = mission.read_text()
    for version in range(2, 62):
        change(client, uri, version, bad if version % 2 else good)
    # version 61 is odd: the broken header is back
    await wait_for(lambda: (15, "R003") in codes(client, uri))
    await asyncio.sleep(0.3)
    assert (15, "R003") in codes(client, uri)
    hover = await client.text_document_hover_async(
        lsp.HoverParams(lsp.TextDocumentIdentifier(uri), lsp.Position(15, 3))
    )
    assert hover is not None and "brace-on-header" in hover.contents.value


async def test_editing_an_included_fragment_relints_the_mission(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: (20, "R003") in codes(client, uri))
    plug = mission.parent / "plug_vehicle.moos"
    plug_uri = open_doc(client, plug)
    await wait_for(lambda: (1, "R003") in codes(client, plug_uri))
    # Now that the fragment is open its finding shows there, not on the include line.
    await wait_for(lambda: (20, "R003") not in codes(client, uri))
    change(client, plug_uri, 2, plug.read_text().replace("pMarinePID {", "pMarinePID\n{"))
    await wait_for(lambda: (1, "R003") not in codes(client, plug_uri))
    # Close the fragment unsaved: the mission reads the disk again.
    client.text_document_did_close(
        lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(plug_uri))
    )
    await wait_for(lambda: (20, "R003") in codes(client, uri))
    assert list(client.diagnostics[plug_uri]) == []


async def test_behavior_file_diagnostics_and_definition(client, mission):
    bhv = mission.parent / "mission.bhv"
    bhv_uri = open_doc(client, bhv, bhv.read_text() + "Behavior = BHV_Loiter\n{\n")
    uri = open_doc(client, mission)
    await wait_for(lambda: client.diagnostics.get(uri))
    assert bhv_uri in client.diagnostics
    text = mission.read_text().splitlines()
    row = next(i for i, line in enumerate(text) if "behaviors" in line)
    loc = await client.text_document_definition_async(
        lsp.DefinitionParams(lsp.TextDocumentIdentifier(uri), lsp.Position(row, 16))
    )
    assert loc.uri == bhv_uri
    row = next(i for i, line in enumerate(text) if line.startswith("#include"))
    loc = await client.text_document_definition_async(
        lsp.DefinitionParams(lsp.TextDocumentIdentifier(uri), lsp.Position(row, 12))
    )
    assert loc.uri == path_to_uri(str(mission.parent / "plug_vehicle.moos"))


async def test_code_actions_fix_and_suppress(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: (24, "L001") in codes(client, uri))
    diags = client.diagnostics[uri]
    l001 = next(d for d in diags if d.code == "L001")
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(
            lsp.TextDocumentIdentifier(uri), l001.range, lsp.CodeActionContext([l001])
        )
    )
    fix = next(a for a in actions if a.is_preferred)
    (edit,) = fix.edit.changes[uri]
    assert edit.new_text == ""
    r007 = next(d for d in diags if d.code == "R007")
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(
            lsp.TextDocumentIdentifier(uri), r007.range, lsp.CodeActionContext([r007])
        )
    )
    (suppress,) = [a for a in actions if a.title.startswith("Suppress R007")]
    (edit,) = suppress.edit.changes[uri]
    # `#output ...` is a `#` line: the comment goes on its own line above it.
    assert edit.range.start == lsp.Position(12, 0)
    assert edit.new_text == "  // moos-lint: ignore[R007]\n"
    # Applying it silences the finding.
    lines = mission.read_text().splitlines(keepends=True)
    lines.insert(12, edit.new_text)
    change(client, uri, 2, "".join(lines))
    await wait_for(lambda: "R007" not in [c for _, c in codes(client, uri)])


async def test_hover_on_a_suppression_code(client, mission):
    uri = open_doc(client, mission)
    await wait_for(lambda: client.diagnostics.get(uri))
    line = mission.read_text().splitlines()[24]
    col = line.index("brace-on-header") + 3
    hover = await client.text_document_hover_async(
        lsp.HoverParams(lsp.TextDocumentIdentifier(uri), lsp.Position(24, col))
    )
    assert hover.contents.value.startswith("# R003 brace-on-header")
    assert hover.range.start.character == line.index("brace-on-header")


async def test_completion_follows_the_catalogue(client, mission):
    caps = client.server_capabilities
    assert caps.hover_provider and caps.definition_provider and caps.code_action_provider
    catalogue = default_catalogue()
    assert (caps.completion_provider is None) == catalogue.empty
    if catalogue.empty:
        return
    text = "ProcessConfig = ANTLER\n{\n  Run = \n}\n"
    uri = open_doc(client, mission.parent / "complete.moos", text)
    result = await client.text_document_completion_async(
        lsp.CompletionParams(lsp.TextDocumentIdentifier(uri), lsp.Position(2, 8))
    )
    assert sorted(i.label for i in result.items) == sorted(c.name for c in catalogue.apps())
