"""Velocity commands as ROS 2 messages: Twist and TwistStamped, built directly on every command
(the publisher's hot path) and by the runner's safety stop. rosbags and numpy load on first use
only, so programs that never publish do not pay for them."""

from functools import cache


def new_message(typename, **fields):
    """A message object of the type store (defaults for the fields not given)."""
    from scoopc.robots import ros_messages  # rosbags and numpy: loaded by programs that publish only

    return ros_messages.new(typename, **fields)


@cache
def _classes():
    """The dataclasses of the messages built on every command (built directly: no defaults to
    compute, a fifteenth of the time of `ros_messages.new`)."""
    from scoopc.robots import ros_messages

    return (
        ros_messages.message_class("geometry_msgs/msg/Vector3"),
        ros_messages.message_class("geometry_msgs/msg/Twist"),
    )


def twist(linear_x, angular_z):
    vector3, twist_class = _classes()
    return twist_class(
        linear=vector3(x=float(linear_x), y=0.0, z=0.0), angular=vector3(x=0.0, y=0.0, z=float(angular_z))
    )


def _now_ns():
    import scoopc.runtime as rt

    try:
        return rt.now_ns()
    except Exception:  # no running runtime (a bare test): the wall clock
        import time

        return time.time_ns()


def twist_stamped(linear_x, angular_z, frame_id=""):
    now = _now_ns()
    stamp = new_message("builtin_interfaces/msg/Time", sec=now // 1_000_000_000, nanosec=now % 1_000_000_000)
    header = new_message("std_msgs/msg/Header", stamp=stamp, frame_id=frame_id)
    return new_message("geometry_msgs/msg/TwistStamped", header=header, twist=twist(linear_x, angular_z))
