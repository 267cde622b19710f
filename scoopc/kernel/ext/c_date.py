"""C_DATE's `external "Python"` features (stdlib/time/c_date.e): the clock and the calendar.

`current_timestamp` reads the wall clock (seconds since 1970-01-01 UTC). With the runtime's
virtual clock (`run_main(..., virtual_clock=True)`) it is the wall time when the program first
read it plus the virtual time elapsed since, so virtual time moves C_DATE and TIME too.
`field` splits a timestamp in local time (the host's time zone, as EiffelTime's C code with
`localtime`) or UTC; milliseconds are truncated, as EiffelTime's.
"""

import math
import time
import weakref

_BASES = weakref.WeakKeyDictionary()  # a runtime's virtual clock -> wall time at its 0


def wall_now(region):
    """Seconds since the epoch now, on the runtime clock of `region` (see above)."""
    rt = getattr(region, "rt", None)
    clock = getattr(rt, "clock", None)
    if clock is None or not getattr(clock, "virtual", False):
        return time.time()
    now = clock.now_ns() / 1e9
    base = _BASES.get(clock)
    if base is None:
        base = _BASES.setdefault(clock, time.time() - now)
    return base + now


def split(timestamp, utc):
    """(year, month, day, hour, minute, second, millisecond) of `timestamp`."""
    whole = math.floor(timestamp)
    ms = min(int((timestamp - whole) * 1000), 999)
    t = time.gmtime(whole) if utc else time.localtime(whole)
    return (t.tm_year, t.tm_mon, t.tm_mday, t.tm_hour, t.tm_min, min(t.tm_sec, 59), ms)


def current_timestamp(current):
    return wall_now(current._region_)


def field(current, a_timestamp, a_utc, a_index):
    """Field `a_index` (1 year, 2 month, 3 day, 4 hour, 5 minute, 6 second, 7 millisecond)."""
    if not 1 <= a_index <= 7:
        raise ValueError(f"C_DATE.field: no field {a_index}")
    return split(a_timestamp, a_utc)[a_index - 1]
