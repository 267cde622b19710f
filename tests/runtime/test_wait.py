"""Wait conditions: clause by clause with the separate arguments used as targets; wait
only when a target of the failing clause was newly reserved (else a precondition
violation); release, sleep until a queried supplier served another client, re-reserve,
re-evaluate; wake-ups are targeted and nothing polls."""

import pytest

import scoopc.runtime as rt

from rt_helpers import Cell, spawn

W = ("TEST", "routine", "test.e", 1)


def _consumer(here, c, evals, got):
    def positive():
        evals.append(1)
        return here.query(c, Cell.get) > 0

    with here.reserve((c,), pre=[(positive, (0,), "positive", W)], where=W):
        got.append(here.query(c, Cell.get))
        here.call(c, Cell.set, (0,))


def _waiting(rt_, proc=None):
    return rt_.watch_blocks(lambda b: b.kind == "wait" and (proc is None or b.proc is proc))


def waiting_consumer(h):
    """A new Cell and a consumer on another processor waiting for its value to be > 0:
    (cell, evaluations of the condition, values got)."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    evals, got = [], []
    waiting = _waiting(h.rt)
    spawn(root, _consumer, c, evals, got)
    assert waiting.wait(10)  # it found the condition false and waits
    return c, evals, got


def test_waits_until_the_condition_holds(h):
    root = h.root
    c, evals, got = waiting_consumer(h)
    assert got == []
    with root.reserve((c,)):
        root.call(c, Cell.set, (5,))
    assert h.finish() == 0
    assert got == [5] and c.value == 0
    assert len(evals) == 2  # once false, once true: no polling


def test_wake_ups_are_targeted(h):
    """Changes to another supplier, and sessions that only query the awaited one, do not
    wake the waiter."""
    root = h.root
    c, other = root.new_separate(Cell, Cell.make), root.new_separate(Cell, Cell.make)
    evals, got = [], []
    waiting = _waiting(h.rt)
    spawn(root, _consumer, c, evals, got)
    assert waiting.wait(10)
    for i in range(20):
        with root.reserve((other,)):
            root.call(other, Cell.set, (i,))
        with root.reserve((c,)):
            assert root.query(c, Cell.get) == 0
    with root.reserve((other,)):
        root.query(other, Cell.get)  # all of the above were served
    assert len(evals) == 1
    with root.reserve((c,)):
        root.call(c, Cell.set, (1,))
    assert h.finish() == 0
    assert len(evals) == 2 and got == [1]


def test_waiting_releases_every_region_it_took(h):
    root = h.root
    c, d = root.new_separate(Cell, Cell.make), root.new_separate(Cell, Cell.make)
    waiting = _waiting(h.rt)

    def waiter(here):
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "c_positive", W)]
        with here.reserve((c, d), pre=pre):
            here.call(d, Cell.add, ("w",))

    spawn(root, waiter)
    assert waiting.wait(10)
    with root.reserve((d,)):  # d is free while the waiter waits
        root.call(d, Cell.add, ("r",))
        assert root.query(d, Cell.items) == ["r"]
    with root.reserve((c,)):
        root.call(c, Cell.set, (1,))
    assert h.finish() == 0
    assert d.log == ["r", "w"]


def test_false_clause_on_a_held_target_is_a_violation(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        with pytest.raises(rt.PreconditionViolation) as info:
            with root.reserve((c,), pre=[(lambda: root.query(c, Cell.get) > 0, (0,), "positive", W)]):
                pass
        assert info.value.tag == "positive" and info.value.where == W
        assert c._region_ in root.held  # the outer reservation is untouched


def test_false_clause_without_separate_target_is_a_violation(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with pytest.raises(rt.PreconditionViolation):
        with root.reserve((c,), pre=[(lambda: True, (0,), "a", W), (lambda: False, (), "b", W)]):
            pass
    assert c._region_ not in root.held


def test_clauses_are_evaluated_in_order_and_all_re_evaluated(harness):
    h = harness()
    root = h.root
    c, d = root.new_separate(Cell, Cell.make), root.new_separate(Cell, Cell.make)
    seen = []
    waiting = _waiting(h.rt)

    def waiter(here):
        def first():
            seen.append("c")
            return here.query(c, Cell.get) > 0

        def second():
            seen.append("d")
            return here.query(d, Cell.get) > 0

        with here.reserve((c, d), pre=[(first, (0,), "c", W), (second, (1,), "d", W)]):
            seen.append("body")

    spawn(root, waiter)
    assert waiting.wait(10)
    assert seen == ["c"]
    with root.reserve((c,)):
        root.call(c, Cell.set, (1,))
    assert h.finish() == 3  # d never becomes positive: deadlock
    assert seen[:3] == ["c", "c", "d"] and "body" not in seen
    assert "wait condition d over P3(Cell)" in h.err.getvalue()


def test_producer_consumer_nothing_lost(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    got = []

    def consumer(here, n):
        for _ in range(n):
            pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "nonempty", W)]
            with here.reserve((c,), pre=pre):
                got.append(here.query(c, Cell.get))
                here.call(c, Cell.set, (0,))

    def producer(here, items):
        for item in items:
            pre = [(lambda: here.query(c, Cell.get) == 0, (0,), "empty", W)]
            with here.reserve((c,), pre=pre):
                here.call(c, Cell.set, (item,))

    spawn(root, consumer, 100)
    spawn(root, consumer, 100)
    spawn(root, producer, range(1, 101))
    spawn(root, producer, range(101, 201))
    assert h.finish() == 0
    assert sorted(got) == list(range(1, 201))
