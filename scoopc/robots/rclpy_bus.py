"""ROS 2 through rclpy: an `RclpyBus` with the interface of `bus.Bus` / `dds.DdsBus`.

UNVERIFIED: rclpy cannot be installed on the development machine (it comes with a ROS 2
distribution, not from PyPI), so this module has never run against a live ROS 2. It is kept thin
on purpose: everything ROS-specific is done by rclpy, and messages cross the boundary as CDR bytes,
so the rest of scoopc keeps using rosbags' type-store messages:

* publish: `cdr.serialize(msg)` -> `Publisher.publish(bytes)` (rclpy publishes a `bytes` object as
  an already serialized message, as `ros2 bag play` does);
* subscribe: `create_subscription(..., raw=True)` hands the callback the serialized bytes, which
  `cdr.deserialize` turns into a type-store message (`raw=True` on our side: the bytes themselves).

rclpy still needs the generated Python message class of each type for the type support
(`rosidl_runtime_py.utilities.get_message("geometry_msgs/msg/Twist")`), so the message packages
must be installed in the ROS 2 environment. QoS follows `dds.topic_kind`: sensor data QoS for
sensor topics, a best-effort keep-last-1 profile for /clock, ROS's default (reliable, keep last
10) for the rest, unless `writer_qos`/`reader_qos` override a topic (a robot profile). One node per
bus, spun by a SingleThreadedExecutor on a thread of the bus (callbacks run there, as with DdsBus);
`close()` stops and joins it and shuts the context down.

The reports of a ROS 2 run (scoopc.robots.silence) get what rclpy tells: QoS incompatibilities
through the endpoints' `incompatible_qos` event callbacks (rclpy/event_handler.py; Humble:
qos_event.py), each topic once as DdsBus words them; publishers per topic (`count_publishers`) and
messages received (`heard`); the graph's topics and types (`get_topic_names_and_types`,
`get_publishers_info_by_topic`/`get_subscriptions_info_by_topic`) for the nearby-topic hints and
the Twist/TwistStamped mismatch.
"""

from __future__ import annotations

import threading
import time

from . import cdr, ros_messages
from .bus import Subscription, Tapped
from .dds import default_type, reliability_of, topic_kind

try:  # rclpy comes with a ROS 2 installation, never from PyPI
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
    from rosidl_runtime_py.utilities import get_message

    try:
        from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
    except ImportError:  # Humble: the same classes in rclpy.qos_event
        from rclpy.qos_event import PublisherEventCallbacks, SubscriptionEventCallbacks
except ImportError:  # pragma: no cover - the backends module reports this
    rclpy = None

#: rclpy.qos.QoSPolicyKind (rmw's incompatible_qos_events_statuses.h): RELIABILITY is 1 << 4
_RELIABILITY_KIND = 1 << 4
_POLICY_KINDS = {1 << 1: "durability", 1 << 2: "deadline", 1 << 3: "liveliness", 1 << 5: "history", 1 << 6: "lifespan"}


def _qos(topic: str, reliability: str | None = None, depth: int | None = None):
    kind = topic_kind(topic)
    if reliability is None and depth is None:
        if kind == "sensor":
            return qos_profile_sensor_data
        if kind == "clock":
            return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
        return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=10)
    chosen = reliability or ("reliable" if kind == "command" else "best_effort")
    policy = ReliabilityPolicy.RELIABLE if chosen == "reliable" else ReliabilityPolicy.BEST_EFFORT
    depth = depth or (10 if kind == "command" else 5 if kind == "sensor" else 1)
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=depth, reliability=policy)


def incompatibility(topic: str, reader: bool, mine: str, policy_kind: int) -> str:
    """The report of an incompatible QoS, worded as DdsBus words it."""
    if int(policy_kind) == _RELIABILITY_KIND:
        if reader:
            other = "best effort" if mine == "reliable" else "reliable"
            return f"{topic}: the publisher is {other}, this reader asks {mine}"
        return f"{topic}: a subscriber asks reliable, this publisher is {mine}"
    policy = _POLICY_KINDS.get(int(policy_kind), f"policy {int(policy_kind)}")
    if reader:
        return f"{topic}: a publisher's QoS is incompatible with this reader's ({policy})"
    return f"{topic}: a subscriber's QoS is incompatible with this publisher's ({policy})"


