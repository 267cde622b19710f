"""Exceptions: a failed synchronous call raises the dirty processor exception in the client
(its cause the supplier's failure; passive regions re-raise it as is); a failed asynchronous
call makes the region dirty for that client (later calls skipped; the next synchronous call is not executed, raises and
cleans it; release cleans it too), as EiffelStudio's processor.c;
a lost exception is reported on stderr, and strict mode makes it a run-time failure."""

import threading

import pytest

import scoopc.runtime as rt

from rt_helpers import GATE_TIMEOUT, Cell


class LCell(Cell):
    @rt.leaf
    def make(self, value=0):
        Cell.make(self, value)


@rt.leaf
def leaf_fail(cell, message):
    raise ValueError(message)


def test_failed_sync_call_raises_the_dirty_processor_exception(h):
    """EiffelStudio (processor.c, rt_processor_execute_call): a synchronous call that fails
    marks the supplier dirty, which, the call being synchronous, cleans itself and answers
    SCOOP_MESSAGE_DIRTY; the client raises "EVE/Qs dirty processor exception"
    (private_queue.c, rt_private_queue_log_call)."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(c, Cell.fail, ("bad query",))
        assert isinstance(info.value.__cause__, ValueError)
        assert str(info.value.__cause__) == "bad query"
        assert str(info.value) == f"EVE/Qs dirty processor exception: a synchronous call on {c._region_} failed"
        assert root.query(c, Cell.get) == 0  # delivered: the region is clean
    lc = root.new_separate(LCell, LCell.make)  # a leaf creation: run here, lc idle
    with root.reserve((lc,)):
        assert root.held[lc._region_].claimed  # claimed: the client runs its queries
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(lc, Cell.fail, ("claimed",))
        assert str(info.value.__cause__) == "claimed"
        with pytest.raises(rt.DirtyRegionError) as info:
            root.leaf_query(lc, leaf_fail, ("leaf",))  # the fast entry point likewise
        assert str(info.value.__cause__) == "leaf"
        assert root.query(lc, Cell.get) == 0
    assert h.finish() == 0


def test_failed_sync_call_run_by_the_suppliers_thread_raises_the_same(h):
    """The same when the supplier's own thread runs the query (queued behind a command)."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    gate = threading.Event()
    queued = h.rt.watch_blocks(lambda b: b.kind == "sync")
    opener = threading.Thread(target=lambda: queued.wait(GATE_TIMEOUT) and gate.set())
    opener.start()
    with root.reserve((c,)):
        root.call(c, Cell.gate, (gate,))  # not a leaf: for the supplier's thread
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(c, Cell.fail, ("on its thread",))  # waits behind the gate
        assert str(info.value.__cause__) == "on its thread"
        assert root.query(c, Cell.get) == 0
    opener.join()
    assert h.finish() == 0


def test_failed_call_on_a_passive_region_reraises_the_same_exception(h):
    """Calls on a passive region are plain calls (EiffelStudio impersonates it): no wrapping."""
    root = h.root
    c = root.new_passive(Cell, Cell.make)
    with root.reserve((c,)):
        with pytest.raises(ValueError, match="passive"):
            root.query(c, Cell.fail, ("passive",))
        assert root.query(c, Cell.get) == 0
    assert h.finish() == 0


def test_async_failure_dirties_until_the_next_synchronous_call(h):
    """EiffelStudio (processor.c, rt_processor_execute_call): after a failed asynchronous call
    the supplier skips the client's logged calls; the first synchronous call is not executed,
    raises the dirty processor exception in the client and cleans the region."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.add, ("before",))
        root.call(c, Cell.fail, ("async",))
        root.call(c, Cell.add, ("skipped",))
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(c, Cell.add, ("not executed",))
        assert str(info.value.__cause__) == "async"
        assert "dirty processor exception" in str(info.value)
        root.call(c, Cell.add, ("after the delivery",))  # clean again: executed
        assert root.query(c, Cell.items) == ["before", "after the delivery"]
    assert h.finish() == 0
    assert h.err.getvalue() == ""  # it was delivered: not lost


def test_a_second_failure_after_a_delivery_is_delivered_again(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.fail, ("first",))
        with pytest.raises(rt.DirtyRegionError) as first:
            root.query(c, Cell.get)
        root.call(c, Cell.fail, ("second",))
        with pytest.raises(rt.DirtyRegionError) as second:
            root.query(c, Cell.get)
        assert (str(first.value.__cause__), str(second.value.__cause__)) == ("first", "second")
        root.call(c, Cell.fail, ("third, never looked at",))
    assert h.finish() == 0
    err = h.err.getvalue()
    assert "exception lost" in err and "third" in err and "first" not in err


def test_release_cleans_a_dirty_region(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.fail, ("async",))
        root.call(c, Cell.add, ("skipped",))
    with root.reserve((c,)):  # unlocking forgot the dirtiness
        root.call(c, Cell.add, ("after",))
        assert root.query(c, Cell.items) == ["after"]
    assert h.finish() == 0
    assert "exception lost" in h.err.getvalue()


def test_rescue_and_retry_succeeds_on_the_second_attempt(h):
    """A routine that rescues the dirty processor exception and retries within the same
    reservation runs its second attempt on a clean region (it looped forever when every
    synchronous call raised until the release)."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    attempts = []
    with root.reserve((c,)):
        while True:  # the shape of a retried routine body
            attempts.append(len(attempts) + 1)
            try:
                if len(attempts) == 1:
                    root.call(c, Cell.fail, ("first attempt",))
                root.call(c, Cell.set, (42,))
                result = root.query(c, Cell.get)
                break
            except rt.DirtyRegionError:
                assert len(attempts) < 5, "retry loops"
    assert (attempts, result) == ([1, 2], 42)
    assert h.finish() == 0 and h.err.getvalue() == ""


def test_lost_exception_is_reported(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,), where=("APP", "run", "app.e", 12)):
        root.call(c, Cell.fail, ("nobody looks",))
    assert h.finish() == 0
    err = h.err.getvalue()
    assert "exception lost" in err and "nobody looks" in err and "app.e:12" in err


def test_strict_mode_makes_a_lost_exception_a_failure(harness):
    h = harness(strict=True)
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.fail, ("strict",))
    assert h.finish() == 3
    assert "run-time failure: lost exception" in h.err.getvalue()


def test_leaf_command_failure_also_dirties(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)

    @rt.leaf
    def bad(cell):
        raise KeyError("leaf")

    with root.reserve((c,)):
        root.call(c, bad)
        with pytest.raises(rt.DirtyRegionError):
            root.query(c, Cell.get)
        assert root.query(c, Cell.get) == 0  # delivered: clean again


def test_uncaught_exception_in_root_is_a_failure():
    import io

    err = io.StringIO()

    class Root:
        def make(self):
            raise RuntimeError("root failed")

    assert rt.run_main(Root, Root.make, stderr=err, stdout=io.StringIO()) == 3
    assert "root failed" in err.getvalue()
