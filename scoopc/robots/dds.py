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
from .discovery import (  # noqa: F401 - part of this module's interface (DdsBus's discovery, tests)
    LOOPBACK_CONFIG,
    RANGES,
    DiscoveryError,
    _acquire_domain,
    _release_domain,
    discovery_config,
    discovery_settings,
    loopback_environment,
)
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


def ros_type_name(dds_name: str) -> str:
    """`geometry_msgs::msg::dds_::Twist_` -> `geometry_msgs/msg/Twist` (other names unchanged)."""
    parts = dds_name.split("::")
    if len(parts) == 4 and parts[2] == "dds_" and parts[3].endswith("_"):
        return f"{parts[0]}/{parts[1]}/{parts[3][:-1]}"
    return dds_name


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


def qos_policies(topic: str, reliability: str | None = None, depth: int | None = None) -> list:
    """The QoS of `topic`'s readers and writers by its family (see the module's docstring);
    `reliability` ("reliable" or "best_effort") and `depth` override the family's (a writer
    standing for a driver that publishes reliably, a profile's QoS)."""
    kind = topic_kind(topic)
    if kind == "command":
        reliability, depth = reliability or "reliable", depth or 10
    else:
        reliability, depth = reliability or "best_effort", depth or (5 if kind == "sensor" else 1)
    if reliability == "reliable":
        rel = Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100))
    else:
        rel = Policy.Reliability.BestEffort
    return [rel, Policy.Durability.Volatile, Policy.History.KeepLast(depth)]


def default_type(topic: str) -> str | None:
    """The robot interface's message type of `topic` (None if it is not a robot topic)."""
    parts = _parts(topic)
    if len(parts) >= 2 and parts[-2] in SENSOR_GROUPS:
        return "sensor_msgs/msg/Range"
    return DEFAULT_TYPES.get(parts[-1]) if parts else None


def domain_id() -> int:
    return int(os.environ.get("ROS_DOMAIN_ID", "0") or 0)


#: DDS QoS policy ids (Cyclone DDS's dds_qos_policy_id_t) named in incompatibility reports
_POLICIES = {
    2: "durability",
    4: "deadline",
    8: "liveliness",
    11: "reliability",
    12: "destination order",
    13: "history",
    23: "data representation",
    24: "type consistency",
}


def reliability_of(topic: str, override: str | None = None) -> str:
    """ "reliable" or "best effort": the reliability `qos_policies` gives `topic`."""
    chosen = override or ("reliable" if topic_kind(topic) == "command" else "best_effort")
    return "reliable" if chosen == "reliable" else "best effort"


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


def qos_for(topic: str, typename: str, store=None, reliability=None, depth=None, distro=None) -> Qos:
    """The QoS of a ROS topic's readers and writers, with the type hash in the user data from
    Iron on (rmw_cyclonedds_cpp/src/rmw_node.cpp create_readwrite_qos, jazzy branch; Humble's
    create_readwrite_qos sets no endpoint user data)."""
    policies = qos_policies(topic, reliability, depth)
    if (distro or ros_messages.distro()) == "humble":
        return Qos(*policies)
    userdata = f"typehash={type_hash(typename, store)};".encode()
    return Qos(*policies, Policy.Userdata(data=userdata))


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
        self.count = 0  # samples received (read by the "nothing heard" report)


