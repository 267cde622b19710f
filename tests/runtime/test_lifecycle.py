"""Termination, Ctrl-C shutdown with hooks, deadlock reports, the live dump, and
structured ownership of threads."""

import io
import os
import signal
import threading
import time

import pytest

import scoopc.runtime as rt
from scoopc.runtime import snapshot

from rt_helpers import Cell, spawn

W_A = ("NODE", "ping", "ring.e", 10)
W_B = ("NODE", "pong", "ring.e", 20)


class Chain:
    """Each link passes a countdown on to the next one: work outlives the root routine."""

    def make(self, nxt, log):
        self.nxt, self.log = nxt, log

    def set_next(self, nxt):
        self.nxt = nxt

    def step(self, n):
        self.log.append(n)
        if n and self.nxt is not None:
            here = self._region_
            with here.reserve((self.nxt,)):
                here.call(self.nxt, Chain.step, (n - 1,))


class Root:
    log = None

    def make(self, links):
        here = self._region_
        Root.log = log = []
        ring = [here.new_separate(Chain, Chain.make, (None, log)) for _ in range(links)]
        for i, link in enumerate(ring):
            with here.reserve((link,)):
                here.call(link, Chain.set_next, (ring[(i + 1) % links],))
        with here.reserve((ring[0],)):
            here.call(ring[0], Chain.step, (links * 50,))


def test_run_main_waits_until_every_processor_is_idle():
    out, err = io.StringIO(), io.StringIO()
    assert rt.run_main(Root, Root.make, (10,), stdout=out, stderr=err) == 0
    assert Root.log == list(range(500, -1, -1)) and err.getvalue() == ""


def test_ctrl_c_runs_shutdown_hooks_and_stops_processors():
    err = io.StringIO()
    events = []
    blocked = threading.Event()

    class App:
        def make(self):
            here = self._region_
            rt.add_shutdown_hook(lambda: events.append("motors stopped"))
            rt.add_shutdown_hook(lambda: events.append("second hook first"))
            c = here.new_separate(Cell, Cell.make)
            ev = rt.current().watch_blocks(lambda b: b.kind == "wait")

            def waiter(h2):
                pre = [(lambda: h2.query(c, Cell.get) > 0, (0,), "never", None)]
                with h2.reserve((c,), pre=pre):
                    events.append("should not run")

            spawn(here, waiter)
            assert ev.wait(10)
            blocked.set()
            raise KeyboardInterrupt  # what the SIGINT handler raises in the main thread

    assert rt.run_main(App, App.make, stderr=err, stdout=io.StringIO()) == 130
    assert blocked.is_set()
    assert events == ["second hook first", "motors stopped"]


class Node(Cell):
    def ping(self, other, barrier):
        here = self._region_
        barrier.wait(10)  # both are inside their routines
        with here.reserve((other,)):
            return here.query(other, Cell.get, (), W_A)


def test_cycle_of_synchronous_calls_is_reported_quickly(harness):
    h = harness()
    root = h.root
    a = root.new_separate(Node, Node.make)
    b = root.new_separate(Node, Node.make)
    barrier = threading.Barrier(2)
    with root.reserve((a,)):  # not (a, b): passing b would pass our locks
        root.call(a, Node.ping, (b, barrier))
    with root.reserve((b,)):
        root.call(b, Node.ping, (a, barrier))
    t0 = time.monotonic()
    assert h.finish() == 3
    assert time.monotonic() - t0 < 5.0  # found, not waited out (the detector looks every 0.4 s or so)
    err = h.err.getvalue()
    assert "deadlock: a cycle of synchronous calls" in err
    for x, y in ((a, b), (b, a)):
        assert (f"{x._region_!r} in NODE.ping (ring.e:10) waits for the result of Cell.get on {y._region_!r}") in err
    (event,) = [e for e in snapshot.events(h.rt) if e.kind == "deadlock"]  # what /scoop/events sends
    assert event.text.startswith("deadlock: a cycle of synchronous calls")
    assert event.text.count("NODE.ping (ring.e:10)") == 2


def test_wait_condition_deadlock_is_reported_but_not_while_an_outside_client_is_open(harness):
    h = harness()
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    src = rt.outside_client("sensor")
    waiting = h.rt.watch_blocks(lambda b: b.kind == "wait")

    def waiter(here):
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "has_message", W_B)]
        with here.reserve((c,), pre=pre):
            pass

    spawn(root, waiter)
    assert waiting.wait(10)
    monitor = h.rt.monitor
    for _ in range(3):  # run the detector by hand: no report while open
        monitor.check()
    assert not h.rt.failures
    src.close()
    t0 = time.monotonic()
    assert h.finish() == 3
    assert time.monotonic() - t0 < 5.0  # found, not waited out (the detector looks every 0.4 s or so)
    assert "waits on wait condition has_message" in h.err.getvalue()


