"""The runtime's state for live views: every processor (its state, queue, client) and every
wait condition being waited on, read on demand; and the status text of `scoopc run --status`.

Nothing here runs unless asked: taking a snapshot reads the processors' and the blocked
threads' fields under their own locks, once each, as the dump does (monitor.py). The only
cost a run pays without a viewer is the time stamp of a thread that really blocks
(`Block.since`) and an event record for the rare dirty region, lost exception or failure.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .errors import fmt_where
from .monitor import _top_frame
from .protocols import Where
from .session import RUNNING, SCHEDULED, Session

if TYPE_CHECKING:
    from .externals import InsideExternal
    from .processor import Processor
    from .sched import Block, Runtime

IDLE_STATE = "idle"
SCHEDULED_STATE = "scheduled"
RUNNING_STATE = "running"
WAIT_CONDITION = "waiting on a wait condition"
RESERVATION = "waiting for a reservation"
QUERY_RESULT = "waiting for a query's result"
INSIDE_EXTERNAL = "inside an external"
SLEEPING = "sleeping"
STATES = (
    IDLE_STATE,
    SCHEDULED_STATE,
    RUNNING_STATE,
    WAIT_CONDITION,
    RESERVATION,
    QUERY_RESULT,
    INSIDE_EXTERNAL,
    SLEEPING,
)

ClauseText = Callable[[Where], "str | None"]  # a wait condition's position -> the clause's source text


@dataclass(frozen=True)
class ProcessorInfo:
    """One processor: `cls` the class of the object whose creation made it; `state` one of
    STATES; `queued` the private queues waiting behind the one served; `serving` the id of the
    client whose private queue it serves now (None: none); `at` its innermost routine, if known."""

    id: int
    cls: str
    state: str
    queued: int
    serving: int | None
    at: str | None
    detail: str | None  # what it waits for, or the external it is inside


@dataclass(frozen=True)
class WaitInfo:
    """One wait condition being waited on: the waiting processor, the routine, the .e file and
    line of the clause that is false, its tag and text, the suppliers it calls, since when
    (`since`: wall-clock seconds; `waited`: seconds so far)."""

    processor: int
    cls: str
    routine: str
    file: str
    line: int
    tag: str | None
    clause: str | None
    over: tuple[int, ...]
    since: float
    waited: float


@dataclass(frozen=True)
class EventInfo:
    """A deadlock (its cycle), a failure, a lost exception or a dirty region; `text` names the
    processors and the Eiffel routines with their file:line."""

    index: int
    kind: str
    text: str
    at: float


@dataclass(frozen=True)
class Snapshot:
    at: float  # wall-clock seconds
    processors: tuple[ProcessorInfo, ...]
    waits: tuple[WaitInfo, ...]


def take(rt: Runtime, clause_text: ClauseText | None = None) -> Snapshot:
    """The processors (sorted by id) and the wait conditions being waited on, now."""
    procs = rt.processors()
    with rt.glock:
        blocks = {ex: ex.blocked for ex in rt.blocked if ex.blocked is not None}
        inside = dict(rt.inside)
    now_wall, now = time.time(), time.monotonic()
    by_proc = {blk.proc: blk for blk in blocks.values()}
    inside_by_proc = {record.proc: record for record in inside.values()}
    rows = tuple(_processor(p, by_proc.get(p), inside_by_proc.get(p)) for p in procs)
    waits = [_wait(blk, clause_text, now_wall, now) for blk in blocks.values() if blk.kind == "wait"]
    waits.sort(key=lambda w: (w.processor, w.since))
    return Snapshot(now_wall, rows, tuple(waits))


def events(rt: Runtime, start: int = 0) -> list[EventInfo]:
    """The events recorded since the `start`-th (0: all)."""
    with rt.glock:
        new = rt.events[start:]
    return [EventInfo(start + i, e.kind, e.text, e.at) for i, e in enumerate(new)]


def _processor(p: Processor, blk: Block | None, record: InsideExternal | None) -> ProcessorInfo:
    with p.lock:
        state, head, queued = p.state, p.head, len(p.qoq)
    serving: int | None = getattr(head.client, "id", None) if head is not None else None  # an outside client: None
    top = _top_frame(p)
    at = fmt_where(top) if top is not None else None
    if blk is not None:
        name, detail = _blocked_state(blk)
        at = fmt_where(blk.where) if blk.where else at
        return ProcessorInfo(p.id, p.name or "", name, queued, serving, at, detail)
    if record is not None:
        return ProcessorInfo(p.id, p.name or "", INSIDE_EXTERNAL, queued, serving, at, record.describe())
    name = RUNNING_STATE if state == RUNNING else SCHEDULED_STATE if state == SCHEDULED else IDLE_STATE
    return ProcessorInfo(p.id, p.name or "", name, queued, serving, at, None)


def _blocked_state(blk: Block) -> tuple[str, str | None]:
    on = blk.on
    if blk.kind == "wait":
        over = ", ".join(repr(p) for p in on) if isinstance(on, tuple) else "?"
        return WAIT_CONDITION, f"wait condition{' ' + str(blk.what) if blk.what else ''} over {over}"
    if blk.kind == "sleep":
        return SLEEPING, None
    assert isinstance(on, Session), "a sync or turn Block is on a Session"
    supplier = on.proc
    if blk.kind == "turn":
        return RESERVATION, f"its turn on passive {supplier!r}"
    with supplier.lock:
        ours = supplier.head is on
        ahead = supplier.head.client if supplier.head is not None else None
    if ours:
        what = getattr(blk.what, "__qualname__", blk.what)
        return QUERY_RESULT, f"the result of {what} on {supplier!r}"
    return RESERVATION, f"{supplier!r}, reserved by {ahead!r}" if ahead is not None else f"{supplier!r}"


def _wait(blk: Block, clause_text: ClauseText | None, now_wall: float, now: float) -> WaitInfo:
    where = blk.where if isinstance(blk.where, tuple) and len(blk.where) == 4 else None
    cls, routine, file, line = where if where is not None else (blk.proc.name or "", "?", "?", 0)
    on = blk.on
    over = tuple(p.id for p in on) if isinstance(on, tuple) else ()
    since = getattr(blk, "since", now)
    text = clause_text(where) if clause_text is not None and where is not None else None
    tag = str(blk.what) if blk.what else None
    return WaitInfo(blk.proc.id, cls, routine, file, int(line), tag, text, over, now_wall - (now - since), now - since)


def render(snap: Snapshot, events_seen: list[EventInfo] | None = None) -> str:
    """The status text: one line per processor not idle, one per wait condition waited on."""
    stamp = time.strftime("%H:%M:%S", time.localtime(snap.at))
    busy = [p for p in snap.processors if p.state != IDLE_STATE]
    lines = [f"scoopc status at {stamp}: {len(snap.processors)} processors, {len(busy)} not idle"]
    for p in busy:
        serving = f", serving P{p.serving}" if p.serving is not None and p.serving != p.id else ""
        at = f" in {p.at}" if p.at else ""
        detail = f": {p.detail}" if p.detail else ""
        lines.append(f"  P{p.id}({p.cls}) {p.state}{detail}{at}{serving}, {p.queued} queued")
    for w in snap.waits:
        clause = f": {w.clause}" if w.clause else (f": {w.tag}" if w.tag else "")
        lines.append(
            f"  wait: P{w.processor} in {w.cls}.{w.routine} ({w.file}:{w.line}){clause} is false, for {w.waited:.1f} s"
        )
    lines += [f"  event: {e.kind}: {e.text.splitlines()[0]}" for e in events_seen or ()]
    return "\n".join(lines) + "\n"
