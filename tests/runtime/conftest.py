"""Fixtures for the runtime tests: a fresh runtime per test, run by the test's thread as
the root processor, finished (and checked for stray failures) at teardown."""

import io

import pytest

from scoopc.runtime.main import finish, start


class Harness:
    def __init__(self, **options):
        options.setdefault("deadlock_tick", 0.05)
        self.out, self.err = io.StringIO(), io.StringIO()
        self.rt, self.root = start(stdout=self.out, stderr=self.err, **options)
        self.status = None

    def finish(self):
        """Wait for termination like run_main; returns the exit status (once)."""
        if self.status is None:
            self.status = finish(self.rt, self.root)
        return self.status


@pytest.fixture
def harness():
    made = []

    def make(**options):
        h = Harness(**options)
        made.append(h)
        return h

    yield make
    for h in made:
        h.finish()


@pytest.fixture
def h(harness):
    """The default harness; its teardown asserts the run ended cleanly."""
    hh = harness()
    yield hh
    status = hh.finish()
    assert status == 0, hh.err.getvalue()
