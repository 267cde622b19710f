"""Private queues (`Session`) and their life in a supplier's queue of queues: enqueueing,
the claim-once fast path, release. A Session is also the reservation object of the
common one-supplier reservation without wait condition (`Processor.reserve`).

Claim once: when a new private queue becomes the head of an IDLE supplier, the client
claims the supplier (RUNNING on its behalf) and keeps it until it releases the
reservation, so its leaf commands and queries are plain calls on its own thread, with no
lock. Nobody else could run the supplier meanwhile anyway: the client's open private
queue is at the head. The claim is dropped (under the supplier's lock) when a call must be
queued for the supplier's own thread (a non-leaf command, a lock-passing call) and at
release.
"""

from __future__ import annotations

from collections.abc import Callable
from types import TracebackType
from typing import TYPE_CHECKING, Final

from .protocols import Args, Call, Routine, Where

if TYPE_CHECKING:
    from .outside import OutsideClient
    from .processor import Processor
    from .sched import Block, Exec

# Final: the compiled runtime inlines them (docs/RUNTIME.md section 10).
IDLE: Final = 0
SCHEDULED: Final = 1
RUNNING: Final = 2
# `Session.direct` (direct.py): a direct block's mode once entered, its flags until then.
DIRECT: Final = 1  # an active region the client has claimed
RAW: Final = 2  # a passive region, or the client's own: failures as they are
BORROWED: Final = 3  # a region whose locks were passed to the client: synchronous failures
MODE: Final = 3  # the mode's bits
TEMP: Final = 4  # the claim is the block's own and ends with it
PENDING: Final = 8  # `claim1` returned it: entering sets the mode
COMMANDS: Final = 16  # the block has commands (they wake wait conditions)


def invoke(routine: Routine, target: object, args: Args) -> object:
    """`routine(target, *args)`. Compiled code builds a list and a tuple for a star call;
    spelled out for the common arities, the call goes straight to the routine."""
    n = len(args)
    if n == 0:
        return routine(target)
    if n == 1:
        return routine(target, args[0])
    if n == 2:
        return routine(target, args[0], args[1])
    return routine(target, *args)


def apply(f: Callable[..., object], args: Args) -> object:
    """`f(*args)`, as `invoke` (a clause table's predicate takes two to four arguments)."""
    n = len(args)
    if n == 2:
        return f(args[0], args[1])
    if n == 3:
        return f(args[0], args[1], args[2])
    if n == 4:
        return f(args[0], args[1], args[2], args[3])
    return f(*args)


