"""The claim-once fast path: a client whose private queue is at the head of an idle
supplier keeps the supplier (RUNNING on its behalf) from reservation to release and runs
its leaf calls and queries itself, lock-free. These tests hold that it keeps every
guarantee: order within the reservation, no interleaving with other clients, dirty
regions, lock passing, passive regions. Suppliers are made with a leaf creation procedure,
which the creating client runs itself, so each is idle (and claimable) deterministically."""

import threading

import pytest

import scoopc.runtime as rt

from rt_helpers import Cell, spawn


class LCell(Cell):
    @rt.leaf
    def make(self, value=0):
        Cell.make(self, value)


@rt.leaf
def leaf_add(cell, item):
    cell.log.append(item)


@rt.leaf
def leaf_items(cell):
    return list(cell.log)


@rt.leaf
def leaf_fail(cell, message):
    raise KeyError(message)


def _other_client(here, c, a_reserved, b_logged):
    assert a_reserved.wait(10)
    with here.reserve((c,)):  # never blocks, though the root holds c
        here.call(c, leaf_add, ("b1",))
        here.call(c, leaf_add, ("b2",))
        b_logged.set()


def test_claimed_supplier_keeps_order_and_no_interleaving(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    a_reserved, b_logged = threading.Event(), threading.Event()
    spawn(root, _other_client, c, a_reserved, b_logged)
    with root.reserve((c,)):
        s = root.held[c._region_]
        assert s.claimed  # claimed at reservation
        root.call(c, leaf_add, ("a1",))
        assert c.log == ["a1"]  # run by us, on our thread
        a_reserved.set()
        assert b_logged.wait(10)  # B's calls are queued meanwhile
        root.call(c, leaf_add, ("a2",))
        assert root.query(c, leaf_items) == ["a1", "a2"]
        assert s.claimed
    assert h.finish() == 0
    assert c.log == ["a1", "a2", "b1", "b2"]


def test_a_queued_call_drops_the_claim_and_keeps_order(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve((c,)):
        root.call(c, leaf_add, (1,))
        root.call(c, Cell.add, (2,))  # not a leaf: for c's own thread
        assert not root.held[c._region_].claimed
        root.call(c, leaf_add, (3,))  # queued behind it, never ahead
        assert root.query(c, leaf_items) == [1, 2, 3]
        root.call(c, leaf_add, (4,))
        assert root.query(c, leaf_items) == [1, 2, 3, 4]


def test_failure_in_a_claimed_leaf_command_dirties_until_release(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve((c,)):
        assert root.held[c._region_].claimed
        root.call(c, leaf_fail, ("claimed",))
        root.call(c, leaf_add, ("skipped",))  # a dirty region skips commands
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(c, leaf_items)
        assert isinstance(info.value.__cause__, KeyError)
    with root.reserve((c,)):  # releasing cleaned it
        assert root.query(c, leaf_items) == []
    assert h.finish() == 0
    assert "exception lost" not in h.err.getvalue()


def test_lost_failure_in_a_claimed_leaf_command_is_reported(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve((c,), where=("APP", "run", "app.e", 7)):
        root.call(c, leaf_fail, ("nobody looks",))
    assert h.finish() == 0
    err = h.err.getvalue()
    assert "exception lost" in err and "nobody looks" in err and "app.e:7" in err


class Relay:
    def make(self):
        self.thread = None

    def touch(self, who, other):
        """`who` is a reference in the client's region: the client's locks are passed,
        including its claimed private queue on `other`."""
        here = self._region_
        here.call(other, leaf_add, ("relay",))
        return here.query(other, leaf_items)


def test_lock_passing_hands_over_claimed_private_queues(h):
    root = h.root
    relay = root.new_separate(Relay, Relay.make)
    other = root.new_separate(LCell, LCell.make)
    mine = root.new(Cell)
    mine.make()
    with root.reserve((relay, other)):
        root.call(other, leaf_add, ("client",))
        assert root.held[other._region_].claimed
        assert root.query(relay, Relay.touch, (mine, other)) == ["client", "relay"]
        root.call(other, leaf_add, ("again",))  # still our private queue
        assert root.query(other, leaf_items) == ["client", "relay", "again"]


def test_claimed_passive_region_runs_every_call_synchronously(h):
    root = h.root
    pc = root.new_passive(Cell, Cell.make)
    with root.reserve((pc,)):
        assert root.held[pc._region_].claimed
        root.call(pc, Cell.add, ("x",))  # not a leaf, still ours to run
        assert pc.log == ["x"]
        with pytest.raises(ValueError):  # synchronous: re-raised here
            root.call(pc, Cell.fail, ("boom",))
        assert root.query(pc, Cell.items) == ["x"]  # and the region is not dirty


def test_nested_reservation_of_a_claimed_region_is_free(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve((c,)) as outer:
        s = root.held[c._region_]
        with root.reserve((c,)) as inner:
            assert inner.taken is None and root.held[c._region_] is s
            root.call(c, leaf_add, ("inner",))
        assert root.held[c._region_] is s and s.claimed
        assert outer.taken == ((c._region_, s),)
        root.call(c, leaf_add, ("outer",))
        assert root.query(c, leaf_items) == ["inner", "outer"]
    assert outer.taken is None
