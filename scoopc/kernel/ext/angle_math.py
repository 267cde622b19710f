"""ANGLE_MATH's `external "Python"` features (stdlib/roboscoop/util/angle_math.e)."""

import math


def arc_tangent_2(current, y, x):
    return math.atan2(y, x)
