"""Recording a run: every message of a bus into one MCAP file, as ROS 2 records it (rosbag2's MCAP).

`Recorder(bus, path)` taps the bus (`bus.tap`: every topic, whoever publishes) and writes:

* profile `ros2`; one schema per message type, encoding `ros2msg`, named `pkg/msg/Name`, whose data
  is the message definition with its dependencies (rosbags' `generate_msgdef`, ROS 2 flavour: the
  type's fields, then `====...` and `MSG: pkg/Name` blocks), as rosbag2 writes it;
* one channel per topic, message encoding `cdr`; each message is our CDR (`cdr.serialize`, with
  the 4-byte encapsulation header), as rosbag2 stores it;
* log time and publish time: the message's own stamp (`header.stamp`, or `clock` of a /clock
  message); for a message without a stamp (Twist, ...) the recorder's `clock()` (e.g. the
  simulator's time in nanoseconds) when given, else the latest stamp seen, else the wall clock.

The result is a single `.mcap` file (zstd-compressed chunks, with the summary and indexes) that
Foxglove opens and `ros2 bag info/play` reads. `close()` finishes the file (idempotent); the recorder
is a context manager too. Messages may come from several threads (a DDS reader thread and the
simulator's): writes are serialised by a lock.
"""

from __future__ import annotations

import threading
import time

from mcap.writer import CompressionType, Writer

from . import cdr, ros_messages

PROFILE = "ros2"
SCHEMA_ENCODING = "ros2msg"
MESSAGE_ENCODING = "cdr"


def message_definition(typename: str, store=None) -> str:
    """The ros2msg schema text of a type: its definition followed by every dependency's."""
    text, _ = (ros_messages.typestore() if store is None else store).generate_msgdef(typename, ros_version=2)
    return text


def stamp_ns(msg) -> int | None:
    """The message's own time in nanoseconds (header.stamp, or a Clock's clock), None if it has none
    (or a zero stamp)."""
    stamp = getattr(getattr(msg, "header", None), "stamp", None)
    if stamp is None and ros_messages.typename_of(msg) == "rosgraph_msgs/msg/Clock":
        stamp = msg.clock
    if stamp is None:
        return None
    ns = int(stamp.sec) * 1_000_000_000 + int(stamp.nanosec)
    return ns if ns > 0 else None


class Recorder:
    """Writes every message published on `bus` to the MCAP file `path` until `close()`."""

    def __init__(self, bus, path, *, clock=None, store=None, compression: str = "zstd"):
        self.path = str(path)
        self.clock = clock
        self.store = store
        self.count = 0
        self.counts = {}  # topic -> messages written
        self._lock = threading.Lock()
        self._stream = open(self.path, "wb")
        kind = {"zstd": CompressionType.ZSTD, "lz4": CompressionType.LZ4, "none": CompressionType.NONE}[compression]
        self._writer = Writer(self._stream, compression=kind)
        self._writer.start(profile=PROFILE, library="scoopc")
        self._schemas = {}  # typename -> schema id
        self._channels = {}  # topic -> (typename, channel id)
        self._last_stamp = None
        self._closed = False
        self._tap = bus.tap(self.write) if bus is not None else None

    def _channel(self, topic: str, typename: str) -> int:
        known = self._channels.get(topic)
        if known is not None:
            if known[0] != typename:
                raise TypeError(f"topic {topic} carries {known[0]}, not {typename}")
            return known[1]
        schema = self._schemas.get(typename)
        if schema is None:
            data = message_definition(typename, self.store).encode()
            schema = self._schemas[typename] = self._writer.register_schema(typename, SCHEMA_ENCODING, data)
        channel = self._writer.register_channel(topic, MESSAGE_ENCODING, schema)
        self._channels[topic] = (typename, channel)
        return channel

    def _log_time(self, msg) -> int:
        own = stamp_ns(msg)
        if own is not None:
            self._last_stamp = own
            return own
        if self.clock is not None:
            return int(self.clock())
        return self._last_stamp if self._last_stamp is not None else time.time_ns()

    def write(self, topic: str, msg, log_time: int | None = None) -> None:
        """Record one message (the tap calls this for every message of the bus)."""
        typename = ros_messages.typename_of(msg)
        data = cdr.serialize(msg, typename, self.store)
        with self._lock:
            if self._closed:
                return
            channel = self._channel(topic, typename)
            when = self._log_time(msg) if log_time is None else int(log_time)
            self.counts[topic] = self.counts.get(topic, 0) + 1
            self._writer.add_message(channel, log_time=when, data=data, publish_time=when, sequence=self.counts[topic])
            self.count += 1

    def close(self) -> str:
        """Stop recording and finish the file (summary, indexes); returns its path."""
        if self._tap is not None:
            self._tap.close()
        with self._lock:
            if self._closed:
                return self.path
            self._closed = True
            self._writer.finish()
            self._stream.close()
        return self.path

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def read(path, store=None):
    """The messages of an MCAP file written by a Recorder: [(topic, log_time_ns, message)] in
    log-time order, decoded with our CDR decoder (for tests and tools)."""
    from mcap.reader import make_reader

    found = []
    with open(path, "rb") as f:
        for schema, channel, message in make_reader(f).iter_messages(log_time_order=True):
            found.append((channel.topic, message.log_time, cdr.deserialize(message.data, schema.name, store)))
    return found
