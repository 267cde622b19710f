"""The scheduler: the pool of worker threads that run processors with work, the registry of
blocked threads, quiescence (termination) and the hook that advances the virtual clock.

Design. A processor is a data structure; an OS thread is attached to it only while its
queue of queues has work (`schedule`), taken from a pool of parked workers. A worker that
finishes a processor first takes the next runnable processor itself, so a chain of
hand-offs (threadring) runs on one thread without a thread switch; a parked worker is woken
only when it can be useful (`_want_worker`), and a new thread is started only when none is
parked. Threads run processor code only while holding a run permit (permits.py); a
permit waiter that finds the holders stuck takes an extra one, so a long computation
delays the other processors by about 10 ms at most.
Blocking (synchronous calls, wait conditions, passive-region turns, sleep) goes through
`block`, which records what the thread waits on for the deadlock monitor and the dump.

Lock order: a processor's `lock` may be held while taking `glock`, never the reverse.
"""

from __future__ import annotations

import itertools
import sys
import threading
import time
import weakref
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Final, TextIO

from .errors import CREATION, Shutdown, fmt_where
from .protocols import OnceTable, Where
from .session import IDLE

if TYPE_CHECKING:
    from .anchor import Anchor
    from .externals import InsideExternal
    from .monitor import Monitor
    from .outside import OutsideClient
    from .processor import Processor
    from .session import Session

STARVE_AFTER: Final = 0.005  # seconds a runnable processor may wait for a permit before a worker comes
MAX_PARKED: Final = 16  # parked workers kept; more exit (joined by the runtime)
# Virtual time never stalls on a busy processor (docs/RUNTIME.md section 4): a processor that
# makes BUSY_CALLS separate calls (reservations: routines with separate arguments, separate
# blocks) without sleeping in between sleeps BUSY_QUANTUM_NS on the virtual clock before the
# next one. Counted per processor and reset by its sleeps only (not by waits, whose occurrence
# can depend on thread timing), so the same program gives the same run.
BUSY_CALLS: Final = 20
BUSY_QUANTUM_NS: Final = 10_000_000  # 10 ms


class RunEvent:
    """Something a live view shows in its log (snapshot.py): `kind` is "deadlock", "failure",
    "lost exception" or "dirty region"; `at` the wall-clock time (seconds)."""

    __slots__ = ("at", "kind", "text")

    def __init__(self, kind: str, text: str, at: float) -> None:
        self.kind = kind
        self.text = text
        self.at = at


def dirty_text(proc: Processor, s: Session, e: BaseException) -> str:
    """The event of a region made dirty for client `s.client` by the failure `e`."""
    reserved = f", reservation at {fmt_where(s.where)}" if s.where is not None and s.where != CREATION else ""
    return f"{proc!r} is dirty for {s.client!r}{reserved}: an asynchronous call failed: {type(e).__name__}: {e}"


class Exec:
    """One OS thread running processor code (a worker, the main thread, a client)."""

    __slots__ = ("blocked", "name", "permit", "plock", "slock")
    blocked: Block | None
    name: str
    permit: bool
    plock: threading.Lock
    slock: threading.Lock

    def __init__(self, name: str) -> None:
        self.blocked = None  # Block or None; written by the owner thread under rt.glock
        self.name = name
        self.permit = False  # [rt.glock] this thread holds a run permit (permits.py)
        self.plock = threading.Lock()  # locked while waiting for a permit
        self.slock = threading.Lock()  # the thread's wake-up lock: held while it is awake;
        self.slock.acquire()  #          `block` sleeps on it, a waker releases it once