class Session:
    """A private queue: the calls of one client to one supplier within one reservation.
    It is also the reservation object of the common one-supplier reservation without
    wait condition (`Processor.reserve`): `with` enters and releases it."""

    __slots__ = (
        "client",
        "proc",
        "calls",
        "closed",
        "dirty",
        "changed",
        "turn",
        "where",
        "heavy",
        "claimed",
        "direct",
        "failure",
        "qwhere",
        "query",
    )
    client: Processor | OutsideClient
    proc: Processor
    calls: list[Call]
    closed: bool
    dirty: BaseException | None
    delivered: bool
    changed: bool
    turn: Block | None
    where: Where | None
    heavy: bool
    claimed: bool
    direct: int
    failure: BaseException | None
    qwhere: Where | None
    query: Routine | None

    def __init__(self, client: Processor | OutsideClient, proc: Processor, where: Where | None = None) -> None:
        self.client = client  # Processor or OutsideClient (immutable)
        self.proc = proc  # the supplier (set by the client before it enqueues the
        #                           session; a reused spare is re-targeted, see `__exit__`)
        self.calls = []  # [proc.lock] (routine, target, args, Block|None, passer|None)
        self.closed = False  # [proc.lock] the client released the reservation
        self.dirty = None  # [proc.lock] exception of a failed asynchronous call, until
        #                           the next synchronous call delivers it (then None again)
        self.changed = False  # [executor of proc] a command ran (wakes wait conditions)
        self.turn = None  # [proc.lock] passive only: Block of the client awaiting its turn
        self.where = where  # reservation position, for reports
        self.heavy = False  # [proc.lock] a non-leaf call was logged: no client may
        #                           run this session's calls on its own thread
        self.claimed = False  # [set/cleared under proc.lock by the session's user; read
        #   by it] `proc` is RUNNING on behalf of this session's user: it is the head, no call
        #   is queued, so the user runs its calls directly, lock-free, until it drops the
        #   claim (close, a queued or lock-passing call). Only one thread uses a session at a
        #   time: its client, or the supplier it passed its locks to while it waits.
        self.direct = 0  # [client] a direct block's flags, then its mode (direct.py); 0 otherwise
        self.failure = None  # [client] the exception a direct block's failed command raised
        self.qwhere = None  # [client] a direct block's first query and its position, named
        self.query = None  #            by a deadlock report while `claim1` waits

    # -- the one-supplier reservation (Processor.reserve) ------------------------------
    def __enter__(self) -> Session:
        here: Processor = self.client  # type: ignore[assignment]  # outside clients never enter one
        rt = here.rt
        p = self.proc
        held = here.held
        if p in held:
            # Nested: the outer reservation keeps `p`. Or `reserve1` with a precondition
            # entered us already: then never yield here, we hold `p` (others would queue
            # behind a client waiting for a permit) and a Shutdown raised here would skip
            # `__exit__`.
            if rt.attention and held[p] is not self:
                rt.attend(here.exec)  # type: ignore[arg-type]  # running: its exec is set
        else:
            if rt.attention:  # a permit waiter asked to yield, or stopping
                rt.attend(here.exec)  # type: ignore[arg-type]  # running: its exec is set
            lock = p.lock  # `enqueue_claim`, inlined (the hottest path)
            lock.acquire()
            if p.head is None:
                p.head = self
                if p.state == IDLE:
                    p.state = RUNNING
                    p.exec = here.exec
                    self.claimed = True
            else:
                p.qoq.append(self)
            lock.release()
            held[p] = self
        if self.direct & PENDING:  # `claim1`'s block (direct.py)
            here.begin_direct(self)
        return self

    def __exit__(
        self, et: type[BaseException] | None = None, ev: BaseException | None = None, tb: TracebackType | None = None
    ) -> bool:
        client: Processor = self.client  # type: ignore[assignment]  # as in `__enter__`
        if self.direct:
            if ev is not None or self.direct & TEMP:
                return client.end_direct(self, ev)  # comes back here with `direct` 0
            self.direct = 0
        held = client.held
        p = self.proc
        if held.get(p) is self:
            del held[p]
            lock = p.lock
            lock.acquire()
            self.closed = True
            if self.claimed and not p.qoq and self.dirty is None:
                if self.changed and p.waiters:
                    p.wake_waiters_locked(self)
                self.claimed = False  # the common case of `close_locked`, inlined
                p.exec = None
                p.state = IDLE
                p.head = None
                lock.release()
                # Nothing refers to us any more (not queued, no call, not held, not
                # dirty): the client's next `reserve1` may reuse us.
                client.spare = self
                return False
            close_locked(p, self)
        return False

    def failed(self, e: BaseException, noticed: Where | None) -> BaseException:
        """A command of the direct block this session reserves failed with `e`: the exception
        to raise (direct.py); `noticed` the position of the block's next query, None after
        the last one."""
        client: Processor = self.client  # type: ignore[assignment]  # as in `__enter__`
        return client.command_failed(self, e, noticed)

    # `enter`/`exit`: the same, for code that cannot use `with` (methods, not aliases: a
    # compiled runtime, docs/RUNTIME.md section 10, has no class-level aliases of methods).
    def enter(self) -> Session:
        return self.__enter__()

    def exit(self) -> None:
        self.__exit__()

    @property
    def taken(self) -> tuple[tuple[Processor, Session]] | None:
        """As `Reservation.taken`: the (region, session) pairs held by this reservation."""
        client: Processor = self.client  # type: ignore[assignment]  # as in `__enter__`
        return ((self.proc, self),) if client.held.get(self.proc) is self else None


def enqueue(p: Processor, s: Session) -> None:
    """[p.lock] Put session `s` in `p`'s queue of queues."""
    if p.head is None:
        p.head = s
    else:
        p.qoq.append(s)


def enqueue_claim(p: Processor, s: Session, ex: Exec | None) -> None:
    """[p.lock] Put a new reservation's session `s` in `p`'s queue of queues; if it is the
    head of an idle `p`, claim `p` for the client's thread `ex` at once (a reservation is
    usually followed by calls the client runs itself)."""
    if p.head is None:
        p.head = s
        if p.state == IDLE:
            p.state = RUNNING
            p.exec = ex
            s.claimed = True
    else:
        p.qoq.append(s)


def drop_claim_locked(p: Processor, s: Session) -> None:
    """[p.lock] `s` gives up its claim on `p`: `p` is idle again, `s` still its head."""
    s.claimed = False
    p.exec = None
    p.state = IDLE


def close(s: Session) -> None:
    """The client releases its reservation `s`. If nobody runs the supplier, the client
    finishes the session itself and serves the leaf calls queued behind it (see `settle`)."""
    p = s.proc
    p.lock.acquire()
    close_locked(p, s)


def close_locked(p: Processor, s: Session) -> None:
    """[p.lock held; releases it] `close` after taking the lock."""
    lock = p.lock
    s.closed = True
    if s.claimed:
        drop_claim_locked(p, s)
    if p.head is s and p.state == IDLE:
        if not s.calls:
            if not p.qoq and s.dirty is None and not (s.changed and p.waiters):
                p.head = None  # the common case: nothing else to do
                lock.release()
                return
            p._advance_locked()
        p.settle_locked(s.client)
        return
    lock.release()
