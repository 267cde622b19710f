"""once per region / process / object, untorn and tagged output, agents."""

import threading

import scoopc.runtime as rt

from rt_helpers import Cell, spawn

counter = {"n": 0}


def _fresh():
    counter["n"] += 1
    return counter["n"]


class Holder:
    def make(self):
        pass

    def my_once(self):
        return self._region_.once("Holder.my_once", _fresh)

    def obj_once(self):
        return rt.once_object(self, "Holder.obj_once", _fresh)


def test_once_is_per_region_not_per_thread(h):
    root = h.root
    a = root.new_separate(Holder, Holder.make)
    b = root.new_separate(Holder, Holder.make)
    mine = root.new(Holder)
    with root.reserve((a, b)):
        va = root.query(a, Holder.my_once)  # run by us, on a's behalf
        vb = root.query(b, Holder.my_once)
        assert root.query(a, Holder.my_once) == va
    assert va != vb
    assert mine.my_once() not in (va, vb)  # the root region has its own
    seen = []

    def other_client(here):  # another thread, same region a
        with here.reserve((a,)):
            seen.append(here.query(a, Holder.my_once))

    spawn(root, other_client)
    assert h.finish() == 0
    assert seen == [va]


def test_once_process_and_object(h):
    root = h.root
    v1 = rt.once_process("k", _fresh)
    got = []
    spawn(root, lambda here: got.append(rt.once_process("k", _fresh)))
    x, y = root.new(Holder), root.new(Holder)
    assert x.obj_once() == x.obj_once() != y.obj_once()
    assert h.finish() == 0
    assert got == [v1]


def test_once_failure_is_remembered(h):
    def boom():
        raise ValueError("once failed")

    for _ in range(2):
        try:
            h.root.once("boom", boom)
        except ValueError as e:
            assert str(e) == "once failed"
        else:
            raise AssertionError("no exception")


class Printer:
    def make(self):
        pass

    def say(self, text, n):
        for _ in range(n):
            self._region_.print(text)


def test_output_is_never_torn(harness):
    h = harness()
    root = h.root
    lines = ["".join(chr(65 + i) for _ in range(300)) + "\n" for i in range(8)]
    for line in lines:
        p = root.new_separate(Printer, Printer.make)
        with root.reserve((p,)):
            root.call(p, Printer.say, (line, 200))
    assert h.finish() == 0
    out = h.out.getvalue().splitlines(keepends=True)
    assert len(out) == 1600 and set(out) == set(lines)


def test_trace_processors_prefixes_every_line(harness):
    h = harness(trace_processors=True)
    root = h.root
    p = root.new_separate(Printer, Printer.make)
    with root.reserve((p,)):
        root.call(p, Printer.say, ("a\nb", 1))
        root.call(p, Printer.say, ("c\n", 1))
    root.print("root line\n")
    root.print("unfinished")
    assert h.finish() == 0
    lines = h.out.getvalue().splitlines()
    pid = p._region_.id
    assert [line for line in lines if line.startswith(f"[P{pid}] ")] == [f"[P{pid}] a", f"[P{pid}] bc"]
    assert "[P1] root line" in lines and lines[-1] == "[P1] unfinished"


def test_agents_on_separate_targets(h):
    root = h.root
    c = root.new_separate(Cell, Cell.make)
    gate, entered = threading.Event(), threading.Event()
    ag = rt.Agent(c, Cell.add, ("closed",))
    assert ag._region_ is c._region_
    with root.reserve((c,)):
        root.call(c, Cell.gate, (gate, entered))
        root.call(ag, rt.Agent.call, (None,))  # asynchronous
        assert entered.wait(10)
        assert c.log == []
        gate.set()
        assert root.query(c, Cell.items) == ["closed"]
        setter = rt.Agent(c, Cell.set)
        root.call(setter, rt.Agent.call, ((9,),))  # a tuple passes locks: synchronous
        assert c.value == 9
