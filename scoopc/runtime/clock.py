"""The runtime clock behind `sleep` and timers: real (monotonic) by default, or virtual,
jumping to the next deadline when every thread running processor code waits.

With the virtual clock, deadlines that fall on the same instant are served in phases: timers of
phase 0 (a simulator's step) fire first, and sleepers and ordinary timers (phase 1) wake only once
everything the first ones caused is over. A controller waking at the instant of a simulator step
therefore always sees that step's sensor data. Sleepers due at the same instant wake one at a
time, in the order they went to sleep, each once everything before it is over (waiting or
asleep again): controllers with the same period take their turns in the same order in every
run, instead of racing.

Timers fire on the clock thread (owned and joined by the runtime), which logs the timer's
command on its target processor like an outside client would.
"""

from __future__ import annotations

import heapq
import itertools
import threading
import time
from typing import TYPE_CHECKING

from .protocols import Args, Routine, Separate, Where
from .sched import BUSY_CALLS, Block

if TYPE_CHECKING:
    from .outside import OutsideClient
    from .processor import Processor
    from .sched import Runtime


class Timer:
    __slots__ = ("deadline", "target", "routine", "args", "period", "cancelled", "source", "phase")
    deadline: int
    target: Separate
    routine: Routine
    args: Args
    period: int | None
    cancelled: bool
    source: OutsideClient
    phase: int

    def __init__(
        self,
        deadline: int,
        target: Separate,
        routine: Routine,
        args: Args,
        period: int | None,
        source: OutsideClient,
        phase: int = 1,
    ) -> None:
        self.deadline = deadline
        self.phase = phase
        self.target, self.routine, self.args = target, routine, args
        self.period = period
        self.cancelled = False  # [rt.glock]
        self.source = source

    def cancel(self) -> None:
        rt = self.source.rt
        with rt.glock:
            self.cancelled = True
            rt.clock.cv.notify_all()


class Clock:
    """Fields marked [g] are protected by the runtime's glock."""

    heap: list[tuple[int, int, int, Timer | Block]]
    due: list[Timer]
    thread: threading.Thread | None

    def __init__(self, rt: Runtime, virtual: bool) -> None:
        self.rt = rt
        self.virtual = virtual
        self.vnow = 0  # [g] virtual time, ns
        self.heap = []  # [g] (deadline, phase, seq, Timer or Block)
        self.seq = itertools.count()  # [g]
        self.due = []  # [g] timers handed to the clock thread
        self.cv = threading.Condition(rt.glock)
        self.thread = None  # [g] the clock thread, started with the first timer
        self.stopped = False  # [g]

    def now_ns(self) -> int:
        if self.virtual:
            return self.vnow  # a plain read of an int: never torn
        return time.monotonic_ns()

    # -- sleeping ----------------------------------------------------------------------
    def sleep(self, proc: Processor, ns: int, where: Where | None = None) -> None:
        proc.busy = BUSY_CALLS  # its run of separate calls without sleeping starts again
        rt = self.rt
        with rt.glock:
            deadline = (self.vnow if self.virtual else time.monotonic_ns()) + max(ns, 0)
            blk = Block("sleep", proc, None, where, deadline)
            if self.virtual:
                heapq.heappush(self.heap, (deadline, 1, next(self.seq), blk))
        rt.block(proc.exec, blk)  # type: ignore[arg-type]  # running: its exec is set

    def real_wait(self, blk: Block, lk: threading.Lock) -> bool:
        """Wait on the real clock for a sleeper's deadline (False) or its wake-up (`lk`
        released: True, and taken again)."""
        deadline = blk.deadline
        assert deadline is not None, "a sleeper's Block has a deadline"
        while True:
            left = deadline - time.monotonic_ns()
            if left <= 0:
                return False
            if lk.acquire(timeout=left / 1e9):
                return True

    # -- timers ------------------------------------------------------------------------
    def add_timer(self, timer: Timer) -> Timer:
        rt = self.rt
        start = None
        with rt.glock:
            timer.deadline += self.vnow if self.virtual else time.monotonic_ns()
            heapq.heappush(self.heap, (timer.deadline, timer.phase, next(self.seq), timer))
            if self.thread is None and not self.stopped:
                start = self.thread = threading.Thread(target=self._run, name="scoop-clock", daemon=True)
            self.cv.notify_all()
        if start is not None:
            start.start()
        return timer

    def pending_locked(self) -> bool:
        """[g] Is a timer still to fire (keeps the program alive)?"""
        return bool(self.due) or any(isinstance(e[-1], Timer) and not e[-1].cancelled for e in self.heap)

    def advance_locked(self) -> None:
        """[g] Virtual clock, every processor thread waiting: jump to the next deadline and
        serve its first phase."""
        while self.heap and getattr(self.heap[0][-1], "cancelled", False):
            heapq.heappop(self.heap)
        if not self.heap or self.due:
            return
        now = self.vnow = max(self.vnow, self.heap[0][0])
        phase = self.heap[0][1]
        while self.heap and self.heap[0][0] <= now and self.heap[0][1] == phase:
            item = heapq.heappop(self.heap)[-1]
            if phase > 0 and isinstance(item, Block):  # sleepers due together wake one at a time
                self.rt.unblock_locked(item)
                break
            if isinstance(item, Timer):
                if not item.cancelled:
                    self.due.append(item)
            else:
                self.rt.unblock_locked(item)
        if self.due:
            self.rt.n_running += 1  # the clock thread runs until it has logged them
            self.cv.notify_all()

    def _run(self) -> None:
        rt = self.rt
        with rt.glock:
            while not self.stopped:
                if self.due:
                    due, self.due = self.due, []
                    if not self.virtual:  # virtual: counted by advance_locked
                        rt.n_running += 1
                    rt.glock.release()
                    try:
                        for t in due:
                            self._fire(t)
                    finally:
                        rt.glock.acquire()
                    rt.n_running -= 1
                    rt._check_quiet()
                    continue
                if self.virtual:
                    self.cv.wait()
                    continue
                self._collect_real()

    def _collect_real(self) -> None:
        """[g] Real clock: wait for the earliest timer and move the due ones to `due`."""
        # On the real clock only timers are in the heap (sleepers wait on their own lock).
        while self.heap and self.heap[0][-1].cancelled:  # type: ignore[union-attr]  # timers only
            heapq.heappop(self.heap)
        if not self.heap:
            self.cv.wait()
            return
        left = self.heap[0][0] - time.monotonic_ns()
        if left > 0:
            self.cv.wait(left / 1e9)
            return
        t = heapq.heappop(self.heap)[-1]
        self.due.append(t)  # type: ignore[arg-type]  # timers only, as above

    def _fire(self, t: Timer) -> None:
        try:
            t.source.call(t.target, t.routine, t.args)
        except Exception as e:  # e.g. a timer on a passive region: collected
            self.rt.fail(f"timer {getattr(t.routine, '__qualname__', t.routine)} could not be logged: {e}", e)
            return
        if t.period:
            with self.rt.glock:
                if not t.cancelled:
                    t.deadline += t.period
                    heapq.heappush(self.heap, (t.deadline, t.phase, next(self.seq), t))

    def stop(self) -> None:
        with self.rt.glock:
            self.stopped = True
            self.cv.notify_all()

    def join(self, timeout: float) -> None:
        t = self.thread
        if t is not None:
            t.join(timeout)
