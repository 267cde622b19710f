"""ROS 2 over DDS without rclpy: a `DdsBus` (same interface as `bus.Bus`) on cyclonedds.

ROS 2's conventions (as rmw_cyclonedds_cpp applies them):

* ROS topic `/<name>` is DDS topic `rt/<name>` (`/robot1/cmd_vel` -> `rt/robot1/cmd_vel`);
* ROS type `pkg/msg/Name` is DDS type `pkg::msg::dds_::Name_` (nested types likewise);
* the domain is `ROS_DOMAIN_ID` (default 0), unless given;
* QoS (`qos_for(topic)`): sensor topics (`odom`, `scan`, `battery_state`, `proximity/*`, `ground/*`)
  get ROS's sensor-data QoS (best effort, volatile, keep last 5); `/clock` gets rclcpp's ClockQoS
  (best effort, volatile, keep last 1); everything else (`cmd_vel`, ...) ROS's default QoS
  (reliable, volatile, keep last 10);
* the endpoint user data holds `typehash=RIHS01_<hex>;` (REP 2011, as ROS 2 Iron/Jazzy+ do), the hash
  computed by rosbags' `hash_rihs01` from the type store's definitions;
* the payload is our CDR (`cdr.serialize`, XCDR1 plain CDR little endian), padded with zeros to a
  multiple of 4 with the padding count in the encapsulation options (XTypes 1.3, 7.6.3.1.2).

The DDS type itself is an `IdlStruct` built from the type store with the ROS DDS type name (so
that the type name and XTypes information are those of the ROS IDL), but samples never go through
cyclonedds' Python serializer: the writer sends our CDR bytes as they are, and the reader hands the
received bytes to `cdr.deserialize`.

Subscriptions: one DDS reader per topic (shared by all subscriptions on that topic of this bus);
one reader thread per DdsBus (started on the first subscription, owned by the bus and joined by
`close()`) waits on a WaitSet and calls the callbacks with type-store messages, in subscription
order. A callback that raises is logged (and kept in `errors`); the other callbacks still run.
A subscription needs the topic's message type: `subscribe(topic, cb, msgtype=...)`, or the `types`
mapping given to the bus, or the robot interface's default (`default_type(topic)`).
"""

from __future__ import annotations

import logging
import os
import threading
import time

from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import GuardCondition, InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import make_idl_struct, types as idl
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from . import cdr, ros_messages
from .bus import Subscription, Tapped
from .ros_messages import ARRAY, BASE, NAME

log = logging.getLogger(__name__)

SENSOR_TOPICS = ("odom", "scan", "battery_state")
SENSOR_GROUPS = ("proximity", "ground")
#: message types of the robot interface (DESIGN section 7), by topic name relative to the namespace
DEFAULT_TYPES = {
    "cmd_vel": "geometry_msgs/msg/Twist",
    "odom": "nav_msgs/msg/Odometry",
    "scan": "sensor_msgs/msg/LaserScan",
    "battery_state": "sensor_msgs/msg/BatteryState",
    "clock": "rosgraph_msgs/msg/Clock",
}


def dds_topic_name(topic: str) -> str:
    """`/robot1/cmd_vel` -> `rt/robot1/cmd_vel` (ROS topics are absolute names here)."""
    if not topic.startswith("/"):
        raise ValueError(f"ROS topic names given to the DDS bus are absolute: {topic!r}")
    return "rt" + topic


def dds_type_name(typename: str) -> str:
    """`geometry_msgs/msg/Twist` -> `geometry_msgs::msg::dds_::Twist_`."""
    package, kind, name = typename.split("/")
    return f"{package}::{kind}::dds_::{name}_"


def _parts(topic: str) -> list[str]:
    return [part for part in topic.split("/") if part]


def topic_kind(topic: str) -> str:
    """ "sensor", "clock" or "command" (the QoS family of a ROS topic)."""
    parts = _parts(topic)
    if parts == ["clock"]:
        return "clock"
    if parts and (parts[-1] in SENSOR_TOPICS or (len(parts) >= 2 and parts[-2] in SENSOR_GROUPS)):
        return "sensor"
    return "command"


def qos_policies(topic: str) -> list:
    kind = topic_kind(topic)
    if kind == "command":
        return [
            Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
            Policy.Durability.Volatile,
            Policy.History.KeepLast(10),
        ]
    depth = 5 if kind == "sensor" else 1
    return [Policy.Reliability.BestEffort, Policy.Durability.Volatile, Policy.History.KeepLast(depth)]


