"""Reservations: atomic, in processor-id order, never blocking, first-come first-served
across clients; which regions to reserve is decided at run time (Void and held regions
are skipped) and only this reservation's regions are released at its exit."""

import random
import threading

from rt_helpers import Cell, gated_cell, spawn


def test_reserving_a_busy_processor_does_not_block(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    gate, entered = threading.Event(), threading.Event()
    with root.reserve((c,)):
        root.call(c, Cell.gate, (gate, entered))
    assert entered.wait(10)  # c is now busy on its own thread
    with root.reserve((c,)):  # returns at once though c is busy
        root.call(c, Cell.add, ("after",))
        assert c.log == []
        gate.set()
        assert root.query(c, Cell.items) == ["after"]


def test_first_come_first_served_across_clients(h):
    root = h.root
    c, gate = gated_cell(root)
    turns = [threading.Event() for _ in range(6)]
    turns[0].set()

    def client(here, i):
        assert turns[i].wait(10)
        with here.reserve((c,)):
            turns[i + 1].set() if i + 1 < len(turns) else None
            here.call(c, Cell.add, (i,))

    for i in (3, 0, 5, 1, 4, 2):  # processors created in another order than they reserve
        spawn(root, client, i)
    assert turns[-1].wait(10)
    gate.set()
    assert h.finish() == 0
    assert c.log == [0, 1, 2, 3, 4, 5]


def _pair_client(here, i, x, y, flip):
    args = (y, x) if flip else (x, y)
    with here.reserve(args):
        here.call(x, Cell.add, (i,))
        here.call(y, Cell.add, (i,))


def test_multi_reservation_is_atomic(h):
    """Each client reserves both x and y and logs its id on both: with atomic reservation
    the two suppliers serve the clients in the same order, whatever the argument order."""
    root = h.root
    x = root.new_separate(Cell, Cell.make)
    y = root.new_separate(Cell, Cell.make)
    rng = random.Random(7)
    for i in range(60):
        spawn(root, _pair_client, i, x, y, rng.random() < 0.5)
    assert h.finish() == 0
    assert sorted(x.log) == list(range(60))
    assert x.log == y.log


def test_void_and_held_regions_are_skipped(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    d = root.new_separate(Cell, Cell.make)
    mine = root.new(Cell)
    mine.make()
    with root.reserve((None, mine)) as r0:
        assert r0.taken == ()
    with root.reserve((c,)) as outer:
        session_c = root.held[c._region_]
        with root.reserve((c, None, d)) as inner:
            assert [reg for reg, _ in inner.taken] == [d._region_]
            assert root.held[c._region_] is session_c
        assert c._region_ in root.held and d._region_ not in root.held
        root.call(c, Cell.add, ("still held",))
        assert root.query(c, Cell.items) == ["still held"]
    assert c._region_ not in root.held
    assert outer.taken is None


def test_nested_reservation_keeps_the_outer_private_queue(h):
    """An inner routine reserving a region the caller holds must not release it: another
    client's calls cannot slip in between the outer routine's calls."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    d = root.new_separate(Cell, Cell.make)
    other_logged = threading.Event()

    def other(here):
        with here.reserve((c,)):
            here.call(c, Cell.add, ("other",))
        other_logged.set()

    with root.reserve((c,)):
        root.call(c, Cell.add, ("outer1",))
        with root.reserve((c, d)):
            root.call(c, Cell.add, ("inner",))
        spawn(root, other)
        assert other_logged.wait(10)
        root.call(c, Cell.add, ("outer2",))
    assert h.finish() == 0
    assert c.log == ["outer1", "inner", "outer2", "other"]


def test_sessions_are_taken_in_processor_id_order(h):
    root = h.root
    cells = [root.new_separate(Cell, Cell.make) for _ in range(5)]
    with root.reserve(tuple(reversed(cells))) as r:
        ids = [reg.id for reg, _ in r.taken]
        assert ids == sorted(ids) and len(ids) == 5
