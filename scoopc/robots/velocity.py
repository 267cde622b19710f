"""Velocity commands as ROS 2 messages: Twist and TwistStamped, built directly on every command
(the publisher's hot path) and by the runner's safety stop. rosbags and numpy load on first use
only, so programs that never publish do not pay for them.

TwistStamped stamps are ROS time, as rclcpp's `get_clock()->now()` gives it: the system clock
(`time.time_ns`, seconds since 1970) on a real robot, the latest /clock with use_sim_time, the
simulated time on the in-process simulator; never a monotonic clock (diff_drive_controller drops a
command whose stamp is older than its cmd_vel_timeout: ros2_controllers,
diff_drive_controller/src/diff_drive_controller.cpp, DiffDriveController::update). The runner sets
the source with `use_clock`.
"""

import time
from functools import cache


def new_message(typename, **fields):
    """A message object of the type store (defaults for the fields not given)."""
    from scoopc.robots import ros_messages  # deferred: start-up (rosbags and numpy load only to publish)

    return ros_messages.new(typename, **fields)


@cache
def _classes_of(distro):
    from scoopc.robots import (
        ros_messages,  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
    )

    return (
        ros_messages.message_class("geometry_msgs/msg/Vector3"),
        ros_messages.message_class("geometry_msgs/msg/Twist"),
    )


def _classes():
    """The dataclasses of the messages built on every command (built directly: no defaults to
    compute, a fifteenth of the time of `ros_messages.new`), of the process's distribution."""
    from scoopc.robots import (
        ros_messages,  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
    )

    return _classes_of(ros_messages.distro())


def twist(linear_x, angular_z):
    vector3, twist_class = _classes()
    return twist_class(
        linear=vector3(x=float(linear_x), y=0.0, z=0.0), angular=vector3(x=0.0, y=0.0, z=float(angular_z))
    )


_clock = [time.time_ns]  # the ROS time source: the system clock unless `use_clock`


def use_clock(now_ns=None):
    """Stamp commands with `now_ns()` (nanoseconds of ROS time); None: the system clock again."""
    _clock[0] = time.time_ns if now_ns is None else now_ns


class SimTime:
    """ROS time from /clock (use_sim_time): the latest Clock message, 0 before the first."""

    def __init__(self):
        self.ns = 0

    def __call__(self):
        return self.ns

    def on_clock(self, msg):
        self.ns = msg.clock.sec * 1_000_000_000 + msg.clock.nanosec


def sim_time(bus):
    """A clock for `use_clock` that follows /clock on `bus`."""
    clock = SimTime()
    bus.subscribe("/clock", clock.on_clock)
    return clock


def now_ns():
    """ROS time now, in nanoseconds (the source `use_clock` set)."""
    return _clock[0]()


def twist_stamped(linear_x, angular_z, frame_id=""):
    now = _clock[0]()
    stamp = new_message("builtin_interfaces/msg/Time", sec=now // 1_000_000_000, nanosec=now % 1_000_000_000)
    header = new_message("std_msgs/msg/Header", stamp=stamp, frame_id=frame_id)
    return new_message("geometry_msgs/msg/TwistStamped", header=header, twist=twist(linear_x, angular_z))
