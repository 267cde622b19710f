"""`scoopc msg`: generated Eiffel message classes pass `scoopc check`; the generic bridge converts both ways."""

import numpy as np
import pytest

from scoopc import cli, kernel
from scoopc.robots import eiffel_bridge, eiffel_messages, ros_messages

TYPES = [
    "geometry_msgs/msg/Twist",
    "nav_msgs/msg/Odometry",
    "sensor_msgs/msg/LaserScan",
    "sensor_msgs/msg/Range",
    "sensor_msgs/msg/BatteryState",
]


def test_names_and_types():
    assert eiffel_messages.class_name("geometry_msgs/msg/Twist") == "GEOMETRY_MSGS_TWIST"
    assert eiffel_messages.class_name("sensor_msgs/msg/LaserScan") == "SENSOR_MSGS_LASER_SCAN"
    assert eiffel_messages.attribute_name("class") == "class_value"
    assert eiffel_messages.attribute_name("out") == "out_value"
    text = eiffel_messages.generate_class("sensor_msgs/msg/LaserScan")
    assert "ranges: ARRAY [REAL_32]" in text and 'Ros_type: STRING = "sensor_msgs/msg/LaserScan"' in text
    assert "header: STD_MSGS_HEADER" in text and "set_range_max (a_value: REAL_32)" in text
    text = eiffel_messages.generate_class("sensor_msgs/msg/Range")
    assert "radiation_type: NATURAL_8" in text and "Ultrasound: NATURAL_8 = 0" in text


def test_generated_classes_pass_check(tmp_path, capsys):
    for typename in TYPES:
        assert cli.main(["msg", typename, "--all", "-o", str(tmp_path)]) == 0
    written = sorted(p.name for p in tmp_path.iterdir())
    assert "geometry_msgs_twist.e" in written and "std_msgs_header.e" in written
    assert "builtin_interfaces_time.e" in written and "geometry_msgs_pose_with_covariance.e" in written
    assert cli.main(["check", "--format", "short", str(tmp_path)]) == 0, capsys.readouterr().err


def test_msg_file_with_keywords_and_arrays(tmp_path, capsys):
    definition = tmp_path / "Thing.msg"
    definition.write_text(
        "int32 class\nbool[2] flags\ngeometry_msgs/Point[2] corners\nstring[] names\n"
        'string<=8 label\nuint8 LEVEL=3\nfloat64 SCALE=0.5\nstring NAME="x"\n'
    )
    out = tmp_path / "out"
    assert cli.main(["msg", "--file", str(definition), "--type", "my_pkg/msg/Thing", "-o", str(out)]) == 0
    text = (out / "my_pkg_thing.e").read_text()
    assert "class_value: INTEGER_32" in text and "corners: ARRAY [GEOMETRY_MSGS_POINT]" in text
    assert "Level: NATURAL_8 = 3" in text and "Scale: REAL_64 = 0.5" in text
    assert not (out / "geometry_msgs_point.e").exists()  # the library has it
    assert cli.main(["check", "--format", "short", str(out)]) == 0, capsys.readouterr().err
    assert cli.main(["msg", "nope_msgs/msg/Missing", "-o", str(out)]) == 2
    assert cli.main(["msg", "-o", str(out)]) == 2


class _Region:
    def new(self, cls):
        obj = cls.__new__(cls)
        obj._region_ = self
        return obj


def _fake_classes(typename):
    for each in ros_messages.nested_types(typename):
        name = eiffel_messages.class_name(each)
        kernel.CLASSES[name] = type(name, (), {})
    for name in ("SPECIAL", "ARRAY", "STRING_8"):
        kernel.CLASSES.setdefault(name, type(name, (), {}))


