"""mutex (SCOOP/Qs): N workers each reserve a shared counter M times and increment it.

Baseline: threads incrementing a counter under a threading.Lock.
"""

import threading

from scoopc.runtime import leaf

from common import check, join_all, run_program, start_all, where

SIZES = {
    "full": {"workers": 32, "iters": 100_000},
    "quick": {"workers": 32, "iters": 2_500},
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


# --- SCOOP, as generated code calls the runtime ----------------------------------
# (@leaf where codegen would put it: routines without loops, separate or blocking calls)
# class COUNTER:  value: INTEGER; increment do value := value + 1 end
# class WORKER:   live do across 1 |..| iters loop increment (counter) end end
#                 increment (c: separate COUNTER) do c.increment end
# class ROOT:     make: create counter; create N workers; launch (w) for each

W_INCREMENT = where("WORKER", "increment", 12)
W_LAUNCH = where("ROOT", "launch", 20)


class Counter:
    @leaf
    def make(self):
        self.value = 0

    @leaf
    def increment(self):
        self.value += 1


class Worker:
    @leaf
    def make(self, counter, iters):
        self.counter, self.iters = counter, iters

    def live(self):
        for _ in range(self.iters):
            self.increment(self.counter)

    def increment(self, c):
        here = self._region_
        # one separate argument, no precondition, body = one command with no argument
        here.command1(c, Counter.increment, (), W_INCREMENT)


class Root:
    def make(self, workers, iters, out):
        here = self._region_
        out["counter"] = counter = here.new_separate(Counter, Counter.make)
        for _ in range(workers):
            self.launch(here.new_separate(Worker, Worker.make, (counter, iters)))

    def launch(self, w):
        here = self._region_
        here.command1(w, Worker.live, (), W_LAUNCH)


def scoop(workers, iters):
    out = {}
    run_program(Root, (workers, iters, out))
    check("mutex scoop count", out["counter"].value, workers * iters)


# --- the dialect version (benchmarks/mutex/*.e), compiled by scoopc ----------------


def program_args(workers, iters):
    return [str(iters), str(workers)]


def program_output(workers, iters):
    return f"mutex: workers={workers} iterations={iters} count={workers * iters}\n"
