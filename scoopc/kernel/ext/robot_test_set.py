"""ROBOT_TEST_SET's `external "Python"` features (stdlib/roboscoop/testing/robot_test_set.e): what
happened to the program's robot in the test's simulated world (scoopc.robots.simulated_test put
the simulator in the runtime's services)."""

import math

from scoopc import runtime
from scoopc.robots import runner
from scoopc.robots.simulated_test import SIMULATOR

_STOP = "robot_test_set.stop_requested_at"  # the test's stop request time, in the runtime's services
MOVED = 5e-4  # metres (or radians) between two steps that count as a movement


def _simulator():
    found = runtime.current().services.get(SIMULATOR)
    if found is None:
        raise RuntimeError("a ROBOT_TEST_SET's test runs with `scoopc test`, in a simulated world")
    return found


def _robot():
    rt = runtime.current()
    settings = runner.settings_of(rt)
    return _simulator().robots[settings.main]


def simulated_time(current):
    return float(_simulator().time)


def mark_stop_request(current):
    runtime.current().services[_STOP] = float(_simulator().time)


def stop_requested_at(current):
    return float(runtime.current().services.get(_STOP, -1.0))


def robot_x(current):
    return float(_robot().x)


def robot_y(current):
    return float(_robot().y)


def robot_heading(current):
    return float(_robot().theta)


def closest_approach(current, x, y):
    return float(min(math.hypot(px - x, py - y) for _t, px, py, _th in _robot().trajectory))


def distance_driven(current):
    return float(_robot().distance)


def battery_left(current):
    return float(_robot().battery)


def collision_count(current):
    return len(_robot().collisions)


def has_fallen(current):
    return bool(_robot().fallen)


def last_moved_at(current):
    path = list(_robot().trajectory)
    for (t, x, y, th), (_t0, x0, y0, th0) in zip(reversed(path), reversed(path[:-1])):
        turned = abs(math.atan2(math.sin(th - th0), math.cos(th - th0)))
        if math.hypot(x - x0, y - y0) > MOVED or turned > MOVED:
            return float(t)
    return 0.0
