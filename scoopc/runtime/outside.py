"""Clients that are not processors (transport callbacks, timers) and agents.

An outside client logs commands from any thread without ever waiting for a processor: each
call is a closed private queue of one call put in the supplier's queue of queues, so calls
of one source to one processor run in the order they were logged."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .errors import ScoopError
from .protocols import Args, Routine, Separate
from .session import IDLE, RUNNING, SCHEDULED, Session, enqueue

if TYPE_CHECKING:
    from .processor import Processor
    from .sched import Exec, Runtime


class OutsideClient:
    """A source of commands from outside the processors; counted open until `close`."""

    exec: Exec | None

    def __init__(self, rt: Runtime, name: str) -> None:
        self.rt = rt
        self.name = name
        self.exec = None  # not a processor: nothing to wait for in the wait-for graph
        self.open = True  # [rt.glock]
        with rt.glock:
            rt.sources += 1

    def __repr__(self) -> str:
        return f"outside client {self.name!r}"

    def call(self, target: Separate, routine: Routine, args: Args = (), leaf: bool = False) -> None:
        """Log `routine(target, *args)` on target's processor. `leaf=True`: the caller vouches
        that the call is a leaf (scoopc.runtime.leaf: it neither blocks nor calls another
        processor) and that this thread runs no processor (a transport's own thread); if the
        processor is idle with nothing queued, this thread then runs the call itself, as a
        worker would (`Runtime.run_here`), saving the thread switch."""
        p = target._region_
        if p.passive:
            raise ScoopError(f"{self!r}: passive region {p!r} needs a processor client")
        s = Session(self, p)
        s.calls.append((routine, target, args, None, None))
        s.heavy = not (leaf or getattr(routine, "_scoop_leaf_", False))
        s.closed = True
        ex = self.rt.outside_exec() if leaf else None
        lock = p.lock
        lock.acquire()
        enqueue(p, s)
        run = p.state == IDLE and p.head is s
        if run:
            if ex is not None and not self.rt.stopping:  # `leaf`
                p.state = RUNNING
                p.exec = ex
                lock.release()
                self.rt.run_here(p, s, ex)
                return
            p.state = SCHEDULED
        lock.release()
        if run:
            self.rt.schedule(p)

    def close(self) -> None:
        with self.rt.glock:
            if self.open:
                self.open = False
                self.rt.sources -= 1


class Agent:
    """An agent object: lives in its target's region; `call` runs routine(target, *closed,
    *operands). On a separate agent, `here.call(agent, Agent.call, (None,))` is
    asynchronous and `(operands_tuple,)` passes locks (a tuple is a client reference)."""

    __slots__ = ("_region_", "target", "routine", "closed")
    _region_: Processor
    target: Separate
    routine: Routine
    closed: Args

    def __init__(self, target: Separate, routine: Routine, closed: Args = ()) -> None:
        self._region_ = target._region_
        self.target, self.routine, self.closed = target, routine, closed

    def call(self, operands: Args | None = None) -> object:
        return self.routine(self.target, *self.closed, *(operands or ()))

    item = call
