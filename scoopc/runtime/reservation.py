"""Reservations of separate arguments (routine entry, separate blocks) and wait conditions.

Which regions to reserve is decided at run time: Void arguments and regions the client
already holds are skipped. The others get one new private queue each, enqueued atomically
under their locks taken in processor-id order (never blocking: a private queue is just put
in the queue of queues). A failed wait condition releases what this reservation took,
registers a targeted wake-up on the suppliers its failing clause queried, and sleeps.
"""

from __future__ import annotations

from collections.abc import Sequence
from types import TracebackType

from .errors import PreconditionViolation
from .processor import Processor
from .protocols import Args, Clause, Separate, Where
from .sched import Block
from .session import Session, apply, close, enqueue_claim

# What a reservation took: (region, its new private queue) pairs.
Taken = Sequence[tuple[Processor, Session]]


def _id(p: Processor) -> int:
    return p.id


class Reservation:
    """`with here.reserve(objs, pre, where):` — also `enter()` / `exit()` explicitly."""

    __slots__ = ("here", "objs", "pre", "where", "taken", "pre_args")
    here: Processor
    objs: Sequence[Separate | None]
    pre: Sequence[Clause] | None
    where: Where | None
    taken: Taken | None
    pre_args: Args | None

    def __init__(
        self,
        here: Processor,
        objs: Sequence[Separate | None],
        pre: Sequence[Clause] | None,
        where: Where | None,
        pre_args: Args | None = None,
    ) -> None:
        self.here = here
        self.pre_args = pre_args  # None: clauses are closures; else passed to each `pred`
        self.objs = objs
        self.pre = pre
        self.where = where
        self.taken = None  # [here's executor] [(region, Session)] this reservation took

    def enter(self) -> Reservation:
        here = self.here
        rt = here.rt
        if rt.attention:  # a permit waiter asked to yield, or stopping
            rt.attend(here.exec)  # type: ignore[arg-type]  # running: its exec is set
        objs = self.objs
        regs: Sequence[Processor]
        if len(objs) == 1:  # the common case, with few calls
            o = objs[0]
            regs = () if o is None or o._region_ in here.held else (o._region_,)
        else:
            regs = self._regions()
        pre = self.pre
        while True:
            if len(regs) == 1:
                self.taken = _reserve_one(here, regs[0], self.where)
            else:
                self.taken = reserve_regions(here, regs, self.where) if regs else ()
            if pre is None:
                return self
            args = self.pre_args
            try:
                for clause in pre:  # in order; the first false one decides
                    if not (clause[0]() if args is None else apply(clause[0], args)):
                        break
                else:
                    return self
            except BaseException:
                self.exit()
                raise
            self._wait(clause, regs)

    def __enter__(self) -> Reservation:
        return self.enter()

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.exit()

    def _regions(self) -> list[Processor]:
        """The regions to reserve: not Void, not held already, each once."""
        held = self.here.held
        regs: list[Processor] = []
        for o in self.objs:
            if o is not None:
                r = o._region_
                if r not in held and r not in regs:
                    regs.append(r)
        return regs

    def _queried(self, clause: Clause, regs: Sequence[Processor]) -> list[Processor]:
        """The newly reserved regions that `clause` uses as targets."""
        queried: list[Processor] = []
        for i in clause[1]:
            o = self.objs[i]
            if o is not None and o._region_ in regs and o._region_ not in queried:
                queried.append(o._region_)
        return queried

    def _wait(self, clause: Clause, regs: Sequence[Processor]) -> None:
        """Release, sleep until a queried supplier served another client, or raise."""
        queried = self._queried(clause, regs)
        if not queried:
            self.exit()
            raise PreconditionViolation(clause[2], clause[3])
        here = self.here
        blk = Block("wait", here, tuple(queried), clause[3] or self.where, None, clause[2])
        _register(blk, queried)  # before releasing: no change can slip in between
        self.exit()
        try:
            here.rt.block(here.exec, blk)  # type: ignore[arg-type]  # running: its exec is set
        finally:
            done = blk.value  # the region whose waker already unlisted blk
            for r in queried:
                if r is not done:
                    with r.lock:
                        if blk in r.waiters:
                            r.waiters.remove(blk)

    def exit(self) -> None:
        taken = self.taken
        if taken:
            held = self.here.held
            for r, s in taken:
                del held[r]
                close(s)
        self.taken = None


def _register(blk: Block, regions: Sequence[Processor]) -> None:
    for r in regions:  # `regions` has no duplicates
        with r.lock:
            r.waiters.append(blk)


def _reserve_one(here: Processor, r: Processor, where: Where | None) -> Taken:
    s = Session(here, r, where)
    lock = r.lock
    lock.acquire()
    enqueue_claim(r, s, here.exec)
    lock.release()
    here.held[r] = s
    return ((r, s),)


def reserve_regions(here: Processor, regs: Sequence[Processor], where: Where | None) -> Taken:
    """Enqueue one new private queue per region atomically; record them as held."""
    if len(regs) == 1:
        return _reserve_one(here, regs[0], where)
    held = here.held
    ordered = sorted(regs, key=_id)
    taken = [(r, Session(here, r, where)) for r in ordered]
    for r in ordered:
        r.lock.acquire()
    ex = here.exec
    for r, s in taken:
        enqueue_claim(r, s, ex)
    for r in ordered:
        r.lock.release()
    for r, s in taken:
        held[r] = s
    return taken
