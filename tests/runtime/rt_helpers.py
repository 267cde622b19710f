"""Small classes written the way generated code uses the runtime, shared by the tests."""

import threading

import scoopc.runtime as rt

GATE_TIMEOUT = 10  # a bound so a broken runtime fails a test instead of hanging it


class Cell:
    """A supplier with a value and a log of commands."""

    def make(self, value=0):
        self.value = value
        self.log = []

    def add(self, item):
        self.log.append(item)

    def set(self, v):
        self.value = v

    def get(self):
        return self.value

    def items(self):
        return list(self.log)

    def gate(self, event, mark=None):
        """Block this processor's thread until the test opens `event`."""
        if mark is not None:
            mark.set()
        assert event.wait(GATE_TIMEOUT), "gate never opened"

    def fail(self, message):
        raise ValueError(message)

    def region_of_caller(self):
        return self._region_

    def thread(self):
        return threading.get_ident()


@rt.leaf
def cell_inc(cell):
    cell.value += 1


class Runner:
    """A processor that runs a test function `fn(here, *args)` as its routine."""

    def make(self):
        self.result = None

    def run(self, fn, *args):
        self.result = fn(self._region_, *args)


def spawn(here, fn, *args):
    """New processor running `fn(its_here, *args)` asynchronously; returns the Runner."""
    r = here.new_separate(Runner, Runner.make)
    with here.reserve((r,)):
        here.call(r, Runner.run, (fn,) + args)
    return r


def result_of(here, runner):
    with here.reserve((runner,)):
        return here.query(runner, _result)


def _result(runner):
    return runner.result


def gated_cell(root):
    """A new Cell whose processor is held busy (in `Cell.gate`) until the returned event is set."""
    c = root.new_separate(Cell, Cell.make)
    gate, entered = threading.Event(), threading.Event()
    with root.reserve((c,)):
        root.call(c, Cell.gate, (gate, entered))
    assert entered.wait(10)
    return c, gate
