"""Deterministic 2D differential-drive simulator: worlds, robots, sensors, a Bus-facing Simulator, rendering."""

from .robot import WATCHDOG, SimRobot
from .simulator import Simulator
from .world import World, WorldError

__all__ = ["Simulator", "SimRobot", "World", "WorldError", "WATCHDOG"]
