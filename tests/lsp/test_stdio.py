"""`scoopc lsp` as an editor starts it: a process speaking LSP on its stdin and stdout (nothing else
may write there), ending with exit code 0 after shutdown and exit."""

from __future__ import annotations

import subprocess
import sys

import pytest

from scoopc.lsp.client import Client


@pytest.mark.slow
def test_the_server_process_speaks_lsp_on_stdio(program):
    server = subprocess.Popen(
        [sys.executable, "-m", "scoopc", "lsp", "--stdio"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    client = Client(server.stdout, server.stdin)
    try:
        capabilities = client.initialize(program)["capabilities"]
        assert capabilities["completionProvider"]["triggerCharacters"] == ["."]
        assert capabilities["hoverProvider"] and capabilities["definitionProvider"]
        uri = client.open(program / "robot_app.e")
        assert [d["code"] for d in client.diagnostics(uri)] == ["VUTA(3)", "VEEN"]
        client.shutdown()
        assert server.wait(timeout=30) == 0
    finally:
        if server.poll() is None:
            server.kill()
            server.wait()
        server.stderr.close()
