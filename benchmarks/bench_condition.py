"""condition (SCOOP/Qs): workers wait until a shared variable has their parity, then increment it.

Half the workers want it even, half odd, so the two groups strictly alternate.
Baseline: one threading.Condition, wait_for on the parity, notify_all after each change.
"""
import threading

from common import check, join_all, start_all

SIZES = {
    "full": {"workers": 4, "iters": 100_000},
    "quick": {"workers": 4, "iters": 10_000},
    "smoke": {"workers": 4, "iters": 100},
}


def ops(workers, iters):
    return workers * iters


# --- hand-written threading --------------------------------------------------

class SharedVariable:
    def __init__(self):
        self.changed = threading.Condition()
        self.value = 0


def _thread_worker(shared, parity, iters):
    for _ in range(iters):
        with shared.changed:
            shared.changed.wait_for(lambda: shared.value % 2 == parity)
            shared.value += 1
            shared.changed.notify_all()


def baseline(workers, iters):
    shared = SharedVariable()
    targets = [(_thread_worker, (shared, i % 2, iters)) for i in range(workers)]
    join_all(start_all(targets))
    check("condition baseline value", shared.value, workers * iters)
