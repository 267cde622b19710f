"""samples/two_robots on the simulator: one program drives two Thymios (namespaces robot1 and robot2)
that shuttle between two rooms through a passage too narrow for both; a shared PASSAGE_SIGNALER makes
them take turns.

Checked on the simulator's trajectories, not on the program's word: the two robots are never in the
passage at the same time, never touch each other or a wall, both cross several times, and they take
turns (the crossings alternate). Without the coordination (the program's `uncoordinated` argument)
they meet head-on in the passage, which shows that the property comes from the signaler.
"""

import io
import re
from pathlib import Path

import numpy as np
import pytest
import yaml

from harness import run_on_simulator

SAMPLE = Path(__file__).resolve().parents[2] / "samples" / "two_robots"
PASSAGE = (2.0, 1.5)  # centre of the passage (samples/worlds/two_robots.yaml)
HALF_LENGTH = 0.2  # the walls are 0.4 m thick
HALF_WIDTH = 0.12  # and 0.24 m apart


def in_passage(traj, radius):
    """Per step: is any part of the robot's disc between the walls' ends?"""
    x, y = traj[:, 1], traj[:, 2]
    return (np.abs(x - PASSAGE[0]) < HALF_LENGTH + radius) & (np.abs(y - PASSAGE[1]) < HALF_WIDTH + radius)


def crossings(traj):
    """Times at which the robot came out of the passage into the other room."""
    x, t = traj[:, 1] - PASSAGE[0], traj[:, 0]
    side, times = 0, []
    for i in np.flatnonzero(np.abs(x) > HALF_LENGTH + 0.1):
        s = 1 if x[i] > 0 else -1
        if side and s != side:
            times.append(t[i])
        side = s
    return times


@pytest.fixture(scope="module")
def coordinated():
    out, err = io.StringIO(), io.StringIO()
    result = run_on_simulator(SAMPLE, stdout=out, stderr=err)
    return result, out.getvalue(), err.getvalue()


def test_the_run_uses_both_robots_of_the_world(coordinated):
    result, out, err = coordinated
    assert result.status == 0, err
    assert result.sim.time >= 295.0
    assert [r.namespace for r in result.sim.robots] == ["robot1", "robot2"]
    assert all(r.cmd_count > 1000 for r in result.sim.robots)  # both driven, at about 10 Hz
    assert "Mission: two robots, one passage, taking turns" in out


def test_never_both_in_the_passage(coordinated):
    result, _, _ = coordinated
    sim = result.sim
    r1, r2 = sim.robots
    inside1 = in_passage(sim.trajectory("robot1"), r1.spec.radius)
    inside2 = in_passage(sim.trajectory("robot2"), r2.spec.radius)
    assert inside1.any() and inside2.any()
    assert not (inside1 & inside2).any()


def test_no_collision_and_always_apart(coordinated):
    result, _, _ = coordinated
    sim = result.sim
    for robot in sim.robots:
        assert robot.collisions == [], robot.name
        assert not robot.fallen
    t1, t2 = sim.trajectory("robot1"), sim.trajectory("robot2")
    gap = np.hypot(t1[:, 1] - t2[:, 1], t1[:, 2] - t2[:, 2]).min()
    assert gap > 0.4, f"closest approach {gap:.2f} m"


def test_both_cross_and_take_turns(coordinated):
    result, out, _ = coordinated
    sim = result.sim
    times = {name: crossings(sim.trajectory(name)) for name in ("robot1", "robot2")}
    assert all(len(t) >= 4 for t in times.values()), times
    order = [name for _, name in sorted((t, name) for name, ts in times.items() for t in ts)]
    assert all(a != b for a, b in zip(order, order[1:])), order  # they alternate
    # The program's account agrees with the trajectories (the mission may end between a robot's
    # leaving the passage and its reaching the point where it reports the crossing).
    for n in (1, 2):
        reported = len(re.findall(rf"Robot {n} \[\d+ s\]: crossed", out))
        assert len(times[f"robot{n}"]) - 1 <= reported <= len(times[f"robot{n}"])
    (granted,) = re.findall(r"Mission: over, (\d+) crossing\(s\) granted", out)
    assert int(granted) == len(re.findall(r"\]: crossing$", out, re.M))
    assert len(re.findall(r"waiting for robot \d", out)) >= 4  # they did have to wait


def test_without_the_passage_signaler_they_meet_in_the_passage():
    out = io.StringIO()
    result = run_on_simulator(SAMPLE, duration=40, argv=("uncoordinated",), stdout=out, stderr=io.StringIO())
    assert result.status == 0
    sim = result.sim
    r1, r2 = sim.robots
    both = in_passage(sim.trajectory("robot1"), r1.spec.radius) & in_passage(sim.trajectory("robot2"), r2.spec.radius)
    assert both.any()
    assert r1.collisions and r2.collisions
    assert crossings(sim.trajectory("robot1")) == crossings(sim.trajectory("robot2")) == []


def test_the_namespaces_come_from_the_world():
    """The program takes the robots' namespaces from ROBOT_ENVIRONMENT: renamed, they still work."""
    world = yaml.safe_load((SAMPLE / "world.yaml").read_text())
    world["robots"][0]["namespace"], world["robots"][1]["namespace"] = "alpha", "beta"
    result = run_on_simulator(SAMPLE, world=world, duration=70, stdout=io.StringIO(), stderr=io.StringIO())
    assert result.status == 0
    sim = result.sim
    assert [r.namespace for r in sim.robots] == ["alpha", "beta"]
    assert all(len(crossings(sim.trajectory(name))) >= 1 for name in ("alpha", "beta"))
    assert all(r.collisions == [] for r in sim.robots)
