"""TIMER's `external "Python"` features (stdlib/roboscoop/util/timer.e): the runtime's clock
(virtual with `--virtual-clock` and on the simulator), in seconds, and delayed or repeated calls
of agents through the runtime's timers (`rt.call_later`): each call is a command logged on the
agent's processor. The timer keeps its runtime Timer handles in `_pending` (Python-side state of
the TIMER object, touched only by its own processor and by the calls it schedules)."""

import scoopc.runtime as rt


def now(current):
    return rt.now_ns() / 1e9


def _pending(current):
    pending = current.__dict__.get("_pending")
    if pending is None:
        pending = current._pending = []
    return pending


def _fire(action, timer, handle_box):
    """On the agent's processor: forget a one-shot call, then call the agent."""
    from .routine import run

    handle = handle_box[0]
    if handle is not None and not handle.period:
        pending = _pending(timer)
        if handle in pending:
            pending.remove(handle)
    if handle is None or not handle.cancelled:
        run(action, None)


def schedule(current, delay_ns, period_ns, action):
    box = [None]
    handle = rt.call_later(int(delay_ns), action, _fire, (current, box), period_ns=int(period_ns) or None)
    box[0] = handle
    _pending(current).append(handle)


def pending_count(current):
    return sum(1 for h in _pending(current) if not h.cancelled)


def cancel(current):
    pending = _pending(current)
    for handle in pending:
        handle.cancel()
    pending.clear()
