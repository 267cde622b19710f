"""The library's ROS 2 message classes (stdlib/roboscoop/communication/messages/) are what
`scoopc msg` writes, and compiled programs publish Eiffel message objects as ROS 2 ros_messages."""

from pathlib import Path

from scoopc import cli
from scoopc.robots import eiffel_messages
from scoopc.semantics.universe import stdlib_root

PROGRAMS = Path(__file__).parent / "programs"
LIBRARY = stdlib_root() / "roboscoop" / "communication" / "messages"


def test_library_message_classes_are_the_generated_ones(tmp_path):
    written = eiffel_messages.generate_library(str(tmp_path))
    assert sorted(Path(p).name for p in written) == sorted(p.name for p in LIBRARY.glob("*.e"))
    for path in written:
        assert Path(path).read_text() == (LIBRARY / Path(path).name).read_text(), (
            f"{Path(path).name} is stale: regenerate with eiffel_messages.generate_library"
        )


def test_msg_skips_the_library_classes_unless_asked(tmp_path, capsys):
    assert cli.main(["msg", "sensor_msgs/msg/Imu", "-o", str(tmp_path / "a")]) == 0
    written = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert written == ["sensor_msgs_imu.e"]  # Header, Quaternion, Vector3 are in the library
    assert "the Roboscoop library already has STD_MSGS_HEADER" in capsys.readouterr().err
    assert cli.main(["msg", "sensor_msgs/msg/Imu", "--all", "-o", str(tmp_path / "b")]) == 0
    assert "std_msgs_header.e" in {p.name for p in (tmp_path / "b").iterdir()}
    assert cli.main(["check", "--format", "short", str(tmp_path / "a")]) == 0, capsys.readouterr().err


def test_programs_publish_eiffel_message_objects(bus, capsys):
    seen = []
    for topic in ("/cmd_vel", "/number"):
        bus.subscribe(topic, lambda msg, topic=topic: seen.append((topic, msg)))
    code = cli.main(["run", str(PROGRAMS / "generic_publish"), "--robot", "none"])
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    assert out == "geometry_msgs/msg/Twist 2\n"
    twist = next(m for t, m in seen if t == "/cmd_vel" and hasattr(m, "linear"))
    assert (twist.linear.x, twist.angular.z) == (0.25, -1.5)
    number = next(m for t, m in seen if t == "/number")
    assert number.data == 2.5
    scan = next(m for t, m in seen if t == "/cmd_vel" and hasattr(m, "ranges"))
    assert scan.header.frame_id == "laser" and list(scan.ranges) == [0.5, 1.25] and scan.range_max == 2.0


def _publish_until_done(bus, topic, make, done):
    """Publish make(i) for i = 1, 2, ... every few milliseconds until `done` is set."""
    import threading

    def run():
        assert bus.wait_for_subscriber(topic, 30)
        i = 0
        while not done.wait(0.005):
            i += 1
            bus.publish(topic, make(i))

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread


def test_a_listener_gets_message_objects(bus, capsys):
    import threading

    from scoopc.robots import ros_messages

    def odometry(i):
        msg = ros_messages.new("nav_msgs/msg/Odometry")
        msg.header.frame_id = "odom"
        msg.pose.pose.position.x = float(i)
        return msg

    done = threading.Event()
    thread = _publish_until_done(bus, "/odom", odometry, done)
    code = cli.main(["run", str(PROGRAMS / "generic_listen"), "--robot", "none"])
    done.set()
    thread.join()
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    frame, x, covariance = out.strip().split(", ")
    assert frame == "frame odom" and float(x.split()[1]) >= 3 and covariance == "covariance 36"


def test_a_listener_of_a_type_made_by_scoopc_msg(bus, tmp_path, capsys):
    import shutil
    import threading

    from scoopc.robots import ros_messages

    program = tmp_path / "imu_listen"
    shutil.copytree(PROGRAMS / "imu_listen", program)
    assert cli.main(["msg", "sensor_msgs/msg/Imu", "-o", str(program)]) == 0
    capsys.readouterr()

    def imu(i):
        msg = ros_messages.new("sensor_msgs/msg/Imu")
        msg.linear_acceleration.z = 9.75
        msg.orientation.w = 1.0
        return msg

    done = threading.Event()
    thread = _publish_until_done(bus, "/imu", imu, done)
    code = cli.main(["run", str(program), "--robot", "none"])
    done.set()
    thread.join()
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    assert out == "imu z 9.75 w 1\n"
