"""samples/go_charging on the simulator: the Thymio roams its arena while a charging behaviour waits
on the battery signaler; below 20% it drives to the charging station, charges, and goes back to work.

Over 30 simulated minutes (the sample's world, whose battery drains in about six minutes of roaming)
the battery never runs out, the robot charges several times and never touches a wall. The battery's
history is replayed from the trajectory with the simulator's battery model (docs/ROBOTS.md) and checked
against the simulator's final charge, so the minimum is the simulator's, not the program's report.
"""

import io
import math
import re
from pathlib import Path

import numpy as np
import pytest

from harness import run_on_simulator

SAMPLE = Path(__file__).resolve().parents[2] / "samples" / "go_charging"
WORLDS = SAMPLE.parent / "worlds"


def battery_history(sim, name=None):
    """(times, charge after each step, charging flags) replayed from the trajectory: the same model as
    the simulator's (drain_idle + drain_motion * effort, or charge_rate inside the station)."""
    robot = sim.robot(name)
    spec, world = robot.spec, sim.world
    traj = sim.trajectory(name)
    t, x, y, th = traj[:, 0], traj[:, 1], traj[:, 2], traj[:, 3]
    dt = np.diff(t)
    v = np.hypot(np.diff(x), np.diff(y)) / dt
    w = np.abs(np.angle(np.exp(1j * np.diff(th)))) / dt
    effort = np.maximum(v / spec.max_linear, w / spec.max_angular)
    sx, sy = world.station
    charging = np.hypot(x[1:] - sx, y[1:] - sy) <= world.station_radius
    b = spec.battery
    level, levels = b.initial, np.empty(len(dt))
    for i in range(len(dt)):
        if charging[i]:
            level = min(1.0, level + b.charge_rate * dt[i])
        else:
            level = max(0.0, level - (b.drain_idle + b.drain_motion * effort[i]) * dt[i])
        levels[i] = level
    return t[1:], levels, charging


def visits(charging):
    """(first, last) step indices of each stay in the station."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], charging.astype(int), [0]))))
    return list(zip(edges[::2], edges[1::2] - 1))


@pytest.fixture(scope="module")
def run():
    out, err = io.StringIO(), io.StringIO()
    result = run_on_simulator(SAMPLE, duration=1800, stdout=out, stderr=err)
    return result, out.getvalue(), err.getvalue()


def test_the_run_lasts_30_minutes_and_ends_cleanly(run):
    result, out, err = run
    assert result.status == 0, err
    assert result.sim.time >= 1795.0
    assert "Mission: over, stopping" in out
    assert re.search(r"stopped after \d+ trip\(s\) to the station", out), out


def test_the_battery_never_runs_out(run):
    result, _, _ = run
    sim = result.sim
    robot = sim.robot()
    _, levels, _ = battery_history(sim)
    assert abs(levels[-1] - robot.battery) < 0.01  # the replay is the simulator's battery
    assert not robot.empty
    # The behaviour leaves at 20%; the farthest corner is about 5 m away, 45 s of driving (-10%).
    assert levels.min() > 0.08, f"lowest charge {levels.min():.3f}"


def test_the_robot_charges_and_goes_back_to_work(run):
    result, out, _ = run
    sim = result.sim
    times, levels, charging = battery_history(sim)
    stays = [(a, b) for a, b in visits(charging) if times[b] - times[a] > 10.0]
    assert len(stays) >= 3, [(times[a], times[b]) for a, b in stays]
    for a, b in stays:
        assert levels[a] < 0.25  # it came because the battery was low
        assert levels[b] >= 0.97  # and left charged
    # Each stay but a last one cut short by the end is followed by work: the robot roams away.
    traj = sim.trajectory()
    for _, b in stays:
        later = traj[b + 1 : b + 1 + 6000, 1:3]  # the next minute
        if len(later) == 6000:
            assert np.hypot(*(later - traj[b, 1:3]).T).max() > 1.0
    reported = re.findall(r"Charging \[\d+ s\]: battery at (\d+)%, back to work", out)
    assert len(reported) == len(stays)
    assert all(int(p) >= 98 for p in reported)


def test_no_collision_no_fall_and_the_watchdog_never_needed(run):
    result, _, _ = run
    robot = result.sim.robot()
    assert robot.collisions == []
    assert not robot.fallen
    assert robot.distance > 100.0  # it did work: about 0.1 m/s for 25 minutes
    # the controllers command every 100 ms: the simulator's watchdog (0.5 s) only fires at the end
    assert all(t > 1790.0 for t in robot.watchdog_stops), robot.watchdog_stops[:5]


def test_the_robot_drives_to_a_station_in_another_corner():
    """samples/worlds/charging_corner.yaml: the station in the lower-right corner, 22% to start with."""
    out = io.StringIO()
    result = run_on_simulator(SAMPLE, world=WORLDS / "charging_corner.yaml", stdout=out, stderr=io.StringIO())
    assert result.status == 0
    sim = result.sim
    times, levels, charging = battery_history(sim)
    stays = visits(charging)
    assert stays, out.getvalue()
    first = stays[0][0]
    assert times[first] < 60.0  # went there at once: about 3 m to drive
    assert levels.min() > 0.1
    assert "back to work" in out.getvalue()
    assert sim.robot().collisions == []
    assert math.isclose(levels[-1], sim.robot().battery, abs_tol=0.01)


@pytest.mark.parametrize("duration, stage", [(20, "on the way"), (60, "charging")])
def test_the_mission_stop_ends_every_stage_cleanly(duration, stage):
    """The mission's stop (one second before the end) reaches the charging behaviour on its way to
    the station (navigator cancelled) or while it charges (wait condition woken): the program ends
    by itself, before the run's duration."""
    out = io.StringIO()
    result = run_on_simulator(
        SAMPLE, world=WORLDS / "charging_corner.yaml", duration=duration, stdout=out, stderr=io.StringIO()
    )
    assert result.status == 0
    assert result.stopped_by == "program", stage
    assert duration - 1.5 < result.sim.time < duration
    text = out.getvalue()
    assert "going to the station" in text and "back to work" not in text
    assert ("at the station" in text) == (stage == "charging")
    assert re.search(r"stopped after 0 trip\(s\)", text), text
