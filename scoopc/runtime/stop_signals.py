"""Signals that end a run: SIGINT (Ctrl-C), SIGTERM (a service manager, `kill`) and SIGHUP (a closed
terminal or SSH session) all take the path Ctrl-C takes, so a program ends the same way whatever
asked it to: the runtime stops its processors, shutdown hooks run, a robot gets its zero velocity,
recordings and pictures are finished.

`stop_on_signals()` installs the handlers around a run: each signal raises `Stopped` (a
KeyboardInterrupt) in the main thread. `shielded()` marks the few steps that must not be cut
short, such as sending the robot its zero velocity: a signal that arrives then is noted and
dropped, since the run is ending already. Signals a platform lacks (SIGHUP on Windows) are
skipped; off the main thread nothing is installed (Python delivers signals to it only).
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType

STOP_SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP")

# What `signal.signal` takes and gives back: a handler, SIG_DFL/SIG_IGN, or None (not set from Python).
_Handler = Callable[[int, FrameType | None], object] | int | signal.Handlers | None


class Stopped(KeyboardInterrupt):
    """A run was asked to stop by a signal; `status` is the shell's convention, 128 + number."""

    def __init__(self, name: str, number: int):
        super().__init__(name)
        self.signal_name = name
        self.status = 128 + number


class _State:
    """Shared by the handler and `shielded` (the handler runs on the main thread, between its
    bytecodes, so a plain counter needs no lock)."""

    shield_depth = 0
    ignored: list[str] = []


def status_of(interrupt: BaseException) -> int:
    """The exit status of a run ended by `interrupt` (130, Ctrl-C's, for a bare KeyboardInterrupt)."""
    return getattr(interrupt, "status", 130)


def _handler(number: int, _frame: object) -> None:
    name = signal.Signals(number).name
    if _State.shield_depth:
        _State.ignored.append(name)
        return
    raise Stopped(name, number)


@contextmanager
def stop_on_signals() -> Iterator[None]:
    """Within the block, SIGINT, SIGTERM and SIGHUP raise `Stopped` in the main thread."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous: dict[int, _Handler] = {}
    for name in STOP_SIGNALS:
        number = getattr(signal, name, None)
        if number is not None:
            previous[number] = signal.signal(number, _handler)
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


@contextmanager
def shielded() -> Iterator[None]:
    """Within the block, a stop signal is noted and dropped instead of raised."""
    _State.shield_depth += 1
    try:
        yield
    finally:
        _State.shield_depth -= 1
