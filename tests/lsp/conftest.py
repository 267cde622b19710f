"""The language server in this process, on two pipes, with the LSP client of scoopc.lsp.client:
the same bytes an editor exchanges with `scoopc lsp` over stdio, without starting a process."""

from __future__ import annotations

import os
import shutil
import threading
from pathlib import Path

import pytest

from scoopc.lsp import server
from scoopc.lsp.client import Client

HERE = Path(__file__).parent


@pytest.fixture
def lsp(tmp_path):
    to_server, from_client = os.pipe()
    to_client, from_server = os.pipe()
    streams = [os.fdopen(fd, mode) for fd, mode in ((to_server, "rb"), (from_server, "wb"))]
    thread = threading.Thread(target=server.serve, args=streams, name="scoopc-lsp", daemon=True)
    thread.start()
    client = Client(os.fdopen(to_client, "rb"), os.fdopen(from_client, "wb"))
    client.initialize(tmp_path)
    yield client
    client.shutdown()
    client.writer.close()  # end of input: the server's reader stops
    thread.join(timeout=10)
    assert not thread.is_alive(), "the language server did not stop after exit"


@pytest.fixture
def program(tmp_path) -> Path:
    """A copy of tests/lsp/program: a motor called without control (VUTA(3)) and a misspelt feature."""
    target = tmp_path / "program"
    shutil.copytree(HERE / "program", target)
    return target
