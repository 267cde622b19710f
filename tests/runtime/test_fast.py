"""Fast entry points for codegen-known facts (fast.py): `reserve1` (one separate argument,
clause tables with `pre_args`), `leaf_call` / `leaf_query` (leaf routine, arguments that
cannot pass locks), and clause tables on the general `reserve`. Each must behave exactly
as the general entry point: these tests repeat the general guarantees through them."""

import threading

import pytest
from test_claim import LCell, leaf_add, leaf_fail, leaf_items

import scoopc.runtime as rt

from rt_helpers import Cell, spawn

W = ("TEST", "routine", "test.e", 1)


@rt.leaf
def leaf_get(cell):
    return cell.value


@rt.leaf
def leaf_set(cell, v):
    cell.value = v


def _waiting(rt_):
    return rt_.watch_blocks(lambda b: b.kind == "wait")


# A clause table as codegen emits it: module-level, predicates take `pre_args`.
EVALS = []
PRE_POSITIVE = ((lambda here, c: EVALS.append(1) or here.leaf_query(c, leaf_get) > 0, (0,), "positive", W),)


def _consumer(here, c, got):
    with here.reserve1(c, W, PRE_POSITIVE, (here, c)):
        got.append(here.leaf_query(c, leaf_get))
        here.leaf_call(c, leaf_set, (0,))


