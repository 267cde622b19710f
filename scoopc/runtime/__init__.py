"""scoopc.runtime: the SCOOP processor runtime that generated code imports (docs/RUNTIME.md)."""
from .errors import (DeadlockError, DirtyRegionError, PreconditionViolation, ScoopError,
                     Shutdown, UncontrolledTarget)
from .main import current, finish, run_main, start
from .monitor import dump as _dump
from .once import once_object, once_process as _once_process
from .outside import Agent, OutsideClient
from .processor import Processor, Session
from . import reservation as _reservation  # noqa: F401  (installs Processor.reserve)


def now_ns():
    """The runtime clock (virtual or real), in nanoseconds."""
    return current().clock.now_ns()


def call_later(delay_ns, target, routine, args=(), period_ns=None, phase=1):
    """Log `routine(target, *args)` on target's processor after `delay_ns` (then every
    `period_ns`); returns a Timer with `cancel()`. `phase=0`: on the virtual clock, fire before
    the sleepers and timers due at the same instant (a simulator's step)."""
    from .clock import Timer
    rt = current()
    src = _timer_source(rt)
    return rt.clock.add_timer(Timer(delay_ns, target, routine, args, period_ns, src, phase))


def _timer_source(rt):
    src = getattr(rt, "_timer_source", None)
    if src is None:
        src = rt._timer_source = OutsideClient(rt, "timers")
        src.close()           # pending timers are counted by the clock, not as a source
    return src


def outside_client(name="outside"):
    return OutsideClient(current(), name)


def once_process(key, fn, args=()):
    return _once_process(current(), key, fn, args)


def add_shutdown_hook(fn):
    rt = current()
    with rt.glock:
        rt.shutdown_hooks.append(fn)


def dump():
    """A text dump of every busy processor and what each blocked one waits for."""
    return _dump(current())


def leaf(fn):
    """Mark a routine as a leaf (codegen: no loop, no separate call, no blocking call, no
    external, calls only leaves): a client holding its idle supplier runs it itself."""
    fn._scoop_leaf_ = True
    return fn
