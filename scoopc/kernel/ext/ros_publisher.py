"""ROS_PUBLISHER's `external "Python"` features (stdlib/roboscoop/communication/ros_publisher.e).

A publication builds a message of the rosbags type store (scoopc.robots.messages)
and puts it on the process's transport (scoopc.robots.transport.current()), synchronously, on
the publishing processor's thread. The Eiffel side passes plain values only.
"""
from functools import cache

from scoopc.robots import transport


def _text(obj):
    from scoopc.kernel import strings
    return strings.text(obj)


def new_message(typename, **fields):
    """A message object of the type store (defaults for the fields not given)."""
    from scoopc.robots import messages  # rosbags and numpy: loaded by programs that publish only
    return messages.new(typename, **fields)


@cache
def _classes():
    """The dataclasses of the messages built on every command (built directly: no defaults to
    compute, a fifteenth of the time of `messages.new`)."""
    from scoopc.robots import messages
    return (messages.message_class("geometry_msgs/msg/Vector3"), messages.message_class("geometry_msgs/msg/Twist"))


def twist(linear_x, angular_z):
    vector3, twist_class = _classes()
    return twist_class(linear=vector3(x=float(linear_x), y=0.0, z=0.0),
                       angular=vector3(x=0.0, y=0.0, z=float(angular_z)))


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