def default_type(topic: str) -> str | None:
    """The robot interface's message type of `topic` (None if it is not a robot topic)."""
    parts = _parts(topic)
    if len(parts) >= 2 and parts[-2] in SENSOR_GROUPS:
        return "sensor_msgs/msg/Range"
    return DEFAULT_TYPES.get(parts[-1]) if parts else None


def domain_id() -> int:
    return int(os.environ.get("ROS_DOMAIN_ID", "0") or 0)


#: Cyclone DDS settings that keep every participant on 127.0.0.1 (no multicast, unicast discovery)
LOOPBACK_CONFIG = """<?xml version="1.0" encoding="UTF-8"?>
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain Id="any">
    <General>
      <Interfaces><NetworkInterface address="127.0.0.1"/></Interfaces>
      <AllowMulticast>false</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>50</MaxAutoParticipantIndex>
      <Peers><Peer address="127.0.0.1"/></Peers>
    </Discovery>
  </Domain>
</CycloneDDS>
"""


def loopback_environment(folder, domain: int) -> dict:
    """Environment variables binding DDS to loopback in `domain`: writes `folder`/cyclonedds.xml and
    returns {"CYCLONEDDS_URI": its file URI, "ROS_DOMAIN_ID": str(domain)} (set them before the
    first participant of a process exists, or pass them to a child process)."""
    from pathlib import Path

    path = Path(folder) / "cyclonedds.xml"
    path.write_text(LOOPBACK_CONFIG)
    return {"CYCLONEDDS_URI": path.resolve().as_uri(), "ROS_DOMAIN_ID": str(domain)}


_BASES = {
    "bool": bool,
    "byte": idl.byte,
    "char": idl.uint8,
    "int8": idl.int8,
    "uint8": idl.uint8,
    "int16": idl.int16,
    "uint16": idl.uint16,
    "int32": idl.int32,
    "uint32": idl.uint32,
    "int64": idl.int64,
    "uint64": idl.uint64,
    "float32": idl.float32,
    "float64": idl.float64,
}
_HANDLE_MASK = (1 << 64) - 1  # instance handles are uint64; the Python API may give them signed
_idl_types: dict = {}  # [_idl_lock] (id(store), typename) -> IdlStruct class
_idl_lock = threading.Lock()


def _idl_field(desc: tuple, store):
    kind, detail = desc
    if kind == BASE:
        name, bound = detail
        if name in ros_messages.STRING_TYPES:
            if name == "wstring":
                raise NotImplementedError("wstring fields are not supported")
            return idl.bounded_str[bound] if bound else str
        return _BASES[name]
    if kind == NAME:
        return idl_type(detail, store)
    element, size = detail
    if kind == ARRAY:
        return idl.array[_idl_field(element, store), size]
    return idl.sequence[_idl_field(element, store), size] if size else idl.sequence[_idl_field(element, store)]


def idl_type(typename: str, store=None):
    """The cyclonedds IdlStruct of a ROS message type, named as ROS names it on DDS."""
    key = (id(store), typename)
    with _idl_lock:
        found = _idl_types.get(key)
    if found is not None:
        return found
    fields = {name: _idl_field(desc, store) for name, desc in ros_messages.fields(typename, store)}
    cls = make_idl_struct(typename.replace("/", "_"), dds_type_name(typename), fields)
    with _idl_lock:
        return _idl_types.setdefault(key, cls)


def type_hash(typename: str, store=None) -> str:
    """`RIHS01_<hex>` (REP 2011) of a message type, from the type store's definitions."""
    return (ros_messages.typestore() if store is None else store).hash_rihs01(typename)


def qos_for(topic: str, typename: str, store=None) -> Qos:
    """The QoS of a ROS topic's readers and writers (with the type hash in the user data)."""
    userdata = f"typehash={type_hash(typename, store)};".encode()
    return Qos(*qos_policies(topic), Policy.Userdata(data=userdata))


def frame(payload: bytes) -> bytes:
    """Pad CDR to a multiple of 4 bytes, the padding count in the encapsulation options' low bits."""
    pad = -len(payload) % 4
    if not pad:
        return payload
    return payload[:3] + bytes([(payload[3] & ~3) | pad]) + payload[4:] + bytes(pad)


class _Reader:
    """One DDS reader and the subscriptions of this bus on its topic."""

    def __init__(self, topic, typename, dds_topic, reader, condition):
        self.topic = topic
        self.typename = typename
        self.dds_topic = dds_topic
        self.reader = reader
        self.condition = condition
        self.subs = []  # [DdsBus._lock] open Subscriptions, in subscription order


