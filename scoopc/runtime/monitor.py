"""Deadlock detection and the live dump: a wait-for graph between blocked threads.

Each blocked thread waits for at most one other thread: the one running the supplier it
called, or the one running the client whose private queue is ahead of its own. A cycle is
a deadlock of synchronous calls. "Every thread blocked, some in wait conditions, no sleeper,
no timer, no open outside client" is a wait-condition deadlock. The monitor thread looks
once a tick, and only reports a candidate seen again, unchanged (same Block objects: a
thread that moved got a new one), on the next tick: no false report from a racy snapshot.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

from .errors import fmt_where
from .protocols import Where
from .session import Session

if TYPE_CHECKING:
    from .processor import Processor
    from .sched import Block, Exec, Runtime


def _target(blk: Block) -> Exec | None:
    """The Exec that must move for `blk`'s thread to move, or None (it can move by itself,
    or waits for time, a condition or an outside client)."""
    if blk.kind not in ("sync", "turn"):
        return None
    s = blk.on
    assert isinstance(s, Session), "a sync or turn Block is on a Session"
    p = s.proc
    with p.lock:
        if p.state == 2:  # RUNNING: whoever runs it
            return p.exec
        h = p.head
        if h is s or h is None or h.calls:
            return None
        client = h.client
    return client.exec


def _top_frame(proc: Processor) -> Where | None:
    """The innermost frame pushed by generated code; read racily (a report, not logic)."""
    try:
        return proc.frames[-1]
    except IndexError:
        return None


def _describe(blk: Block) -> str:
    where = fmt_where(blk.where if blk.where is not None else _top_frame(blk.proc))
    on = blk.on
    if blk.kind == "sync":
        assert isinstance(on, Session)
        what = getattr(blk.what, "__qualname__", blk.what)
        inside = on.proc.rt.inside.get(on.proc.exec) if on.proc.exec is not None else None
        running = f", which is inside external {inside.feature} ({inside.what})" if inside is not None else ""
        return f"{blk.proc!r} in {where} waits for the result of {what} on {on.proc!r}{running}"
    if blk.kind == "turn":
        assert isinstance(on, Session)
        return f"{blk.proc!r} in {where} waits for its turn on passive {on.proc!r}"
    if blk.kind == "wait":
        assert isinstance(on, tuple)
        regions = ", ".join(repr(p) for p in on)
        tag = f" {blk.what}" if blk.what else ""
        return f"{blk.proc!r} in {where} waits on wait condition{tag} over {regions}"
    return f"{blk.proc!r} in {where} sleeps"


def _suspended(blk: Block) -> str:
    """The other end of a cycle within one thread: a processor that waits for `blk`'s processor
    while its thread runs that processor's calls (the client runs a supplier's pending calls
    itself rather than hand them over), and that `blk` now waits for."""
    on = blk.on
    assert isinstance(on, Session), "a sync or turn Block is on a Session"
    waiting = on.proc
    top = _top_frame(waiting)
    where = f" in {fmt_where(top)}" if top is not None else ""
    return f"{waiting!r}{where} waits for {blk.proc!r}, whose calls its thread runs meanwhile"


def snapshot(rt: Runtime) -> tuple[dict[Exec, Block], bool]:
    """(blocks, all_waiting, quiet_otherwise) read under glock."""
    with rt.glock:
        blocks = {ex: ex.blocked for ex in rt.blocked if ex.blocked is not None}
        all_blocked = rt.n_running == len(rt.blocked) and not rt.runnable
        no_wakers = rt.sources == 0 and not rt.clock.pending_locked() and not rt.clock.heap
    return blocks, all_blocked and no_wakers


def find_deadlock(rt: Runtime) -> tuple[frozenset[Block], list[str]] | None:
    """A candidate deadlock as (frozenset of Blocks, report lines), or None."""
    blocks, stuck = snapshot(rt)
    if not blocks:
        return None
    edges = {ex: _target(blk) for ex, blk in blocks.items()}
    for start in edges:
        path: list[Exec] = []
        ex: Exec | None = start
        while ex in edges and ex not in path:
            path.append(ex)
            ex = edges[ex]
        if ex in path:
            cycle = path[path.index(ex) :]
            lines = ["deadlock: a cycle of synchronous calls"]
            for e in cycle:
                lines.append("  " + _describe(blocks[e]))
                if edges[e] is e:  # the supplier it waits for is suspended on this very thread
                    lines.append("  " + _suspended(blocks[e]))
            return frozenset(blocks[e] for e in cycle), lines
    kinds = {blk.kind for blk in blocks.values()}
    if stuck and "wait" in kinds and "sleep" not in kinds:
        lines = ["deadlock: every processor is idle or blocked and none can make a wait condition true"]
        lines += ["  " + _describe(blk) for blk in blocks.values()]
        return frozenset(blocks.values()), lines
    return None


def dump(rt: Runtime) -> str:
    """A text dump of every live processor and every blocked thread."""
    from .processor import STATE_NAMES  # deferred: a cycle (scoopc.runtime.processor imports this module)

    procs = rt.processors()
    lines = [f"scoop runtime dump: {len(procs)} processors"]
    for p in procs:
        with p.lock:
            state, head, n = STATE_NAMES[p.state], p.head, len(p.qoq)
        if state == "idle" and head is None:
            continue
        holder = f", serving {head.client!r}" if head is not None else ""
        top = _top_frame(p)
        frame = f" at {fmt_where(top)}" if top is not None else ""
        lines.append(f"  {p!r}: {state}{holder}, {n} queued{frame}")
    blocks, _ = snapshot(rt)
    for blk in blocks.values():
        lines.append("  blocked: " + _describe(blk))
    with rt.glock:
        inside = sorted(rt.inside.values(), key=lambda r: r.proc.id)
    lines += ["  inside external: " + record.describe() for record in inside]
    return "\n".join(lines) + "\n"


def _after_lost(rt: Runtime, blocks: frozenset[Block]) -> str | None:
    """One line for a deadlock that follows from a lost exception (already reported): the
    processors that wait on a region whose asynchronous call failed, or None."""
    with rt.glock:
        lost = set(rt.lost)
    waiting = [blk for blk in blocks if _waits_on(blk) & lost]
    if not waiting:
        return None
    shown = "; ".join(_describe(blk) for blk in waiting)
    return f"deadlock, a consequence of the lost exception reported above: {shown}"


def _waits_on(blk: Block) -> set[Processor]:
    on = blk.on
    if isinstance(on, tuple):
        return set(on)
    proc = getattr(on, "proc", None)
    return {proc} if proc is not None else set()


class Monitor:
    """The deadlock watchdog thread, owned by run_main (started, stopped and joined)."""

    def __init__(self, rt: Runtime) -> None:
        self.rt = rt
        self.stopped = threading.Event()
        self.thread = threading.Thread(target=self._run, name="scoop-monitor", daemon=True)
        self.previous: frozenset[Block] | None = None

    def start(self) -> None:
        self.thread.start()

    def stop(self) -> None:
        self.stopped.set()
        self.thread.join()

    def _run(self) -> None:
        rt = self.rt
        try:
            while not self.stopped.wait(rt.deadlock_tick):
                self.check()
        except BaseException as e:  # collected by the owner
            rt.fail(f"internal error in the deadlock monitor: {e!r}", e)

    def check(self) -> None:
        found = find_deadlock(self.rt)
        if found is None:
            self.previous = None
            return
        blocks, lines = found
        if self.previous is not None and self.previous == blocks:
            self.rt.fail(_after_lost(self.rt, blocks) or "\n".join(lines), kind="deadlock")
            self.stopped.set()
            return
        self.previous = blocks
