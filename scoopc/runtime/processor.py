"""Processors (regions) and private queues (sessions): logging calls, serving them, and the
client-executes fast path. Reservation and wait conditions live in reservation.py.

A processor's state: IDLE (no thread attached), SCHEDULED (in the runnable queue), RUNNING
(one thread executes on its behalf: a worker, or a client running a query itself). Only the
thread that moved a processor to RUNNING runs its code or touches its executor-only fields.
The queue of queues is `head` (the private queue being served) plus `qoq` (those waiting).
A client whose private queue is at the head of an IDLE supplier runs its synchronous calls
itself on its own thread ("client executes", as SCOOP/Qs): no thread hand-off. It keeps
that claim (`Session.claimed`) until it releases the reservation, so its later calls on the
supplier take no lock at all.
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Sequence
from typing import TYPE_CHECKING, Final, TypeVar

from .anchor import Anchor
from .errors import CREATION, PASS_THROUGH, Shutdown, UncontrolledTarget, dirty_error, sync_failure
from .fast import FastPaths
from .once import once_in
from .protocols import Args, Call, Clause, OnceKey, OnceTable, Routine, Separate, Where
from .sched import BUSY_CALLS, BUSY_QUANTUM_NS, Block, dirty_text
from .session import IDLE, RUNNING, SCHEDULED, Session, close, drop_claim_locked, invoke  # noqa: F401

if TYPE_CHECKING:
    from collections.abc import Callable

    from .fast import _Nothing
    from .outside import OutsideClient
    from .sched import Exec, Runtime

S = TypeVar("S", bound=Separate)
# The sessions a server or a client running calls on a supplier's behalf takes at once.
Batches = list[tuple[Session, list[Call]]]
BATCH_SESSIONS: Final = 64  # sessions a server takes under one lock hold
HELP_LIMIT: Final = 256  # leaf calls a releasing client serves for others before handing off
STATE_NAMES = ("idle", "scheduled", "running")
# Argument types that are never references into a region (no lock passing): checked first,
# since `getattr(a, "_region_", None)` on them costs an AttributeError inside getattr.
VALUES = frozenset((int, float, str, bool, type(None), bytes, complex))


class Processor(FastPaths):
    """A region and its processor. The public methods (and those of `FastPaths`, fast.py)
    are the API for generated code."""

    __slots__ = (
        "id",
        "rt",
        "lock",
        "head",
        "qoq",
        "state",
        "passive",
        "exec",
        "held",
        "waiters",
        "onces",
        "frames",
        "name",
        "spare",
        "busy",
        "anchor",
    )
    id: int
    rt: Runtime
    lock: threading.Lock
    head: Session | None
    qoq: deque[Session]
    state: int
    passive: bool
    exec: Exec | None
    held: dict[Processor, Session | Processor]
    waiters: list[Block]
    onces: OnceTable
    frames: list[Where]
    name: str | None
    spare: Session | None
    busy: int
    anchor: Anchor

    def __init__(self, rt: Runtime, passive: bool = False, name: str | None = None) -> None:
        self.rt = rt
        self.anchor = Anchor(self)  # its entry in the runtime's registry (anchor.py)
        self.id = rt.register(self)
        self.lock = threading.Lock()
        self.head = None  # [lock] Session being served
        self.qoq = deque()  # [lock] Sessions waiting behind the head, FIFO
        self.state = IDLE  # [lock]
        self.passive = passive
        self.exec = None  # [lock to set] Exec of the thread running on our behalf
        self.held = {self: self}  # [executor] region -> Session, or region itself (own/borrowed)
        self.waiters = []  # [lock] Blocks of processors in wait conditions on us
        self.onces = {}  # [executor] once-per-region values
        self.frames = []  # [executor] optional Eiffel frame stack (where tuples)
        self.name = name  # class name of the first object, for reports
        self.spare = None  # [executor] a finished Session of ours no one refers to,
        #                           reused by the next `reserve1` (saves an allocation)
        self.busy = BUSY_CALLS  # [executor] separate calls left before a virtual-time quantum

    def __repr__(self) -> str:
        return f"P{self.id}" + (f"({self.name})" if self.name else "")

    # -- object creation ---------------------------------------------------------------
    def new(self, cls: type[S]) -> S:
        """A new object of `cls` in this region (its creation procedure is not called). Generated
        classes define no `__init__`, so calling the class makes the bare object, in half the
        time of `cls.__new__(cls)` (whose wrapper checks its argument against the ancestors)."""
        obj = cls()
        obj._region_ = self
        return obj

    def new_separate(self, cls: type[S], creator: Routine | None, args: Args = (), gen: object = None) -> S:
        """Separate creation: a new processor; `creator` is logged on it as a command.
        `gen`: the actual generics of a generic class (set as `_gen_` before `creator` runs)."""
        return self._create(Processor(self.rt, False, cls.__name__), cls, creator, args, gen)

    def new_passive(self, cls: type[S], creator: Routine | None, args: Args = (), gen: object = None) -> S:
        """`create <NONE>`: a passive region whose calls its clients run under reservation."""
        return self._create(Processor(self.rt, True, cls.__name__), cls, creator, args, gen)

    def _create(self, proc: Processor, cls: type[S], creator: Routine | None, args: Args, gen: object = None) -> S:
        obj = proc.new(cls)
        if gen is not None:
            obj._gen_ = gen  # type: ignore[attr-defined]  # only generic classes have `_gen_`
        s = Session(self, proc, CREATION)
        proc.head = s  # the new processor is ours alone: no lock needed yet
        self.held[proc] = s
        try:
            if creator is not None:
                self.call(obj, creator, args)
        finally:
            del self.held[proc]
            close(s)
        return obj

    # -- calls -------------------------------------------------------------------------
    def call(self, target: Separate, routine: Routine, args: Args = ()) -> None:
        """A separate command: asynchronous unless it passes locks or the region is passive."""
        p = target._region_
        s = self.held.get(p)
        if type(s) is Session:
            if s.claimed and s.dirty is None and (not args or not self._passes(args)):
                if p.passive:  # synchronous, failures reach the client
                    if self.rt.stopping:
                        raise Shutdown()
                    s.changed = True
                    invoke(routine, target, args)
                    return
                if getattr(routine, "_scoop_leaf_", False):
                    self._leaf_claimed(p, s, routine, target, args)
                    return
            if (args and self._passes(args)) or p.passive:
                self._sync(s, p, routine, target, args, None, True)
                return
            lock = p.lock
            lock.acquire()
            if s.claimed:
                drop_claim_locked(p, s)
            if s.dirty is None:  # a dirty region skips later calls
                if getattr(routine, "_scoop_leaf_", False):
                    if p.state != RUNNING and not s.heavy:
                        if p.head is s and not s.calls:  # the fast path
                            self._leaf_now(p, s, routine, target, args)
                            return
                        ahead = _ahead_locked(p, s)
                        if ahead is not None:  # client executes the short command
                            self._inline(p, s, _take(p, s, ahead), routine, target, args, None, True)
                            return
                else:
                    s.heavy = True
                s.calls.append((routine, target, args, None, None))
                if p.state == IDLE and p.head is s:
                    p.state = SCHEDULED
                    lock.release()
                    self.rt.schedule(p)
                    return
            lock.release()
        elif s is p:
            if p is self:
                invoke(routine, target, args)
            else:
                self._borrowed(p, routine, target, args)
        else:
            raise UncontrolledTarget(f"{self} calls {routine.__qualname__} on {p}, not reserved")

    def query(self, target: Separate, routine: Routine, args: Args = (), where: Where | None = None) -> object:
        """A separate query: synchronous (wait by necessity)."""
        p = target._region_
        s = self.held.get(p)
        if type(s) is Session:
            if s.claimed and s.dirty is None and not self.rt.stopping and (not args or not self._passes(args)):
                try:
                    return invoke(routine, target, args)  # `p` is ours until we release it
                except Exception as e:
                    if p.passive:
                        raise
                    raise sync_failure(p, e)  # noqa: B904 (its cause is set)
            return self._sync(s, p, routine, target, args, where, False)
        if s is p:
            if p is self:
                return invoke(routine, target, args)
            return self._borrowed(p, routine, target, args)
        raise UncontrolledTarget(f"{self} queries {routine.__qualname__} on {p}, not reserved")

    def _passes(self, args: Args) -> bool:
        """Lock passing: an argument is a reference into a region we hold (or a TUPLE)."""
        held = self.held
        for a in args:
            c = type(a)
            if c in VALUES:
                continue
            if c is tuple or getattr(a, "_region_", None) in held:
                return True
        return False

    def _sync(
        self,
        s: Session,
        p: Processor,
        routine: Routine,
        target: Separate,
        args: Args,
        where: Where | None,
        is_cmd: bool,
        what: object = None,
    ) -> object:
        """A synchronous call: run it ourselves if `p` is free for us, else wait for it.
        `what`: set by `claim1` (direct.py), whose call is a no-op leaf: the block's first
        query, which a report names while we wait."""
        if self.rt.stopping:
            raise Shutdown()
        passer = self if args and self._passes(args) else None
        lock = p.lock
        while True:
            lock.acquire()
            if s.claimed:  # queued or passing calls need `p` free for its thread
                drop_claim_locked(p, s)
            if s.dirty is not None:  # not executed; delivering cleans the region
                err = s.dirty
                s.dirty = None
                lock.release()
                raise dirty_error(p, err)
            if p.state != RUNNING:
                if p.head is s and not s.calls and passer is None:  # the fast path
                    return self._query_now(p, s, routine, target, args, is_cmd)
                ahead = _ahead_locked(p, s)
                if ahead is not None:
                    return self._inline(p, s, _take(p, s, ahead), routine, target, args, passer, is_cmd)
            blk = Block("turn" if p.passive else "sync", self, s, where, None, routine if what is None else what)
            if p.passive:
                s.turn = blk
            else:
                s.calls.append((routine, target, args, blk, passer))
                if passer is not None or not (what is not None or getattr(routine, "_scoop_leaf_", False)):
                    s.heavy = True
            lock.release()
            self.rt.block(self.exec, blk)  # type: ignore[arg-type]  # running: its exec is set
            if not p.passive:
                if blk.error is not None:
                    raise blk.error
                return blk.value

    def _claim_locked(self, p: Processor, s: Session) -> bool:
        """[p.lock held, then released; p free, `s` its head with nothing pending] Claim `p`
        for a call we run ourselves. Our own session keeps the claim until we release it; a
        supplier running on our behalf by lock passing claims per call, so `p.exec` never
        names a thread that has gone on (the monitor's wait-for graph reads it). True if
        kept."""
        p.state = RUNNING
        p.exec = self.exec
        if s.client is self:
            s.claimed = True
            p.lock.release()
            return True
        p.lock.release()
        return False

    def _leaf_now(self, p: Processor, s: Session, routine: Routine, target: Separate, args: Args) -> None:
        """[p.lock held, p free, our session at its head with nothing pending] Run a leaf
        command ourselves. A leaf never blocks, so no frame is pushed for the monitor."""
        if self._claim_locked(p, s):
            self._leaf_claimed(p, s, routine, target, args)
            return
        try:
            self._leaf_claimed(p, s, routine, target, args)
        finally:
            p.release_claim()

    def _leaf_claimed(self, p: Processor, s: Session, routine: Routine, target: Separate, args: Args) -> None:
        """[`p` claimed for `s`] A leaf command: its failure only makes `s` dirty."""
        s.changed = True
        try:
            invoke(routine, target, args)
        except PASS_THROUGH:
            raise
        except BaseException as e:
            lock = p.lock
            lock.acquire()
            s.dirty = e
            lock.release()
            p.rt.note("dirty region", dirty_text(p, s, e))

    def _query_now(
        self, p: Processor, s: Session, routine: Routine, target: Separate, args: Args, is_cmd: bool
    ) -> object:
        """[p.lock held, p free, our session at its head with nothing pending] Run a
        synchronous call ourselves on `p`'s behalf (client executes)."""
        if is_cmd:
            s.changed = True
        kept = self._claim_locked(p, s)
        try:
            return invoke(routine, target, args)
        except Exception as e:
            if p.passive:
                raise
            raise sync_failure(p, e)  # noqa: B904 (its cause is set)
        finally:
            if not kept:
                p.release_claim()

    def _inline(
        self,
        p: Processor,
        s: Session,
        batches: Batches,
        routine: Routine,
        target: Separate,
        args: Args,
        passer: Processor | None,
        is_cmd: bool,
    ) -> object:
        """[p.lock held, p claimed by `_take`] Run the calls queued ahead of ours, then this
        one, on our own thread on `p`'s behalf; a leaf command's failure only dirties `s`."""
        p.exec = self.exec
        p.lock.release()
        try:
            if batches:
                p._run_backlog(batches)
                if s.dirty is not None:
                    if is_cmd and passer is None:
                        return None  # skipped: the region is dirty
                    with p.lock:
                        err = s.dirty
                        s.dirty = None
                    raise dirty_error(p, err)
            if is_cmd:
                s.changed = True
                if passer is None and not p.passive:  # a leaf command: failure dirties
                    try:
                        return invoke(routine, target, args)
                    except PASS_THROUGH:
                        raise
                    except BaseException as e:
                        with p.lock:
                            s.dirty = e
                        p.rt.note("dirty region", dirty_text(p, s, e))
                        return None
            try:
                if passer is None:
                    return invoke(routine, target, args)
                return p._invoke_passing(passer, routine, target, args)
            except Exception as e:
                if p.passive:
                    raise
                raise sync_failure(p, e)  # noqa: B904 (its cause is set)
        finally:
            p.unclaim()

    def _borrowed(self, p: Processor, routine: Routine, target: Separate, args: Args) -> object:
        """A callback into a region whose locks were passed to us: its own thread is blocked
        waiting for us, so we run the call on its behalf, on our thread."""
        saved = p.exec
        p.exec = self.exec
        try:
            return invoke(routine, target, args)
        except Exception as e:
            if p.passive:
                raise
            raise sync_failure(p, e)  # noqa: B904 (its cause is set)
        finally:
            p.exec = saved

    def _invoke_passing(self, passer: Processor, routine: Routine, target: Separate, args: Args) -> object:
        """Run a call while holding every lock of `passer` (lock passing)."""
        saved = self.held
        held = dict(saved)
        held.update(passer.held)
        held[self] = self
        self.held = held
        try:
            return invoke(routine, target, args)
        finally:
            self.held = saved

    # -- serving -----------------------------------------------------------------------
    def release_claim(self) -> None:
        """A per-call claim ends (the session stays at the head, nothing queued)."""
        lock = self.lock
        lock.acquire()
        self.exec = None
        self.state = IDLE
        lock.release()

    def unclaim(self) -> None:
        """The thread running on our behalf stops; hand remaining work to the pool."""
        lock = self.lock
        lock.acquire()
        self.exec = None
        s = self.head
        if s is not None and (s.calls or s.closed) and not self.passive:
            self.state = SCHEDULED
            lock.release()
            self.rt.schedule(self)
            return
        self.state = IDLE
        lock.release()

    def run_scheduled(self, ex: Exec) -> None:
        """Worker entry: serve the queue of queues until it has nothing runnable."""
        lock = self.lock
        lock.acquire()
        if self.state != SCHEDULED:  # taken by a client in the meantime
            lock.release()
            return
        self.state = RUNNING
        self.exec = ex
        self._serve_locked()  # the same lock hold: one round fewer per hand-off

    def _serve_locked(self) -> None:
        """[lock held] Serve the queue of queues. Under one lock hold it takes the head's
        calls and, while sessions are closed, the calls of those behind it (in order: each
        closed session is finished before the next starts), so a shared supplier with many
        short client sessions pays one lock round per batch, not per session."""
        lock = self.lock
        while True:
            s = self.head
            while s is not None and not s.calls and s.closed:
                s = self._advance_locked()
            if s is None or not s.calls:
                self.exec = None
                self.state = IDLE
                lock.release()
                return
            batches = [(s, s.calls)]
            s.calls = []
            if s.closed:
                for q in self.qoq:
                    if len(batches) >= BATCH_SESSIONS:
                        break
                    batches.append((q, q.calls))
                    q.calls = []
                    if not q.closed:
                        break
            lock.release()
            for q, batch in batches:
                if batch:
                    self._run_calls(q, batch)
            lock.acquire()
            for _ in range(len(batches) - 1):  # all but the last are closed
                self._advance_locked()

    def _run_calls(self, s: Session, batch: list[Call]) -> None:
        rt = self.rt
        for routine, target, args, blk, passer in batch:
            if s.dirty is not None:
                if blk is not None:  # not executed; delivering cleans the region
                    with self.lock:
                        err = s.dirty
                        s.dirty = None
                    blk.error = dirty_error(self, err)
                    rt.unblock(blk)
                continue
            try:
                if passer is None:
                    r = invoke(routine, target, args)
                else:
                    r = self._invoke_passing(passer, routine, target, args)
            except PASS_THROUGH:
                raise
            except BaseException as e:
                if blk is None:
                    with self.lock:
                        s.dirty = e
                    self.rt.note("dirty region", dirty_text(self, s, e))
                else:
                    blk.error = sync_failure(self, e) if isinstance(e, Exception) else e
                    rt.unblock(blk)
                continue
            if blk is None or passer is not None:
                s.changed = True
            if blk is not None:
                blk.value = r
                rt.unblock(blk)

    def settle_locked(self, helper: Processor | OutsideClient | None) -> None:
        """[lock held, state IDLE; releases it] After a session ended: run the leaf calls
        queued next on the helper's thread (a releasing client), up to HELP_LIMIT, so a
        busy shared supplier does not need a thread hand-off per client; hand anything
        else to the pool."""
        lock = self.lock
        ex = getattr(helper, "exec", None)
        done = 0
        while True:
            h = self.head
            while h is not None and h.closed and not h.calls:
                h = self._advance_locked()
            if h is None or not h.calls:
                lock.release()
                return
            if h.heavy or ex is None or done >= HELP_LIMIT or self.passive:
                self.state = SCHEDULED
                lock.release()
                self.rt.schedule(self)
                return
            self.state = RUNNING
            self.exec = ex
            batch = h.calls
            h.calls = []
            lock.release()
            self._run_calls(h, batch)
            done += len(batch)
            lock.acquire()
            self.state = IDLE
            self.exec = None

    def _run_backlog(self, batches: Batches) -> None:
        """Run taken batches in order (ours last), finishing each session ahead of ours."""
        for h, batch in batches:
            if batch:
                self._run_calls(h, batch)
        if len(batches) > 1:
            with self.lock:
                for _ in range(len(batches) - 1):
                    self._advance_locked()

    def _advance_locked(self) -> Session | None:
        """[lock] The head session is finished: report, wake waiters, move to the next."""
        s: Session = self.head  # type: ignore[assignment]  # called only with a head
        if s.dirty is not None:
            self.rt.report_lost(self, s)
        if s.changed and self.waiters:
            self.wake_waiters_locked(s)
        nxt = self.qoq.popleft() if self.qoq else None
        self.head = nxt
        if nxt is not None and nxt.turn is not None:
            self.rt.unblock(nxt.turn)
            nxt.turn = None
        return nxt

    def wake_waiters_locked(self, s: Session) -> None:
        """[lock] Session `s`, in which a command ran, ends: wake the other clients
        waiting on a wait condition over us (targeted wake-up)."""
        self.wake_others_locked(s.client)

    def wake_others_locked(self, client: Processor | OutsideClient) -> None:
        """[lock] A command of `client` changed us: wake the other clients waiting on a wait
        condition over us."""
        keep = []
        for blk in self.waiters:
            if blk.proc is client:
                keep.append(blk)
            else:
                blk.value = self  # tells the waiter it is off our list already
                self.rt.unblock(blk)
        self.waiters = keep

    # -- services ----------------------------------------------------------------------
    def print(self, text: str) -> None:
        """Write `text` whole (never torn by another processor's output)."""
        if self.rt.stopping:
            raise Shutdown()
        self.rt.out.write(self, text)

    def print_error(self, text: str) -> None:
        """Write `text` whole on the run's stderr (the `stderr` given to run_main), under the
        lock of the standard output, so no output line of either stream is torn; flushed
        at once, like C's stderr. Not tagged in trace mode."""
        if self.rt.stopping:
            raise Shutdown()
        self.rt.out.write_other(self.rt.stderr, text)

    def flush_output(self) -> None:
        """Flush the run's stdout and stderr streams (IO_MEDIUM.flush on the console)."""
        self.rt.out.flush_streams(self.rt.stderr)

    def sleep(self, ns: int, where: Where | None = None) -> None:
        """Sleep `ns` nanoseconds on the runtime clock (virtual or real)."""
        self.rt.clock.sleep(self, ns, where)

    def busy_quantum(self) -> None:
        """`busy` ran out: this separate call follows BUSY_CALLS others made without sleeping.
        On the virtual clock, sleep one quantum first, so that a processor that never sleeps
        lets time go on (sched.py); this call is then the first of the next run."""
        if self.rt.clock.virtual:
            self.rt.clock.sleep(self, BUSY_QUANTUM_NS)  # sets `busy` again
        self.busy = BUSY_CALLS - 1

    def once(self, key: OnceKey, fn: Callable[..., object], args: Args = ()) -> object:
        """A once routine per region: keyed by this region, whichever thread runs it."""
        return once_in(self.onces, key, fn, args)

    def push_frame(self, where: Where) -> None:
        self.frames.append(where)

    def pop_frame(self) -> None:
        self.frames.pop()

    def reserve(
        self,
        objs: Sequence[Separate | None],
        pre: Sequence[Clause] | None = None,
        where: Where | None = None,
        pre_args: Args | None = None,
    ) -> Session | _Nothing | Reservation:
        """A reservation of the separate arguments `objs` (see reservation.py); the common
        one-supplier reservation without wait condition is its private queue itself.
        `pre_args`: None (each clause's `pred()` takes no argument) or the tuple passed
        to every `pred` (a module-level clause table, see docs/RUNTIME.md)."""
        if pre is None and len(objs) == 1:
            return self.reserve1(objs[0], where)
        self.busy -= 1
        if self.busy < 0:
            self.busy_quantum()
        return Reservation(self, objs, pre, where, pre_args)


def _ahead_locked(p: Processor, s: Session) -> Sequence[Session] | None:
    """[p.lock, p not RUNNING] The sessions ahead of `s` in `p`'s queue of queues if a
    client may run them itself (all closed, leaf calls only), else None. Running them in
    order keeps every guarantee: it is what the supplier would do next, on another thread."""
    h = p.head
    if h is s:
        return ()
    if p.passive or h is None or not h.closed or h.heavy:
        return None
    ahead = [h]
    for q in p.qoq:
        if q is s:
            return ahead
        if not q.closed or q.heavy:
            return None
        ahead.append(q)
    return None


def _take(p: Processor, s: Session, ahead: Sequence[Session]) -> Batches:
    """[p.lock] Claim `p` and take the calls of the sessions ahead and of `s` itself."""
    p.state = RUNNING
    batches = []
    for h in ahead:
        batches.append((h, h.calls))
        h.calls = []
    if s.calls or ahead:
        batches.append((s, s.calls))
        s.calls = []
    return batches


# Last, as it imports this module (a cycle): the class `reserve` builds, looked up once here
# rather than imported on every call.
from .reservation import Reservation  # noqa: E402