class DdsBus(Tapped):
    """Publish/subscribe on ROS 2 topics over DDS (cyclonedds), with ROS 2's names, types and QoS."""

    own_thread_callbacks = True  # the reader thread (see bus.Bus)

    def __init__(
        self,
        domain: int | None = None,
        types: dict | None = None,
        store=None,
        *,
        writer_qos=None,
        reader_qos=None,
        environ=None,
        report=None,
    ):
        """`writer_qos`/`reader_qos`: {ROS topic: (reliability, depth)} overriding the topic family's
        QoS ("reliable" or "best_effort"; depth None keeps the family's); `environ`: where the
        discovery variables are read (default os.environ); `report(text)`: where QoS
        incompatibilities are told, once per topic (default: the log)."""
        self.domain = domain_id() if domain is None else domain
        self.store = store
        self.distro = ros_messages.distro()
        self.types = dict(types or {})
        self.writer_qos = dict(writer_qos or {})
        self.reader_qos = dict(reader_qos or {})
        self.report = report or (lambda text: log.warning("%s", text))
        self.errors = []  # exceptions raised by callbacks (the first few)
        self.reported = set()  # topics whose QoS incompatibility was told
        self._history = {}  # [_lock] topic -> (publishers, samples) of closed readers
        config, self.discovery, self.discovery_warnings = discovery_config(self.distro, environ)
        self._held = _acquire_domain(self.domain, config)
        if not self._held:
            self.discovery += " (not applied: another participant of this process opened the domain first)"
        try:
            self.participant = DomainParticipant(self.domain, qos=Qos(Policy.Userdata(data=b"enclave=/;")))
        except Exception:
            if self._held:
                _release_domain(self.domain)
            raise
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
        self.entity_hooks = []  # called after a reader or writer is made or deleted (graph.GraphNode)
        self.owned = []  # objects with DDS entities of this participant, closed before it (graph.GraphNode)

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
                writer = DataWriter(
                    self.participant,
                    dds_topic,
                    qos=qos_for(topic, typename, self.store, *self.writer_qos.get(topic, (None, None))),
                )
                self._writers[topic] = writer
                self._own.add(writer.get_instance_handle() & _HANDLE_MASK)  # as SampleInfo has it: unsigned
                self._entities_changed()
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

    def endpoint_guids(self) -> tuple[list, list]:
        """(GUIDs of this bus's readers, of its writers): the node's entities in the ROS graph."""
        with self._lock:
            readers = [e.reader.guid for e in self._readers.values()]
            writers = [w.guid for w in self._writers.values()]
            for child in self.owned:
                theirs = child.guids() if hasattr(child, "guids") else ([], [])
                readers += theirs[0]
                writers += theirs[1]
            return readers, writers

    def _entities_changed(self) -> None:
        for hook in list(self.entity_hooks):
            hook()

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
                reader = DataReader(
                    self.participant,
                    dds_topic,
                    qos=qos_for(topic, typename, self.store, *self.reader_qos.get(topic, (None, None))),
                )
                condition = ReadCondition(reader, SampleState.NotRead | ViewState.Any | InstanceState.Any)
                entry = _Reader(topic, typename, dds_topic, reader, condition)
                self._readers[topic] = entry
                self._waitset.attach(condition)
                self._entities_changed()
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
                self._remember(entry)
                del self._readers[sub.topic]
                self._waitset.detach(entry.condition)
                entry.condition.__del__()
                entry.reader.__del__()
                self._entities_changed()

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

    # -- what the graph holds (the "nothing heard" report) ----------------------------------------
    def _remember(self, entry) -> None:
        """Keep what a reader heard once it is deleted (the report at the end of a run) [_lock]."""
        try:
            publishers = entry.reader.get_subscription_matched_status().current_count
        except Exception:  # noqa: BLE001 - being deleted
            publishers = 0
        before = self._history.get(entry.topic, (0, 0))
        self._history[entry.topic] = (max(publishers, before[0]), entry.count + before[1])

    def heard(self) -> dict:
        """{ROS topic subscribed (now or before): (matched publishers, samples received)}."""
        with self._lock:
            entries = list(self._readers.values())
            found = dict(self._history)
        for e in entries:
            publishers = e.reader.get_subscription_matched_status().current_count
            before = found.get(e.topic, (0, 0))
            found[e.topic] = (max(publishers, before[0]), e.count + before[1])
        return found

    def graph_topics(self, readers: bool = False) -> dict:
        """{ROS topic: ROS type name} of every writer (`readers`: reader) discovery knows of, in any
        participant (this one's too)."""
        from cyclonedds.builtin import (  # deferred: start-up (cyclonedds loads only when this is used)
            BuiltinDataReader,
            BuiltinTopicDcpsPublication,
            BuiltinTopicDcpsSubscription,
        )

        with self._lock:
            self._check_open()
            graph = self.__dict__.setdefault("_graph", {})
            if readers not in graph:
                graph[readers] = BuiltinDataReader(
                    self.participant, BuiltinTopicDcpsSubscription if readers else BuiltinTopicDcpsPublication
                )
            found = {}
            for sample in graph[readers].read(N=4096) or ():
                name = getattr(sample, "topic_name", "")
                if name.startswith("rt/"):
                    found[name[2:]] = ros_type_name(getattr(sample, "type_name", ""))
        return found

    def unmatched_writers(self) -> list[tuple[str, str, str]]:
        """[(topic, our type, the type a reader of the graph asks)] for our writers that no reader
        matched while some node reads the topic with another type (Twist against TwistStamped)."""
        with self._lock:
            writers = [(t, w, self._topics[t][0]) for t, w in self._writers.items()]
        lonely = [(t, typename) for t, w, typename in writers if w.get_publication_matched_status().current_count == 0]
        if not lonely:
            return []
        graph = self.graph_topics(readers=True)
        return [(t, typename, graph[t]) for t, typename in lonely if t in graph and graph[t] != typename]

    def check_qos(self) -> list[str]:
        """New QoS incompatibilities (each topic once), told through `report` and returned:
        "/robot1/odom: the publisher is best effort, this reader asks reliable"."""
        found = []
        with self._lock:
            if self._closed:
                return found
            readers = [(t, e.reader, self.reader_qos.get(t, (None, None))) for t, e in self._readers.items()]
            writers = [(t, w, self.writer_qos.get(t, (None, None))) for t, w in self._writers.items()]
        for topic, reader, override in readers:
            if topic in self.reported:
                continue
            status = reader.get_requested_incompatible_qos_status()
            if status.total_count:
                mine = reliability_of(topic, override[0])
                policy = int(status.last_policy_id)
                if policy == 11:
                    other = "best effort" if mine == "reliable" else "reliable"
                    found.append((topic, f"{topic}: the publisher is {other}, this reader asks {mine}"))
                else:
                    found.append(
                        (
                            topic,
                            f"{topic}: a publisher's QoS is incompatible with this reader's "
                            f"({_POLICIES.get(policy, f'policy {policy}')})",
                        )
                    )
        for topic, writer, override in writers:
            if topic in self.reported:
                continue
            status = writer.get_offered_incompatible_qos_status()
            if status.total_count:
                mine = reliability_of(topic, override[0])
                policy = int(status.last_policy_id)
                if policy == 11:
                    found.append((topic, f"{topic}: a subscriber asks reliable, this publisher is {mine}"))
                else:
                    found.append(
                        (
                            topic,
                            f"{topic}: a subscriber's QoS is incompatible with this publisher's "
                            f"({_POLICIES.get(policy, f'policy {policy}')})",
                        )
                    )
        texts = []
        for topic, text in found:
            if topic not in self.reported:
                self.reported.add(topic)
                texts.append(text)
                self.report(text)
        return texts

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
            entry.count += len(samples)
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
            for reader in self.__dict__.pop("_graph", {}).values():
                reader.__del__()
            for child in reversed(list(self.owned)):
                child.close()
            self.owned.clear()
            self.participant.__del__()
        if self._held:
            _release_domain(self.domain)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
