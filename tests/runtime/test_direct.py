"""Direct blocks (direct.py): `claim1` returns once the client may call the reserved
supplier's leaf routines itself, and `failed`/the block's end give the exceptions the general
path gives. These tests drive it as generated code does (codegen/direct.py) and check it
against the general path's guarantees: order behind another client's queue, dirty regions,
passive and own regions."""

import threading

import pytest
from test_claim import LCell, leaf_add, leaf_fail, leaf_items

import scoopc.runtime as rt
from scoopc.runtime.session import BORROWED, MODE

from rt_helpers import Cell, spawn

W = ("TEST", "routine", "test.e", 1)
W_QUERY = ("TEST", "routine", "test.e", 3)


def _command(block, routine, target, *args):
    """A command of a direct block, as codegen emits it."""
    try:
        routine(target, *args)
    except BaseException as e:
        raise block.failed(e, W_QUERY)  # noqa: B904 (as generated: its cause is set)


def test_an_idle_supplier_is_claimed_and_its_calls_run_here(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
        held = root.held[c._region_]
        assert held is s and s.claimed
        _command(s, leaf_add, c, 1)
        assert c.log == [1]  # run on our thread, at once
        assert leaf_items(c) == [1]
    assert c._region_ not in root.held
    with root.reserve1(c, W):  # released: anyone may take it again
        assert root.leaf_query(c, leaf_items) == [1]


def test_a_busy_supplier_is_claimed_after_the_queues_ahead(h):
    """Another client's private queue is ahead (a command still running on the supplier's
    thread): `claim1` returns only after it, as the block's first query would."""
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    running, gate = threading.Event(), threading.Event()

    def other(here):
        with here.reserve1(c, W):
            here.call(c, Cell.add, ("other",))
            here.call(c, Cell.gate, (gate, running))

    spawn(root, other)
    assert running.wait(10)
    threading.Timer(0.2, gate.set).start()
    with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
        assert gate.is_set()
        assert root.held[c._region_].claimed
        _command(s, leaf_add, c, "mine")
        assert leaf_items(c) == ["other", "mine"]


def test_a_failed_command_raises_the_dirty_processor_exception_of_the_next_query(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with pytest.raises(rt.DirtyRegionError) as info:
        with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
            _command(s, leaf_fail, c, "boom")
            pytest.fail("the block goes on after a failed command")
    error = info.value
    assert error.asynchronous and error.noticed == W_QUERY
    assert isinstance(error.__cause__, KeyError)
    assert any(e.kind == "dirty region" for e in h.rt.events)
    with root.reserve1(c, W):  # delivered: the region is clean, nothing is lost
        assert root.leaf_query(c, leaf_items) == []
    assert h.finish() == 0
    assert "exception lost" not in h.err.getvalue()


def test_a_failed_query_raises_its_synchronous_failure_at_the_end_of_the_block(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with pytest.raises(rt.DirtyRegionError) as info:
        with root.claim1(c, W, W_QUERY, leaf_fail, False):
            leaf_fail(c, "query")
    error = info.value
    assert not error.asynchronous and isinstance(error.__cause__, KeyError)
    assert error.noticed is not None and error.noticed[0] == __file__
    # The supplier's failure keeps its own frames only, as when the runtime calls it.
    frames = [f.f_code.co_name for f, _ in __import__("traceback").walk_tb(error.__cause__.__traceback__)]
    assert frames == ["leaf_fail"]
    with root.reserve1(c, W):
        assert root.leaf_query(c, leaf_items) == []


def test_a_dirty_outer_reservation_raises_at_the_inner_block(h):
    """Nested in a reservation whose command failed: the block's first query would deliver
    the dirty processor exception (its commands before it are skipped), so `claim1` does."""
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W):
        root.leaf_call(c, leaf_fail, ("outer",))
        with pytest.raises(rt.DirtyRegionError) as info:
            with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
                _command(s, leaf_add, c, "skipped")
        assert info.value.asynchronous
        assert c.log == []
        assert root.leaf_query(c, leaf_items) == []  # delivered: clean again


def test_passive_and_own_regions_let_failures_through_as_they_are(h):
    root = h.root
    for target in (root.new_passive(LCell, LCell.make), root.new(LCell)):
        if target._region_ is root:
            target.make()
        with root.claim1(target, W, W_QUERY, leaf_items, True) as s:
            _command(s, leaf_add, target, 1)
            assert leaf_items(target) == [1]
        with pytest.raises(KeyError):
            with root.claim1(target, W, W_QUERY, leaf_items, True) as s:
                _command(s, leaf_fail, target, "raw")
        with pytest.raises(KeyError):
            with root.claim1(target, W, W_QUERY, leaf_fail, False):
                leaf_fail(target, "raw query")


def test_commands_of_a_block_wake_a_wait_condition(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    pre = ((lambda here, c: here.leaf_query(c, leaf_items) != [], (0,), "some", W),)
    got = []

    def waiter(here):
        with here.claim1(c, W, W_QUERY, leaf_items, False, pre, (here, c)):
            got.append(leaf_items(c))

    spawn(root, waiter)
    assert h.rt.watch_blocks(lambda b: b.kind == "wait").wait(10)
    with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
        _command(s, leaf_add, c, "x")
        assert leaf_items(c) == ["x"]
    assert h.finish() == 0
    assert got == [["x"]]


def _trailing(block, routine, target, *args):
    """A command after the block's last query, as codegen emits it."""
    try:
        routine(target, *args)
    except BaseException as e:
        raise block.failed(e, None)  # noqa: B904 (as generated)


def test_a_command_failing_after_the_last_query_is_lost_and_skips_the_rest(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.claim1(c, ("APP", "run", "app.e", 7), W_QUERY, leaf_items, True) as s:
        assert leaf_items(c) == []
        _trailing(s, leaf_fail, c, "late")
        _trailing(s, leaf_add, c, "skipped")
    assert c.log == []
    assert h.finish() == 0
    err = h.err.getvalue()
    assert err.count("exception lost") == 1 and "app.e:7" in err


def test_a_trailing_failure_in_a_nested_block_is_delivered_by_the_outer_query(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W):
        with root.claim1(c, W, W_QUERY, leaf_items, True) as s:
            assert leaf_items(c) == []
            _trailing(s, leaf_fail, c, "late")
        root.leaf_call(c, leaf_add, ("skipped",))  # the outer reservation is dirty
        with pytest.raises(rt.DirtyRegionError) as info:
            root.leaf_query(c, leaf_items)
        assert info.value.asynchronous and isinstance(info.value.__cause__, KeyError)
    assert c.log == []
    assert h.finish() == 0
    assert "exception lost" not in h.err.getvalue()


class _Server:
    def make(self):
        self.seen = []

    def visit(self, cell):
        """A routine run with its client's locks (`cell` is in the client's region): a
        direct block on `cell` is a callback there; a failure in it is synchronous."""
        here = self._region_
        with here.claim1(cell, W, W_QUERY, leaf_items, True) as s:
            assert s.direct & MODE == BORROWED
            _command(s, leaf_add, cell, "visited")
            self.seen.append(leaf_items(cell))
        try:
            with here.claim1(cell, W, W_QUERY, leaf_items, True) as s:
                _command(s, leaf_fail, cell, "callback")
        except rt.DirtyRegionError as e:
            self.seen.append(("failed", e.asynchronous, type(e.__cause__).__name__))


def test_a_block_on_a_region_whose_locks_were_passed_is_a_synchronous_callback(h):
    root = h.root
    server = root.new_separate(_Server, _Server.make)
    mine = root.new(LCell)
    mine.make()
    with root.reserve1(server, W):
        root.call(server, _Server.visit, (mine,))  # passes our lock: synchronous
        assert mine.log == ["visited"]
        assert root.query(server, _seen) == [["visited"], ("failed", False, "KeyError")]


def _seen(server):
    return server.seen


class _Node(Cell):
    def ping(self, other, barrier):
        here = self._region_
        barrier.wait(10)  # both are inside their routines: neither is free for the other
        with here.claim1(other, W, W_QUERY, Cell.get, False):
            return Cell.get(other)


def test_a_deadlock_while_claiming_names_the_first_query(harness):
    """Waiting in `claim1` is waiting for the block's first query: the report says so."""
    h = harness()
    root = h.root
    a = root.new_separate(_Node, _Node.make)
    b = root.new_separate(_Node, _Node.make)
    barrier = threading.Barrier(2)
    root.command1(a, _Node.ping, (b, barrier), W)
    root.command1(b, _Node.ping, (a, barrier), W)
    assert h.finish() == 3
    err = h.err.getvalue()
    assert "deadlock: a cycle of synchronous calls" in err
    for x, y in ((a, b), (b, a)):
        assert f"{x._region_!r} in TEST.routine (test.e:3) waits for the result of Cell.get on {y._region_!r}" in err
