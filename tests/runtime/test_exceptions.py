"""Exceptions: synchronous calls re-raise; a failed asynchronous call makes the region dirty
for that client (later calls skipped; the next synchronous call is not executed, raises and
cleans it; release cleans it too), as EiffelStudio's processor.c;
a lost exception is reported on stderr, and strict mode makes it a run-time failure."""

import pytest

import scoopc.runtime as rt

from rt_helpers import Cell


def test_sync_call_reraises_the_suppliers_exception(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        with pytest.raises(ValueError, match="bad query"):
            root.query(c, Cell.fail, ("bad query",))
        assert root.query(c, Cell.get) == 0  # a sync failure is not dirt


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
