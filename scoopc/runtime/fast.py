"""Fast entry points for facts the code generator knows statically (docs/RUNTIME.md 2-3).

The general entry points (`reserve`, `call`, `query`) decide everything at run time:
how many objects to reserve, whether a routine is a leaf, whether an argument passes
locks. Codegen knows most of that from the Eiffel source, and in pure Python every check
costs about as much as the work it guards, so these entry points skip them:

- `reserve1(x, where, pre, pre_args)`: exactly one separate argument (or separate block
  expression); `pre` a module-level clause table evaluated with `pre_args`, so no tuple
  or closure is allocated per call.
- `leaf_call` / `leaf_query`: the routine is `@leaf` and no actual argument can pass
  locks (every argument is of an expanded type, or there is none). On a supplier the
  client has claimed they are a plain call; otherwise they fall back to `call`/`query`,
  which decide at run time exactly as before.

Every guarantee is kept by falling back to the general path whenever the fast one does
not apply; the fast paths only skip checks whose answer codegen promised.
"""

from __future__ import annotations

from collections.abc import Sequence
from types import TracebackType
from typing import TYPE_CHECKING

from .direct import DirectBlocks
from .errors import PASS_THROUGH, PreconditionViolation, sync_failure
from .protocols import Args, Clause, Routine, Separate, Where
from .sched import Block, dirty_text
from .session import IDLE, SCHEDULED, Session, apply, close_locked, enqueue, invoke

if TYPE_CHECKING:
    from .processor import Processor


class _Nothing:
    """The reservation of a Void separate argument: nothing to take or release."""

    __slots__ = ()
    taken = None

    def __enter__(self) -> _Nothing:
        return self

    def __exit__(
        self, et: type[BaseException] | None = None, ev: BaseException | None = None, tb: TracebackType | None = None
    ) -> None:
        return None

    def enter(self) -> _Nothing:
        return self

    def exit(self) -> None:
        return None


NOTHING = _Nothing()


