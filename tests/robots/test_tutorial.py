"""The tutorial's program (samples/first_controller, docs/tutorial.md) does what the tutorial says."""

import re
from pathlib import Path

from harness import run_on_simulator

SAMPLE = Path(__file__).parents[2] / "samples" / "first_controller"


def test_first_controller_stops_in_front_of_three_obstacles(capsys):
    result = run_on_simulator(SAMPLE)
    out, err = capsys.readouterr()
    assert result.status == 0, err
    assert result.stopped_by == "program"
    stops = [
        tuple(int(v) / 100 for v in m.groups()) for m in re.finditer(r"Stop \d at x = (-?\d+) cm, y = (-?\d+) cm", out)
    ]
    assert len(stops) == 3, out
    sim = result.sim
    robot = sim.robot()
    assert robot.collisions == [] and not robot.fallen
    # each stop is within proximity range (12 cm from the body) of a wall or the box
    world = sim.world
    for x, y in stops:
        assert world.clearance([(x, y)])[0] < robot.spec.radius + 0.13, (x, y)
    assert stops[0][0] < 1.35 and abs(stops[0][1] - 0.6) < 0.02  # first, the box straight ahead
    assert out.splitlines()[-1].startswith("Done after ")
