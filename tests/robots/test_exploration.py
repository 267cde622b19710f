"""EXPLORATION_BEHAVIOR on the simulator (simulated time, `run_on_simulator`): in the ten seeded
worlds samples/worlds/explore_01..10.yaml (1.6-1.8 m Thymio arenas with boxes, holes and a 5 cm
thick wall stub; 50 ms steps) the exploring Thymio never falls, never touches anything and covers at least 60% of the
reachable floor in 5 simulated minutes; a stop request halts the robot within 100 ms of
simulated time and every controller of the behaviour ends.

The ten 5-minute runs are independent programs: they run two at a time in child processes (the
first one in this process, which also compiles the program into the cache)."""

import io
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
import yaml

from harness import run_on_simulator

ROOT = Path(__file__).parents[2]
EXPLORATION = ROOT / "samples" / "exploration"
WORLDS = sorted((ROOT / "samples" / "worlds").glob("explore_*.yaml"))
STOP_PROGRAM = Path(__file__).parent / "programs" / "h1_explore_stop"

CHILD = """
import io, json, sys
import scoopc
r = scoopc.run([sys.argv[1]], robot="sim", world=sys.argv[2], stdout=io.StringIO(), stderr=io.StringIO())
print(json.dumps({
    "status": r.status, "time": r.sim.time, "coverage": r.sim.coverage(),
    "collisions": len(r.sim.robot().collisions), "fallen": r.sim.robot().fallen,
    "distance": r.sim.robot().distance, "commands": r.sim.robot().cmd_count,
    "watchdog_stops": len(r.sim.robot().watchdog_stops)}))
"""


def summary(result):
    robot = result.sim.robot()
    return {
        "status": result.status,
        "time": result.sim.time,
        "coverage": result.sim.coverage(),
        "collisions": len(robot.collisions),
        "fallen": robot.fallen,
        "distance": robot.distance,
        "commands": robot.cmd_count,
        "watchdog_stops": len(robot.watchdog_stops),
    }


def explore_in_child(world):
    done = subprocess.run(
        [sys.executable, "-c", CHILD, str(EXPLORATION), str(world)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=240,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def explorations():
    first = run_on_simulator(EXPLORATION, world=WORLDS[0], stdout=io.StringIO(), stderr=io.StringIO())
    results = {WORLDS[0].stem: summary(first)}
    with ThreadPoolExecutor(2) as pool:
        for world, outcome in zip(WORLDS[1:], pool.map(explore_in_child, WORLDS[1:])):
            results[world.stem] = outcome
    return results


def test_there_are_ten_seeded_worlds():
    assert [w.stem for w in WORLDS] == [f"explore_{i:02d}" for i in range(1, 11)]


@pytest.mark.parametrize("world", [f"explore_{i:02d}" for i in range(1, 11)])
def test_exploration_covers_the_floor_without_falling_or_touching(explorations, world):
    r = explorations[world]
    assert r["status"] == 0 and r["time"] == pytest.approx(300.0), r
    assert r["collisions"] == 0, r
    assert not r["fallen"], r
    assert r["coverage"] >= 0.60, r
    # no busy loop, no flood: the controllers' guards run every 50 ms, one command each at most;
    # and the commands never stop coming while it explores (the simulator's watchdog never fires)
    assert r["commands"] <= 2 * 300 / 0.05, r
    assert r["watchdog_stops"] == 0, r


def stop_run(seconds, *more):
    """The stop program in the first world, stepped every 10 ms (the exploration worlds step every
    50 ms, the rate of the Thymio's proximity sensors) to time the stop finely."""
    world = yaml.safe_load(WORLDS[0].read_text())
    world["step"] = 0.01
    out = io.StringIO()
    result = run_on_simulator(
        STOP_PROGRAM, world=world, argv=[seconds, *more], duration=60, stdout=out, stderr=io.StringIO()
    )
    stop_time = float(out.getvalue().split()[-1])
    return result, stop_time


@pytest.mark.parametrize("seconds, how", [("7.3", "stop"), ("12.31", "stop"), ("20", "parent")])
def test_a_stop_request_halts_the_robot_within_100_ms(seconds, how):
    """`stop` on the behaviour, or a stop of a parent STOP_SIGNALER (`set_parent`)."""
    result, stop_time = stop_run(seconds, how)
    assert result.status == 0
    assert stop_time == pytest.approx(float(seconds))
    assert result.stopped_by == "program"  # every controller ended: the program was over
    trajectory = result.sim.trajectory()
    before = trajectory[(trajectory[:, 0] >= stop_time - 0.1) & (trajectory[:, 0] <= stop_time)]
    assert np.ptp(before[:, 1:4], axis=0).max() > 0  # it was moving (or turning) just before
    after = trajectory[trajectory[:, 0] >= stop_time + 0.1]
    assert len(after) > 10  # the run went on for a second after the stop
    assert np.ptp(after[:, 1:4], axis=0).max() == 0  # and the robot never moved again
    assert result.sim.robot().cmd == (0.0, 0.0)
