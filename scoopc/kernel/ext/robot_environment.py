"""ROBOT_ENVIRONMENT's `external "Python"` features (stdlib/roboscoop/util/robot_environment.e):
the settings `scoopc run` gave this run (scoopc.robots.runner.settings_of the running runtime)."""

import sys

from scoopc import runtime
from scoopc.kernel import strings
from scoopc.robots import runner


def _settings():
    return runner.settings_of(runtime.current())


def _namespaces():
    return _settings().namespaces or [""]


def namespace_of(current, i):
    return strings.new_string_8(current._region_, _namespaces()[i - 1])


def robot_count(current):
    return len(_namespaces())


def main_robot(current):
    return _settings().main + 1


def _limit(i, which):
    limits = _settings().limits
    return float(limits[i - 1][which]) if i - 1 < len(limits) else runner.ROS2_LIMITS[which]


def max_linear_of(current, i):
    return _limit(i, 0)


def max_angular_of(current, i):
    return _limit(i, 1)


def _goal(k):
    goal = _settings().goal
    return float(goal[k]) if goal is not None else 0.0


def goal_x(current):
    return _goal(0)


def goal_y(current):
    return _goal(1)


def _station(k):
    station = _settings().station
    return float(station[k]) if station is not None else 0.0


def station_x(current):
    return _station(0)


def station_y(current):
    return _station(1)


def station_radius(current):
    return _station(2)


def duration(current):
    return float(_settings().duration)


def is_simulated(current):
    return _settings().mode == "sim"


def is_ros2(current):
    return _settings().mode == "ros2"


def has_goal(current):
    return _settings().goal is not None


def has_charging_station(current):
    return _settings().station is not None


def ros_distro(current):
    return strings.new_string_8(current._region_, _settings().distro)


def has_profile(current):
    return _settings().profile is not None


def profile_stamped(current):
    settings = _settings()
    if settings.profile is not None:
        return settings.profile.stamped
    return bool(settings.stamped[settings.main]) if settings.main < len(settings.stamped) else False


def profile_topic(current, namespace, name):
    namespace, name = strings.text(namespace), strings.text(name)
    profile = _settings().profile
    found = profile.topic(name, namespace) if profile is not None and name in profile.topics else f"{namespace}/{name}"
    return strings.new_string_8(current._region_, found)


def report(current, text):

    sys.stderr.write(f"scoopc: {strings.shown(text)}\n")
    sys.stderr.flush()
