"""Navigation on the simulator (simulated time, `run_on_simulator`): the laser's access
(ROS_SUBSCRIBER.listen_scan, LASER_SIGNALER), GO_TO_GOAL_BEHAVIOR in an open world, and
TANGENT_BUG_BEHAVIOR in the worlds samples/worlds/nav_*.yaml: it reaches every reachable goal
(11 worlds: open, cluttered, pillars, rooms, wall, narrow gap, niche, U trap, deep U trap, zigzag,
corridor maze) before the world's duration with a path at most 4x the straight-line distance from
start to goal, and reports "unreachable" in the 3 worlds nav_enclosed_*.yaml (goal in a closed box,
goal in a closed corner room, robot in a closed room); it never touches anything and the robot is
still at the end."""

import io
import math
import threading
from pathlib import Path

import numpy as np
import pytest

from scoopc import cli
from scoopc.robots import ros_messages, transport
from scoopc.robots.bus import Bus

from harness import run_on_simulator

ROOT = Path(__file__).parents[2]
PROGRAMS = Path(__file__).parent / "programs"
TANGENT_BUG = ROOT / "samples" / "tangent_bug"
GO_TO_GOAL = ROOT / "samples" / "go_to_goal"
WORLDS = sorted((ROOT / "samples" / "worlds").glob("nav_*.yaml"))
REACHABLE = [w for w in WORLDS if not w.stem.startswith("nav_enclosed_")]
ENCLOSED = [w for w in WORLDS if w.stem.startswith("nav_enclosed_")]
PATH_BOUND = 4.0  # path length <= 4x the straight line from start to goal


def run(program, world):
    out = io.StringIO()
    result = run_on_simulator(program, world=world, stdout=out, stderr=io.StringIO())
    return result, out.getvalue()


def straight_line(sim):
    robot = sim.robot()
    gx, gy = sim.world.goal
    sx, sy = robot.spec.start[:2]
    return math.hypot(gx - sx, gy - sy)


def test_listen_scan_feeds_a_laser_signaler(capsys):
    bus = Bus()
    previous = transport.use(bus)

    def publish():
        assert bus.wait_for_subscriber("/scan", 30)
        for k, stamp in enumerate((3.0, 4.5)):  # coalesced or not, the last one arrives
            header = ros_messages.new(
                "std_msgs/msg/Header",
                stamp=ros_messages.new("builtin_interfaces/msg/Time", sec=int(stamp), nanosec=int(stamp % 1 * 1e9)),
            )
            ranges = np.array([0.5, math.inf, 2.5, 1.5 + k], dtype=np.float32)
            bus.publish(
                "/scan",
                ros_messages.new(
                    "sensor_msgs/msg/LaserScan",
                    header=header,
                    angle_min=-math.pi,
                    angle_increment=math.pi / 2,
                    range_min=0.1,
                    range_max=2.0,
                    ranges=ranges,
                ),
            )

    thread = threading.Thread(target=publish, daemon=True)
    thread.start()
    try:
        code = cli.main(["run", str(PROGRAMS / "nav_scan"), "--virtual-clock", "--robot", "none"])
    finally:
        transport.use(previous)
    thread.join(10)
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    beams, ranges, stale = out.splitlines()
    words = beams.split()
    assert words[:2] == ["beams", "4"] and abs(float(words[3]) + math.pi) < 1e-6
    assert abs(float(words[5]) - math.pi / 2) < 1e-6 and float(words[7]) == 2.0
    assert ranges == "ranges 0.5 Infinity Infinity Infinity"  # inf and beyond range_max: no hit
    assert stale == "stale False updates>0 True"
    assert bus.subscriber_count("/scan") == 0


def test_laser_signaler_segments_endpoints_and_queries(capsys):
    code = cli.main(["run", str(PROGRAMS / "nav_laser"), "--robot", "none"])
    out, err = capsys.readouterr()
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "segments 1 1 1 0 0 0 2 2 2 1 count 2",  # beam 10 continues beam 1 (full circle)
        "endpoints 3/1 7/-1 9/1",  # obstacle ends next to free space / a farther one
        "hit 1 nohit True",
        "range_at 0 True range_at 1.26 0.55000000000000004",
        "min_range_in 1 0.5",
        "nearest 7 0.5 in 7",
        "corridor True False clear 350",
        "copy 10 3 0.90000000000000002",
    ]


def test_go_to_goal_reaches_the_goal_in_an_open_world():
    result, out = run(GO_TO_GOAL, None)
    sim, robot = result.sim, result.sim.robot()
    assert result.status == 0 and result.stopped_by == "program", out
    assert "go to goal: goal reached" in out
    gx, gy = sim.world.goal
    assert math.hypot(robot.x - gx, robot.y - gy) <= 0.12
    assert robot.collisions == []
    assert robot.distance <= 1.2 * straight_line(sim)
    assert sim.time < 20.0


@pytest.fixture(scope="module")
def tangent_bug_runs():
    return {}


def outcome(runs, world):
    if world.stem not in runs:
        runs[world.stem] = run(TANGENT_BUG, world)
    return runs[world.stem]


def finished_with(runs, world, verdict):
    """The tangent-bug run in `world`: it ended by itself, said `verdict`, touched nothing and
    left the robot stopped. Returns the simulator."""
    result, out = outcome(runs, world)
    sim, robot = result.sim, result.sim.robot()
    assert result.status == 0, out
    assert result.stopped_by == "program", f"{world.stem}: no outcome within {sim.world.duration} s\n{out}"
    assert f"tangent bug: {verdict}" in out, out
    assert robot.collisions == [], robot.collisions
    assert robot.cmd == (0.0, 0.0)
    return sim


@pytest.mark.parametrize("world", REACHABLE, ids=[w.stem for w in REACHABLE])
def test_tangent_bug_reaches_every_reachable_goal(tangent_bug_runs, world):
    sim = finished_with(tangent_bug_runs, world, "goal reached")
    robot = sim.robot()
    gx, gy = sim.world.goal
    assert math.hypot(robot.x - gx, robot.y - gy) <= 0.2
    assert robot.distance <= PATH_BOUND * straight_line(sim), (robot.distance, straight_line(sim))


@pytest.mark.parametrize("world", ENCLOSED, ids=[w.stem for w in ENCLOSED])
def test_tangent_bug_reports_an_enclosed_goal_unreachable(tangent_bug_runs, world):
    finished_with(tangent_bug_runs, world, "goal unreachable")


def test_the_worlds_are_as_announced():
    assert len(REACHABLE) >= 10 and len(ENCLOSED) >= 3
    for world in WORLDS:
        from scoopc.robots.sim.world import World

        w = World.load(str(world))
        assert w.goal is not None and w.robots[0].kind == "diff_drive" and w.robots[0].laser is not None


def test_a_stopped_tangent_bug_halts_the_robot():
    result, out = run(PROGRAMS / "nav_stop", WORLDS[0].parent / "nav_u_trap.yaml")
    assert result.status == 0, out
    first, outcome = out.splitlines()
    assert first.startswith("stopping at ") and outcome == "stopped"
    stop_at = int(first.split()[2]) / 1000.0
    trajectory = result.sim.trajectory()
    before = trajectory[trajectory[:, 0] <= stop_at]
    assert np.hypot(*(before[-1, 1:3] - before[0, 1:3])) > 0.5  # it was under way
    after = trajectory[trajectory[:, 0] >= stop_at + 0.1]
    assert len(after) > 1 and np.allclose(after[:, 1:4], after[0, 1:4])  # still within 100 ms
    assert result.sim.robot().collisions == []
