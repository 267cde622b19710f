"""Robot profiles (scoopc/robots/profile.py): robot.yaml read for DIFF_DRIVE_ROBOT.make_from_profile,
its mistakes reported with file:line:col and the key's path, and `scoopc run --profile`'s exit 2."""

from pathlib import Path

import pytest

from scoopc.exits import UsageError
from scoopc.robots import profile, runner

PROGRAM = Path(__file__).parent / "programs" / "profile_ros2"


def test_the_sample_profile_gives_names_types_qos_and_limits():
    found = profile.load(PROGRAM / "robot.yaml")
    assert (found.name, found.max_linear, found.max_angular, found.stamped) == ("wheels", 0.3, 1.2, True)
    assert found.topic("cmd_vel", "/r1") == "/wheels/cmd" and found.topic("scan", "/r1") == "/r1/scan"
    assert found.qos("/r1") == ({}, {"/wheels/odom": ("reliable", 3)})


def test_an_empty_profile_is_the_robot_interface():
    found = profile.parse("", "robot.yaml")
    assert not found.stamped and found.max_linear is None
    assert [found.topic(k, "") for k in profile.TOPIC_TYPES] == ["/cmd_vel", "/odom", "/battery_state", "/scan"]
    assert found.qos("") == ({}, {})


@pytest.mark.parametrize(
    "text, message",
    [
        ("topics:\n  cmd_vel:\n    qos: {depth: 0}\n", "robot.yaml:3:18: topics.cmd_vel.qos.depth: must be a whole"),
        ("topics:\n  odom: {qos: {reliability: best}}\n", "robot.yaml:2:29: topics.odom.qos.reliability: must be"),
        ("topics: {cmd_vel: {type: Twist}}\n", "robot.yaml:1:26: topics.cmd_vel.type: must be one of"),
        ("topics: {odom: {type: x}}\n", "robot.yaml:1:17: topics.odom.type: unknown key (expected one of: name, qos)"),
        ("topics: {lidar: {}}\n", "robot.yaml:1:10: topics.lidar: unknown key"),
        ("limits: {max_linear: -1}\n", "robot.yaml:1:22: limits.max_linear: must be a number greater than 0"),
        ("limits: {max_linear: 1, max_linear: 2}\n", "robot.yaml:1:25: limits.max_linear: given twice"),
        ("topics: {scan: {name: 'a b'}}\n", "robot.yaml:1:23: topics.scan.name: not a ROS 2 topic name"),
        ("topics: [odom]\n", "robot.yaml:1:9: topics: must be a mapping"),
        ("limits: {max_linear: [1\n", "robot.yaml:2:1: not valid YAML"),
    ],
)
def test_mistakes_name_the_place_and_the_key(text, message):
    with pytest.raises(profile.ProfileError) as caught:
        profile.parse(text, "robot.yaml")
    assert str(caught.value).startswith(message), str(caught.value)


def test_a_wrong_profile_stops_the_run_before_it_starts(tmp_path):
    """runner.load_profile runs before the robot does; its RobotError is a usage error (exit 2)."""
    bad = tmp_path / "robot.yaml"
    bad.write_text("topics:\n  odom:\n    qos: {depth: many}\n")
    with pytest.raises(runner.RobotError) as caught:
        runner.load_profile([str(PROGRAM)], bad)
    assert str(caught.value) == f"{bad}:3:18: topics.odom.qos.depth: must be a whole number from 1 to 10000, not 'many'"
    assert isinstance(caught.value, UsageError)
    (tmp_path / "app.e").write_text("")
    with pytest.raises(runner.RobotError, match="robot.yaml:3:18"):  # robot.yaml beside the program
        runner.load_profile([str(tmp_path / "app.e")])
    assert runner.load_profile([str(PROGRAM)]).name == "wheels"
    assert runner.load_profile([str(PROGRAM.parent / "stop")]) is None
