"""ROS_SUBSCRIBER's `external "Python"` features (stdlib/roboscoop/communication/ros_subscriber.e).

A subscription listens on the process's transport (scoopc.robots.transport.current()). Each
incoming message becomes an ASYNCHRONOUS call on the listener's processor, logged by an outside
client of the runtime (`rt.outside_client`): the transport thread never writes a field of an
Eiffel object. Messages are coalesced per subscription: only the newest undelivered message is
kept, and one call is logged when none is pending, so a slow signaler sees the latest reading
and no queue grows. The call converts the message to plain values on the listener's processor
and calls the listener's routine (`on_odometry`, `on_range`, `on_scan`, `on_battery`) with them.
The subscriptions close when the runtime shuts down (a shutdown hook) or on `close`.
"""

import math
import threading

import scoopc.runtime as rt
from scoopc.kernel import link
from scoopc.robots import transport


def _text(obj):
    from scoopc.kernel import strings

    return strings.text(obj)


def _stamp(header):
    return header.stamp.sec + header.stamp.nanosec * 1e-9


def yaw(q):
    """The rotation about z of the quaternion `q` (x, y, z, w), in (-pi, pi]."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def odometry_values(msg):
    pose, twist = msg.pose.pose, msg.twist.twist
    return (
        float(pose.position.x),
        float(pose.position.y),
        yaw(pose.orientation),
        float(twist.linear.x),
        float(twist.angular.z),
        _stamp(msg.header),
    )


def range_values(msg):
    return (float(msg.range), float(msg.min_range), float(msg.max_range))


def scan_values(msg):
    """The scan's plain values; the ranges stay a host list until `deliver` makes the array."""
    return (
        float(msg.angle_min),
        float(msg.angle_increment),
        float(msg.range_min),
        float(msg.range_max),
        _stamp(msg.header),
        _RangeList(float(r) for r in msg.ranges),
    )


class _RangeList(list):
    """Ranges to become an Eiffel ARRAY [REAL_64] in the listener's region (see `_eiffel_values`)."""

    def eiffel(self, region):
        return real_array(region, self)


class _Message:
    """A message to become an object of its Eiffel message class in the listener's region."""

    __slots__ = ("msg",)

    def __init__(self, msg):
        self.msg = msg

    def eiffel(self, region):
        from scoopc.robots import eiffel_bridge

        return eiffel_bridge.from_message(self.msg, region)


def message_value(msg):
    return (_Message(msg),)


def real_array(region, values):
    """A new ARRAY [REAL_64] (1-based) in `region` holding `values`."""
    from scoopc import kernel
    from scoopc.kernel import types

    generic = (types.t("REAL_64"),)
    items = list(values)
    special = region.new(kernel.cls("SPECIAL"))
    special._gen_, special._items, special._cap = generic, items, len(items)
    array = region.new(kernel.cls("ARRAY"))
    array._gen_, array.area, array.lower, array.upper = generic, special, 1, len(items)
    return array


def _eiffel_values(listener, values):
    return tuple(v.eiffel(listener._region_) if isinstance(v, (_RangeList, _Message)) else v for v in values)


def battery_values(msg):
    level = float(msg.percentage)
    return (level if not math.isnan(level) else -1.0, float(msg.voltage))


class Link:
    """One subscription of one listener: coalesces messages into calls on its processor."""

    def __init__(self, topic, listener, routine, convert, extra=(), msgtype=None):
        self.topic = topic
        self.listener = listener
        self.routine = routine  # the listener's Python method name
        self.convert = convert  # message -> tuple of plain values
        self.extra = extra  # leading plain arguments (a sensor index)
        self.lock = threading.Lock()
        self.pending = None  # [lock] newest message not yet delivered
        self.scheduled = False  # [lock] a call is logged and has not taken it yet
        self.closed = False  # [lock]
        self.received = 0  # [lock] messages seen on the bus
        self.logged = 0  # [lock] calls logged on the listener's processor
        self.source = rt.outside_client(f"subscription {topic}")
        rt.add_shutdown_hook(self.close)
        bus = transport.current()
        # On a bus with a thread of its own, a leaf listener routine runs on that thread when
        # the listener's processor is idle (no thread switch per message).
        self.leaf = getattr(bus, "own_thread_callbacks", False) and link.is_leaf_routine(type(listener), routine)
        if msgtype is None:
            self.subscription = bus.subscribe(topic, self.on_message)
        else:  # a transport that must know the type (DDS, rclpy)
            self.subscription = bus.subscribe(topic, self.on_message, msgtype=msgtype)

    def on_message(self, msg):
        """On the transport's thread: keep `msg`, log one call if none is pending."""
        with self.lock:
            if self.closed:
                return
            self.received += 1
            self.pending = msg
            if self.scheduled:
                return
            self.scheduled = True
            self.logged += 1
        try:
            self.source.call(self.listener, deliver, (self,), leaf=self.leaf)
        except Exception:  # the runtime is shutting down: drop it
            with self.lock:
                self.scheduled = False

    def take(self):
        with self.lock:
            msg, self.pending, self.scheduled = self.pending, None, False
            return msg

    def close(self):
        with self.lock:
            if self.closed:
                return
            self.closed = True
        self.subscription.close()
        self.source.close()


def deliver(listener, link):
    """On the listener's processor: the newest message, as plain values, to its routine."""
    msg = link.take()
    if msg is not None:
        getattr(listener, link.routine)(*link.extra, *_eiffel_values(listener, link.convert(msg)))


def _links(current):
    links = current.__dict__.get("_links")
    if links is None:
        links = current._links = []
    return links


def _listen(current, listener, routine, convert, extra=(), msgtype=None):
    _links(current).append(Link(_text(current.topic), listener, routine, convert, extra, msgtype))


def listen(current, listener):
    """ROS_SUBSCRIBER [M].listen: messages as objects of M (its ROS type from M's class name)."""
    from scoopc.robots import eiffel_bridge

    name = current._gen_[0].key
    try:
        typename = eiffel_bridge.typename_of_class(name)
    except KeyError:
        from scoopc.kernel.ext.exception import failure

        raise failure(
            current._region_,
            "DEVELOPER_EXCEPTION",
            f"ROS_SUBSCRIBER [{name.split('@')[0]}]: `listen' needs a message class "
            f"(from `scoopc msg' or communication/messages/) as its actual generic",
        ) from None
    _listen(current, listener, "on_message", message_value, msgtype=typename)


def listen_odometry(current, listener):
    _listen(current, listener, "on_odometry", odometry_values)


def listen_range(current, listener, sensor):
    _listen(current, listener, "on_range", range_values, (sensor,))


def listen_scan(current, listener):
    _listen(current, listener, "on_scan", scan_values)


def listen_battery(current, listener):
    _listen(current, listener, "on_battery", battery_values)


def close(current):
    for each in _links(current):
        each.close()


def received_count(current):
    return sum(link.received for link in _links(current))


def logged_count(current):
    return sum(link.logged for link in _links(current))