class Block:
    """What a blocked thread waits for; a new one per episode, so identity marks progress.

    Its waker sets `woken` under glock, and releases the thread's wake-up lock (`Exec.slock`,
    held by its thread whenever it is awake) if the thread published it to sleep on it
    (`Runtime.block`, under glock too): a Block whose waker came first (a query answered
    before its client blocks, a wait condition changed meanwhile) touches no lock. The lock
    is released at most once per Block, and `block` takes it back when its thread woke
    otherwise (a deadline, a stop, an interrupt), so it is held again before the next sleep."""

    __slots__ = ("kind", "proc", "on", "where", "lock", "woken", "deadline", "exec", "value", "error", "what", "since")
    kind: str
    proc: Processor
    on: Session | tuple[Processor, ...] | None
    where: Where | None
    lock: threading.Lock | None
    woken: bool
    deadline: int | None
    exec: Exec | None
    value: object
    error: BaseException | None
    what: object
    since: float

    def __init__(
        self,
        kind: str,
        proc: Processor,
        on: Session | tuple[Processor, ...] | None,
        where: Where | None,
        deadline: int | None = None,
        what: object = None,
    ) -> None:
        self.kind = kind  # 'sync' | 'turn' | 'wait' | 'sleep'
        self.proc = proc  # the processor that waits (innermost context)
        self.on = on  # sync/turn: the Session; wait: tuple of processors
        self.where = where
        self.lock = None  # [glock] its thread's wake-up lock (Exec.slock) while the thread sleeps
        self.woken = False  # [glock] its waker ran (`unblock_locked`)
        self.deadline = deadline  # sleep only
        self.exec = None  # the blocked thread's Exec, set by `block`
        self.value = None  # sync: the result, written before `unblock`; wait: the
        #                           region whose waker took it off its `waiters` list
        self.error = None  # sync: the exception to re-raise in the client
        self.what = what  # sync: the routine called; wait: the clause tag


def _proc_id(p: Processor) -> int:
    return p.id


def _blocked_of(ex: Exec) -> Block | None:
    """`ex.blocked` read afresh. Where a function set `ex.blocked` itself and blocked since, the
    type checker still takes it for what was set; a compiled runtime (docs/RUNTIME.md section
    10) checks that type on the read, and another thread may have cleared it meanwhile."""
    return ex.blocked


def wake(lock: threading.Lock) -> None:
    """Release a wake-up lock; releasing one already released (a worker's, by a stop racing
    `schedule`) is harmless."""
    try:
        lock.release()
    except RuntimeError:
        pass


class Worker:
    __slots__ = ("rt", "lock", "exec", "thread")
    rt: Runtime
    lock: threading.Lock
    exec: Exec
    thread: threading.Thread

    def __init__(self, rt: Runtime, n: int) -> None:
        self.rt = rt
        self.lock = threading.Lock()  # held while parked; released by `schedule`
        self.lock.acquire()
        self.exec = Exec(f"worker-{n}")
        self.thread = threading.Thread(target=self.run, name=self.exec.name, daemon=True)

    def run(self) -> None:
        rt, ex = self.rt, self.exec
        try:
            fresh = True  # started by `schedule`, which counted it in n_waking
            while True:
                p = rt.next_work(self, fresh)
                fresh = False
                if p is None:
                    return
                if not ex.permit:
                    rt.permits.acquire(ex)
                p.run_scheduled(ex)
        except Shutdown:
            rt.leave_running(ex)
        except BaseException as e:  # an internal error: the owner collects it
            rt.fail(f"internal error in {ex.name}: {e!r}", e)
            rt.leave_running(ex)


