"""Run permits: how many threads run processor code at once (one under the GIL).

Why. Under the GIL, threads that all want to run are switched every 5 ms wherever they
are; a client switched out while it holds a reservation makes every other client of
that supplier queue behind it, and each of them then waits for a thread switch (a
convoy). With permits, a thread runs processor code only while it holds one; the others
sleep on their own lock, so the GIL is not contested and a thread runs until it blocks
in the runtime, where it hands its permit directly to the next waiter (FIFO).

Fairness and progress, without polling: a permit waiter sleeps at most one SLICE at a
time. After a slice it asks the holders to yield (`want_yield`, checked at reservation
entry, a point where yielding holds up no queue); if no permit changed hands during a
whole further slice, the holders are stuck in a long computation or a blocking call
outside the runtime, and the waiter takes an extra permit (given back later). So a long
computation or a blocking external call never stops the other processors for more than
about two slices. Correctness never depends on permits: every shared structure has its
own lock; permits only decide who runs.
"""

from __future__ import annotations

import os
import sys
from collections import deque
from typing import TYPE_CHECKING, Final

from .errors import Shutdown

if TYPE_CHECKING:
    from .sched import Exec, Runtime

SLICE: Final = 0.005  # seconds


def base_permits() -> int:
    """One permit with the GIL; one per CPU on a free-threaded interpreter."""
    gil: bool = getattr(sys, "_is_gil_enabled", lambda: True)()
    return 1 if gil else (os.cpu_count() or 1)


class Permits:
    """Fields marked [g] are protected by the runtime's glock (`rt.glock`)."""

    waiting: deque[Exec]

    def __init__(self, rt: Runtime) -> None:
        self.rt = rt
        self.base = base_permits()
        self.total = self.base  # [g] permits, including extra ones for stuck holders
        self.held = 0  # [g]
        self.waiting = deque()  # [g] Execs waiting for a permit, FIFO
        self.moves = 0  # [g] permits changed hands (progress, for stuck checks)
        self.want_yield = False  # [g] written; read racily at yield points

    def acquire(self, ex: Exec) -> None:
        """Take a permit for thread `ex` (waiting for one if none is free)."""
        glock = self.rt.glock  # no `with` on a hot path (docs/RUNTIME.md section 10)
        glock.acquire()
        try:
            queued = self.acquire_locked(ex)
        finally:
            glock.release()
        if queued:
            self._wait(ex)

    def acquire_locked(self, ex: Exec) -> bool:
        """[g] Take a free permit for `ex` (False), or queue `ex` for one (True: the
        caller must then call `wait_turn` after releasing glock)."""
        if self.held < self.total and not self.waiting or self.rt.stopping:
            self.held += 1
            ex.permit = True
            return False
        ex.plock.acquire()
        self.waiting.append(ex)
        return True

    def release_locked(self, ex: Exec) -> None:
        """[g] Give thread `ex`'s permit to the first waiter, or back."""
        if not ex.permit:
            return
        ex.permit = False
        self.moves += 1
        if self.waiting:
            self._want_yield(False)
            self.waiting.popleft().plock.release()  # the permit moves over
            return
        self.held -= 1
        if self.total > self.base:
            self.total -= 1  # an extra permit is given back

    def release(self, ex: Exec) -> None:
        glock = self.rt.glock  # no `with` (as `acquire`)
        glock.acquire()
        try:
            self.release_locked(ex)
        finally:
            glock.release()

    def _want_yield(self, flag: bool) -> None:
        """[g] Set `want_yield` and the runtime's summary flag read at reservation entry."""
        self.want_yield = flag
        self.rt.attention = flag or self.rt.stopping

    def yield_point(self, ex: Exec) -> None:
        """Called at reservation entry when `want_yield` is set: let a waiter run."""
        rt = self.rt
        with rt.glock:
            self._want_yield(False)
            if not self.waiting or not ex.permit:
                return
            self.moves += 1
            self.waiting.popleft().plock.release()
            ex.plock.acquire()
            self.waiting.append(ex)
        self._wait(ex)

    def wait_turn(self, ex: Exec) -> None:
        self._wait(ex)

    def _wait(self, ex: Exec) -> None:
        rt = self.rt
        lk = ex.plock
        seen: int | None = None
        while not lk.acquire(timeout=SLICE):
            with rt.glock:
                spawn = rt.overdue_worker_locked()
            if spawn is not None:
                spawn.thread.start()
            with rt.glock:
                extra, seen = self._after_slice(ex, seen)
            if extra:
                break
        lk.release()
        ex.permit = True
        if rt.stopping:
            raise Shutdown()

    def _after_slice(self, ex: Exec, seen: int | None) -> tuple[bool, int | None]:
        """[g] `ex` waited a whole slice for a permit. (True, _): it takes an extra one now (the
        holders are stuck, or stopping); else (False, the moves seen) and it waits once more.
        (A function rather than `continue` inside `with`, which a compiled runtime lacks.)"""
        if ex not in self.waiting:  # handed over just now: the next acquire takes it
            return False, seen
        if not self.rt.stopping and (seen != self.moves or not self.want_yield):
            self._want_yield(True)  # ask the holders to yield, wait a slice more
            return False, self.moves
        self.waiting.remove(ex)  # stuck holders (or stopping): one more permit
        self.total += 1
        self.held += 1
        return True, seen

    def stop_locked(self) -> None:
        """[g] Shutdown: let every waiter run (to meet Shutdown at its next runtime call)."""
        while self.waiting:
            ex = self.waiting.popleft()
            self.total += 1
            self.held += 1
            ex.plock.release()
