"""The Roboscoop library's robots, signalers, utilities and robot samples: TIMER and EVENT on the
virtual clock, stale data on the bus, THYMIO_ROBOT / DIFF_DRIVE_ROBOT with GROUP_SIGNALER and the
laser RANGE_SIGNALER on the simulator, and the samples exploration, wander, cancellable_control."""

import io
import math
import threading
from pathlib import Path

import numpy as np
import pytest

from scoopc import cli
from scoopc.robots import ros_messages

from harness import run_on_simulator

ROOT = Path(__file__).parents[2]
PROGRAMS = Path(__file__).parent / "programs"
SAMPLES = ROOT / "samples"


def run_on_bus(capsys, name):
    code = cli.main(["run", str(PROGRAMS / name), "--virtual-clock", "--robot", "none"])
    out, err = capsys.readouterr()
    return code, out, err


def test_timer_calls_agents_later_and_repeatedly_and_cancels_and_event_publishes(capsys):
    code, out, err = run_on_bus(capsys, "h1_timer_event")
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "pending 3",
        "after 1.1 s: tick@2 tick@4 once@5 tick@6 pending 0",  # every 0.2 s until cancelled by the 3rd
        "event total 21 publishes 2 subscribers 2",  # (3 + 6) + (4 + 8)
    ]


def odometry_msg():
    return ros_messages.new("nav_msgs/msg/Odometry")


def range_msg(value, max_range=0.12):
    return ros_messages.new("sensor_msgs/msg/Range", range=value, min_range=0.0, max_range=max_range)


def test_signalers_report_stale_data_when_a_topic_goes_silent(bus, capsys):
    def feed():
        assert bus.wait_for_subscriber("/range/b", 30)
        bus.publish("/odom", odometry_msg())
        bus.publish("/odom2", odometry_msg())
        bus.publish("/range/a", range_msg(0.05))
        bus.publish("/range/b", range_msg(math.inf))

    thread = threading.Thread(target=feed, daemon=True)
    thread.start()
    code, out, err = run_on_bus(capsys, "h1_stale")
    thread.join(10)
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "start: odometry stale True, group stale True, nearest -1 (sensor -1), below 0.1: 0",
        "fresh: odometry stale False, group stale False, nearest 0.050000000000000003 (sensor 0), below 0.1: 1",
        "after 0.3 s: odometry stale False, group stale False, nearest 0.050000000000000003 (sensor 0), below 0.1: 1",
        "watched odometry stale at 0.59999999999999998",  # woken by the check every 0.1 s
        "after 0.7 s: odometry stale True, group stale True, nearest 0.050000000000000003 (sensor 0), below 0.1: 1",
    ]


SENSOR_WORLD = {
    "name": "sensors",
    "size": [3.0, 3.0],
    "step": 0.02,
    "duration": 5,
    "boxes": [{"min": [2.0, 2.0], "max": [2.4, 2.6]}],
    "robots": [
        {"name": "thymio", "namespace": "robot1", "kind": "thymio", "start": [0.3, 1.0, math.pi]},
        {"name": "bot", "namespace": "robot2", "kind": "diff_drive", "start": [1.7, 2.2, 0.0]},
    ],
}


def test_robots_expose_their_signalers_group_and_laser_sectors():
    out = io.StringIO()
    result = run_on_simulator(PROGRAMS / "h1_sensors", world=SENSOR_WORLD, stdout=out, stderr=io.StringIO())
    assert result.status == 0 and result.stopped_by == "program"
    lines = out.getvalue().splitlines()
    assert lines[0] == "namespaces /robot1 /robot2 /robot1/odom"
    # the Thymio faces the left wall 0.3 m away, out of its sensors' range (0.12 m from the body):
    # only the floor is seen (10 mm under the ground sensors), nothing is an obstacle.
    assert lines[1] == (
        "thymio: obstacle False left False right False hole False proximity sensors 7 "
        "nearest sensor -1 at -1000 mm, ground 2 nearest 10 mm"
    )
    # the laser robot's centre is 0.3 m from the wide box ahead: an obstacle (under 0.35 m) in the
    # centre sector, and in the 15-45 degree sectors either side (0.31 m at 15 degrees)
    assert lines[2] == "laser: obstacle True left True right True behind False front at 30 cm, stale False"


