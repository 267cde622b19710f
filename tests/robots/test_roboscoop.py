"""The Roboscoop library (stdlib/roboscoop/): Eiffel programs run in-process with
`scoopc run --virtual-clock`, meeting Python publishers/subscribers on transport.current()."""

import math
import threading
from pathlib import Path

import numpy as np

from scoopc import cli
from scoopc.kernel.ext import ros_publisher
from scoopc.robots import transport
from scoopc.robots.bus import Bus

PROGRAMS = Path(__file__).parent / "programs"
ROBOSCOOP = Path(__file__).parents[2] / "stdlib" / "roboscoop"


def run(capsys, name):
    code = cli.main(["run", str(PROGRAMS / name), "--virtual-clock", "--robot", "none"])
    out, err = capsys.readouterr()
    return code, out, err


def new(typename, **fields):
    return ros_publisher.new_message(typename, **fields)


def odometry(x, y=0.0, theta=0.0, vx=0.0, vtheta=0.0, stamp=0):
    def vec(a=0.0, b=0.0, c=0.0):
        return new("geometry_msgs/msg/Vector3", x=a, y=b, z=c)

    header = new("std_msgs/msg/Header", stamp=new("builtin_interfaces/msg/Time", sec=stamp, nanosec=0), frame_id="odom")
    pose = new(
        "geometry_msgs/msg/Pose",
        position=new("geometry_msgs/msg/Point", x=x, y=y, z=0.0),
        orientation=new("geometry_msgs/msg/Quaternion", x=0.0, y=0.0, z=math.sin(theta / 2), w=math.cos(theta / 2)),
    )
    return new(
        "nav_msgs/msg/Odometry",
        header=header,
        child_frame_id="base_link",
        pose=new("geometry_msgs/msg/PoseWithCovariance", pose=pose, covariance=np.zeros(36)),
        twist=new(
            "geometry_msgs/msg/TwistWithCovariance",
            twist=new("geometry_msgs/msg/Twist", linear=vec(vx), angular=vec(c=vtheta)),
            covariance=np.zeros(36),
        ),
    )


def test_bus_delivers_in_subscription_order_and_close_stops():
    b, seen = Bus(), []
    s1 = b.subscribe("/t", lambda m: seen.append(("a", m)))
    b.subscribe("/t", lambda m: seen.append(("b", m)))
    b.subscribe("/other", lambda m: seen.append(("c", m)))
    b.publish("/t", 1)
    s1.close()
    s1.close()
    b.publish("/t", 2)
    assert seen == [("a", 1), ("b", 1), ("b", 2)]
    assert b.subscriber_count("/t") == 1 and b.wait_for_subscriber("/t", 0)
    assert not b.wait_for_subscriber("/none", 0.01)


def test_transport_current_is_one_bus_until_use():
    mine = Bus()
    previous = transport.use(mine)
    try:
        assert transport.current() is mine is transport.current()
    finally:
        transport.use(previous)


def test_every_roboscoop_class_checks():
    assert cli.main(["check", str(ROBOSCOOP)]) == 0


def test_differential_drive_publishes_twists(bus, capsys):
    seen = []
    bus.subscribe("/robot1/cmd_vel", seen.append)
    code, out, err = run(capsys, "drive")
    assert (code, out, err) == (0, "sent 2 0.5 1\n", "")
    assert [type(m).__name__ for m in seen] == ["geometry_msgs__msg__Twist"] * 2
    assert [(m.linear.x, m.linear.y, m.angular.z) for m in seen] == [(0.25, 0.0, -0.5), (0.5, 0.0, 1.0)]


def test_odometry_signaler_follows_the_bus_and_coalesces(bus, capsys):
    counts = {}

    def publish():
        assert bus.wait_for_subscriber("/odom", 30)
        bus.publish("/odom", odometry(0.5))
        bus.publish("/odom", odometry(1.5, vx=0.2))
        for i in range(1, 1001):
            bus.publish("/odom", odometry(float(i), theta=0.5, stamp=i))
        counts["done"] = True

    thread = threading.Thread(target=publish, daemon=True)
    thread.start()
    code, out, err = run(capsys, "odometry")
    thread.join(10)
    assert code == 0 and err == "" and counts.get("done")
    past, last = out.splitlines()
    assert past.startswith("past ") and float(past.split()[1]) > 1.0
    words = last.split()
    assert words[:2] == ["last", "1000"] and abs(float(words[3]) - 0.5) < 1e-9
    updates = int(words[5])
    assert 1 <= updates <= 500, updates  # 1002 messages, far fewer calls
    assert bus.subscriber_count("/odom") == 0  # closed by the program / at shutdown


def test_stop_signaler_propagates_to_children(capsys):
    assert run(capsys, "stop") == (0, "all stopped\n", "")


def test_pid_controller_outputs(capsys):
    code, out, err = run(capsys, "pid")
    assert (code, err) == (0, "")
    assert out.splitlines() == ["3", "1.5 2", "1 3", "2 -2 0", "False"]
