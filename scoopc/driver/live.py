"""Driver, `scoopc run --live PORT`: the running program served to Foxglove over the Foxglove
WebSocket protocol (the foxglove-sdk package, the `live` extra; docs/LIVE.md).

Channels: /scoop/processors, /scoop/waits and /scoop/events from the runtime's snapshot
(scoopc/runtime/snapshot.py), sampled at most 20 times a second and sent when they change
(events as they come); /sim/scene and /sim/robots from the simulator; and every ROS topic of
the run's bus, CDR-encoded with its ROS 2 schema, as `--record` writes them. The server starts
before the run (a port in use is a usage error); the run waits up to FIRST_CLIENT seconds for a
client's first subscription, and the server stops after the run, once the last messages are out.
"""

from __future__ import annotations

import json
import re
import sys
import threading
import time
from collections.abc import Callable
from typing import Any, Protocol, TextIO

from ..exits import UsageError
from ..robots import cdr, record, ros_messages, transport
from ..robots.runner import SIMULATOR_SERVICE
from ..runtime import snapshot
from ..runtime.protocols import Where
from ..runtime.sched import Runtime
from . import live_scene

FIRST_CLIENT = 10.0  # seconds the run waits for a client before it starts anyway
PERIOD = 0.05  # seconds between samples of the runtime's state (20 Hz)
DRAIN = 0.5  # seconds left to the server to send the last messages after the run
MISSING = 'scoopc: --live needs the foxglove-sdk package: pip install "scoopc[live]"'

PROCESSORS, WAITS, EVENTS = "/scoop/processors", "/scoop/waits", "/scoop/events"
SCENE, ROBOTS = "/sim/scene", "/sim/robots"
SOURCE = re.compile(r"([A-Z][A-Z0-9_]*)\.(\w+) \(([^()]*\.e):(\d+)\)")  # CLASS.routine (file.e:line) in reports

_STAMP = {"type": "object", "properties": {"sec": {"type": "integer"}, "nsec": {"type": "integer"}}}


def _object(**properties: Any) -> dict[str, Any]:
    return {"type": "object", "properties": properties}


def _rows(rows: str, **properties: Any) -> dict[str, Any]:
    return _object(timestamp=_STAMP, **{rows: {"type": "array", "items": _object(**properties)}})


_TEXT, _INT, _NUM = {"type": "string"}, {"type": "integer"}, {"type": "number"}
_MAYBE_TEXT, _MAYBE_INT = {"type": ["string", "null"]}, {"type": ["integer", "null"]}
SCHEMAS: dict[str, tuple[str, dict[str, Any]]] = {
    PROCESSORS: (
        "scoopc.Processors",
        _rows(
            "processors",
            id=_INT,
            name=_TEXT,
            **{"class": _TEXT},
            state={"type": "string", "enum": list(snapshot.STATES)},
            queued=_INT,
            serving=_MAYBE_TEXT,
            at=_MAYBE_TEXT,
            detail=_MAYBE_TEXT,
        ),
    ),
    WAITS: (
        "scoopc.Waits",
        _rows(
            "waits",
            processor=_TEXT,
            **{"class": _TEXT},
            routine=_TEXT,
            file=_TEXT,
            line=_INT,
            tag=_MAYBE_TEXT,
            clause=_MAYBE_TEXT,
            over={"type": "array", "items": _TEXT},
            since=_STAMP,
            waited=_NUM,
        ),
    ),
    # foxglove.Log's fields (Foxglove's log panel reads them), with the event's kind and its sources
    EVENTS: (
        "foxglove.Log",
        _object(
            timestamp=_STAMP,
            level=_INT,
            message=_TEXT,
            name=_TEXT,
            file=_TEXT,
            line=_INT,
            kind=_TEXT,
            sources={"type": "array", "items": _object(routine=_TEXT, file=_TEXT, line=_INT)},
        ),
    ),
    SCENE: ("foxglove.SceneUpdate", _object(deletions={"type": "array"}, entities={"type": "array"})),
    ROBOTS: (
        "scoopc.Robots",
        _rows(
            "robots",
            name=_TEXT,
            x=_NUM,
            y=_NUM,
            heading=_NUM,
            linear=_NUM,
            angular=_NUM,
            battery=_NUM,
            charging={"type": "boolean"},
            fallen={"type": "boolean"},
        ),
    ),
}
LEVELS = {"deadlock": 5, "failure": 5, "lost exception": 4, "dirty region": 3}  # foxglove.Log: 3 warning .. 5 fatal


def sdk() -> Any:
    """The foxglove package, or a usage error saying how to install it."""
    try:
        import foxglove  # optional: the `live` extra
    except ImportError:
        raise UsageError(MISSING) from None
    return foxglove


