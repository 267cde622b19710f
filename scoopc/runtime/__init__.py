"""scoopc.runtime: the SCOOP processor runtime that generated code imports (docs/RUNTIME.md)."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

from . import (
    externals,  # noqa: F401  (the program's externals run through it: externals.call)
    processor as _processor,
)
from .errors import DeadlockError, DirtyRegionError, PreconditionViolation, ScoopError, Shutdown, UncontrolledTarget
from .externals import InsideExternal, inside_externals
from .main import current, finish, run_main, start
from .monitor import dump as _dump
from .once import once_object, once_process as _once_process
from .outside import Agent, OutsideClient
from .processor import Processor
from .protocols import Args, OnceKey, Routine, Separate
from .session import Session

# Whether the runtime's hot modules were compiled to C when the package was built (mypyc,
# tools/build_runtime.py; docs/RUNTIME.md section 10), or run as the Python source here.
COMPILED = not (_processor.__file__ or "").endswith(".py")

if TYPE_CHECKING:
    from .clock import Timer
    from .sched import Runtime

__all__ = [
    "COMPILED",
    "Agent",
    "DeadlockError",
    "DirtyRegionError",
    "InsideExternal",
    "OutsideClient",
    "PreconditionViolation",
    "Processor",
    "ScoopError",
    "Session",
    "Shutdown",
    "UncontrolledTarget",
    "add_shutdown_hook",
    "call_later",
    "current",
    "dump",
    "finish",
    "inside_externals",
    "leaf",
    "now_ns",
    "once_object",
    "once_process",
    "outside_client",
    "run_main",
    "start",
]

F = TypeVar("F", bound=Callable[..., object])


def now_ns() -> int:
    """The runtime clock (virtual or real), in nanoseconds."""
    return current().clock.now_ns()


def call_later(
    delay_ns: int, target: Separate, routine: Routine, args: Args = (), period_ns: int | None = None, phase: int = 1
) -> Timer:
    """Log `routine(target, *args)` on target's processor after `delay_ns` (then every
    `period_ns`); returns a Timer with `cancel()`. `phase=0`: on the virtual clock, fire before
    the sleepers and timers due at the same instant (a simulator's step)."""
    from .clock import Timer  # deferred: a cycle (scoopc.runtime.clock imports this module)

    rt = current()
    src = _timer_source(rt)
    return rt.clock.add_timer(Timer(delay_ns, target, routine, args, period_ns, src, phase))


def _timer_source(rt: Runtime) -> OutsideClient:
    src: OutsideClient | None = getattr(rt, "_timer_source", None)
    if src is None:
        src = rt._timer_source = OutsideClient(rt, "timers")
        src.close()  # pending timers are counted by the clock, not as a source
    return src


def outside_client(name: str = "outside") -> OutsideClient:
    return OutsideClient(current(), name)


def once_process(key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    return _once_process(current(), key, fn, args)


def add_shutdown_hook(fn: Callable[[], object]) -> None:
    rt = current()
    with rt.glock:
        rt.shutdown_hooks.append(fn)


def dump() -> str:
    """A text dump of every busy processor and what each blocked one waits for."""
    return _dump(current())


def leaf(fn: F) -> F:
    """Mark a routine as a leaf (codegen: no loop, no separate call, no blocking call, no
    external, calls only leaves): a client holding its idle supplier runs it itself."""
    fn._scoop_leaf_ = True  # type: ignore[attr-defined]  # a marker on the function object
    return fn
