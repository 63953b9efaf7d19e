"""End to end with a real editor: headless Neovim runs ``moos-lint server`` on a bad mission.

Neovim 0.7 (Debian 12) has no ``vim.lsp.start()``; ``vim.lsp.start_client`` and
``vim.lsp.buf_attach_client`` are what its own docs use. The test is skipped
where ``nvim`` is not installed (``.ci/run`` installs it when it can).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("pygls")

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "lsp"

INIT_LUA = r"""
local out_path = os.getenv("MOOS_LINT_NVIM_OUT")
local server = vim.fn.json_decode(os.getenv("MOOS_LINT_NVIM_CMD"))
vim.api.nvim_create_autocmd("VimEnter", {
  callback = function()
    local bufnr = vim.api.nvim_get_current_buf()
    local client_id = vim.lsp.start_client({
      name = "moos-lint",
      cmd = server,
      root_dir = vim.fn.getcwd(),
    })
    vim.lsp.buf_attach_client(bufnr, client_id)
    local ok = vim.wait(30000, function()
      return #vim.diagnostic.get(bufnr) >= 3
    end, 50)
    local rows = {}
    for _, d in ipairs(vim.diagnostic.get(bufnr)) do
      local lsp_data = (d.user_data and d.user_data.lsp) or {}
      table.insert(rows, {
        lnum = d.lnum,
        col = d.col,
        severity = d.severity,
        source = d.source,
        message = d.message,
        code = d.code or lsp_data.code,
      })
    end
    local f = io.open(out_path, "w")
    f:write(vim.fn.json_encode({ ok = ok, diagnostics = rows }))
    f:close()
    vim.lsp.stop_client(client_id)
    vim.cmd("qa!")
  end,
})
"""


@pytest.mark.skipif(shutil.which("nvim") is None, reason="Neovim (nvim) is not installed")
def test_neovim_shows_the_servers_diagnostics(tmp_path: Path):
    work = tmp_path / "mission"
    work.mkdir()
    for f in FIXTURES.iterdir():
        shutil.copy(f, work / f.name)
    init = tmp_path / "init.lua"
    init.write_text(INIT_LUA)
    out = tmp_path / "out.json"
    env = dict(os.environ)
    env.update(
        MOOS_LINT_NVIM_OUT=str(out),
        MOOS_LINT_NVIM_CMD=json.dumps([sys.executable, "-m", "moos_lint", "server"]),
        XDG_CONFIG_HOME=str(tmp_path / "config"),
        XDG_DATA_HOME=str(tmp_path / "data"),
        XDG_STATE_HOME=str(tmp_path / "state"),
        XDG_CACHE_HOME=str(tmp_path / "cache"),
    )
    subprocess.run(
        ["nvim", "--headless", "-i", "NONE", "-u", str(init), "mission.moos"],
        cwd=work,
        env=env,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        timeout=90,
        check=False,
    )
    data = json.loads(out.read_text())
    assert data["ok"], data
    got = sorted((d["lnum"], d["col"], d["code"]) for d in data["diagnostics"])
    assert got == [(12, 2, "R007"), (15, 0, "R003"), (20, 0, "R003"), (24, 16, "L001")]
    assert {d["source"] for d in data["diagnostics"]} == {"moos-lint"}
    header = next(d for d in data["diagnostics"] if d["lnum"] == 15)
    assert header["severity"] == 1  # vim.diagnostic.severity.ERROR
    assert "MOOS never finds the block `pHelmIvP`" in header["message"]