def test_robot_waiting_for_its_first_message_is_not_deadlocked(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    src = rt.outside_client("odometry")
    waiting = h.rt.watch_blocks(lambda b: b.kind == "wait")
    got = []

    def controller(here):
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "has_message", W_B)]
        with here.reserve((c,), pre=pre):
            got.append(here.query(c, Cell.get))

    spawn(root, controller)
    assert waiting.wait(10)
    for _ in range(3):
        h.rt.monitor.check()
    src.call(c, Cell.set, (42,))
    src.close()
    assert h.finish() == 0
    assert got == [42]


def test_dump_names_blocked_processors(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    src = rt.outside_client("keep-alive")
    waiting = h.rt.watch_blocks(lambda b: b.kind == "wait")

    def waiter(here):
        here.push_frame(("APP", "wait_for_data", "app.e", 33))
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "ready", None)]
        with here.reserve((c,), pre=pre):
            pass
        here.pop_frame()

    spawn(root, waiter)
    assert waiting.wait(10)
    text = rt.dump()
    assert "APP.wait_for_data (app.e:33) waits on wait condition ready over" in text
    src.call(c, Cell.set, (1,))
    src.close()


def test_sigusr1_prints_the_dump():
    if not hasattr(signal, "SIGUSR1"):
        return
    err = io.StringIO()

    class App:
        def make(self):
            os.kill(os.getpid(), signal.SIGUSR1)
            self._region_.sleep(1_000_000)  # let the handler run in the main thread

    assert rt.run_main(App, App.make, stderr=err, stdout=io.StringIO()) == 0
    assert "scoop runtime dump" in err.getvalue()


def test_every_worker_is_joined(h):
    root = h.root
    for _ in range(20):
        spawn(root, lambda here: None)
    assert h.finish() == 0
    assert all(not w.thread.is_alive() for w in h.rt.workers)
    assert h.rt.monitor.thread.is_alive() is False


def test_ctrl_c_stops_a_processor_that_keeps_calling():
    running = threading.Event()

    class App:
        def make(self):
            here = self._region_
            c = here.new_separate(Cell, Cell.make)

            def forever(h2):
                while True:
                    with h2.reserve((c,)):
                        h2.call(c, Cell.set, (1,))
                    running.set()

            spawn(here, forever)
            assert running.wait(10)
            raise KeyboardInterrupt

    t0 = time.monotonic()
    err = io.StringIO()
    assert rt.run_main(App, App.make, stderr=err, stdout=io.StringIO()) == 130
    assert time.monotonic() - t0 < 5 and "still running" not in err.getvalue()


def test_deadlock_on_passive_regions_is_reported(harness):
    """Two clients each hold one passive region and ask for the other's: a cycle of
    processors waiting for their turn."""
    h = harness()
    root = h.root
    p = root.new_passive(Cell, Cell.make)
    q = root.new_passive(Cell, Cell.make)
    barrier = threading.Barrier(2)

    def client(here, first, second):
        with here.reserve((first,)):
            here.call(first, Cell.set, (1,))
            barrier.wait(10)
            with here.reserve((second,), where=W_B):
                here.query(second, Cell.get, (), W_B)

    spawn(root, client, p, q)
    spawn(root, client, q, p)
    assert h.finish() == 3
    err = h.err.getvalue()
    assert "deadlock: a cycle" in err and err.count("waits for its turn on passive") == 2


def test_sleepers_are_not_deadlocked(harness):
    h = harness(deadlock_tick=0.01)
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    waiting = h.rt.watch_blocks(lambda b: b.kind == "wait")

    def waiter(here):
        pre = [(lambda: here.query(c, Cell.get) > 0, (0,), "set", W_B)]
        with here.reserve((c,), pre=pre):
            pass

    spawn(root, waiter)
    assert waiting.wait(10)
    root.sleep(100_000_000)  # a sleeper: time may still change things
    assert not h.rt.failures
    with root.reserve((c,)):
        root.call(c, Cell.set, (1,))
    assert h.finish() == 0


@rt.leaf
def _interrupted(cell):
    """Ctrl-C arriving while the main thread runs this leaf on the supplier's behalf (the
    supplier's own thread never gets SIGINT, so it just counts)."""
    if threading.current_thread() is threading.main_thread():
        raise KeyboardInterrupt
    cell.value += 1


@pytest.mark.parametrize("entry", ["call", "leaf_call"])
def test_ctrl_c_inside_a_client_executed_leaf_command_stops_the_program(entry):
    """A leaf command the root runs itself on a claimed supplier is still the main thread:
    Ctrl-C there ends the program (hooks, 130); it is not a failure of the call, lost."""
    events = []

    class App:
        def make(self):
            here = self._region_
            rt.add_shutdown_hook(lambda: events.append("hook"))
            c = here.new_separate(Cell, Cell.make)
            with here.reserve((c,)):
                here.query(c, Cell.get)  # waits until c is idle (created)
            for _ in range(1000):  # so the root runs the leaf itself, at once
                with here.reserve((c,)):
                    getattr(here, entry)(c, _interrupted, ())
            events.append("never interrupted")

    err = io.StringIO()
    assert rt.run_main(App, App.make, stderr=err, stdout=io.StringIO()) == 130
    assert events == ["hook"] and "lost" not in err.getvalue()