def test_reserve1_claims_and_leaf_calls_run_in_order_without_interleaving(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    a_reserved, b_logged = threading.Event(), threading.Event()

    def other(here):
        assert a_reserved.wait(10)
        with here.reserve1(c, W):  # never blocks, though root holds c
            here.leaf_call(c, leaf_add, ("b1",))
            here.leaf_call(c, leaf_add, ("b2",))
            b_logged.set()

    spawn(root, other)
    with root.reserve1(c, W) as r:
        assert root.held[c._region_] is r and r.claimed
        root.leaf_call(c, leaf_add, ("a1",))
        assert c.log == ["a1"]  # a plain call on our thread
        a_reserved.set()
        assert b_logged.wait(10)
        root.leaf_call(c, leaf_add, ("a2",))
        assert root.leaf_query(c, leaf_items) == ["a1", "a2"]
    assert c._region_ not in root.held
    assert h.finish() == 0
    assert c.log == ["a1", "a2", "b1", "b2"]


def test_reserve1_of_void_or_held_takes_nothing(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(None, W) as r:
        assert r.taken is None
    with root.reserve1(c, W) as outer:
        with root.reserve1(c, W) as inner:  # nested: the outer queue is kept
            assert inner.taken is None and root.held[c._region_] is outer
            root.leaf_call(c, leaf_add, (1,))
        assert root.held[c._region_] is outer
    with root.reserve1(root.new(Cell), W) as own:  # our own region: nothing to take
        assert own.taken is None
    assert c.log == [1]


def test_leaf_calls_fall_back_when_the_supplier_is_not_claimed(h):
    """Behind a non-leaf call (queued for the supplier's thread) the leaf call is queued
    too, never run ahead; the query waits for both."""
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W):
        root.call(c, Cell.add, (1,))  # not a leaf: drops the claim
        assert not root.held[c._region_].claimed
        root.leaf_call(c, leaf_add, (2,))
        assert root.leaf_query(c, leaf_items, (), W) == [1, 2]


def test_leaf_call_failure_dirties_until_release_and_is_reported_if_lost(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W):
        root.leaf_call(c, leaf_fail, ("claimed",))
        root.leaf_call(c, leaf_add, ("skipped",))  # a dirty region skips commands
        with pytest.raises(rt.DirtyRegionError) as info:
            root.leaf_query(c, leaf_items)
        assert isinstance(info.value.__cause__, KeyError)
    with root.reserve1(c, ("APP", "run", "app.e", 7)):
        assert root.leaf_query(c, leaf_items) == []
        root.leaf_call(c, leaf_fail, ("nobody looks",))
    assert h.finish() == 0
    err = h.err.getvalue()
    assert err.count("exception lost") == 1 and "app.e:7" in err


def test_leaf_call_on_a_passive_region_is_synchronous(h):
    root = h.root
    pc = root.new_passive(LCell, LCell.make)
    with root.reserve1(pc, W):
        root.leaf_call(pc, leaf_add, (1,))
        assert pc.log == [1]
        with pytest.raises(KeyError):  # failures reach the client at once
            root.leaf_call(pc, leaf_fail, ("passive",))
        assert root.leaf_query(pc, leaf_items) == [1]


def test_reserve1_waits_on_its_clause_table_until_it_holds(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    got = []
    EVALS.clear()
    waiting = _waiting(h.rt)
    spawn(root, _consumer, c, got)
    assert waiting.wait(10)  # false, released, waiting
    assert got == []
    with root.reserve1(c, W):  # c is free while it waits
        assert root.leaf_query(c, leaf_get) == 0  # a query-only session wakes nobody
    with root.reserve1(c, W):
        root.leaf_call(c, leaf_set, (5,))
    assert h.finish() == 0
    assert got == [5] and c.value == 0
    assert len(EVALS) == 2  # once false, once true: no polling


def test_reserve1_clause_on_held_or_no_target_is_a_violation(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W):
        with pytest.raises(rt.PreconditionViolation) as info:
            with root.reserve1(c, W, PRE_POSITIVE, (root, c)):
                pass
        assert info.value.tag == "positive" and info.value.where == W
        assert c._region_ in root.held  # the outer reservation is untouched
    no_target = ((lambda: True, (0,), "a", W), (lambda: False, (), "b", W))
    with pytest.raises(rt.PreconditionViolation) as info:
        with root.reserve1(c, W, no_target, ()):
            pass
    assert info.value.tag == "b" and c._region_ not in root.held


def test_reserve1_clause_that_raises_releases(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with pytest.raises(ZeroDivisionError):
        with root.reserve1(c, W, ((lambda: 1 // 0, (0,), "t", W),), ()):
            pass
    assert c._region_ not in root.held
    with root.reserve1(c, W):  # nothing left behind
        root.leaf_call(c, leaf_add, (1,))
    assert h.finish() == 0 and c.log == [1]


def test_general_reserve_takes_a_clause_table_with_pre_args(h):
    root = h.root
    c, d = root.new_separate(LCell, LCell.make), root.new_separate(LCell, LCell.make)
    waiting = _waiting(h.rt)
    table = ((lambda here, a, b: here.leaf_query(a, leaf_get) > 0, (0,), "a_pos", W),)

    def waiter(here):
        with here.reserve((c, d), pre=table, where=W, pre_args=(here, c, d)):
            here.leaf_call(d, leaf_add, ("w",))

    spawn(root, waiter)
    assert waiting.wait(10)
    with root.reserve((c,)):
        root.leaf_call(c, leaf_set, (1,))
    assert h.finish() == 0
    assert d.log == ["w"]


def test_reserve1_wait_deadlock_is_reported(harness):
    h = harness()
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    with pytest.raises(rt.Shutdown):
        with root.reserve1(c, W, PRE_POSITIVE, (root, c)):  # nobody will ever set it
            pass
    assert h.finish() == 3
    assert "waits on wait condition positive" in h.err.getvalue()


def test_a_finished_private_queue_is_reused_only_when_nothing_refers_to_it(h):
    """`reserve1` reuses the client's last private queue (`spare`) only after it left the
    supplier entirely; one still queued (released while another client was ahead) is not."""
    root = h.root
    c, d = root.new_separate(LCell, LCell.make), root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W) as first:
        root.leaf_call(c, leaf_add, (1,))
    assert root.spare is first
    with root.reserve1(d, W) as second:  # re-targeted to another supplier
        assert second is first and second.proc is d._region_ and not second.closed
        root.leaf_call(d, leaf_add, (2,))
        assert root.held[d._region_] is second and root.spare is None
    gate, entered = threading.Event(), threading.Event()
    holder = spawn(root, lambda here: _hold(here, c, gate, entered))
    assert entered.wait(10)
    root.spare = None
    with root.reserve1(c, W) as queued:  # behind the holder: not claimed
        assert not queued.claimed
        root.leaf_call(c, leaf_add, (3,))  # queued for the supplier
    assert root.spare is None  # still in c's queue of queues
    gate.set()
    assert h.finish() == 0
    assert c.log == [1, "h", 3] and d.log == [2] and holder is not None


def _hold(here, c, gate, entered):
    with here.reserve1(c, W):
        here.leaf_call(c, leaf_add, ("h",))
        entered.set()
        assert gate.wait(10)


# A leaf command goes through `command1` (which reads the routine's mark) or, when codegen
# proved it a leaf, `leaf_command1`: the same behaviour either way.
LEAF_ENTRIES = pytest.mark.parametrize("leaf_entry", ["command1", "leaf_command1"])


@LEAF_ENTRIES
def test_command1_runs_an_idle_leaf_here_and_queues_behind_a_holder(h, leaf_entry):
    root = h.root
    leaf_command1 = getattr(root, leaf_entry)
    c = root.new_separate(LCell, LCell.make)
    leaf_command1(c, leaf_add, (1,), W)
    assert c.log == [1] and c._region_ not in root.held  # run here, released
    assert c._region_.head is None and c._region_.state == rt.session.IDLE  # no private queue left
    gate, entered = threading.Event(), threading.Event()
    spawn(root, lambda here: _hold(here, c, gate, entered))
    assert entered.wait(10)
    leaf_command1(c, leaf_add, (2,), W)  # never blocks; queued behind "h"
    root.command1(c, Cell.add, (3,), W)  # non-leaf: for c's thread, in order
    assert c.log == [1, "h"]
    gate.set()
    with root.reserve1(c, W):
        assert root.leaf_query(c, leaf_items) == [1, "h", 2, 3]


def test_command1_non_leaf_is_asynchronous_and_fifo(h):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    gate, mark = threading.Event(), threading.Event()
    root.command1(c, Cell.gate, (gate, mark), W)  # runs on c's thread, blocks there
    assert mark.wait(10)
    root.command1(c, Cell.add, ("a",), W)  # logged, returns at once
    root.command1(c, leaf_add, ("b",), W)
    assert c.log == []
    gate.set()
    with root.reserve1(c, W):
        assert root.leaf_query(c, leaf_items) == ["a", "b"]


@LEAF_ENTRIES
def test_command1_on_a_held_or_passive_region_is_a_plain_synchronous_call(h, leaf_entry):
    root = h.root
    leaf_command1 = getattr(root, leaf_entry)
    c = root.new_separate(LCell, LCell.make)
    with root.reserve1(c, W) as outer:
        leaf_command1(c, leaf_add, (1,), W)  # nested: the outer queue is kept
        assert root.held[c._region_] is outer and c.log == [1]
    pc = root.new_passive(LCell, LCell.make)
    root.command1(pc, Cell.add, (2,), W)
    assert pc.log == [2]
    with pytest.raises(KeyError):  # a passive failure reaches the client
        leaf_command1(pc, leaf_fail, ("passive",), W)


@LEAF_ENTRIES
def test_command1_leaf_failure_is_reported_lost(h, leaf_entry):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    getattr(root, leaf_entry)(c, leaf_fail, ("nobody looks",), ("APP", "run", "app.e", 9))
    with root.reserve1(c, W):  # the region is clean again
        assert root.leaf_query(c, leaf_items) == []
    assert h.finish() == 0
    err = h.err.getvalue()
    assert err.count("exception lost") == 1 and "app.e:9" in err


@LEAF_ENTRIES
def test_command1_wakes_a_waiter(h, leaf_entry):
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    got = []
    EVALS.clear()
    waiting = _waiting(h.rt)
    spawn(root, _consumer, c, got)
    assert waiting.wait(10)
    getattr(root, leaf_entry)(c, leaf_set, (7,), W)
    assert h.finish() == 0
    assert got == [7] and len(EVALS) == 2


def test_entering_a_guarded_reserve1_never_yields_while_holding_it(h):
    """`reserve1` with a precondition returns its private queue already held; the `with`
    entering it must not yield the run permit (others would queue behind a client that
    waits for a permit: a convoy that once starved prodcons) nor raise before `with`
    could release it. A nested reservation entry still is a yield point, as before."""
    root = h.root
    c = root.new_separate(LCell, LCell.make)
    pm = h.rt.permits
    r = root.reserve1(c, W, ((lambda: True, (0,), "t", W),), ())
    # a yield asked for, with no permit waiter: a yield point answers it (want_yield goes
    # back to False) and goes on (the runtime's methods are not patched: they may be compiled)
    pm.want_yield = h.rt.attention = True
    try:
        with r:
            assert pm.want_yield and root.held[c._region_] is r  # not a yield point
            with root.reserve1(c, W):
                pass
            assert not pm.want_yield  # the nested entry was one
    finally:
        pm.want_yield = h.rt.attention = False
    assert c._region_ not in root.held
