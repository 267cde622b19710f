"""Stress: 1,000 processors and 1,000,000 separate calls in all: nothing lost, nothing
reordered within a private queue, no false deadlock report (the detector runs at a short
tick throughout)."""

import pytest

from rt_helpers import Cell, spawn

W = ("STRESS", "consume", "stress.e", 1)


class Acc:
    __slots__ = ("_region_", "total", "last")

    def make(self):
        self.total = 0
        self.last = {}

    def add(self, client, seq):
        assert self.last.get(client, -1) < seq  # in order per client
        self.last[client] = seq
        self.total += 1


def _hammer(here, me, accs, rounds):
    seq = 0
    for _ in range(rounds):
        for a in accs:
            with here.reserve((a,)):
                for _ in range(10):
                    here.call(a, Acc.add, (me, seq))
                    seq += 1


@pytest.mark.slow  # 5 to 12 s: outside the quick selection
def test_thousand_processors_million_calls(harness):
    h = harness(deadlock_tick=0.02)
    root = h.root
    accs = [root.new_separate(Acc, Acc.make) for _ in range(1000)]
    clients = 20
    rounds = 5  # 20 clients x 5 rounds x 1000 accs x 10 = 1,000,000
    for me in range(clients):
        spawn(root, _hammer, me, accs, rounds)
    assert h.finish() == 0, h.err.getvalue()
    assert sum(a.total for a in accs) == 1_000_000
    assert h.err.getvalue() == ""


def _consumer(here, buf, n, got):
    for _ in range(n):
        pre = [(lambda: here.query(buf, Cell.get) > 0, (0,), "nonempty", W)]
        with here.reserve((buf,), pre=pre):
            got.append(here.query(buf, Cell.get))
            here.call(buf, Cell.set, (0,))


def _producer(here, buf, items):
    for item in items:
        pre = [(lambda: here.query(buf, Cell.get) == 0, (0,), "empty", W)]
        with here.reserve((buf,), pre=pre):
            here.call(buf, Cell.set, (item,))


def test_wait_conditions_under_load_no_false_deadlock(harness):
    h = harness(deadlock_tick=0.01)
    root = h.root
    buf = root.new_separate(Cell, Cell.make)
    got = []
    for i in range(8):
        spawn(root, _consumer, buf, 250, got)
        spawn(root, _producer, buf, range(1 + i * 250, 1 + (i + 1) * 250))
    assert h.finish() == 0, h.err.getvalue()
    assert sorted(got) == list(range(1, 2001))


def test_many_idle_processors_cost_no_threads(h):
    """10,000 processors (each ran its creation call) share a small pool of threads."""
    import tracemalloc

    root = h.root
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    cells = [root.new_separate(Cell, Cell.make) for _ in range(10_000)]
    per_processor = (tracemalloc.get_traced_memory()[0] - before) / len(cells)
    tracemalloc.stop()
    assert h.finish() == 0
    assert len(h.rt.workers) <= 64  # threads ever started, not one per processor
    assert per_processor < 2_000  # bytes, including the object and its lock