class Runtime:
    """Process-wide runtime state. `glock` protects every field marked [g]."""

    describe: Callable[[BaseException, Processor], str] | None
    runnable: deque[Processor]
    parked: list[Worker]
    blocked: set[Exec]
    workers: list[Worker]
    failures: list[tuple[str, BaseException | None]]
    lost: set[Processor]
    procs: weakref.WeakValueDictionary[int, Anchor]
    stderr: TextIO
    shutdown_hooks: list[Callable[[], object]]
    services: dict[str, object]
    process_onces: OnceTable
    monitor: Monitor | None
    watchers: list[tuple[Callable[[Block], object], threading.Event]]
    _timer_source: OutsideClient  # the source of timers' commands, made by the first call_later

    def __init__(
        self,
        *,
        virtual_clock: bool = False,
        trace_processors: bool = False,
        strict: bool = False,
        stdout: TextIO | None = None,
        stderr: TextIO | None = None,
        deadlock_tick: float = 0.2,
    ) -> None:
        from .clock import Clock  # deferred: a cycle (scoopc.runtime.clock imports this module)
        from .output import Output  # deferred: a cycle (scoopc.runtime.output imports this module)
        from .permits import Permits  # deferred: a cycle (scoopc.runtime.permits imports this module)

        self.glock = threading.Lock()
        self.describe = None  # describe(exception, processor) -> text, set by run_main
        self.permits = Permits(self)
        self.runnable = deque()  # [g] processors in state SCHEDULED, FIFO
        self.runnable_since = 0.0  # [g] monotonic time the runnable queue's head was queued
        self.parked = []  # [g] parked Workers
        self.n_waking = 0  # [g] workers woken but not yet looking for work
        self.n_running = 0  # [g] threads counted as running processor code
        self.blocked = set()  # [g] Execs currently blocked
        self.workers = []  # [g] every Worker started and not yet joined
        self.sources = 0  # [g] open outside clients
        self.failures = []  # [g] (message, exception) run-time failures
        self.lost = set()  # [g] processors whose failed asynchronous call no client saw (reported)
        self.events: list[RunEvent] = []  # [g] dirty regions, lost exceptions, failures (snapshot.py)
        self.stopping = False  # [g] set once; read racily as a fast check
        self.attention = False  # [g] stopping or permits.want_yield: one racy read
        #                                  at reservation entry instead of two
        self.changed = threading.Condition(self.glock)  # quiescence / stop, for run_main
        self.wait_set = 0  # [g] number of blocked threads of kind 'wait'
        self.idlock = threading.Lock()
        self.ids = itertools.count(1)  # [idlock]
        self.procs = weakref.WeakValueDictionary()  # [idlock] id -> the Anchor of a live Processor
        self.strict = strict
        self.trace_processors = trace_processors
        self.deadlock_tick = deadlock_tick
        self.stderr = stderr or sys.stderr
        self.out = Output(stdout or sys.stdout, trace_processors)
        self.clock = Clock(self, virtual_clock)
        self.shutdown_hooks = []  # [g]
        self.inside: dict[Exec, InsideExternal] = {}  # [g] threads inside an external (externals.py)
        self.interrupted_inside: InsideExternal | None = None  # the external a stop signal interrupted
        self.interrupt_watch: threading.Thread | None = None  # externals.py's watcher, once installed
        self.services = {}  # what the embedding run offers the program's externals, by
        #                                  name (set by `on_start`, before the root object exists)
        self.process_onces = {}  # [g] once ("PROCESS") values
        self.monitor = None
        self.watchers = []  # [g] (predicate, Event): scheduling hooks for tests
        self._outside = threading.local()  # .exec: the Exec of an outside thread (run_here)

    # -- identities ------------------------------------------------------------------
    def register(self, proc: Processor) -> int:
        with self.idlock:
            pid = next(self.ids)
            self.procs[pid] = proc.anchor
        return pid

    def processors(self) -> list[Processor]:
        """The live processors, sorted by id (for dumps and live views)."""
        with self.idlock:
            procs = [a.proc for a in self.procs.values()]
        procs.sort(key=_proc_id)
        return procs

    # -- the pool --------------------------------------------------------------------
    def schedule(self, p: Processor) -> None:
        """`p` was set SCHEDULED under its lock: make sure some thread will run it."""
        glock = self.glock  # no `with` (section 10)
        glock.acquire()
        try:
            if not self.runnable:
                self.runnable_since = time.monotonic()
            self.runnable.append(p)
            spawn = self._wake_one_locked() if self._want_worker() else None
        finally:
            glock.release()
        if spawn is not None:
            spawn.thread.start()

    def _want_worker(self) -> bool:
        """[g] Should one more worker come for the runnable queue? Not if one is already on
        its way. When every permit is taken and threads wait for one, a worker would only
        wait too, and the permit usually comes back to the runnable queue soon (a waiter
        blocks or finishes): wake one only once the queue's head has waited STARVE_AFTER.
        The waiters may be busy processors handing the permit among themselves at
        reservation entry, which would otherwise starve the runnable queue."""
        if self.n_waking:
            return False
        pm = self.permits
        if pm.held < pm.total or not pm.waiting:
            return True
        return time.monotonic() - self.runnable_since > STARVE_AFTER

    def overdue_worker_locked(self) -> Worker | None:
        """[g] A worker for the runnable queue if its head has waited too long (permit
        waiters call this on every slice; returned: start it unlocked)."""
        if self.runnable and self._want_worker():
            return self._wake_one_locked()
        return None

    def _wake_one_locked(self) -> Worker | None:
        """[g] Wake a parked worker, or make a new one (returned: start it unlocked)."""
        self.n_waking += 1
        self.n_running += 1
        if self.parked:
            self.parked.pop().lock.release()
            return None
        if self.stopping:
            self.n_waking -= 1
            self.n_running -= 1
            return None
        w = Worker(self, len(self.workers))
        self.workers.append(w)
        return w

    def next_work(self, w: Worker, fresh: bool) -> Processor | None:
        """The next runnable processor for worker `w`, parking it while there is none.
        A worker taking work while more is waiting wakes another one first: a processor
        that runs for long (or blocks outside the runtime) never holds up the others."""
        spawn = None
        glock = self.glock  # no `with` (section 10)
        glock.acquire()
        try:
            if fresh:
                self.n_waking -= 1
            while True:
                if self.stopping:
                    self.permits.release_locked(w.exec)
                    self.n_running -= 1
                    self.changed.notify_all()
                    return None
                if self.runnable:
                    p = self.runnable.popleft()
                    if self.runnable:
                        self.runnable_since = time.monotonic()
                        if self._want_worker():
                            spawn = self._wake_one_locked()
                    break
                self.permits.release_locked(w.exec)
                if len(self.parked) >= MAX_PARKED:
                    self.n_running -= 1
                    self._check_quiet()
                    return None
                self.parked.append(w)
                self.n_running -= 1
                self._check_quiet()
                glock.release()
                try:
                    w.lock.acquire()
                finally:
                    glock.acquire()
                self.n_waking -= 1
        finally:
            glock.release()
        if spawn is not None:
            spawn.thread.start()
        return p

    def outside_exec(self) -> Exec:
        """The Exec of the calling thread, which runs no processor (a transport's own)."""
        ex = getattr(self._outside, "exec", None)
        if ex is None:
            ex = self._outside.exec = Exec(f"outside-{threading.current_thread().name}")
        return ex

    def run_here(self, p: Processor, s: Session, ex: Exec) -> None:
        """An outside thread (Exec `ex`) runs the leaf calls of its closed session `s`, the head
        of `p`, which it has set RUNNING on its behalf (OutsideClient.call): as a worker would,
        counted running and holding a permit, minus the thread switch. Then it ends the session
        (waking the wait conditions over `p`) and leaves what is queued behind to the pool."""
        with self.glock:
            self.n_running += 1
            queued = self.permits.acquire_locked(ex)
        try:
            if queued:
                self.permits.wait_turn(ex)
            batch, s.calls = s.calls, []
            p._run_calls(s, batch)
        except Shutdown:  # stopping: the transport's thread goes on (and stops)
            pass
        finally:
            lock = p.lock
            lock.acquire()
            p.exec = None
            p.state = IDLE
            if p.head is s and not s.calls and not p.qoq and s.dirty is None and not (s.changed and p.waiters):
                p.head = None  # the common case: nothing else to do
                lock.release()
            else:
                p.settle_locked(None)  # end `s` (wakes waiters); the pool takes the rest
            self.leave_running(ex)

    def leave_running(self, ex: Exec) -> None:
        glock = self.glock  # no `with` (section 10)
        glock.acquire()
        try:
            spawn = self._release_permit_locked(ex)
            self.n_running -= 1
            self._check_quiet()
        finally:
            glock.release()
        if spawn is not None:
            spawn.thread.start()

    def _release_permit_locked(self, ex: Exec) -> Worker | None:
        """[g] Give up `ex`'s permit; if it is now free and processors wait in the
        runnable queue with no worker coming, wake one (returned: start it unlocked)."""
        self.permits.release_locked(ex)
        if self.runnable and self._want_worker():
            return self._wake_one_locked()
        return None

    def _check_quiet(self) -> None:
        """[g held] Wake run_main on quiescence; advance the virtual clock when all wait."""
        if self.n_running == len(self.blocked) and not self.runnable:
            if self.n_running == 0:
                self.changed.notify_all()
            if self.clock.virtual:
                self.clock.advance_locked()

    def attend(self, ex: Exec) -> None:
        """Reservation entry found `attention` set: a safe point to yield the permit to a
        waiter that asked; a stop point when shutting down."""
        if self.permits.want_yield:
            self.permits.yield_point(ex)
        if self.stopping:
            raise Shutdown()

    # -- blocking --------------------------------------------------------------------
    def block(self, ex: Exec, blk: Block) -> None:
        """Block thread `ex` until `blk`'s waker runs (`unblock`); raise Shutdown when the
        runtime stops. The re-check of `woken` under glock pairs with `unblock`, so a thread
        is never counted blocked after its waker ran (the virtual clock relies on it)."""
        if blk.woken:  # a plain read: if stale, the check under glock decides
            return
        blk.exec = ex
        blk.since = time.monotonic()  # for live views (snapshot.py): only a thread that really blocks pays it
        lk = ex.slock
        glock = self.glock  # taken and released explicitly on this path (section 10: no `with`)
        glock.acquire()
        try:
            if blk.woken:
                return
            blk.lock = lk
            ex.blocked = blk
            self.blocked.add(ex)
            if blk.kind == "wait":
                self.wait_set += 1
            if self.watchers:
                self._notify_watchers(blk)
            self._check_quiet()
            stopping = self.stopping
            had_permit = ex.permit
            spawn = self._release_permit_locked(ex)
        finally:
            glock.release()
        if spawn is not None:
            spawn.thread.start()
        woke = queued = got = False
        try:
            if not stopping:
                if blk.deadline is not None and not self.clock.virtual:
                    got = self.clock.real_wait(blk, lk)
                else:
                    got = lk.acquire()
            woke = True
        finally:
            glock.acquire()
            try:
                if not got:  # a sleeper's deadline, a stop, an interrupt: the lock must stay held
                    if blk.woken:  # its waker released it (under glock, once): take it back
                        lk.acquire(False)
                    else:
                        blk.woken = True  # and no waker will release it any more
                blk.lock = None
                if _blocked_of(ex) is blk:
                    self.blocked.discard(ex)
                    ex.blocked = None
                if blk.kind == "wait":
                    self.wait_set -= 1
                stopping = self.stopping
                if woke and had_permit and not stopping:  # one glock round for both
                    queued = self.permits.acquire_locked(ex)
            finally:
                glock.release()
        if stopping:
            raise Shutdown()
        if queued:
            self.permits.wait_turn(ex)

    def watch_blocks(self, predicate: Callable[[Block], object]) -> threading.Event:
        """Scheduling hook: an Event set when a thread blocks on a Block for which
        `predicate(block)` is true (tests wait on it instead of sleeping)."""
        ev = threading.Event()
        with self.glock:
            self.watchers.append((predicate, ev))
            for ex in self.blocked:
                if ex.blocked is not None and predicate(ex.blocked):
                    ev.set()
        return ev

    def _notify_watchers(self, blk: Block) -> None:
        for pred, ev in self.watchers:
            if pred(blk):
                ev.set()

    def unblock(self, blk: Block) -> None:
        """Wake the thread blocked (or about to block) on `blk`; at most once matters."""
        glock = self.glock  # no `with` (section 10)
        glock.acquire()
        try:
            self.unblock_locked(blk)
        finally:
            glock.release()

    def unblock_locked(self, blk: Block) -> None:
        if blk.woken:
            return
        blk.woken = True
        ex = blk.exec
        if ex is not None and ex.blocked is blk:
            self.blocked.discard(ex)
            ex.blocked = None
        lk = blk.lock
        if lk is not None:  # the thread sleeps on it
            wake(lk)

    # -- failures and stopping -------------------------------------------------------
    def fail(self, message: str, exc: BaseException | None = None, kind: str = "failure") -> None:
        with self.glock:
            self.failures.append((message, exc))
            self.events.append(RunEvent(kind, message, time.time()))
        self.stop()

    def note(self, kind: str, text: str) -> None:
        """Record an event for live views (snapshot.py): rare ones only (a dirty region, a lost
        exception); the run's failures are recorded by `fail`."""
        with self.glock:
            self.events.append(RunEvent(kind, text, time.time()))

    def report_lost(self, proc: Processor, s: Session) -> None:
        """[proc.lock held] An asynchronous call failed and no client ever saw it. A failed
        creation leaves its object half made: later failures on that region follow from it and
        get one line each, not a report of their own."""
        e = s.dirty
        assert e is not None, "a lost exception is a dirty session's"
        detail = self.describe(e, proc) if self.describe is not None else f"{type(e).__name__}: {e}"
        with self.glock:
            again = proc in self.lost
            if s.where == CREATION:
                self.lost.add(proc)
        self.note("lost exception", f"exception lost on {proc!r} (client {s.client!r}): {detail}")
        if again:
            first, _, rest = detail.partition("\n")
            where = rest.split("\n", 1)[0].strip()
            self.stderr.write(f"scoopc:   then on {proc!r}, as a consequence: {first}{', ' + where if where else ''}\n")
        elif s.where == CREATION:
            self.stderr.write(f"scoopc: exception lost in the creation of {proc!r} by {s.client!r}: {detail}\n")
        else:
            reserved = f", reservation at {fmt_where(s.where)}" if s.where is not None else ""
            self.stderr.write(
                f"scoopc: exception lost in an asynchronous call on {proc!r} (client {s.client!r}{reserved}): "
                f"{detail}\n"
            )
        if self.strict:
            self.fail(f"lost exception on {proc!r}: {detail}", e)

    def stop(self) -> None:
        """Stop every processor at its next runtime call and wake every blocked thread."""
        with self.glock:
            if self.stopping:
                return
            self.stopping = True
            self.attention = True
            for ex in list(self.blocked):
                blk = ex.blocked
                assert blk is not None, "[g] a thread in `blocked` has its Block"
                self.unblock_locked(blk)
            self.permits.stop_locked()
            for w in self.parked:  # counted as woken, as `schedule` does
                self.n_waking += 1
                self.n_running += 1
                wake(w.lock)
            self.parked.clear()
            self.changed.notify_all()
        self.clock.stop()

    def join_workers(self, timeout: float = 2.0) -> list[str]:
        """Join every worker (structured ownership) within `timeout` seconds in all, not each: a
        worker busy in a computation that makes no runtime call does not notice the stop, and
        fifty of them must not cost fifty timeouts. Returns the names of those still alive (daemon
        threads: they end with the process)."""
        with self.glock:
            workers = list(self.workers)
        deadline = time.monotonic() + timeout
        alive = []
        for w in workers:
            if w.thread.ident is not None:
                w.thread.join(max(0.0, deadline - time.monotonic()))
                if w.thread.is_alive():
                    alive.append(w.exec.name)
        return alive

    def wait_quiet(self) -> None:
        """Block the main thread until quiescence or stop; interruptible by Ctrl-C."""
        with self.glock:
            while not self.stopping and not (
                self.n_running == 0 and not self.runnable and not self.clock.pending_locked()
            ):
                self.changed.wait(0.5)
