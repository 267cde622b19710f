"""TIME's `external "Python"` feature (stdlib/base/time/time.e): `fine_seconds_now`, on the same
clock as C_DATE (scoopc.kernel.ext.c_date), with EiffelTime's millisecond precision (its
`make_now` goes through C_DATE's `millisecond_now`)."""

from scoopc.kernel.ext import c_date as _c_date


def fine_seconds_now(current, a_utc):
    """Seconds since midnight now, in UTC if `a_utc`, local time otherwise."""
    _y, _mo, _d, h, mi, s, ms = _c_date.split(_c_date.wall_now(current._region_), a_utc)
    return h * 3600 + mi * 60 + s + ms / 1000
