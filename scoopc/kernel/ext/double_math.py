"""DOUBLE_MATH's `external "Python"` features (stdlib/base/support/double_math.e).

Python's math module calls the C library (libm) for these functions, so results are those of
EiffelStudio's C externals bit for bit. Where C returns a special value instead of failing
(outside the domain, overflow), so do these: NaN, or an infinity, never a Python exception
(preconditions may be off).
"""

import math

_NAN = math.nan
_INF = math.inf


def _c(fn, v, outside=_NAN):
    try:
        return fn(v)
    except ValueError:  # domain error: C gives NaN (or the special value given)
        return outside
    except OverflowError:  # range error: C gives HUGE_VAL
        return _INF


def cosine(current, v):
    return _c(math.cos, v)


def sine(current, v):
    return _c(math.sin, v)


def tangent(current, v):
    return _c(math.tan, v)


def arc_cosine(current, v):
    return _c(math.acos, v)


def arc_sine(current, v):
    return _c(math.asin, v)


def arc_tangent(current, v):
    return _c(math.atan, v)


def sqrt(current, v):
    return _c(math.sqrt, v)


def exp(current, x):
    return _c(math.exp, x)


def _log(fn, v):
    if v == 0.0:
        return -_INF  # pole error: C gives -HUGE_VAL
    return _c(fn, v)


def log(current, v):
    return _log(math.log, v)


def log_2(current, v):
    return _log(math.log2, v)


def log10(current, v):
    return _log(math.log10, v)


def _integral(fn, v):
    if math.isinf(v) or math.isnan(v):
        return v
    r = float(fn(v))
    return math.copysign(0.0, v) if r == 0.0 else r  # C keeps the sign of a zero result


def floor(current, v):
    return _integral(math.floor, v)


def ceiling(current, v):
    return _integral(math.ceil, v)
