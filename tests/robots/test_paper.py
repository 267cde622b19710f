"""samples/paper: the Roboscoop paper's listings as programs, each run twice in simulated time with
the same result (docs/LIBRARY.md, "The paper's names"; samples/paper/README.md).

- look: both eyes move, once, after the ball becomes visible;
- move_limbs: both limbs move, as often as each other;
- cancellable_control: once cancelled, the loop brings the speed to 0 within 1 s, with commands
  that never increase (a loop that never sleeps: simulated time goes on by the runtime's quantum);
- go_charging: the robot leaves for the station once the battery is below 20%, and reaches it;
- exploration: in samples/worlds/explore_01..03 the paper's exploration never enters a hole and
  covers at least half of the free floor in 5 simulated minutes.

Runs that take longer than a few seconds are marked slow, as are the `--realtime --duration 20` runs.
"""

import io
import json
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import scoopc
from scoopc.robots.sim.robot import SimRobot

from harness import run_on_simulator

ROOT = Path(__file__).resolve().parents[2]
PAPER = ROOT / "samples" / "paper"
WORLDS = ROOT / "samples" / "worlds"


def run_twice(name, **options):
    """Two runs of samples/paper/<name> in simulated time: (RunResult, stdout) each."""
    runs = []
    for _ in range(2):
        out, err = io.StringIO(), io.StringIO()
        result = run_on_simulator(PAPER / name, stdout=out, stderr=err, **options)
        assert result.status == 0, err.getvalue()
        runs.append((result, out.getvalue()))
    return runs


def plain_runs_twice(name):
    """Two runs of a program that drives no robot, on the virtual clock: their stdouts."""
    outs = []
    for _ in range(2):
        out, err = io.StringIO(), io.StringIO()
        result = scoopc.run([str(PAPER / name)], virtual_clock=True, png=False, stdout=out, stderr=err)
        assert result.status == 0, err.getvalue()
        outs.append(out.getvalue())
    return outs


# --- every listing checks clean --------------------------------------------------------------------


@pytest.mark.slow  # a check of its own per program: the runs below check them too, with the run
@pytest.mark.parametrize("name", ["look", "move_limbs", "go_charging", "cancellable_control", "exploration"])
def test_each_paper_program_checks_clean(name):
    result = scoopc.check([str(PAPER / name)])
    assert result.status == 0 and not result.diagnostics, [str(d) for d in result.diagnostics]


def listings():
    """The listings of samples/paper/README.md: (title, code) of each ```eiffel block under a
    '### Listing' heading."""
    text = (PAPER / "README.md").read_text(encoding="utf-8")
    found = re.findall(r"^### (Listing[^\n]*)\n(?:(?!^### ).)*?```eiffel\n(.*?)```", text, re.S | re.M)
    assert len(found) >= 7, "samples/paper/README.md lists the paper's listings"
    return found


def squeezed(text):
    return re.sub(r"\s+", " ", text).strip()


def test_the_listings_are_typed_in_unchanged():
    """Each listing of the README appears, word for word (layout aside), in the program or the library
    class that holds it."""
    sources = [p.read_text(encoding="utf-8") for p in sorted(PAPER.rglob("*.e"))]
    sources += [p.read_text(encoding="utf-8") for p in sorted((ROOT / "stdlib" / "roboscoop").rglob("*.e"))]
    haystack = squeezed("\n".join(sources))
    for title, code in listings():
        assert squeezed(code) in haystack, f"{title} is not typed in unchanged"


# --- look, move_limbs -----------------------------------------------------------------------------------


def test_look_moves_both_eyes_after_the_ball_is_visible():
    first, second = run_twice("look", png=False)
    out = first[1]
    assert out == second[1]
    lines = out.splitlines()
    shown = lines.index("Ball visible at 1 s")
    moves = [i for i, line in enumerate(lines) if re.fullmatch(r"(Left|Right) eye at 1 s: looks -?\d+ degrees", line)]
    assert len(moves) == 2 and min(moves) > shown
    assert lines[-1] == "Eyes moved: left 1, right 1"


def test_move_limbs_moves_both_limbs():
    first, second = plain_runs_twice("move_limbs")
    assert first == second
    lines = first.splitlines()
    assert [line for line in lines if line.startswith("Arm ")] == ["Arm to 30 degrees", "Arm to -30 degrees"] * 1 + [
        "Arm to 30 degrees"
    ]
    assert [line for line in lines if line.startswith("Leg ")] == ["Leg to 30 degrees", "Leg to -30 degrees"] + [
        "Leg to 30 degrees"
    ]
    assert lines[-1] == "Limbs moved: arm 3, leg 3"


# --- cancellable_control --------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def cancellable_runs():
    """Two runs of the cancellable loop, with every velocity command the simulated robot got."""
    logs = []
    original = SimRobot.command

    def logged(self, linear, angular, now):
        logs[-1].append((now, linear, angular))
        original(self, linear, angular, now)

    runs = []
    SimRobot.command = logged
    try:
        for _ in range(2):
            logs.append([])
            out, err = io.StringIO(), io.StringIO()
            result = run_on_simulator(PAPER / "cancellable_control", png=False, stdout=out, stderr=err)
            assert result.status == 0, err.getvalue()
            runs.append((result, out.getvalue(), logs[-1]))
    finally:
        SimRobot.command = original
    return runs


