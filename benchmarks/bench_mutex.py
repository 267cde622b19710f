"""mutex (SCOOP/Qs): N workers each reserve a shared counter M times and increment it.

Baseline: threads incrementing a counter under a threading.Lock.
"""
import threading

from common import check, join_all, start_all

SIZES = {
    "full": {"workers": 32, "iters": 50_000},
    "quick": {"workers": 32, "iters": 5_000},
    "smoke": {"workers": 4, "iters": 200},
}


def ops(workers, iters):
    return workers * iters


# --- hand-written threading --------------------------------------------------

class LockedCounter:
    def __init__(self):
        self.lock = threading.Lock()
        self.value = 0


def _thread_worker(counter, iters):
    for _ in range(iters):
        with counter.lock:
            counter.value += 1


def baseline(workers, iters):
    counter = LockedCounter()
    join_all(start_all([(_thread_worker, (counter, iters))] * workers))
    check("mutex baseline count", counter.value, workers * iters)
