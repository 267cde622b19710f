"""SINGLE_MATH's `external "Python"` features (stdlib/base/support/single_math.e).

As EiffelBase's C externals: the REAL_32 argument is widened to double, the C library function
(Python's math calls libm) computes in double, and the result is rounded to single precision.
"""

import math
import struct

from scoopc.kernel.ext import double_math as _d

_PACK = struct.Struct("f")


def to_single(x):
    """`x` rounded to the nearest REAL_32 (an infinity past the single range, as C's cast)."""
    try:
        return _PACK.unpack(_PACK.pack(x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def cosine(current, v):
    return to_single(_d.cosine(current, v))


def sine(current, v):
    return to_single(_d.sine(current, v))


def tangent(current, v):
    return to_single(_d.tangent(current, v))


def arc_cosine(current, v):
    return to_single(_d.arc_cosine(current, v))


def arc_sine(current, v):
    return to_single(_d.arc_sine(current, v))


def arc_tangent(current, v):
    return to_single(_d.arc_tangent(current, v))


def sqrt(current, v):
    return to_single(_d.sqrt(current, v))


def exp(current, x):
    return to_single(_d.exp(current, x))


def log(current, v):
    return to_single(_d.log(current, v))


def log_2(current, v):
    return to_single(_d.log_2(current, v))


def log10(current, v):
    return to_single(_d.log10(current, v))


def floor(current, v):
    return to_single(_d.floor(current, v))


def ceiling(current, v):
    return to_single(_d.ceiling(current, v))
