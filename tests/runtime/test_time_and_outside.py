"""The runtime clock (virtual and real), timers, and outside clients logging commands."""

import threading

import scoopc.runtime as rt
from scoopc.runtime.sched import BUSY_CALLS, BUSY_QUANTUM_NS

from rt_helpers import Cell, gated_cell

SECOND = 1_000_000_000


class Sleeper:
    def make(self):
        self.woke = []

    def nap(self, ns, label):
        self._region_.sleep(ns)
        self.woke.append((label, rt.now_ns()))


def test_virtual_clock_jumps_when_everyone_waits(harness):
    h = harness(virtual_clock=True)
    root = h.root
    s1 = root.new_separate(Sleeper, Sleeper.make)
    s2 = root.new_separate(Sleeper, Sleeper.make)
    with root.reserve((s1, s2)):
        root.call(s1, Sleeper.nap, (3600 * SECOND, "hour"))
        root.call(s2, Sleeper.nap, (60 * SECOND, "minute"))
    root.sleep(10 * SECOND)
    assert rt.now_ns() == 10 * SECOND
    assert h.finish() == 0
    assert s2.woke == [("minute", 60 * SECOND)] and s1.woke == [("hour", 3600 * SECOND)]


def test_virtual_clock_waits_for_running_processors(harness):
    """Time does not jump while some processor still computes."""
    h = harness(virtual_clock=True)
    root = h.root
    gate, entered = threading.Event(), threading.Event()
    s = root.new_separate(Sleeper, Sleeper.make)
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c, s)):
        root.call(c, Cell.gate, (gate, entered))
        root.call(s, Sleeper.nap, (5 * SECOND, "nap"))
    asleep = h.rt.watch_blocks(lambda b: b.kind == "sleep")
    assert entered.wait(10) and asleep.wait(10)
    assert rt.now_ns() == 0 and s.woke == []
    gate.set()
    assert h.finish() == 0
    assert s.woke == [("nap", 5 * SECOND)]


def test_timers_fire_in_order_and_cancel(harness):
    h = harness(virtual_clock=True)
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    rt.call_later(3 * SECOND, c, Cell.add, ("three",))
    rt.call_later(1 * SECOND, c, Cell.add, ("one",))
    t = rt.call_later(2 * SECOND, c, Cell.add, ("tick",), period_ns=2 * SECOND)
    dropped = rt.call_later(1 * SECOND, c, Cell.add, ("cancelled",))
    dropped.cancel()

    class Stopper:
        def make(self):
            pass

        def stop(self, timer):
            timer.cancel()

    st = root.new_separate(Stopper, Stopper.make)
    rt.call_later(7 * SECOND, st, Stopper.stop, (t,))
    assert h.finish() == 0
    assert c.log == ["one", "tick", "three", "tick", "tick"]
    assert rt_now(h) == 7 * SECOND


def rt_now(h):
    return h.rt.clock.now_ns()


def test_real_clock_sleep(h):
    t0 = rt.now_ns()
    h.root.sleep(20_000_000)
    assert rt.now_ns() - t0 >= 20_000_000


def test_outside_client_logs_in_order_without_blocking(h):
    root = h.root
    c, gate = gated_cell(root)
    src = rt.outside_client("transport")
    logged = threading.Event()

    def transport():  # e.g. a ROS callback thread
        for i in range(1000):
            src.call(c, Cell.add, (i,))
        logged.set()

    t = threading.Thread(target=transport)
    t.start()
    assert logged.wait(10)  # done while c is still busy: it never blocked
    t.join()
    assert c.log == []
    gate.set()
    src.close()
    assert h.finish() == 0
    assert c.log == list(range(1000))


class Stepper:
    """Like a simulator's step: hands data to another processor through an outside client."""

    def make(self, sink):
        self.sink = sink
        self.source = rt.outside_client("stepper")

    def step(self):
        import time

        time.sleep(0.05)  # real time: a sleeper woken too early would get ahead
        self.source.call(self.sink, Cell.add, ("data",))


def test_phase_zero_timers_settle_before_sleepers_wake(harness):
    """With the virtual clock, what a phase-0 timer causes (here: a command it logs elsewhere)
    is over before a sleeper due at the same instant wakes."""
    h = harness(virtual_clock=True)
    root = h.root
    sink = root.new_separate(Cell, Cell.make)
    stepper = root.new_separate(Stepper, Stepper.make, (sink,))
    timer = rt.call_later(SECOND, stepper, Stepper.step, period_ns=SECOND, phase=0)
    seen = []
    for _ in range(3):
        root.sleep(SECOND)
        with root.reserve((sink,)):
            seen.append((rt.now_ns(), root.query(sink, Cell.items)))
    timer.cancel()
    stepper.source.close()
    assert h.finish() == 0
    assert seen == [(k * SECOND, ["data"] * k) for k in (1, 2, 3)]