def test_bridge_round_trip_on_the_object_model():
    _fake_classes("sensor_msgs/msg/LaserScan")
    scan = ros_messages.new(
        "sensor_msgs/msg/LaserScan",
        angle_max=1.5,
        range_max=2.0,
        ranges=np.array([0.5, 1.0, 2.0], dtype=np.float32),
        header=ros_messages.new(
            "std_msgs/msg/Header", frame_id="laser", stamp=ros_messages.new("builtin_interfaces/msg/Time", sec=3)
        ),
    )
    obj = eiffel_bridge.from_message(scan, _Region())
    assert type(obj).__name__ == "SENSOR_MSGS_LASER_SCAN"
    assert obj.range_max == 2.0 and obj.ranges.upper == 3 and obj.ranges.area._items == [0.5, 1.0, 2.0]
    assert obj.header.stamp.sec == 3
    back = eiffel_bridge.to_message(obj)
    assert back.header.frame_id == "laser" and back.range_max == 2.0 and back.header.stamp.sec == 3
    assert back.ranges.dtype == np.float32 and list(back.ranges) == [0.5, 1.0, 2.0]
    assert eiffel_bridge.typename_of_class("GEOMETRY_MSGS_TWIST") == "geometry_msgs/msg/Twist"


def test_a_string_field_carries_the_bytes_of_a_string_8_one_to_one(monkeypatch):
    """ROS strings are UTF-8 and a STRING_8 holds bytes: a message's text arrives as its UTF-8
    bytes ("é" has count 2, as in EiffelStudio) and the bytes of a STRING_8 go out unchanged, even
    those that are not UTF-8, through the CDR on the wire and back."""
    from scoopc.kernel import strings
    from scoopc.robots import cdr

    _fake_classes("std_msgs/msg/String")
    monkeypatch.setitem(kernel.CLASSES, "STRING_8", type("STRING_8", (), {"_conforms_": ("STRING_8",)}))
    text = "h\u00e9llo \u2200 \U0001f600"
    obj = eiffel_bridge.from_message(ros_messages.new("std_msgs/msg/String", data=text), _Region())
    assert obj.data._s == "h\xc3\xa9llo \xe2\x88\x80 \xf0\x9f\x98\x80" and len(obj.data._s) == 15
    assert eiffel_bridge.to_message(obj).data == text
    obj.data = strings.new_string_8(_Region(), "caf\xe9 \xc3\xa9")  # a byte that is not UTF-8, then "é"
    wire = cdr.serialize(eiffel_bridge.to_message(obj), "std_msgs/msg/String")
    assert b"caf\xe9 \xc3\xa9\x00" in bytes(wire)
    back = eiffel_bridge.from_message(cdr.deserialize(wire, "std_msgs/msg/String"), _Region())
    assert back.data._s == "caf\xe9 \xc3\xa9"


def test_service_classes(tmp_path, capsys, monkeypatch):
    """`scoopc msg pkg/srv/Name` writes the request and response classes (those of
    tests/robots/programs/service_ros2 are its output); a .srv of one's own with --file; an unknown
    service is a usage error naming the known ones."""
    from pathlib import Path

    monkeypatch.delenv("ROS_DISTRO", raising=False)
    program = Path(__file__).parent / "programs" / "service_ros2"
    assert cli.main(["msg", "std_srvs/srv/SetBool", "-o", str(tmp_path)]) == 0
    for name in ("std_srvs_set_bool_request.e", "std_srvs_set_bool_response.e"):
        assert (tmp_path / name).read_text() == (program / name).read_text()
    srv = tmp_path / "Move.srv"
    srv.write_text("float64 distance  # metres\n---\nbool done\n")
    assert cli.main(["msg", "--file", str(srv), "--type", "my_pkg/srv/Move", "-o", str(tmp_path / "own")]) == 0
    text = (tmp_path / "own" / "my_pkg_move_request.e").read_text()
    assert "distance: REAL_64" in text and 'Ros_type: STRING = "my_pkg/srv/Move_Request"' in text
    capsys.readouterr()
    assert cli.main(["msg", "nope/srv/Missing"]) == 2
    assert "unknown ROS 2 service type `nope/srv/Missing`" in capsys.readouterr().err


