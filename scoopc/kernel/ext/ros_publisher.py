"""ROS_PUBLISHER's `external "Python"` features (stdlib/roboscoop/communication/ros_publisher.e).

A publication builds a message of the rosbags type store (scoopc.robots.messages when present)
and puts it on the process's transport (scoopc.robots.transport.current()), synchronously, on
the publishing processor's thread. The Eiffel side passes plain values only.
"""
from scoopc.robots import transport


def _text(obj):
    from scoopc.kernel import strings
    return strings.text(obj)


def _store():
    from rosbags.typesys import Stores, get_typestore
    global _STORE
    if _STORE is None:
        _STORE = get_typestore(Stores.ROS2_HUMBLE)
    return _STORE


_STORE = None


def new_message(typename, **fields):
    """A message object: scoopc.robots.messages.new when helper M's module exists, else the
    type store's dataclass built here (geometry_msgs Vector3/Twist/TwistStamped only)."""
    try:
        from scoopc.robots import messages
    except ImportError:
        messages = None
    if messages is not None and hasattr(messages, "new"):
        return messages.new(typename, **fields)
    return _store().types[typename](**fields)


def _vector3(x=0.0, y=0.0, z=0.0):
    return new_message("geometry_msgs/msg/Vector3", x=float(x), y=float(y), z=float(z))


def twist(linear_x, angular_z):
    return new_message("geometry_msgs/msg/Twist", linear=_vector3(linear_x), angular=_vector3(z=angular_z))


def _now_ns():
    import scoopc.runtime as rt
    try:
        return rt.now_ns()
    except Exception:           # no running runtime (a bare test): the wall clock
        import time
        return time.time_ns()


def twist_stamped(linear_x, angular_z, frame_id=""):
    now = _now_ns()
    stamp = new_message("builtin_interfaces/msg/Time", sec=now // 1_000_000_000, nanosec=now % 1_000_000_000)
    header = new_message("std_msgs/msg/Header", stamp=stamp, frame_id=frame_id)
    return new_message("geometry_msgs/msg/TwistStamped", header=header, twist=twist(linear_x, angular_z))


def publish_twist(current, linear_x, angular_z):
    topic = _text(current.topic)
    if current.is_stamped:
        msg = twist_stamped(linear_x, angular_z)
    else:
        msg = twist(linear_x, angular_z)
    transport.current().publish(topic, msg)


def publish_float64(current, value):
    transport.current().publish(_text(current.topic), new_message("std_msgs/msg/Float64", data=float(value)))


def publish_message(current, message):
    from scoopc.robots import eiffel_bridge
    transport.current().publish(_text(current.topic), eiffel_bridge.to_message(message))
