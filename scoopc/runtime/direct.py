"""Direct blocks: a reservation of one separate argument whose calls the client makes itself,
as plain Python calls, with no runtime entry point per call (docs/RUNTIME.md section 3).

Codegen (scoop_calls.direct_block) emits one where it can prove the general path means the
same: the body is only calls of leaf routines on the reserved argument, none of whose actual
arguments can pass locks or fail (constants, locals, formal arguments, attributes of
Current), and assignments of leaf query results; it contains a query. For CREATURE.visit:

    with here.claim1(m, _W_3, _W_2, MALL.outcome_of, True) as _s:
        try:
            MALL.arrive(m, self.id, self.colour)
        except BaseException as _e:
            raise _s.failed(_e, _W_2)
        Result = MALL.outcome_of(m, self.id)

Why it means what the general path means:
- Waiting. The general path logs the commands before the first query and waits at that
  query until the supplier has served every private queue ahead of ours; `claim1` waits for
  the same thing before the block (our own commands never wait for anything: leaves do not
  block). The client does nothing else in between, so nothing it does moves; a deadlock
  report names the first query, where the general path would wait.
- A failed command. The general path makes the region dirty, skips the commands after it,
  and the next query raises the dirty processor exception, which delivers (cleans) it: there
  is always a next query here. `failed` notes the dirty region and raises that exception at
  once, marked as noticed at that query (reports name its line); the statements it skips are
  the ones the general path would skip or not reach.
- A failed command after the last query: the general path makes the region dirty and skips
  the block's other commands; the failure is reported lost when the reservation ends unless a
  query of an enclosing reservation delivers it. `failed` makes the region dirty the same way
  and raises `SkipRest`, which the block's end swallows.
- A failed query: the synchronous failure, raised when the block ends (`end_direct`).
- Modes follow the general path's rules for the region the calls go to: an active region we
  have claimed (DIRECT, as above); a passive one, or our own region (RAW: failures reach the
  client as they are); a region whose locks were passed to us (BORROWED: every call is
  synchronous, its failure is the synchronous failure). TEMP: the claim is the block's own
  (the reservation belongs to the client that passed us its locks) and ends with it.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from .errors import PASS_THROUGH, DirtyRegionError, dirty_error, sync_failure
from .protocols import Args, Clause, Routine, Separate, Where
from .sched import dirty_text
from .session import BORROWED, COMMANDS, DIRECT, MODE, PENDING, RAW, RUNNING, TEMP, Session

if TYPE_CHECKING:
    from .processor import Processor


def _reach(target: object) -> None:
    """The call `claim1` waits on when its supplier is not free yet: it does nothing (a
    leaf: `_sync` knows it from its `what`)."""
    return None


class SkipRest(BaseException):
    """Raised by `failed` when a command after a direct block's last query fails: the block's
    end swallows it (the general path would skip the block's remaining commands)."""


class DirectBlocks:
    """Mixin of `Processor` (through `FastPaths`): the entry and exits of a direct block."""

    __slots__ = ()

    def claim1(  # type: ignore[misc]
        self: Processor,
        x: Separate,
        where: Where | None,
        qwhere: Where | None,
        query: Routine,
        commands: bool,
        pre: Sequence[Clause] | None = None,
        pre_args: Args = (),
    ) -> Session:
        """`with here.claim1(x, where, qwhere, query, commands[, pre, pre_args]) as _s:`
        reserves `x` (as `reserve1`, `x` never Void); entering returns once the client may
        call `x`'s routines itself (`begin_direct`). `query`/`qwhere`: the block's first
        query and its position (what a deadlock report names while the client waits);
        `commands`: whether the block has commands (they wake wait conditions when the
        reservation ends)."""
        self.busy -= 1
        if self.busy < 0:
            self.busy_quantum()
        s = self._session1(x._region_, where)
        if pre is not None:
            s = self._guarded1(s, pre, pre_args)  # entered already: `with` finds it held
        s.direct = PENDING | COMMANDS if commands else PENDING
        s.qwhere = qwhere
        s.query = query
        return s

    def begin_direct(self: Processor, s: Session) -> None:  # type: ignore[misc]
        """[`s` entered, `s.direct` its flags] Set the block's mode, waiting as its first
        query would; on a failure, release `s` (`with` will not) and raise."""
        p = s.proc
        flags = s.direct
        held = self.held.get(p)
        if type(held) is Session and held.claimed and held.dirty is None and not p.passive and not self.rt.stopping:
            mode = DIRECT
        else:
            s.direct = 0
            try:
                mode = self._claim_slow(held, p, s.qwhere, s.query)
            except BaseException:
                s.__exit__()
                raise
        if flags & COMMANDS and type(held) is Session:
            held.changed = True
        s.direct = mode

    def _claim_slow(  # type: ignore[misc]
        self: Processor,
        held: Session | Processor | None,
        p: Processor,
        qwhere: Where | None,
        query: Routine | None,
    ) -> int:
        """The mode of a direct block whose supplier is not claimed and clean already: wait
        (as a query would) until it is free for us; raise what that query would raise (the
        dirty processor exception, Shutdown)."""
        if held is p:
            # Our own region, or one whose locks were passed to us. (For the latter the general
            # path names our thread as the region's executor during each call, for the monitor;
            # a direct block's leaf calls never block, so no report could tell.)
            return RAW if p is self or p.passive else BORROWED
        assert type(held) is Session, "claim1 reserved the region"
        while True:
            if held.claimed and held.dirty is None and not self.rt.stopping:
                return RAW if p.passive else DIRECT
            self._sync(held, p, _reach, p, (), qwhere, False, query)  # type: ignore[arg-type]
            lock = p.lock
            lock.acquire()
            if not held.claimed and p.state != RUNNING and p.head is held and not held.calls:
                if not self._claim_locked(p, held):  # released; not kept: not our session
                    return (RAW if p.passive else DIRECT) | TEMP
            else:
                lock.release()

    def command_failed(  # type: ignore[misc]
        self: Processor, s: Session, e: BaseException, noticed: Where | None
    ) -> BaseException:
        """`_s.failed(e, noticed)`: a command of the direct block `s` failed with `e`; the
        exception its client gets now (see the module's docstring). The general path would
        raise it at the next query, at `noticed`, or (None) not at all: the region is dirty
        and the rest of the block is skipped."""
        mode = s.direct & MODE
        p = s.proc
        _caught_here(e)
        error: BaseException
        if isinstance(e, PASS_THROUGH) or mode == RAW:
            error = e
        elif mode == BORROWED:
            error = sync_failure(p, e) if isinstance(e, Exception) else e
        else:
            held = self.held.get(p)
            owner = held if type(held) is Session else s
            p.rt.note("dirty region", dirty_text(p, owner, e))
            if noticed is None:  # as `_leaf_claimed`: dirty until delivered or reported lost
                lock = p.lock
                lock.acquire()
                owner.dirty = e
                lock.release()
                error = SkipRest()
            else:
                dirty = dirty_error(p, e)
                dirty.noticed = noticed
                error = dirty
        s.failure = error
        return error

    def end_direct(self: Processor, s: Session, ev: BaseException | None) -> bool:  # type: ignore[misc]
        """The direct block `s` ends with `ev` (or its claim was its own): release, then
        raise the synchronous failure of a query that failed. True: swallow `ev`."""
        mode = s.direct
        failure = s.failure
        s.direct = 0
        s.failure = None
        p = s.proc
        if mode & TEMP:
            p.release_claim()
        s.__exit__()
        if ev is None or mode & MODE == RAW or not isinstance(ev, Exception):
            return ev is not None and ev is failure and isinstance(ev, SkipRest)
        if ev is failure:
            return False
        tb = ev.__traceback__
        _caught_here(ev)
        error = sync_failure(p, ev)
        if tb is not None and isinstance(error, DirtyRegionError):
            # raised here, it reaches the client's frame at the block's first line
            error.noticed = (tb.tb_frame.f_code.co_filename, tb.tb_lineno)
        raise error


def _caught_here(e: BaseException) -> None:
    """Drop the client's frame from the traceback of `e`, which a supplier's routine raised
    in a direct block: the general path calls it from the runtime, so a report shows the
    supplier's frames, then the client's where it noticed the failure."""
    tb = e.__traceback__
    if tb is not None:
        e.__traceback__ = tb.tb_next