class FastPaths(DirectBlocks):
    """Mixin of `Processor` (fields documented there). Its methods take `self: Processor`, which
    mypy refuses for a subclass (error code misc, ignored on each `def`): a Protocol would not
    do, since they pass `self` on as the client of a Session or the waiter of a Block."""

    __slots__ = ()
    spare: Session | None  # Processor's slot
    busy: int  # Processor's slot

    def reserve1(  # type: ignore[misc]
        self: Processor,
        x: Separate | None,
        where: Where | None = None,
        pre: Sequence[Clause] | None = None,
        pre_args: Args = (),
    ) -> Session | _Nothing:
        """`with here.reserve1(x, where):` reserves the one separate argument `x` (Void
        or already held: nothing). With `pre` (a tuple of clauses `(pred, targets, tag,
        where)`, `pred(*pre_args) -> bool`, `targets` `(0,)` if the clause calls `x`,
        else `()`), the precondition is established (waiting as needed) before the
        private queue is returned; its `__enter__` then only re-checks it is held."""
        if x is None:
            return NOTHING
        self.busy -= 1
        if self.busy < 0:
            self.busy_quantum()
        s = self._session1(x._region_, where)
        if pre is None:
            return s
        return self._guarded1(s, pre, pre_args)

    def _session1(self: Processor, p: Processor, where: Where | None) -> Session:  # type: ignore[misc]
        """A private queue for `p`: the client's spare one if any (see `Session.__exit__`)."""
        s = self.spare
        if s is None:
            return Session(self, p, where)
        self.spare = None
        s.proc = p
        s.where = where
        s.closed = s.changed = s.heavy = False
        return s

    def _guarded1(self: Processor, s: Session, pre: Sequence[Clause], pre_args: Args) -> Session:  # type: ignore[misc]
        """Reserve through `s`, evaluate the clauses; wait or raise on a false one."""
        p = s.proc
        while True:
            s.__enter__()
            try:
                for clause in pre:  # in order; the first false one decides
                    if not apply(clause[0], pre_args):
                        break
                else:
                    return s
            except BaseException:
                s.__exit__()
                raise
            if not clause[1] or self.held.get(p) is not s:  # not newly reserved by us
                s.__exit__()
                raise PreconditionViolation(clause[2], clause[3])
            self._wait1(s, p, clause)
            s = self._session1(p, s.where)  # a private queue for the next try

    def _wait1(self: Processor, s: Session, p: Processor, clause: Clause) -> None:  # type: ignore[misc]
        """Register the wake-up and release `s` under one hold of `p.lock` (no change can
        slip in between), sleep until another client's session with a command ends."""
        blk = Block("wait", self, (p,), clause[3] or s.where, None, clause[2])
        del self.held[p]
        lock = p.lock
        lock.acquire()
        p.waiters.append(blk)
        if s.claimed and not p.qoq and s.dirty is None and not s.changed:
            s.claimed = False  # the common case of `close_locked`: only
            s.closed = True  # queries ran, nobody queued behind us
            p.exec = None
            p.state = IDLE
            p.head = None
            lock.release()
            self.spare = s  # unreferenced now: reusable
        else:
            close_locked(p, s)  # releases p.lock
        try:
            self.rt.block(self.exec, blk)  # type: ignore[arg-type]  # running: its exec is set
        finally:
            if blk.value is not p:  # our waker did not unlist us already
                with p.lock:
                    if blk in p.waiters:
                        p.waiters.remove(blk)

    def command1(  # type: ignore[misc]
        self: Processor,
        x: Separate,
        routine: Routine,
        args: Args = (),
        where: Where | None = None,
    ) -> None:
        """`with here.reserve1(x, where): here.call(x, routine, args)` in one step: a
        routine (or separate block) with one separate argument `x`, no precondition, whose
        body is the single command `x.routine (args)`, none of whose arguments can pass
        locks (rules: docs/RUNTIME.md section 3). A leaf command is `leaf_command1`'s; a
        non-leaf one is logged in a closed private queue for the supplier's thread with one
        lock round."""
        if getattr(routine, "_scoop_leaf_", False):
            self.leaf_command1(x, routine, args, where)
            return
        p = x._region_
        self.busy -= 1
        if self.busy < 0:
            self.busy_quantum()
        if p.passive or self.rt.attention or p in self.held:
            self._command1_reserved(x, routine, args, where)
        else:
            self._log1(p, x, routine, args, where)

    def leaf_command1(  # type: ignore[misc]
        self: Processor,
        x: Separate,
        routine: Routine,
        args: Args = (),
        where: Where | None = None,
    ) -> None:
        """`command1` of a routine codegen proved a leaf (`@leaf`). On an idle supplier it runs
        here, claimed, with no `with` protocol and no `held` entry (a leaf makes no separate
        call, so nothing consults it)."""
        p = x._region_
        self.busy -= 1
        if self.busy < 0:
            self.busy_quantum()
        if p.passive or self.rt.attention:
            self._command1_reserved(x, routine, args, where)
            return
        lock = p.lock
        lock.acquire()
        # An idle supplier nobody has reserved (a supplier we hold has our private queue in
        # its queue of queues, so `held` needs no look here): the leaf runs now, under the
        # supplier's lock, as a reservation released at once. A leaf is short and takes no
        # processor's lock, so others wait for the lock no longer than for a claim.
        if p.head is not None or p.state != IDLE:
            lock.release()
            self._command1_busy(p, x, routine, args, where)
            return
        try:
            invoke(routine, x, args)
        except BaseException as e:
            self._leaf_failed(p, e, where)  # releases p.lock; re-raises what passes through
            return
        if p.waiters:
            p.wake_others_locked(self)
        lock.release()

    def _command1_reserved(self: Processor, x: Separate, routine: Routine, args: Args, where: Where | None) -> None:  # type: ignore[misc]
        """`command1` as the composition it stands for: on a supplier we hold, a passive one, or
        when the runtime asks for attention."""
        self.busy += 1  # counted once, by reserve1
        with self.reserve1(x, where):
            self.call(x, routine, args)

    def _command1_busy(  # type: ignore[misc]
        self: Processor,
        p: Processor,
        x: Separate,
        routine: Routine,
        args: Args,
        where: Where | None,
    ) -> None:
        """A leaf `command1` on a supplier that is not idle: one we hold, or one with a queue."""
        if p in self.held:
            self._command1_reserved(x, routine, args, where)
            return
        s = self._session1(p, where)
        lock = p.lock
        lock.acquire()
        if p.head is not None or p.state != IDLE:
            self._busy1(p, s, x, routine, args)  # releases p.lock
            return
        lock.release()  # idle again meanwhile: take the fast path once more
        self.spare = s
        self.busy += 1
        self.leaf_command1(x, routine, args, where)

    def _leaf_failed(self: Processor, p: Processor, e: BaseException, where: Where | None) -> None:  # type: ignore[misc]
        """[p.lock held; released] A leaf `command1` ran on the idle supplier `p` failed with
        `e`: what the release of a one-command reservation does with it. A stop passes
        through; any other failure makes the reservation dirty, and since no client can see
        it any more, it is reported as lost."""
        if isinstance(e, PASS_THROUGH):
            if p.waiters:
                p.wake_others_locked(self)
            p.lock.release()
            raise e
        s = Session(self, p, where)
        s.changed = True
        s.dirty = e
        p.head = s  # nobody queued behind us: we held p.lock with p idle and no head
        close_locked(p, s)  # reports the loss, wakes the waiters; releases p.lock
        p.rt.note("dirty region", dirty_text(p, s, e))

    def _busy1(  # type: ignore[misc]
        self: Processor,
        p: Processor,
        s: Session,
        x: Separate,
        routine: Routine,
        args: Args,
    ) -> None:
        """[p.lock held; released] `command1` on a busy supplier: the general path with the
        private queue `s`, enqueued behind the others (never blocks)."""
        s.changed = False
        enqueue(p, s)
        p.lock.release()
        self.held[p] = s
        try:
            self.call(x, routine, args)
        finally:
            s.__exit__()

    def _log1(  # type: ignore[misc]
        self: Processor,
        p: Processor,
        x: Separate,
        routine: Routine,
        args: Args,
        where: Where | None,
    ) -> None:
        """Log a non-leaf command in a new closed private queue (one lock round)."""
        s = Session(self, p, where)
        s.calls.append((routine, x, args, None, None))
        s.heavy = True
        s.closed = True
        lock = p.lock
        lock.acquire()
        if p.head is None:
            p.head = s
            if p.state == IDLE:
                p.state = SCHEDULED
                lock.release()
                self.rt.schedule(p)
                return
        else:
            p.qoq.append(s)
        lock.release()

    def leaf_call(self: Processor, target: Separate, routine: Routine, args: Args = ()) -> None:  # type: ignore[misc]
        """`call` of a `@leaf` command whose arguments cannot pass locks (codegen-checked:
        all expanded, or none). On a claimed supplier: a plain call; a failure dirties."""
        p = target._region_
        s = self.held.get(p)
        if type(s) is Session and s.claimed and s.dirty is None and not p.passive:
            self._leaf_claimed(p, s, routine, target, args)
            return
        self.call(target, routine, args)

    def leaf_query(  # type: ignore[misc]
        self: Processor,
        target: Separate,
        routine: Routine,
        args: Args = (),
        where: Where | None = None,
    ) -> object:
        """`query` of a `@leaf` routine whose arguments cannot pass locks (as `leaf_call`)."""
        p = target._region_
        s = self.held.get(p)
        if type(s) is Session and s.claimed and s.dirty is None and not self.rt.stopping:
            try:
                return invoke(routine, target, args)
            except Exception as e:
                if p.passive:
                    raise
                raise sync_failure(p, e)  # noqa: B904 (its cause is set)
        return self.query(target, routine, args, where)
