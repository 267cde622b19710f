"""A small LSP client over a pair of byte streams, as an editor speaks to `scoopc lsp`: requests
with ids, notifications, and the server's notifications collected by method. The tests and the
re-check benchmark drive the server with it."""

from __future__ import annotations

import json
import queue
import threading
import time
from pathlib import Path
from typing import Any, BinaryIO


class Client:
    def __init__(self, reader: BinaryIO, writer: BinaryIO) -> None:
        self.reader, self.writer = reader, writer
        self.next_id = 0
        self.responses: dict[int, queue.Queue] = {}
        self.notifications: queue.Queue = queue.Queue()
        self.lock = threading.Lock()
        self.thread = threading.Thread(target=self._read, name="lsp-client", daemon=True)
        self.thread.start()

    # ---- the wire ------------------------------------------------------------------------------
    def _send(self, message: dict[str, Any]) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode()
        with self.lock:
            self.writer.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
            self.writer.flush()

    def _read(self) -> None:
        while True:
            length = 0
            while True:
                line = self.reader.readline()
                if not line:
                    return  # the server closed its output
                if line in (b"\r\n", b"\n"):
                    break
                name, _, value = line.decode().partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            message = json.loads(self.reader.read(length))
            if "id" in message and "method" not in message:
                self.responses.setdefault(message["id"], queue.Queue()).put(message)
            elif "id" in message:  # a request of the server's (configuration, ...): answer nothing
                self._send({"id": message["id"], "result": None})
            else:
                self.notifications.put(message)

    # ---- requests and notifications -----------------------------------------------------------
    def request(self, method: str, params: Any, timeout: float = 60) -> Any:
        with self.lock:
            self.next_id += 1
            number = self.next_id
            self.responses.setdefault(number, queue.Queue())
        self._send({"id": number, "method": method, "params": params})
        answer = self.responses[number].get(timeout=timeout)
        if "error" in answer:
            raise RuntimeError(f"{method}: {answer['error']}")
        return answer.get("result")

    def notify(self, method: str, params: Any) -> None:
        self._send({"method": method, "params": params})

    def initialize(self, root: Path) -> Any:
        result = self.request("initialize", {"processId": None, "rootUri": root.as_uri(), "capabilities": {}})
        self.notify("initialized", {})
        return result

    def shutdown(self) -> None:
        self.request("shutdown", None)
        self.notify("exit", None)

    # ---- documents ----------------------------------------------------------------------------
    def open(self, path: Path, text: str | None = None, version: int = 1) -> str:
        uri = path.resolve().as_uri()
        text = path.read_text() if text is None else text
        item = {"uri": uri, "languageId": "eiffel", "version": version, "text": text}
        self.notify("textDocument/didOpen", {"textDocument": item})
        return uri

    def change(self, uri: str, text: str, version: int) -> None:
        document = {"uri": uri, "version": version}
        self.notify("textDocument/didChange", {"textDocument": document, "contentChanges": [{"text": text}]})

    def diagnostics(self, uri: str, version: int | None = None, timeout: float = 60) -> list[dict[str, Any]]:
        """The next diagnostics published for `uri` (for `version`, when given)."""
        deadline = time.monotonic() + timeout
        while True:
            message = self.notifications.get(timeout=max(deadline - time.monotonic(), 0.001))
            if message.get("method") != "textDocument/publishDiagnostics":
                continue
            params = message["params"]
            if params["uri"] == uri and (version is None or params.get("version") == version):
                return params["diagnostics"]

    def at(self, method: str, uri: str, line: int, character: int, **extra: Any) -> Any:
        """A request about a position (0-based line and character, as LSP counts)."""
        params = {"textDocument": {"uri": uri}, "position": {"line": line, "character": character}, **extra}
        return self.request(method, params)
