"""Driver, the live channels of a recorded run: `--record run.mcap` keeps run.mcap a rosbag2 MCAP
file (ROS 2 types only, scoopc/robots/record.py) and writes /scoop/processors, /scoop/waits,
/scoop/events, /sim/scene and /sim/robots to `run.scoop.mcap` beside it: JSON messages with their
JSON schemas (what Foxglove's panels read), on the simulated clock of the recording when there is
one, so that Foxglove shows both files of a run on one time line."""

from __future__ import annotations

import json
import sys
import threading
from pathlib import Path
from typing import Any, TextIO

from mcap.writer import CompressionType, Writer

from ..runtime.sched import Runtime
from .live import SCHEMAS


def beside(record: str | Path) -> Path:
    """run.mcap -> run.scoop.mcap"""
    path = Path(record)
    return path.with_name(path.stem + ".scoop.mcap")


class JsonRecording:
    """The sampler's messages in an MCAP file, one channel per live topic. The file is made when the
    run starts, once the rosbag2 recording beside it has been (whose path errors are reported first)."""

    def __init__(self, path: str | Path, stderr: TextIO | None = None) -> None:
        self.path = Path(path)
        self.stderr = stderr or sys.stderr
        self._lock = threading.Lock()
        self._closed = True  # until `attach` opens the file
        self._channels: dict[str, int] = {}

    def attach(self, rt: Runtime) -> None:
        try:
            self._stream = open(self.path, "wb")
        except OSError as e:
            self.stderr.write(f"scoopc: cannot write the live channels to {self.path}: {e.strerror or e}\n")
            return
        self._writer = Writer(self._stream, compression=CompressionType.ZSTD)
        self._writer.start(profile="", library="scoopc")
        for topic, (name, schema) in SCHEMAS.items():
            schema_id = self._writer.register_schema(name, "jsonschema", json.dumps(schema).encode())
            self._channels[topic] = self._writer.register_channel(topic, "json", schema_id)
        self._closed = False

    def send(self, topic: str, message: dict[str, Any], wall_ns: int, sim_ns: int | None) -> None:
        when = sim_ns if sim_ns is not None else wall_ns
        with self._lock:
            if not self._closed:
                self._writer.add_message(
                    self._channels[topic], log_time=when, publish_time=when, data=json.dumps(message).encode()
                )

    def heard(self, topic: str, msg: Any) -> None:
        pass  # the ROS topics are in the rosbag2 file itself

    def close(self) -> None:
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._writer.finish()  # type: ignore[no-untyped-call]  # mcap's Writer is not annotated
            self._stream.close()
        self.stderr.write(f"scoopc: live channels written to {self.path}\n")
