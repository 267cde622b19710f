"""`once` routines: per region (the Eiffel default), process-wide, or per object.

Values are keyed by region, never by thread: a call run on another thread on a region's
behalf (client executes, callbacks) sees that region's values.

The body of a once routine gets, as its last argument, the `Running` cell of its first call:
a once function keeps its `Result` in `cell.result`, so a call of the routine during its own
first execution returns the value of `Result` so far (ECMA-367 8.23.22; EiffelStudio keeps
the once's result in its once data, which `Result` designates), and a once procedure's
recursive call does nothing."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

from .protocols import Args, OnceKey, OnceTable, Separate

if TYPE_CHECKING:
    from .processor import Processor
    from .sched import Runtime


class Running:
    """The entry of a once routine whose first call is under way: `result` is its `Result`."""

    __slots__ = ("result",)

    def __init__(self) -> None:
        self.result: object = None


class _Failed:
    """A once routine whose first call raised: later calls raise the same exception."""

    __slots__ = ("exc",)

    def __init__(self, exc: BaseException) -> None:
        self.exc = exc


def once_in(table: OnceTable, key: OnceKey, fn: Callable[..., object], args: Args) -> object:
    """Run `fn(*args, cell)` the first time `key` is seen in `table` (`cell`: a new `Running`,
    the entry meanwhile); the caller owns `table`. A call during that first run returns
    `cell.result`."""
    try:
        v = table[key]
    except KeyError:
        cell = Running()
        table[key] = cell
        try:
            v = fn(*args, cell)
        except BaseException as e:
            table[key] = _Failed(e)
            raise
        table[key] = v
        return v
    if v.__class__ is _Failed:
        raise v.exc
    if v.__class__ is Running:
        return v.result
    return v


_process_lock = threading.RLock()  # serialises first calls of process-wide onces


def once_process(rt: Runtime, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    table = rt.process_onces
    v = table.get(key, table)  # fast path: a plain dict read once computed
    if v is not table and v.__class__ is not _Failed and v.__class__ is not Running:
        return v
    with _process_lock:
        return once_in(table, key, fn, args)


def once_object(obj: Separate, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    """Per-object once; `obj`'s routines run only on its region, which owns the table."""
    table: OnceTable = obj.__dict__.setdefault("_onces_", {})
    return once_in(table, key, fn, args)


# --- once per thread (EiffelThread) ----------------------------------------------------------
# A thread launched by an Eiffel THREAD runs its routines on behalf of the region of the THREAD
# object, but EiffelStudio gives each thread its own once values ("THREAD", the default in a
# thread system). Such a thread has its own table here; every other thread has none and keeps
# the region's (a processor's thread is its region's thread).

_thread = threading.local()


def thread_onces() -> OnceTable | None:
    """The once table of the calling thread if an Eiffel THREAD launched it, else None."""
    return getattr(_thread, "onces", None)


def begin_thread_onces() -> None:
    """Give the calling thread (launched by an Eiffel THREAD) once values of its own, and make
    `Processor.once` look for them (the first launch only: programs without threads keep the
    plain per-region lookup)."""
    _thread.onces = {}
    from . import processor  # deferred: processor.py imports this module

    if processor.Processor.once is not _once_per_thread:
        processor.Processor.once = _once_per_thread  # type: ignore[method-assign]  # swapped once threads exist


def _once_per_thread(self: Processor, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    """Processor.once once threads exist: the calling thread's table if it has one."""
    table = getattr(_thread, "onces", None)
    return once_in(self.onces if table is None else table, key, fn, args)