def test_a_leaf_outside_call_runs_on_the_callers_thread_when_the_processor_is_idle(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        assert root.query(c, Cell.items) == []  # created, and idle once released
    src = rt.outside_client("transport")
    ran_on = []

    def record(cell, item):
        ran_on.append(threading.get_ident())
        cell.log.append(item)

    def transport():
        src.call(c, record, ("here",), leaf=True)

    t = threading.Thread(target=transport)
    t.start()
    t.join(10)
    assert ran_on == [t.ident]  # no worker: the transport's thread ran it
    with root.reserve((c,)):
        assert root.query(c, Cell.items) == ["here"]
    src.close()
    assert h.finish() == 0


def test_a_leaf_outside_call_to_a_busy_processor_is_queued(h):
    root = h.root
    c, gate = gated_cell(root)
    src = rt.outside_client("transport")
    t = threading.Thread(target=lambda: [src.call(c, Cell.add, (i,), leaf=True) for i in range(3)])
    t.start()
    t.join(10)
    assert not t.is_alive() and c.log == []  # logged behind the gate, never waited for it
    gate.set()
    src.close()
    assert h.finish() == 0
    assert c.log == [0, 1, 2]


def test_a_leaf_outside_call_run_by_the_transport_wakes_a_wait_condition(h):
    from test_wait import waiting_consumer

    c, evals, got = waiting_consumer(h)  # a consumer waits for c's value > 0
    src = rt.outside_client("transport")
    t = threading.Thread(target=lambda: src.call(c, Cell.set, (7,), leaf=True))
    t.start()
    t.join(10)
    src.close()
    assert h.finish() == 0
    assert got == [7] and c.value == 0


def busy_until(here, cell, sensor, until_ns):
    """A loop that never sleeps: one reservation of `cell` per iteration until the clock reaches
    `until_ns`; returns the iterations and the clock when `sensor` (set by a timer) was first seen."""
    n, seen_at = 0, None
    while rt.now_ns() < until_ns:
        with here.reserve1(cell):
            here.call(cell, Cell.add, (n,))
        with here.reserve1(sensor):
            if seen_at is None and here.query(sensor, Cell.get):
                seen_at = rt.now_ns()
        n += 1
    return n, seen_at


def busy_run(harness):
    h = harness(virtual_clock=True)
    root = h.root
    cell = root.new_separate(Cell, Cell.make)
    sensor = root.new_separate(Cell, Cell.make)
    rt.call_later(SECOND // 2, sensor, Cell.set, (True,), phase=0)  # as a simulator step
    result = busy_until(root, cell, sensor, SECOND)
    end = rt.now_ns()
    assert h.finish() == 0
    return result, end


def test_virtual_clock_goes_on_under_a_busy_processor(harness):
    """A processor that never sleeps is charged BUSY_QUANTUM_NS every BUSY_CALLS reservations:
    the clock reaches its deadline, the timer's command runs in between, and two runs agree."""
    (n, seen_at), end = busy_run(harness)
    # Two reservations per iteration; the quantum that reaches 1 s comes inside the iteration that
    # began at 0.99 s, which still completes.
    assert n == SECOND // BUSY_QUANTUM_NS * BUSY_CALLS // 2 + 1
    assert seen_at == SECOND // 2 and end == SECOND
    assert busy_run(harness) == ((n, seen_at), end)


def test_a_thread_holds_its_wake_up_lock_whenever_it_is_awake(h, monkeypatch):
    """`block` sleeps on the thread's own wake-up lock: however the sleep ends (a waker, a
    deadline, a waker racing the deadline), the lock is held again afterwards, so the next
    sleep really sleeps."""
    from scoopc.runtime.sched import Block

    root = h.root
    ex = root.exec
    assert ex.slock.locked()
    c = root.new_separate(Cell, Cell.make)
    with root.reserve((c,)):
        root.call(c, Cell.set, (5,))
        assert root.query(c, Cell.get) == 5  # may sleep until c's thread answers
    assert ex.slock.locked()
    root.sleep(1_000_000)  # the deadline ends it
    assert ex.slock.locked()

    def deadline_then_waker(blk, lk):  # the waker comes after the deadline, before `block` looks
        h.rt.unblock(blk)
        return False

    monkeypatch.setattr(h.rt.clock, "real_wait", deadline_then_waker)
    blk = Block("sleep", root, None, None, rt.now_ns() + 1_000_000)
    h.rt.block(ex, blk)
    assert ex.slock.locked()  # taken back
    monkeypatch.undo()
    late = Block("sleep", root, None, None, rt.now_ns() + 1_000_000)
    h.rt.block(ex, late)
    h.rt.unblock(late)  # a waker after the thread went on: ignored
    assert ex.slock.locked()
    t0 = rt.now_ns()
    root.sleep(20_000_000)
    assert rt.now_ns() - t0 >= 20_000_000