class Sink(Protocol):
    """Where the sampler's messages go: the Foxglove server, or the recording beside `--record`."""

    def attach(self, rt: Runtime) -> None: ...

    def send(self, topic: str, message: dict[str, Any], wall_ns: int, sim_ns: int | None) -> None: ...

    def heard(self, topic: str, msg: Any) -> None: ...

    def close(self) -> None: ...


class Sampler:
    """Samples the runtime's state (and the simulator's) for its sinks: at most every PERIOD seconds,
    each channel only when it changed, events as they come; made before the run, `attach`ed when
    the runtime starts, its last samples sent by a shutdown hook, `close`d after the run."""

    def __init__(self, clause_text: Callable[[Where], str | None], sinks: list[Sink]) -> None:
        self.clause_text = clause_text
        self.sinks = sinks
        self.stopped = threading.Event()
        self.thread: threading.Thread | None = None
        self.rt: Runtime | None = None
        self.scans: dict[str, Any] = {}  # [lock] robot name -> its last LaserScan
        self.proximity: dict[str, dict[str, float]] = {}  # [lock] robot name -> {sensor: last range}
        self.lock = threading.Lock()
        self.last: dict[str, object] = {}  # topic -> what was sent last (changes only)
        self.events_sent = 0
        self.tap: Any = None

    def attach(self, rt: Runtime) -> None:
        """When the run starts (before the root object exists)."""
        self.rt = rt
        for sink in self.sinks:
            sink.attach(rt)
        bus = transport.current()  # type: ignore[no-untyped-call]  # the robots layer is not annotated
        if bus is not None and hasattr(bus, "tap"):
            self.tap = bus.tap(self._heard)
        self.thread = threading.Thread(target=self._run, name="scoop-live", daemon=True)
        self.thread.start()
        with rt.glock:
            rt.shutdown_hooks.append(self.finish)

    def _run(self) -> None:
        while not self.stopped.wait(PERIOD):
            self.publish()

    def finish(self) -> None:
        """The run is over (a shutdown hook): the last samples and events go out."""
        self.stopped.set()
        if self.thread is not None:
            self.thread.join()
        if self.tap is not None:
            self.tap.close()
        self.publish()

    def close(self) -> None:
        for sink in self.sinks:
            sink.close()

    def publish(self) -> None:
        rt = self.rt
        if rt is None:
            return
        sim: Any = rt.services.get(SIMULATOR_SERVICE)
        now, sim_ns = time.time_ns(), (int(sim.time_ns) if sim is not None else None)
        snap = snapshot.take(rt, self.clause_text)
        self._changed(PROCESSORS, "processors", [_processor(p) for p in snap.processors], now, sim_ns)
        waits = [_wait(w) for w in snap.waits]
        key = [{**w, "waited": None, "since": None} for w in waits]
        self._changed(WAITS, "waits", waits, now, sim_ns, key)
        for event in snapshot.events(rt, self.events_sent):
            self._send(EVENTS, _event(event), now, sim_ns)
            self.events_sent = event.index + 1
        if sim is not None:
            with self.lock:
                scans, near = dict(self.scans), {name: dict(v) for name, v in self.proximity.items()}
            self._changed(ROBOTS, "robots", live_scene.robots(sim, now)["robots"], now, sim_ns)
            scene = live_scene.scene(sim, now, scans, near)
            self._changed(SCENE, "", scene, now, sim_ns, (_scene_key(sim), repr(near)))

    def _changed(self, topic: str, field: str, rows: Any, now: int, sim_ns: int | None, key: object = None) -> None:
        seen = key if key is not None else rows
        if self.last.get(topic) == seen:
            return
        self.last[topic] = seen
        self._send(topic, rows if not field else {"timestamp": live_scene.stamp(now), field: rows}, now, sim_ns)

    def _send(self, topic: str, message: dict[str, Any], now: int, sim_ns: int | None) -> None:
        for sink in self.sinks:
            sink.send(topic, message, now, sim_ns)

    def _heard(self, topic: str, msg: Any) -> None:
        """A message on the run's bus (any thread): a laser scan is kept for the scene."""
        typename = ros_messages.typename_of(msg)
        parts = topic.strip("/").split("/")
        if typename == "sensor_msgs/msg/LaserScan":
            with self.lock:
                self.scans[parts[0]] = msg
        elif typename == "sensor_msgs/msg/Range" and len(parts) == 3 and parts[1] == "proximity":
            with self.lock:
                self.proximity.setdefault(parts[0], {})[parts[2]] = float(msg.range)
        for sink in self.sinks:
            sink.heard(topic, msg)


