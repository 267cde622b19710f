"""Deep trees: the compiler's phases recurse on syntax trees nested up to 2,000 deep
(scoopc/parse/nesting.py), deeper than Python's default recursion limit and the main thread's
stack allow. `deeply` runs a phase in a thread with a large stack and a high recursion limit."""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from typing import TypeVar

STACK_BYTES = 512 * 1024 * 1024  # reserved, not used: pages are touched only as deep as it goes
RECURSION_LIMIT = 200_000
Result = TypeVar("Result")

_lock = threading.Lock()
_running = 0  # phases running deeply: the first raises the recursion limit, the last restores it
_saved_limit = 0
_inside = threading.local()


def deeply(function: Callable[..., Result], *args, **kwargs) -> Result:
    """`function(*args, **kwargs)` run in a thread of its own with a big stack (its exception
    raised here); run directly when already in such a thread."""
    if getattr(_inside, "deep", False):
        return function(*args, **kwargs)
    outcome: dict[str, object] = {}

    def run() -> None:
        _inside.deep = True
        try:
            outcome["value"] = function(*args, **kwargs)
        except BaseException as problem:  # raised again in the caller's thread
            outcome["error"] = problem

    _enter()
    try:
        with _lock:
            previous = threading.stack_size(STACK_BYTES)
            try:
                thread = threading.Thread(target=run, name="scoopc-phase", daemon=True)
                thread.start()
            finally:
                threading.stack_size(previous)
        thread.join()
    finally:
        _leave()
    if "error" in outcome:
        raise outcome["error"]  # type: ignore[misc]
    return outcome["value"]  # type: ignore[return-value]


def _enter() -> None:
    global _running, _saved_limit
    with _lock:
        if _running == 0:
            _saved_limit = sys.getrecursionlimit()
            sys.setrecursionlimit(max(_saved_limit, RECURSION_LIMIT))
        _running += 1


def _leave() -> None:
    global _running
    with _lock:
        _running -= 1
        if _running == 0:
            sys.setrecursionlimit(_saved_limit)
