"""The runtime snapshot of live views and `--status` (scoopc/runtime/snapshot.py): processor
states, the wait conditions waited on with their clause text and age, and the event log."""

import threading

import scoopc.runtime as rt
from scoopc.runtime import externals, snapshot

from rt_helpers import Cell, spawn

W_READY = ("APP", "wait_for_data", "app.e", 33)


def _clause(where):
    return {W_READY: "ready: c.get > 0"}.get(where)


def test_a_waiting_processor_and_its_wait_condition(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    src = rt.outside_client("keep-alive")
    waiting = h.rt.watch_blocks(lambda b: b.kind == "wait")

    def waiter(here):
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "ready", W_READY)]
        with here.reserve((c,), pre=pre):
            pass

    runner = spawn(root, waiter)
    assert waiting.wait(10)
    snap = snapshot.take(h.rt, _clause)
    states = {p.id: p for p in snap.processors}
    assert states[runner._region_.id].state == snapshot.WAIT_CONDITION
    assert states[runner._region_.id].cls == "Runner"
    assert states[c._region_.id].state == snapshot.IDLE_STATE
    (wait,) = snap.waits
    assert (wait.processor, wait.cls, wait.routine, wait.file, wait.line) == (
        runner._region_.id,
        "APP",
        "wait_for_data",
        "app.e",
        33,
    )
    assert (wait.tag, wait.clause, wait.over) == ("ready", "ready: c.get > 0", (c._region_.id,))
    assert 0 <= wait.waited < 10 and wait.since <= snap.at
    text = snapshot.render(snap)
    assert f"P{runner._region_.id}(Runner) waiting on a wait condition: wait condition ready over" in text
    assert f"wait: P{runner._region_.id} in APP.wait_for_data (app.e:33): ready: c.get > 0 is false, for" in text
    src.call(c, Cell.set, (1,))
    src.close()
    assert h.finish() == 0
    assert snapshot.take(h.rt).waits == ()


def test_a_client_waiting_for_a_query_result_and_one_for_its_reservation(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    gate = threading.Event()
    entered = threading.Event()
    synced = h.rt.watch_blocks(lambda b: b.kind == "sync")

    class Slow:
        def make(self):
            pass

        def hold(self):
            entered.set()
            gate.wait(10)  # a long call outside the runtime, that the test ends

    s = root.new_separate(Slow, Slow.make)

    def asker(here):
        with here.reserve((s,)):
            here.query(s, Slow.hold)

    def follower(here):
        entered.wait(10)
        with here.reserve((s,)):
            here.query(s, Slow.make)

    a = spawn(root, asker)
    assert entered.wait(10)
    f = spawn(root, follower)
    assert synced.wait(10)
    deadline = threading.Event()
    for _ in range(200):  # the follower blocks a moment after the asker (each a new Block)
        states = {p.id: p.state for p in snapshot.take(h.rt).processors}
        if states[f._region_.id] == snapshot.RESERVATION:
            break
        deadline.wait(0.01)
    assert states[f._region_.id] == snapshot.RESERVATION
    assert states[s._region_.id] == snapshot.RUNNING_STATE
    assert states[a._region_.id] in (snapshot.QUERY_RESULT, snapshot.RUNNING_STATE)  # the client may run it itself
    gate.set()
    del c
    assert h.finish() == 0


def test_events_record_a_dirty_region_and_the_lost_exception(h):
    root = h.root

    class Bad:
        def make(self):
            pass

        def boom(self):
            raise ValueError("no")

    b = root.new_separate(Bad, Bad.make)
    with root.reserve((b,)):
        root.call(b, Bad.boom)
    assert h.finish() == 0
    dirty, lost = snapshot.events(h.rt)
    assert (dirty.kind, lost.kind) == ("dirty region", "lost exception")
    assert dirty.text.startswith(f"P{b._region_.id}(Bad) is dirty for P{root.id}") and "ValueError: no" in dirty.text
    assert [e.index for e in snapshot.events(h.rt, 1)] == [1]


def test_a_processor_inside_an_external():
    runtime, root = rt.start()
    seen = {}

    def host():
        (seen["row"],) = [p for p in snapshot.take(runtime).processors if p.id == root.id]

    try:
        externals.call(root, "APP.f", "C f", host, [])
    finally:
        rt.finish(runtime, root)
    assert seen["row"].state == snapshot.INSIDE_EXTERNAL
    assert seen["row"].detail.startswith("P1(ROOT) is inside external APP.f (C f) for")