class FoxgloveServer:
    """A Foxglove WebSocket server on 127.0.0.1:`port` for one run: started when made (the port
    is taken then, before the run); the run waits for a client's first subscription."""

    def __init__(self, port: int, stderr: TextIO | None = None) -> None:
        fg = sdk()
        self.fg = fg
        self.stderr = stderr or sys.stderr
        self.subscribed = threading.Event()
        self.context = fg.Context()
        self.channels = {
            topic: fg.Channel(topic, schema=self._schema(name, schema), message_encoding="json", context=self.context)
            for topic, (name, schema) in SCHEMAS.items()
        }
        self.ros: dict[str, Any] = {}  # [lock] topic -> Channel of a ROS topic (CDR)
        self.lock = threading.Lock()
        try:
            self.server = fg.start_server(
                name="scoopc", host="127.0.0.1", port=port, server_listener=_Listener(self), context=self.context
            )
        except Exception as e:  # the SDK's own error type: the port is taken, or not ours to use
            raise UsageError(f"--live: cannot serve on port {port}: {e}") from None
        self.stderr.write(f"scoopc: live view on ws://127.0.0.1:{port} (open it in Foxglove, docs/LIVE.md)\n")

    def _schema(self, name: str, schema: dict[str, Any]) -> Any:
        return self.fg.Schema(name=name, encoding="jsonschema", data=json.dumps(schema).encode())

    def attach(self, rt: Runtime) -> None:
        if not self.subscribed.wait(FIRST_CLIENT):
            self.stderr.write(f"scoopc: no Foxglove client after {FIRST_CLIENT:g} s: running without one\n")

    def send(self, topic: str, message: dict[str, Any], wall_ns: int, sim_ns: int | None) -> None:
        self.channels[topic].log(message, log_time=wall_ns)

    def heard(self, topic: str, msg: Any) -> None:
        """A ROS message of the run: on its topic, CDR-encoded with its ROS 2 schema."""
        typename = ros_messages.typename_of(msg)
        with self.lock:
            channel = self.ros.get(topic)
            if channel is None:
                data = record.message_definition(typename).encode()
                schema = self.fg.Schema(name=typename, encoding="ros2msg", data=data)
                channel = self.fg.Channel(topic, schema=schema, message_encoding="cdr", context=self.context)
                self.ros[topic] = channel
        channel.log(cdr.serialize(msg, typename), log_time=record.stamp_ns(msg) or time.time_ns())

    def close(self) -> None:
        """After the run: give the server DRAIN seconds to send what is queued, then stop it."""
        if self.subscribed.is_set():
            time.sleep(DRAIN)
        self.server.stop()


class _Listener:
    """The server's callbacks: the first subscription lets the run start."""

    def __init__(self, view: FoxgloveServer) -> None:
        self.view = view

    def on_subscribe(self, client: Any, channel: Any) -> None:
        self.view.subscribed.set()

    def __getattr__(self, name: str) -> Callable[..., None]:  # the other callbacks: nothing to do
        if not name.startswith("on_"):
            raise AttributeError(name)
        return lambda *args: None


def _processor(p: snapshot.ProcessorInfo) -> dict[str, Any]:
    return {
        "id": p.id,
        "name": f"P{p.id}({p.cls})",
        "class": p.cls,
        "state": p.state,
        "queued": p.queued,
        "serving": f"P{p.serving}" if p.serving is not None else None,
        "at": p.at,
        "detail": p.detail,
    }


def _wait(w: snapshot.WaitInfo) -> dict[str, Any]:
    since = int(w.since * 1e9)
    return {
        "processor": f"P{w.processor}",
        "class": w.cls,
        "routine": w.routine,
        "file": w.file,
        "line": w.line,
        "tag": w.tag,
        "clause": w.clause,
        "over": [f"P{i}" for i in w.over],
        "since": live_scene.stamp(since),
        "waited": round(w.waited, 1),
    }


def _event(e: snapshot.EventInfo) -> dict[str, Any]:
    sources = [{"routine": f"{c}.{r}", "file": f, "line": int(n)} for c, r, f, n in SOURCE.findall(e.text)]
    first = sources[0] if sources else {"file": "", "line": 0}
    return {
        "timestamp": live_scene.stamp(int(e.at * 1e9)),
        "level": LEVELS.get(e.kind, 4),
        "message": e.text,
        "name": e.kind,
        "file": first["file"],
        "line": first["line"],
        "kind": e.kind,
        "sources": sources,
    }


def _scene_key(sim: Any) -> object:
    """What changes the scene: the robots' poses and the number of scans seen (changes only)."""
    return tuple((r.x, r.y, r.theta, len(r.trajectory)) for r in sim.robots)
