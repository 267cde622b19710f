"""Robot tests (ROBOT_TEST_SET, run by `scoopc test`): one test's program in a simulated world of
its own, on simulated time. The simulator is a runtime service (SIMULATOR) that the test set's
queries and assertions read (scoopc/kernel/ext/robot_test_set.py). A world is deterministic and
the virtual clock too, so the same test in the same world gives the same run."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, TextIO

from ..results import RunResult
from . import runner, velocity
from .bus import Bus

SIMULATOR = "simulator"  # the Simulator's key in the runtime's services


def run_in_world(
    launch: Callable[[Callable[[Any], None]], int],
    world: Any = None,
    program_paths: Sequence[str] = (),
    stderr: TextIO | None = None,
) -> RunResult:
    """Run `launch(on_start)` (a test on a virtual clock) with the simulator of `world` (a path, a
    dict or None: world.yaml beside `program_paths`, else the built-in arena) stepping until the
    test ends; the robot is stopped at the end. RobotError when the world cannot be read."""
    from .sim.simulator import Simulator  # deferred: start-up (numpy, the world's geometry)

    found, _source = runner.find_world(program_paths, world)
    settings = runner.sim_settings(found, duration=-1.0)  # no end but the test's
    settings.distro = runner.choose_distro(None)[0]
    bus = Bus()
    sim = Simulator(found, bus)
    velocity.use_clock(lambda: sim.time_ns)
    try:
        return runner.run_with_robot(
            launch,
            settings,
            bus,
            sim=sim,
            duration=-1.0,
            stderr=stderr,
            extra_start=lambda rt: rt.services.__setitem__(SIMULATOR, sim),
        )
    finally:
        velocity.use_clock(None)
        sim.close()
