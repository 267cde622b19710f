"""The transport the running program uses: one Bus where the simulator, the ROS 2 bridges and
the Eiffel library (ROS_PUBLISHER / ROS_SUBSCRIBER) meet.

`current()` is a process-wide default Bus unless `use(bus)` installed another one; `use(None)`
goes back to a fresh default. `reset()` gives a fresh default bus (tests).
"""

import threading

from .bus import Bus

_lock = threading.Lock()
_current = None  # [_lock] the Bus in use


def current():
    """The Bus in use (created on first use)."""
    global _current
    with _lock:
        if _current is None:
            _current = Bus()
        return _current


def use(bus):
    """Make `bus` the transport of the process (None: a fresh default on next `current()`).
    Returns the previous bus (or None)."""
    global _current
    with _lock:
        previous, _current = _current, bus
        return previous


def reset():
    """A fresh default bus (and returns it)."""
    bus = Bus()
    use(bus)
    return bus