class DdsBus(Tapped):
    """Publish/subscribe on ROS 2 topics over DDS (cyclonedds), with ROS 2's names, types and QoS."""

    own_thread_callbacks = True  # the reader thread (see bus.Bus)

    def __init__(self, domain: int | None = None, types: dict | None = None, store=None):
        self.domain = domain_id() if domain is None else domain
        self.store = store
        self.types = dict(types or {})
        self.errors = []  # exceptions raised by callbacks (the first few)
        self.participant = DomainParticipant(self.domain)
        self._lock = threading.RLock()
        self._topics = {}  # [_lock] ROS topic -> (typename, Topic)
        self._writers = {}  # [_lock] ROS topic -> DataWriter
        self._readers = {}  # [_lock] ROS topic -> _Reader
        self._waitset = WaitSet(self.participant)
        self._wake = GuardCondition(self.participant)
        self._waitset.attach(self._wake)
        self._thread = None  # [_lock] the reader thread, started on first subscribe
        self._closed = False
        self._taps = []  # Taps (a list replaced on change: read without the lock)
        self._own = set()  # [_lock] instance handles of our writers

    # -- entities ---------------------------------------------------------------------------------
    def _topic(self, topic: str, typename: str) -> Topic:
        with self._lock:
            self._check_open()
            known = self._topics.get(topic)
            if known is not None:
                if known[0] != typename:
                    raise TypeError(f"topic {topic} carries {known[0]}, not {typename}")
                return known[1]
            entity = Topic(
                self.participant, dds_topic_name(topic), idl_type(typename, self.store), qos=Qos(*qos_policies(topic))
            )
            self._topics[topic] = (typename, entity)
            return entity

    def writer(self, topic: str, typename: str) -> DataWriter:
        """The DDS writer of `topic` (created on first use)."""
        with self._lock:
            writer = self._writers.get(topic)
            if writer is None:
                dds_topic = self._topic(topic, typename)
                writer = DataWriter(self.participant, dds_topic, qos=qos_for(topic, typename, self.store))
                self._writers[topic] = writer
                self._own.add(writer.get_instance_handle() & _HANDLE_MASK)  # as SampleInfo has it: unsigned
            elif self._topics[topic][0] != typename:
                raise TypeError(f"topic {topic} carries {self._topics[topic][0]}, not {typename}")
            return writer

    def _typename(self, topic: str, msgtype: str | None) -> str:
        """The message type of `topic`: given, already in use on this bus, configured, or the default."""
        with self._lock:
            known = self._topics.get(topic)
        typename = msgtype or (known and known[0]) or self.types.get(topic) or default_type(topic)
        if typename is None:
            raise TypeError(f"no message type known for {topic}: pass msgtype=")
        return typename

    def _check_open(self):
        if self._closed:
            raise RuntimeError("the DDS bus is closed")

    # -- the Bus interface -----------------------------------------------------------------------
    def publish(self, topic: str, msg) -> None:
        typename = ros_messages.typename_of(msg)
        writer = self.writer(topic, typename)
        ret = ddspy_write(writer._ref, frame(cdr.serialize(msg, typename, self.store)))
        if ret < 0:
            raise RuntimeError(f"DDS write on {topic} failed ({ret})")
        self._tapped(topic, msg)

    def publish_raw(self, topic: str, typename: str, payload: bytes) -> None:
        """Publish CDR bytes as they are (header included) on `topic`."""
        ret = ddspy_write(self.writer(topic, typename)._ref, frame(bytes(payload)))
        if ret < 0:
            raise RuntimeError(f"DDS write on {topic} failed ({ret})")
        if self._taps:
            self._tapped(topic, cdr.deserialize(payload, typename, self.store))

    def subscribe(self, topic: str, callback, msgtype: str | None = None, raw: bool = False) -> Subscription:
        """Call `callback(msg)` on the bus's reader thread for every message on `topic`
        (`raw=True`: the received CDR bytes, encapsulation header and padding included)."""
        typename = self._typename(topic, msgtype)
        sub = Subscription(self, topic, callback)
        sub.raw = raw
        with self._lock:
            entry = self._readers.get(topic)
            if entry is None:
                dds_topic = self._topic(topic, typename)
                reader = DataReader(self.participant, dds_topic, qos=qos_for(topic, typename, self.store))
                condition = ReadCondition(reader, SampleState.NotRead | ViewState.Any | InstanceState.Any)
                entry = _Reader(topic, typename, dds_topic, reader, condition)
                self._readers[topic] = entry
                self._waitset.attach(condition)
            elif entry.typename != typename:
                raise TypeError(f"topic {topic} carries {entry.typename}, not {typename}")
            entry.subs.append(sub)
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name=f"dds-bus-{self.domain}", daemon=True)
                self._thread.start()
        return sub

    def _remove(self, sub: Subscription) -> None:
        with self._lock:
            entry = self._readers.get(sub.topic)
            if entry is None or sub not in entry.subs:
                return
            entry.subs.remove(sub)
            if not entry.subs and not self._closed:
                del self._readers[sub.topic]
                self._waitset.detach(entry.condition)
                entry.condition.__del__()
                entry.reader.__del__()

    def subscriber_count(self, topic: str) -> int:
        with self._lock:
            entry = self._readers.get(topic)
            return len(entry.subs) if entry else 0

    def topics(self) -> list[str]:
        with self._lock:
            return sorted(self._readers)

    def wait_for_subscriber(self, topic: str, timeout: float | None = None, msgtype: str | None = None) -> bool:
        """Block until a DDS reader (any participant, this one included) matches our writer of `topic`."""
        typename = self._typename(topic, msgtype)
        writer = self.writer(topic, typename)
        return self._wait_matched(lambda: writer.get_publication_matched_status().current_count > 0, timeout)

    def wait_for_publisher(self, topic: str, timeout: float | None = None) -> bool:
        """Block until a DDS writer matches our reader of `topic` (subscribe first)."""
        with self._lock:
            entry = self._readers[topic]
        return self._wait_matched(lambda: entry.reader.get_subscription_matched_status().current_count > 0, timeout)

    @staticmethod
    def _wait_matched(matched, timeout):
        # discovery has no condition we can share with the reader thread: poll the status briefly
        deadline = None if timeout is None else time.monotonic() + timeout
        while not matched():
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.005)
        return True

    # -- the reader thread -----------------------------------------------------------------------
    def _run(self) -> None:
        while True:
            with self._lock:
                if self._closed:
                    return
                entries = list(self._readers.values())
            for entry in entries:
                self._drain(entry)
            with self._lock:  # a callback may have closed the bus
                if self._closed:
                    return
            self._waitset.wait(duration(seconds=1))

    def _drain(self, entry: _Reader) -> None:
        while True:
            with self._lock:
                if self._closed or self._readers.get(entry.topic) is not entry:
                    return
                samples = ddspy_take(entry.reader._ref, entry.condition.mask, 64)
                subs = tuple(entry.subs)
                own = self._own if self._taps else ()
            if isinstance(samples, int):
                log.error("DDS take on %s failed (%d)", entry.topic, samples)
                return
            if not samples:
                return
            for data, info in samples:
                if not info.valid_data:
                    continue
                targets = subs
                try:
                    msg = cdr.deserialize(data, entry.typename, self.store)
                except Exception as e:  # a malformed sample: drop it, keep the bus alive
                    log.error("undecodable %s sample on %s: %s", entry.typename, entry.topic, e)
                    targets = tuple(sub for sub in subs if sub.raw)
                    msg = None
                if msg is not None and self._taps and (info.publication_handle & _HANDLE_MASK) not in own:
                    self._tapped(entry.topic, msg)
                for sub in targets:
                    if sub.closed:
                        continue
                    try:
                        sub.callback(data if sub.raw else msg)
                    except Exception as e:  # the other subscribers still get the message
                        log.exception("subscriber of %s raised", entry.topic)
                        if len(self.errors) < 100:
                            self.errors.append(e)

    # -- shutdown ---------------------------------------------------------------------------------
    def close(self) -> None:
        """Stop the reader thread (joined) and delete every DDS entity of this bus (idempotent)."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            thread, self._thread = self._thread, None
            self._wake.set(True)
        if thread is not None and thread is not threading.current_thread():
            thread.join()
        with self._lock:
            for entry in self._readers.values():
                for sub in entry.subs:
                    sub.closed = True
                self._waitset.detach(entry.condition)
                entry.condition.__del__()
                entry.reader.__del__()
            self._readers.clear()
            for writer in self._writers.values():
                writer.__del__()
            self._writers.clear()
            self._waitset.detach(self._wake)
            self._wake.__del__()
            self._waitset.__del__()
            for _, entity in self._topics.values():
                entity.__del__()
            self._topics.clear()
            self.participant.__del__()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