def test_thymio_proximity_group_sees_a_near_wall():
    world = dict(
        SENSOR_WORLD, robots=[dict(SENSOR_WORLD["robots"][0], start=[0.12, 1.0, math.pi]), SENSOR_WORLD["robots"][1]]
    )
    out = io.StringIO()
    result = run_on_simulator(PROGRAMS / "h1_sensors", world=world, stdout=out, stderr=io.StringIO())
    assert result.status == 0
    thymio = out.getvalue().splitlines()[1]
    # centre at 0.12 m from the wall: the centre beam sees it 0.065 m from the body
    assert thymio.startswith(
        "thymio: obstacle True left True right True hole False proximity sensors 7 nearest sensor 2 at 65 mm"
    ), thymio


def test_sample_exploration_explores_without_touching(tmp_path):
    out = io.StringIO()
    result = run_on_simulator(SAMPLES / "exploration", duration=60, stdout=out, stderr=io.StringIO())
    assert result.status == 0 and result.stopped_by == "duration"
    assert out.getvalue() == "Exploring with /robot1\n"
    robot = result.sim.robot()
    assert robot.collisions == [] and not robot.fallen and robot.distance > 5.0
    assert robot.watchdog_stops == []  # commands keep coming while it explores


def test_sample_wander_stops_when_asked():
    out = io.StringIO()
    result = run_on_simulator(SAMPLES / "wander", stdout=out, stderr=io.StringIO())
    assert result.status == 0 and result.stopped_by == "program"
    assert out.getvalue() == "Wandering with /robot1\nStopped after 120 s\n"
    robot = result.sim.robot()
    assert robot.collisions == [] and not robot.fallen and robot.distance > 5.0
    trajectory = result.sim.trajectory()
    after = trajectory[trajectory[:, 0] >= 120.1]
    assert np.ptp(after[:, 1:4], axis=0).max() == 0  # at rest after the stop


def test_sample_cancellable_control_stops_after_a_metre():
    out = io.StringIO()
    result = run_on_simulator(SAMPLES / "cancellable_control", stdout=out, stderr=io.StringIO())
    assert result.status == 0 and result.stopped_by == "program"
    lines = out.getvalue().splitlines()
    assert lines[0] == "Supervisor: 1 m from the start, stop requested"
    assert sorted(lines[1:]) == sorted(["Robot at rest", lines[2] if lines[1] == "Robot at rest" else lines[1]])
    steps = [line for line in lines if line.startswith("Driver: stop seen after ")]
    assert len(steps) == 1 and int(steps[0].split()[-2]) > 10
    robot = result.sim.robot()
    start = robot.spec.start
    assert math.hypot(robot.x - start[0], robot.y - start[1]) == pytest.approx(1.0, abs=0.05)
    assert robot.cmd == (0.0, 0.0) and robot.collisions == []


def test_diff_drive_robot_sends_twist_stamped_when_made_so():
    world = {
        "name": "stamped",
        "size": [3.0, 3.0],
        "step": 0.02,
        "duration": 10,
        "robots": [{"name": "bot", "kind": "diff_drive", "start": [1.0, 1.5, 0.0], "cmd_vel_stamped": True}],
    }
    out = io.StringIO()
    result = run_on_simulator(PROGRAMS / "h1_stamped", world=world, stdout=out, stderr=io.StringIO())
    assert result.status == 0 and result.stopped_by == "program"
    assert out.getvalue() == "stamped True travelled 20 cm\n"  # 1 s at 0.2 m/s
    assert result.sim.robot().distance == pytest.approx(0.2, abs=0.01)