def test_action_classes(tmp_path, capsys, monkeypatch):
    """`scoopc msg pkg/action/Name` writes the goal, result and feedback classes for the distribution
    (samples/navigate_to_pose has Jazzy's output); an .action of one's own with --file; an unknown
    action is a usage error naming the known ones."""
    from pathlib import Path

    monkeypatch.delenv("ROS_DISTRO", raising=False)
    sample = Path(__file__).parents[2] / "samples" / "navigate_to_pose"
    assert cli.main(["msg", "nav2_msgs/action/NavigateToPose", "-o", str(tmp_path / "jazzy")]) == 0
    written = sorted(p.name for p in (tmp_path / "jazzy").iterdir())
    assert written == [
        "builtin_interfaces_duration.e",
        "nav2_msgs_navigate_to_pose_feedback.e",
        "nav2_msgs_navigate_to_pose_goal.e",
        "nav2_msgs_navigate_to_pose_result.e",
    ]
    for name in written:
        assert (tmp_path / "jazzy" / name).read_text() == (sample / name).read_text()
    previous = ros_messages.distro()
    try:
        humble = ["msg", "nav2_msgs/action/NavigateToPose", "--ros-distro", "humble", "-o", str(tmp_path / "h")]
        assert cli.main(humble) == 0
    finally:
        ros_messages.use_distro(previous)  # `scoopc msg` chose the process's distribution
    assert "result_value: STD_MSGS_EMPTY" in (tmp_path / "h" / "nav2_msgs_navigate_to_pose_result.e").read_text()
    action = tmp_path / "Dock.action"
    action.write_text("string dock_id\n---\nbool docked\n---\nfloat32 distance\n")
    out = tmp_path / "own"
    assert cli.main(["msg", "--file", str(action), "--type", "my_pkg/action/Dock", "-o", str(out)]) == 0
    assert "docked: BOOLEAN" in (out / "my_pkg_dock_result.e").read_text()
    assert 'Ros_type: STRING = "my_pkg/action/Dock_Feedback"' in (out / "my_pkg_dock_feedback.e").read_text()
    assert cli.main(["check", "--format", "short", str(out)]) == 0, capsys.readouterr().err
    capsys.readouterr()
    assert cli.main(["msg", "nope/action/Missing"]) == 2
    assert "unknown ROS 2 action type `nope/action/Missing`" in capsys.readouterr().err


def _msg(tmp_path, text, *more, name="Thing.msg", binary=False):
    definition = tmp_path / name
    definition.write_bytes(text) if binary else definition.write_text(text)
    return cli.main(["msg", "--file", str(definition), "--type", "my_pkg/msg/Thing", *more])


@pytest.mark.parametrize(
    ("text", "binary", "says"),
    [
        ("int32 x\nfoo_msgs/Unknown y\n", False, "unknown ROS 2 message type `foo_msgs/msg/Unknown`"),
        (b"\x00\x01\xff\xfe", True, "is not a text file (UTF-8)"),
        (b"int32 x\n\x00\n", True, "holds NUL bytes"),
        ("int8 A=300\n", False, "constant `A`: 300 is not a value of int8 (-128 to 127)"),
        ("uint8 B=-1\n", False, "constant `B`: -1 is not a value of uint8"),
        ("uint64 C=18446744073709551616\n", False, "constant `C`: 18446744073709551616 is not a value of uint64"),
        ("int32[-1] arr\n", False, "the array size must not be negative, not -1"),
        ("int32[<=-2] seq\n", False, "the sequence bound must not be negative, not -2"),
    ],
)
def test_msg_refuses_a_definition_whose_classes_would_not_check(tmp_path, capsys, text, binary, says):
    assert _msg(tmp_path, text, "-o", str(tmp_path / "out"), binary=binary) == 2
    err = capsys.readouterr().err
    assert says in err and "Traceback" not in err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_msg_output_must_be_a_folder(tmp_path, capsys):
    existing = tmp_path / "existing.e"
    existing.write_text("keep me")
    assert _msg(tmp_path, "int32 x\n", "-o", str(existing)) == 2
    assert "names a file, not a folder" in capsys.readouterr().err
    assert existing.read_text() == "keep me"
    assert cli.main(["msg", "std_srvs/srv/SetBool", "-o", str(existing)]) == 2


def test_msg_constants_at_their_bounds_give_classes_that_check(tmp_path, capsys):
    text = "".join(
        f"{base} {name}_LOW={low}\n{base} {name}_HIGH={high}\n" for name, (base, (low, high)) in enumerate_bases()
    )
    assert _msg(tmp_path, text + "int32[0] empty\n", "-o", str(tmp_path / "out")) == 0
    capsys.readouterr()
    assert cli.main(["check", "--format", "short", str(tmp_path / "out")]) == 0, capsys.readouterr().err


def enumerate_bases():
    return [(f"C{i}", item) for i, item in enumerate(eiffel_messages.INTEGER_RANGES.items())]
