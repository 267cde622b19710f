"""Lock passing decided at run time: a separate call with a non-Void reference argument in
a region the client holds is synchronous and hands all the client's locks to the supplier;
callbacks into the client's region run while it waits; dirtiness survives."""

import threading

import pytest

import scoopc.runtime as rt

from rt_helpers import Cell, spawn


class Server:
    def make(self):
        self.seen = []

    def visit(self, who):
        """`who: separate CELL` — a callback into the caller's region."""
        here = self._region_
        here.call(who, Cell.add, ("visited",))
        self.seen.append(here.query(who, Cell.items))

    def use_other(self, who, other):
        """Uses `other`, which only the client holds: possible only with its locks."""
        here = self._region_
        here.call(other, Cell.add, ("from server",))
        return here.query(other, Cell.items)

    def read_other(self, who, other):
        return self._region_.query(other, Cell.get)

    def note(self, x):
        self.seen.append(x)


def test_reference_argument_makes_the_call_synchronous_with_callbacks(h):
    root = h.root
    s = root.new_separate(Server, Server.make)
    mine = root.new(Cell)
    mine.make()
    with root.reserve((s,)):
        root.call(s, Server.visit, (mine,))  # a command, yet synchronous
        assert mine.log == ["visited"]  # the callback ran while we waited
        assert s.seen == [["visited"]]


def test_passed_locks_include_the_clients_reservations(h):
    root = h.root
    s = root.new_separate(Server, Server.make)
    other = root.new_separate(Cell, Cell.make)
    mine = root.new(Cell)
    mine.make()
    with root.reserve((s, other)):
        root.call(other, Cell.add, ("client",))
        assert root.query(s, Server.use_other, (mine, other)) == ["client", "from server"]
        root.call(other, Cell.add, ("client again",))  # still our private queue
        assert root.query(other, Cell.items) == ["client", "from server", "client again"]


def test_non_reference_and_void_arguments_do_not_pass_locks(h):
    root = h.root
    s = root.new_separate(Server, Server.make)
    gate, entered = threading.Event(), threading.Event()
    with root.reserve((s,)):
        root.call(s, Cell.gate, (gate, entered))  # any routine works on any object
        root.call(s, Server.note, (None,))
        root.call(s, Server.note, (3,))
        assert entered.wait(10)  # make has run, the gate holds s
        assert s.seen == []  # asynchronous: nothing ran yet
        gate.set()
        root.query(s, Cell.thread)
    assert s.seen == [None, 3]


def test_tuple_argument_passes_locks(h):
    root = h.root
    s = root.new_separate(Server, Server.make)
    with root.reserve((s,)):
        root.call(s, Server.note, ((1, 2),))
        assert s.seen == [(1, 2)]


def test_dirtiness_survives_lock_passing(h):
    root = h.root
    s = root.new_separate(Server, Server.make)
    other = root.new_separate(Cell, Cell.make)
    mine = root.new(Cell)
    mine.make()
    with root.reserve((s, other)):
        root.call(other, Cell.fail, ("boom",))
        with pytest.raises(rt.DirtyRegionError) as info:
            root.query(s, Server.read_other, (mine, other))
        assert isinstance(info.value.__cause__, ValueError)


def test_callback_from_another_processor_client(h):
    """A processor (not the root) passes its locks and gets called back on its region."""
    root = h.root
    s = root.new_separate(Server, Server.make)
    done = []

    def client(here):
        mine = here.new(Cell)
        mine.make()
        with here.reserve((s,)):
            here.call(s, Server.visit, (mine,))
        done.append(mine.log)

    spawn(root, client)
    assert h.finish() == 0
    assert done == [["visited"]]


class Greeter:
    def make_with(self, who):
        """Creation procedure calling back the creator's object: needs the creator's locks."""
        here = self._region_
        here.call(who, Cell.add, ("created",))


def test_separate_creation_with_a_reference_argument_passes_locks(h):
    root = h.root
    mine = root.new(Cell)
    mine.make()
    g = root.new_separate(Greeter, Greeter.make_with, (mine,))
    assert mine.log == ["created"]  # synchronous: done when creation returned
    assert g._region_ is not root
