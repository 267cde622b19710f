"""The library's ROS 2 message classes (stdlib/roboscoop/communication/messages/) are what
`scoopc msg` writes, and compiled programs publish Eiffel message objects as ROS 2 messages."""
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
        assert Path(path).read_text() == (LIBRARY / Path(path).name).read_text(), \
            f"{Path(path).name} is stale: regenerate with eiffel_messages.generate_library"


def test_msg_skips_the_library_classes_unless_asked(tmp_path, capsys):
    assert cli.main(["msg", "sensor_msgs/msg/Imu", "-o", str(tmp_path / "a")]) == 0
    written = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert written == ["sensor_msgs_imu.e"]                  # Header, Quaternion, Vector3 are in the library
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