class RclpyBus(Tapped):
    """Publish/subscribe on ROS 2 topics through an rclpy node (see the module's note: unverified)."""

    own_thread_callbacks = True  # the executor's thread (see bus.Bus)

    def __init__(
        self,
        domain: int | None = None,
        types: dict | None = None,
        node_name: str = "scoopc",
        namespace: str | None = None,
        writer_qos=None,
        reader_qos=None,
        report=None,
    ):
        if rclpy is None:
            raise ImportError("rclpy is not importable: source a ROS 2 installation first")
        self.types = dict(types or {})
        self.writer_qos = dict(writer_qos or {})  # {topic: (reliability, depth)}, as DdsBus
        self.reader_qos = dict(reader_qos or {})
        self.report = report or (lambda text: None)
        self.reported = set()  # [_lock] topics whose QoS incompatibility was told
        self._pending = []  # [_lock] incompatibilities told by rclpy's events, not yet reported
        self._counts = {}  # [_lock] topic -> messages received (kept after the subscription closes)
        self.errors = []
        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=domain)  # None: ROS_DOMAIN_ID
        self.node = rclpy.create_node(node_name, context=self.context, namespace=namespace or None)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._lock = threading.RLock()
        self._publishers = {}  # [_lock] topic -> (typename, Publisher)
        self._subscriptions = {}  # [_lock] topic -> (typename, rclpy Subscription, [Subscription])
        self._closed = False
        self._taps = []  # Taps (a list replaced on change: read without the lock)
        self._thread = threading.Thread(target=self._spin, name="rclpy-bus", daemon=True)
        self._thread.start()

    def _spin(self):
        while not self._closed and self.context.ok():
            self.executor.spin_once(timeout_sec=0.1)

    def _typename(self, topic: str, msgtype: str | None) -> str:
        with self._lock:
            known = self._publishers.get(topic) or self._subscriptions.get(topic)
        typename = msgtype or (known and known[0]) or self.types.get(topic) or default_type(topic)
        if typename is None:
            raise TypeError(f"no message type known for {topic}: pass msgtype=")
        return typename

    def _publisher(self, topic: str, typename: str):
        with self._lock:
            if self._closed:
                raise RuntimeError("the rclpy bus is closed")
            known = self._publishers.get(topic)
            if known is None:
                override = self.writer_qos.get(topic, (None, None))
                events = PublisherEventCallbacks(
                    incompatible_qos=lambda info, t=topic, o=override[0]: self._incompatible(t, False, o, info)
                )
                known = (
                    typename,
                    self.node.create_publisher(
                        get_message(typename), topic, _qos(topic, *override), event_callbacks=events
                    ),
                )
                self._publishers[topic] = known
            elif known[0] != typename:
                raise TypeError(f"topic {topic} carries {known[0]}, not {typename}")
            return known[1]

    # -- the Bus interface -----------------------------------------------------------------------
    def publish(self, topic: str, msg) -> None:
        typename = ros_messages.typename_of(msg)
        self._publisher(topic, typename).publish(cdr.serialize(msg, typename))
        if self._taps and not self.subscriber_count(topic):
            self._tapped(topic, msg)

    def publish_raw(self, topic: str, typename: str, payload: bytes) -> None:
        self._publisher(topic, typename).publish(bytes(payload))
        if self._taps and not self.subscriber_count(topic):
            self._tapped(topic, cdr.deserialize(payload, typename))

    def subscribe(self, topic: str, callback, msgtype: str | None = None, raw: bool = False) -> Subscription:
        typename = self._typename(topic, msgtype)
        sub = Subscription(self, topic, callback)
        sub.raw = raw
        with self._lock:
            if self._closed:
                raise RuntimeError("the rclpy bus is closed")
            entry = self._subscriptions.get(topic)
            if entry is None:
                subs = []
                override = self.reader_qos.get(topic, (None, None))
                events = SubscriptionEventCallbacks(
                    incompatible_qos=lambda info, t=topic, o=override[0]: self._incompatible(t, True, o, info)
                )
                handle = self.node.create_subscription(
                    get_message(typename),
                    topic,
                    lambda data, t=topic: self._deliver(t, data),
                    _qos(topic, *override),
                    event_callbacks=events,
                    raw=True,
                )
                self._counts.setdefault(topic, 0)
                entry = (typename, handle, subs)
                self._subscriptions[topic] = entry
            elif entry[0] != typename:
                raise TypeError(f"topic {topic} carries {entry[0]}, not {typename}")
            entry[2].append(sub)
        return sub

    def _deliver(self, topic: str, data: bytes) -> None:
        with self._lock:
            self._counts[topic] = self._counts.get(topic, 0) + 1
            entry = self._subscriptions.get(topic)
            subs = tuple(entry[2]) if entry else ()
        if not subs:
            return
        msg = cdr.deserialize(data, entry[0]) if self._taps or any(not s.raw for s in subs) else None
        if self._taps:
            self._tapped(topic, msg)
        for sub in subs:
            if sub.closed:
                continue
            try:
                sub.callback(data if sub.raw else msg)
            except Exception as e:  # the other subscribers still get the message
                if len(self.errors) < 100:
                    self.errors.append(e)

    def _remove(self, sub: Subscription) -> None:
        with self._lock:
            entry = self._subscriptions.get(sub.topic)
            if entry is None or sub not in entry[2]:
                return
            entry[2].remove(sub)
            if not entry[2] and not self._closed:
                del self._subscriptions[sub.topic]
                self.node.destroy_subscription(entry[1])

    def subscriber_count(self, topic: str) -> int:
        with self._lock:
            entry = self._subscriptions.get(topic)
            return len(entry[2]) if entry else 0

    def topics(self) -> list[str]:
        with self._lock:
            return sorted(self._subscriptions)

    def wait_for_subscriber(self, topic: str, timeout: float | None = None, msgtype: str | None = None) -> bool:
        publisher = self._publisher(topic, self._typename(topic, msgtype))
        return self._poll(lambda: publisher.get_subscription_count() > 0, timeout)

    def wait_for_publisher(self, topic: str, timeout: float | None = None) -> bool:
        return self._poll(lambda: self.node.count_publishers(topic) > 0, timeout)

    # -- what the graph holds (the reports of a ROS 2 run, scoopc.robots.silence) -------------------
    def _incompatible(self, topic: str, reader: bool, override, info) -> None:
        """rclpy's incompatible_qos event (on the executor's thread): kept for `check_qos`."""
        text = incompatibility(topic, reader, reliability_of(topic, override), info.last_policy_kind)
        with self._lock:
            self._pending.append((topic, text))

    def check_qos(self) -> list[str]:
        """New QoS incompatibilities (each topic once), told through `report` and returned."""
        with self._lock:
            pending, self._pending = self._pending, []
            texts = []
            for topic, text in pending:
                if topic not in self.reported:
                    self.reported.add(topic)
                    texts.append(text)
        for text in texts:
            self.report(text)
        return texts

    def heard(self) -> dict:
        """{ROS topic subscribed (now or before): (publishers in the graph, messages received)}."""
        with self._lock:
            counts = dict(self._counts)
        return {topic: (self.node.count_publishers(topic), count) for topic, count in counts.items()}

    def graph_topics(self, readers: bool = False) -> dict:
        """{ROS topic: type} of every publisher (`readers`: subscription) in the graph."""
        found = {}
        for topic, _ in self.node.get_topic_names_and_types():
            infos = (
                self.node.get_subscriptions_info_by_topic(topic)
                if readers
                else self.node.get_publishers_info_by_topic(topic)
            )
            if infos:
                found[topic] = infos[0].topic_type
        return found

    def unmatched_writers(self) -> list[tuple[str, str, str]]:
        """[(topic, our type, the type a subscription of the graph asks)] for our publishers that no
        subscription matched while some node reads the topic with another type."""
        with self._lock:
            lonely = [(t, typename) for t, (typename, p) in self._publishers.items() if p.get_subscription_count() == 0]
        if not lonely:
            return []
        graph = self.graph_topics(readers=True)
        return [(t, typename, graph[t]) for t, typename in lonely if t in graph and graph[t] != typename]

    @staticmethod
    def _poll(done, timeout):
        deadline = None if timeout is None else time.monotonic() + timeout
        while not done():
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.005)
        return True

    # -- shutdown ---------------------------------------------------------------------------------
    def close(self) -> None:
        with self._lock:
            if self._closed:
                return
            self._closed = True
            for entry in self._subscriptions.values():
                for sub in entry[2]:
                    sub.closed = True
        if self._thread is not threading.current_thread():
            self._thread.join()
        self.executor.shutdown()
        self.node.destroy_node()
        self.context.try_shutdown()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
