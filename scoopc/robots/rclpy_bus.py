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
10) for the rest. One node per bus, spun by a SingleThreadedExecutor on a thread of the bus
(callbacks run there, as with DdsBus); `close()` stops and joins it and shuts the context down.
"""

from __future__ import annotations

import threading
import time

from . import cdr, ros_messages
from .bus import Subscription, Tapped
from .dds import default_type, topic_kind

try:  # rclpy comes with a ROS 2 installation, never from PyPI
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
    from rosidl_runtime_py.utilities import get_message
except ImportError:  # pragma: no cover - the backends module reports this
    rclpy = None


def _qos(topic: str):
    kind = topic_kind(topic)
    if kind == "sensor":
        return qos_profile_sensor_data
    if kind == "clock":
        return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=10)


class RclpyBus(Tapped):
    """Publish/subscribe on ROS 2 topics through an rclpy node (see the module's note: unverified)."""

    own_thread_callbacks = True  # the executor's thread (see bus.Bus)

    def __init__(self, domain: int | None = None, types: dict | None = None, node_name: str = "scoopc"):
        if rclpy is None:
            raise ImportError("rclpy is not importable: source a ROS 2 installation first")
        self.types = dict(types or {})
        self.errors = []
        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=domain)  # None: ROS_DOMAIN_ID
        self.node = rclpy.create_node(node_name, context=self.context)
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
                known = (typename, self.node.create_publisher(get_message(typename), topic, _qos(topic)))
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
                handle = self.node.create_subscription(
                    get_message(typename), topic, lambda data, t=topic: self._deliver(t, data), _qos(topic), raw=True
                )
                entry = (typename, handle, subs)
                self._subscriptions[topic] = entry
            elif entry[0] != typename:
                raise TypeError(f"topic {topic} carries {entry[0]}, not {typename}")
            entry[2].append(sub)
        return sub

    def _deliver(self, topic: str, data: bytes) -> None:
        with self._lock:
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