@pytest.mark.slow
def test_cancelled_loop_brings_the_speed_to_zero_within_a_second(cancellable_runs):
    for result, out, commands in cancellable_runs:
        cancelled = float(re.search(r"stop requested after (\d+) s", out).group(1))
        after = [(t, abs(v), abs(w)) for t, v, w in commands if t >= cancelled]
        assert after, "a command after the cancellation"
        speeds = [max(v, w) for _, v, w in after]
        assert all(b <= a for a, b in zip(speeds, speeds[1:])), "commands never increase"
        assert after[-1][1:] == (0.0, 0.0) and after[-1][0] <= cancelled + 1.0
        traj = result.sim.trajectory()
        late = traj[traj[:, 0] >= cancelled + 1.0]
        assert len(late) == 0 or np.ptp(late[:, 1:], axis=0).max() < 1e-9, "at rest a second later"
        turned = [c for c in commands if c[0] < cancelled and c[1] == 0.0 and c[2] != 0.0]
        assert turned, "the loop turned away from the wall before the cancellation"


@pytest.mark.slow
def test_a_loop_that_never_sleeps_gives_the_same_trajectory_twice(cancellable_runs):
    (first, out1, commands1), (second, out2, commands2) = cancellable_runs
    assert out1 == out2 and commands1 == commands2
    assert np.array_equal(first.sim.trajectory(), second.sim.trajectory())


# --- go_charging --------------------------------------------------------------------------------------


@pytest.mark.slow
def test_go_charging_reaches_the_station_once_the_battery_is_below_20_percent():
    runs = run_twice("go_charging", png=False)
    (first, _), (second, _) = runs
    assert np.array_equal(first.sim.trajectory(), second.sim.trajectory())
    sim = first.sim
    robot, world = sim.robot(), sim.world
    battery = robot.spec.battery
    traj = sim.trajectory()
    moved = np.hypot(traj[:, 1] - traj[0, 1], traj[:, 2] - traj[0, 2]) > 1e-6
    departure = traj[np.argmax(moved), 0]
    low = (battery.initial - 0.2) / battery.drain_idle  # at rest until then: idle drain only
    assert low <= departure <= low + 1.5  # battery states come at 1 Hz
    sx, sy = world.station
    assert np.hypot(traj[-1, 1] - sx, traj[-1, 2] - sy) <= world.station_radius
    assert not robot.collisions and not robot.fallen


# --- exploration --------------------------------------------------------------------------------------

CHILD = """
import io, json, sys
import scoopc
r = scoopc.run([sys.argv[1]], robot="sim", world=sys.argv[2], png=False, stdout=io.StringIO(), stderr=io.StringIO())
rb = r.sim.robot()
print(json.dumps({"status": r.status, "time": r.sim.time, "coverage": r.sim.coverage(), "fallen": rb.fallen,
                  "collisions": len(rb.collisions), "trajectory": r.sim.trajectory().tolist()}))
"""


def explore(world):
    done = subprocess.run(
        [sys.executable, "-c", CHILD, str(PAPER / "exploration"), str(world)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def summary(result):
    rb = result.sim.robot()
    return {
        "status": result.status,
        "time": result.sim.time,
        "coverage": result.sim.coverage(),
        "fallen": rb.fallen,
        "collisions": len(rb.collisions),
        "trajectory": result.sim.trajectory().tolist(),
    }


@pytest.fixture(scope="module")
def explorations():
    """explore_01 twice, explore_02 and explore_03 once: the first in this process (which compiles
    the program into the cache), the others two at a time in child processes."""
    worlds = [WORLDS / f"explore_0{i}.yaml" for i in (1, 1, 2, 3)]
    first = run_on_simulator(
        PAPER / "exploration", world=worlds[0], png=False, stdout=io.StringIO(), stderr=io.StringIO()
    )
    outcomes = [summary(first)]
    with ThreadPoolExecutor(2) as pool:
        outcomes += list(pool.map(explore, worlds[1:]))
    return list(zip(worlds, outcomes))


@pytest.mark.slow
def test_paper_exploration_covers_half_the_floor_and_never_falls(explorations):
    for world, outcome in explorations:
        assert outcome["status"] == 0 and outcome["time"] >= 300.0 - 1e-6, world.stem
        assert not outcome["fallen"], world.stem
        assert outcome["coverage"] >= 0.5, (world.stem, outcome["coverage"])


@pytest.mark.slow
def test_paper_exploration_gives_the_same_trajectory_twice(explorations):
    (_, first), (_, second) = explorations[:2]
    assert first["trajectory"] == second["trajectory"]


# --- real time -----------------------------------------------------------------------------------------

REALTIME = ["look", "go_charging", "cancellable_control", "exploration"]
REALTIME_CHILD = """
import io, json, sys
import scoopc
r = scoopc.run([sys.argv[1]], robot="sim", realtime=True, duration=20, png=False, stdout=io.StringIO(),
               stderr=io.StringIO())
rb = r.sim.robot()
print(json.dumps({"status": r.status, "time": r.sim.time, "fallen": rb.fallen, "collisions": len(rb.collisions)}))
"""


def run_in_real_time(name):
    done = subprocess.run(
        [sys.executable, "-c", REALTIME_CHILD, str(PAPER / name)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def realtime_runs():
    """`--realtime --duration 20` runs of the robot programs, all at once in child processes (they
    mostly wait for the wall clock); the standard library is compiled into the cache first, here,
    by a run of `look` in simulated time."""
    assert run_on_simulator(PAPER / "look", png=False, stdout=io.StringIO(), stderr=io.StringIO()).status == 0
    with ThreadPoolExecutor(len(REALTIME)) as pool:
        return dict(zip(REALTIME, pool.map(run_in_real_time, REALTIME)))


@pytest.mark.slow
@pytest.mark.parametrize("name", REALTIME)
def test_paper_programs_run_in_real_time(name, realtime_runs):
    outcome = realtime_runs[name]
    assert outcome["status"] == 0 and 0.0 < outcome["time"] <= 20.0 + 1e-6
    assert not outcome["fallen"] and outcome["collisions"] == 0
