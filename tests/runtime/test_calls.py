"""Separate creation, passive regions, asynchronous commands, synchronous queries, and
the private queues: calls of one client within one reservation run in order, never
interleaved with another client's."""

import threading

import scoopc.runtime as rt

from rt_helpers import Cell, Runner, cell_inc, result_of, spawn


def test_separate_creation_makes_a_new_region(h):
    root = h.root
    a = root.new_separate(Cell, Cell.make, (5,))
    b = root.new_separate(Cell, Cell.make, (6,))
    assert a._region_ is not root and b._region_ is not a._region_
    assert not a._region_.passive
    with root.reserve((a, b)):
        assert root.query(a, Cell.get) == 5 and root.query(b, Cell.get) == 6
        # a query run by the client itself still runs on behalf of the supplier's region
        assert root.query(a, Cell.region_of_caller) is a._region_


def test_non_separate_creation_stays_in_the_region(h):
    c = h.root.new(Cell)
    c.make(3)
    assert c._region_ is h.root
    h.root.call(c, Cell.set, (4,))  # own region: a plain call
    assert c.value == 4


def test_command_is_asynchronous_and_query_waits(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    gate, entered = threading.Event(), threading.Event()
    with root.reserve((c,)):
        root.call(c, Cell.gate, (gate, entered))
        root.call(c, Cell.set, (7,))
        assert entered.wait(10)  # the supplier runs the gate on its own thread...
        assert c.value == 0  # ...and has not reached `set` yet: we did not wait
        gate.set()
        assert root.query(c, Cell.get) == 7  # wait by necessity


def test_passive_region_runs_calls_on_the_client_thread(h):
    root = h.root
    p = root.new_passive(Cell, Cell.make, (1,))
    assert p._region_.passive
    with root.reserve((p,)):
        root.call(p, Cell.set, (9,))
        assert p.value == 9  # synchronous: done before call returned
        assert root.query(p, Cell.thread) == threading.get_ident()
        assert root.query(p, Cell.region_of_caller) is p._region_


def test_calls_within_one_reservation_run_in_order(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        for i in range(500):
            root.call(c, Cell.add, (i,))
        assert root.query(c, Cell.items) == list(range(500))


def _client_a(here, c, a_reserved, b_logged):
    with here.reserve((c,)):
        here.call(c, Cell.add, ("a1",))
        a_reserved.set()
        assert b_logged.wait(10)  # B has logged its calls meanwhile
        here.call(c, Cell.add, ("a2",))
        here.call(c, Cell.add, ("a3",))


def _client_b(here, c, a_reserved, b_logged):
    assert a_reserved.wait(10)
    with here.reserve((c,)):  # never blocks, though A holds c
        here.call(c, Cell.add, ("b1",))
        here.call(c, Cell.add, ("b2",))
        b_logged.set()


def test_no_interleaving_between_clients(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    a_reserved, b_logged = threading.Event(), threading.Event()
    spawn(root, _client_a, c, a_reserved, b_logged)
    spawn(root, _client_b, c, a_reserved, b_logged)
    assert h.finish() == 0
    assert c.log == ["a1", "a2", "a3", "b1", "b2"]


def _bump_many(here, c, n):
    for _ in range(n):
        with here.reserve((c,)):
            here.call(c, cell_inc)
            here.call(c, Cell.add, (1,))


def test_many_clients_nothing_lost(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    for _ in range(8):
        spawn(root, _bump_many, c, 300)
    assert h.finish() == 0
    assert c.value == 2400 and len(c.log) == 2400


def test_runner_results(h):
    r = spawn(h.root, lambda here, x: x * 2, 21)
    assert result_of(h.root, r) == 42
    assert isinstance(r, Runner)


def test_client_serves_closed_leaf_sessions_ahead_in_order(h):
    """A client whose private queue waits behind closed sessions of leaf calls runs them
    itself, in order, before its own query (no thread hand-off, same result)."""
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    entered = threading.Event()
    hold = threading.Event()
    logged = threading.Event()

    def holder(here):  # keeps c reserved (open) until told
        with here.reserve((c,)):
            here.call(c, Cell.add, ("h",))
            entered.set()
            assert hold.wait(10)

    def leafer(here, i):
        with here.reserve((c,)):
            here.call(c, cell_inc)
            here.call(c, cell_inc)
        if i == 4:
            logged.set()

    spawn(root, holder)
    assert entered.wait(10)
    seq = [threading.Event() for _ in range(5)]
    for i in range(5):
        spawn(root, lambda here, i=i: (i == 0 or seq[i - 1].wait(10), leafer(here, i), seq[i].set()))
    assert logged.wait(10)  # five closed sessions queued behind the holder
    with root.reserve((c,)):
        hold.set()
        assert root.query(c, Cell.get) == 10
        assert root.query(c, Cell.items) == ["h"]


def test_failure_in_another_clients_session_does_not_dirty_ours(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    hold, entered, logged = threading.Event(), threading.Event(), threading.Event()

    @rt.leaf
    def leaf_fail(cell):
        raise ValueError("theirs")

    def holder(here):
        with here.reserve((c,)):
            here.call(c, Cell.add, ("h",))
            entered.set()
            assert hold.wait(10)

    def failer(here):
        with here.reserve((c,), where=("F", "f", "f.e", 3)):
            here.call(c, leaf_fail)
        logged.set()

    spawn(root, holder)
    assert entered.wait(10)
    spawn(root, failer)
    assert logged.wait(10)
    with root.reserve((c,)):
        hold.set()
        assert root.query(c, Cell.items) == ["h"]  # no DirtyRegionError for us
    assert h.finish() == 0
    assert "theirs" in h.err.getvalue() and "f.e:3" in h.err.getvalue()


class Spinner:
    def make(self):
        self.spins = 0

    def spin_until(self, flag_cell, started):
        """A long computation with no runtime call: it ends only once another processor
        has run (it reads a plain attribute that another processor's command sets)."""
        import time

        started.set()
        deadline = time.monotonic() + 10
        while not flag_cell.value and time.monotonic() < deadline:
            self.spins += 1
        assert flag_cell.value, "the other processor never ran"


def _set_flag(here, flag):
    with here.reserve((flag,)):
        here.call(flag, Cell.set, (1,))


def test_long_computation_does_not_stop_other_processors(h):
    root = h.root
    flag = root.new_separate(Cell, Cell.make)
    s = root.new_separate(Spinner, Spinner.make)
    started = threading.Event()
    with root.reserve((s,)):
        root.call(s, Spinner.spin_until, (flag, started))  # flag not held: asynchronous
    assert started.wait(10)
    spawn(root, _set_flag, flag)  # runs on another processor while s computes
    assert h.finish() == 0
    assert h.err.getvalue() == "" and s.spins > 0


class Busy:
    """A processor that reserves and calls, never blocking, until another one sets a flag."""

    def make(self):
        self.timed_out = False

    def loop(self, flag, counter, started):
        import time

        here = self._region_
        started.set()
        deadline = time.monotonic() + 3  # a bound: the flag comes within milliseconds
        while not flag.value:
            if time.monotonic() > deadline:
                self.timed_out = True
                return
            with here.reserve((counter,)):
                here.call(counter, cell_inc)


def test_busy_processors_handing_the_permit_around_do_not_starve_a_runnable_one(h):
    """Three processors that only yield their run permit to each other at reservation entry
    must not keep a newly scheduled processor from running (it gets a worker within a few
    permit slices, not when they stop)."""
    root = h.root
    flag = root.new_separate(Cell, Cell.make)
    started, busies = [], []
    for _ in range(3):
        busy = root.new_separate(Busy, Busy.make)
        busies.append(busy)
        counter = root.new_separate(Cell, Cell.make)
        started.append(threading.Event())
        with root.reserve((busy,)):
            root.call(busy, Busy.loop, (flag, counter, started[-1]))
    assert all(e.wait(10) for e in started)
    spawn(root, _set_flag, flag)
    assert h.finish() == 0, h.err.getvalue()
    assert not any(b.timed_out for b in busies), "the runnable processor starved"


def _block_outside(here, event):
    event.wait(10)  # a blocking external call (I/O, a transport) in user code


def _open(here, event):
    event.set()


def test_processors_blocked_outside_the_runtime_do_not_keep_a_scheduled_one_waiting(h):
    """A blocks in an external call and the root waits outside the runtime too: B, already
    scheduled, still gets a thread and runs (it is what the root waits for)."""
    root = h.root
    a_may_go, b_ran = threading.Event(), threading.Event()
    spawn(root, _block_outside, a_may_go)
    spawn(root, _open, b_ran)
    ran = b_ran.wait(5)  # the root blocks outside the runtime
    a_may_go.set()
    assert ran, "the scheduled processor never ran"
