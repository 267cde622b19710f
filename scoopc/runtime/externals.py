"""Processors inside externals: the runtime's side of the program's own externals (user Python
functions, C and C++ code; scoopc/kernel/externals.py).

An external runs on its object's processor, on the thread that runs that processor. A blocking
external (EiffelStudio's `external "C blocking ..."`, which generates EIF_ENTER_C / EIF_EXIT_C
around the call so that the other threads never wait for it) gives up the thread's run permit
(permits.py) while it runs, so the other processors run at once instead of after a slice or two;
an external not marked blocking keeps its permit, as EiffelStudio keeps such a thread in Eiffel
mode: no hand-over, and the others wait for it as for Eiffel code that computes (about 10 ms,
then they take an extra permit). A C call releases the GIL either way (cffi does). The thread is
recorded as inside the external (`Runtime.inside`, read by `inside_externals`): the live dump
and the deadlock report name it, and the live view (scoopc's `/scoop/processors`) can show it.

Ctrl-C while the main thread is inside an external: Python runs its signal handler only
between bytecodes, so a C call that does not return would keep the program from ending. The
first external called on the main thread installs a watcher (`signal.set_wakeup_fd`, written by
the C-level handler at once): when a stop signal arrives and the main thread is still inside the
same external after GRACE seconds, the watcher says which external was running, runs the
shutdown hooks (a robot's stop) and ends the process with the signal's status.
"""

from __future__ import annotations

import os
import signal
import socket
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .processor import Processor
    from .sched import Exec, Runtime

GRACE = 1.0  # seconds the main thread gets to leave an external after a stop signal
_STOP_NUMBERS = {int(getattr(signal, n)) for n in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, n)}


@dataclass(frozen=True)
class InsideExternal:
    """A processor's thread running an external: the processor, the external routine
    ("CLASS.name"), what it calls ("C sin", "Python mymod.double") and since when
    (time.monotonic())."""

    proc: Processor
    feature: str
    what: str
    since: float

    def describe(self, now: float | None = None) -> str:
        seconds = (time.monotonic() if now is None else now) - self.since
        return f"{self.proc!r} is inside external {self.feature} ({self.what}) for {seconds:.1f} s"


def call(
    proc: Processor | None,
    feature: str,
    what: str,
    fn: Callable[..., object],
    args: Sequence[object],
    blocking: bool = True,
) -> object:
    """Run `fn(*args)`, the host function of external `feature`, on the calling thread, which runs
    `proc`: marked inside the external meanwhile, and without its run permit when `blocking`."""
    ex = proc.exec if proc is not None else None
    if proc is None or ex is None:
        return fn(*args)
    rt = proc.rt
    record = InsideExternal(proc, feature, what, time.monotonic())
    if threading.current_thread() is threading.main_thread():
        _watch_interrupts(rt)
    with rt.glock:
        rt.inside[ex] = record
        had_permit = blocking and ex.permit
        spawn = rt._release_permit_locked(ex) if blocking else None
    if spawn is not None:
        spawn.thread.start()
    try:
        return fn(*args)
    except KeyboardInterrupt:
        rt.interrupted_inside = record
        raise
    finally:
        _leave(rt, ex, had_permit)


def _leave(rt: Runtime, ex: Exec, had_permit: bool) -> None:
    with rt.glock:
        rt.inside.pop(ex, None)
        queued = had_permit and rt.permits.acquire_locked(ex)
    if queued:
        rt.permits.wait_turn(ex)


def inside_externals(rt: Runtime) -> list[InsideExternal]:
    """The processors inside an external now (the hook for live views and reports)."""
    with rt.glock:
        return sorted(rt.inside.values(), key=lambda r: r.proc.id)


def interrupted_lines(rt: Runtime) -> list[str]:
    """After a stop signal: which externals were running (report lines)."""
    found = inside_externals(rt)
    if rt.interrupted_inside is not None and rt.interrupted_inside not in found:
        found.insert(0, rt.interrupted_inside)
    return [f"scoopc: interrupted while {r.describe()}" for r in found]


# --- the watcher for the main thread ---------------------------------------------------------------
def _watch_interrupts(rt: Runtime) -> None:
    if rt.interrupt_watch is not None:
        return
    receive, send = socket.socketpair()
    receive.setblocking(True)
    send.setblocking(False)
    try:
        previous = signal.set_wakeup_fd(send.fileno(), warn_on_full_buffer=False)
    except ValueError:  # not the main thread of the main interpreter
        receive.close()
        send.close()
        return
    watcher = threading.Thread(target=_watch, args=(rt, receive), name="scoop-external-watch", daemon=True)
    rt.interrupt_watch = watcher

    def stop() -> None:
        if threading.current_thread() is watcher:
            return  # the watcher ending the process runs the hooks
        signal.set_wakeup_fd(previous)
        send.send(b"\xff")  # ends the watcher
        watcher.join(1.0)
        send.close()

    rt.shutdown_hooks.append(stop)
    watcher.start()


def _watch(rt: Runtime, receive: socket.socket) -> None:
    try:
        while True:
            data = receive.recv(64)
            if not data or b"\xff" in data:
                return
            for number in set(data) & _STOP_NUMBERS:
                _after_stop_signal(rt, number)
    finally:
        receive.close()


def _after_stop_signal(rt: Runtime, number: int) -> None:
    main = _main_record(rt)
    deadline = time.monotonic() + GRACE
    while main is not None and time.monotonic() < deadline:
        time.sleep(0.02)
        if _main_record(rt) is not main:
            return  # the external returned: Python's handler takes over
    if main is None or _main_record(rt) is not main:
        return
    name = signal.Signals(number).name
    rt.stderr.write(f"scoopc: stopped by {name} while {main.describe()}; it cannot be interrupted, the process ends\n")
    for fn in reversed(list(rt.shutdown_hooks)):
        try:
            fn()
        except Exception as e:  # noqa: BLE001 - a failing hook must not stop the others
            rt.stderr.write(f"scoopc: shutdown hook {fn!r} failed: {e!r}\n")
    rt.out.flush()
    rt.stderr.flush()
    os._exit(128 + number)


def _main_record(rt: Runtime) -> InsideExternal | None:
    main = threading.main_thread()
    with rt.glock:
        for ex, record in rt.inside.items():
            if record.proc.exec is ex and ex.name == "main" and main.is_alive():
                return record
    return None
