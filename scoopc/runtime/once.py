"""`once` routines: per region (the Eiffel default), process-wide, or per object.

Values are keyed by region, never by thread: a call run on another thread on a region's
behalf (client executes, callbacks) sees that region's values."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

from .protocols import Args, OnceKey, OnceTable, Separate

if TYPE_CHECKING:
    from .sched import Runtime


class _Failed:
    """A once routine whose first call raised: later calls raise the same exception."""

    __slots__ = ("exc",)

    def __init__(self, exc: BaseException) -> None:
        self.exc = exc


def once_in(table: OnceTable, key: OnceKey, fn: Callable[..., object], args: Args) -> object:
    """Run `fn(*args)` the first time `key` is seen in `table`; the caller owns `table`."""
    try:
        v = table[key]
    except KeyError:
        try:
            v = fn(*args)
        except BaseException as e:
            table[key] = _Failed(e)
            raise
        table[key] = v
        return v
    if v.__class__ is _Failed:
        raise v.exc
    return v


_process_lock = threading.RLock()  # serialises first calls of process-wide onces


def once_process(rt: Runtime, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    table = rt.process_onces
    v = table.get(key, table)  # fast path: a plain dict read once computed
    if v is not table and v.__class__ is not _Failed:
        return v
    with _process_lock:
        return once_in(table, key, fn, args)


def once_object(obj: Separate, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
    """Per-object once; `obj`'s routines run only on its region, which owns the table."""
    table: OnceTable = obj.__dict__.setdefault("_onces_", {})
    return once_in(table, key, fn, args)
