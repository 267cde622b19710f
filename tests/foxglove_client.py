"""A small client of the Foxglove WebSocket protocol (foxglove/ws-protocol, docs/spec.md, subprotocol
`foxglove.websocket.v1`, which the SDK's server names `foxglove.sdk.v1`) for the tests: it reads the
server's advertised channels, subscribes, and decodes Message Data frames (opcode 1: subscription
id u32, receive time u64, payload; all little-endian); JSON channels are parsed, others kept as bytes."""

from __future__ import annotations

import json
import re
import socket
import struct
import threading
import time

from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect

# the SDK's server (foxglove-sdk 0.30) speaks the protocol as `foxglove.sdk.v1`; Foxglove offers both
SUBPROTOCOLS = ("foxglove.sdk.v1", "foxglove.websocket.v1")
MESSAGE_DATA = 0x01
# The SDK's server can answer a subscription sent at once after a channel's advertisement with this
# status (the channel is not registered for the connection yet): the client subscribes again.
UNKNOWN = re.compile(r"Unknown channel ID: (\d+)")
RETRIES = 20


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class FoxgloveClient:
    """Connects to ws://127.0.0.1:`port` (retrying until `timeout`), subscribes to every channel
    advertised whose topic is in `topics` (all when None), and records what arrives until the
    server closes the connection, in a thread of its own."""

    def __init__(self, port: int, topics: set[str] | None = None, timeout: float = 60.0) -> None:
        self.port = port
        self.topics = topics
        self.timeout = timeout
        self.channels: dict[int, dict] = {}  # channel id -> its advertisement
        self.server_info: dict | None = None
        self.messages: list[tuple[str, object]] = []  # (topic, decoded payload) in arrival order
        self.error: BaseException | None = None
        self._subscriptions: dict[int, int] = {}  # subscription id -> channel id
        self._retries = 0
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _connect(self):
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                return connect(
                    f"ws://127.0.0.1:{self.port}",
                    subprotocols=list(SUBPROTOCOLS),
                    open_timeout=5,
                    proxy=None,
                    max_size=None,
                    compression=None,
                )
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)

    def _run(self) -> None:
        try:
            with self._connect() as ws:
                assert ws.subprotocol in SUBPROTOCOLS
                for frame in ws:
                    if isinstance(frame, str):
                        self._text(ws, json.loads(frame))
                    else:
                        self._binary(frame)
        except ConnectionClosed:
            pass
        except BaseException as e:  # reported by the test through `error`
            self.error = e

    def _text(self, ws, message: dict) -> None:
        op = message["op"]
        if op == "serverInfo":
            self.server_info = message
        elif op == "advertise":
            wanted = []
            for channel in message["channels"]:
                self.channels[channel["id"]] = channel
                if self.topics is None or channel["topic"] in self.topics:
                    sub = len(self._subscriptions) + 1
                    self._subscriptions[sub] = channel["id"]
                    wanted.append({"id": sub, "channelId": channel["id"]})
            if wanted:
                ws.send(json.dumps({"op": "subscribe", "subscriptions": wanted}))
        elif op == "status" and UNKNOWN.match(message["message"]) and self._retries < RETRIES:
            self._retries += 1
            channel = int(UNKNOWN.match(message["message"]).group(1))
            time.sleep(0.02)
            sub = len(self._subscriptions) + 1
            self._subscriptions[sub] = channel
            ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": sub, "channelId": channel}]}))

    def _binary(self, frame: bytes) -> None:
        if frame[0] != MESSAGE_DATA:
            return
        sub, _received = struct.unpack_from("<IQ", frame, 1)
        channel = self.channels[self._subscriptions[sub]]
        payload = frame[13:]
        decoded = json.loads(payload) if channel["encoding"] == "json" else payload
        self.messages.append((channel["topic"], decoded))

    def on(self, topic: str) -> list:
        return [m for t, m in self.messages if t == topic]

    def close(self, timeout: float = 30.0) -> None:
        self.thread.join(timeout)
        if self.error is not None:
            raise self.error
