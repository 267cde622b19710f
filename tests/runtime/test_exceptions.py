"""Exceptions: synchronous calls re-raise; a failed asynchronous call makes the region dirty
for that client (later calls skipped, next synchronous call raises, release cleans it);
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
        assert root.query(c, Cell.get) == 0            # a sync failure is not dirt


def test_async_failure_makes_the_region_dirty_until_release(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.add, ("before",))
        root.call(c, Cell.fail, ("async",))
        root.call(c, Cell.add, ("skipped",))
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(c, Cell.items)
        assert str(info.value.__cause__) == "async"
        root.call(c, Cell.add, ("skipped too",))
        with pytest.raises(rt.DirtyRegionError):
            root.query(c, Cell.items)
    with root.reserve((c,)):                            # release cleaned it
        root.call(c, Cell.add, ("after",))
        assert root.query(c, Cell.items) == ["before", "after"]
    assert h.finish() == 0
    assert h.err.getvalue() == ""                       # it was delivered: not lost


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


def test_uncaught_exception_in_root_is_a_failure():
    import io
    err = io.StringIO()

    class Root:
        def make(self):
            raise RuntimeError("root failed")
    assert rt.run_main(Root, Root.make, stderr=err, stdout=io.StringIO()) == 3
    assert "root failed" in err.getvalue()
