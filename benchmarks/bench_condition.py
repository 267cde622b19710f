"""condition (SCOOP/Qs): workers wait until a shared variable has their parity, then increment it.

Half the workers want it even, half odd, so the two groups strictly alternate.
Baseline: one threading.Condition, wait_for on the parity, notify_all after each change.
"""

import threading

from scoopc.runtime import leaf

from common import check, join_all, run_program, start_all, where

SIZES = {
    "full": {"workers": 4, "iters": 100_000},
    "quick": {"workers": 4, "iters": 5_000},
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


# --- SCOOP, as generated code calls the runtime ----------------------------------
# (@leaf where codegen would put it: routines without loops, separate or blocking calls)
# class SHARED:  value: INTEGER; increment do value := value + 1 end
# class WORKER:  live do across 1 |..| iters loop change (shared) end end
#                change (s: separate SHARED) require s.value \\ 2 = parity do s.increment end

W_CHANGE = where("WORKER", "change", 14)
W_PARITY = where("WORKER", "change", 15)
W_LAUNCH = where("ROOT", "launch", 22)


class Shared:
    @leaf
    def make(self):
        self.value = 0

    @leaf
    def get_value(self):
        return self.value

    @leaf
    def increment(self):
        self.value += 1


# The precondition as codegen emits it: a module-level clause table, one predicate per
# clause taking `pre_args` (here: the processor, Current, the separate argument).
PRE_CHANGE = (
    (
        lambda here, current, s: here.leaf_query(s, Shared.get_value, (), W_PARITY) % 2 == current.parity,
        (0,),
        "parity",
        W_PARITY,
    ),
)


class Worker:
    @leaf
    def make(self, shared, parity, iters):
        self.shared, self.parity, self.iters = shared, parity, iters

    def live(self):
        for _ in range(self.iters):
            self.change(self.shared)

    def change(self, s):
        here = self._region_
        with here.reserve1(s, W_CHANGE, PRE_CHANGE, (here, self, s)):
            here.leaf_call(s, Shared.increment)


class Root:
    def make(self, workers, iters, out):
        here = self._region_
        out["shared"] = shared = here.new_separate(Shared, Shared.make)
        for i in range(workers):
            self.launch(here.new_separate(Worker, Worker.make, (shared, i % 2, iters)))

    def launch(self, w):
        here = self._region_
        here.command1(w, Worker.live, (), W_LAUNCH)


def scoop(workers, iters):
    out = {}
    run_program(Root, (workers, iters, out))
    check("condition scoop value", out["shared"].value, workers * iters)


# --- the dialect version (benchmarks/condition/*.e), compiled by scoopc --------------


def program_args(workers, iters):
    return [str(iters), str(workers)]


def program_output(workers, iters):
    return f"condition: workers={workers} iterations={iters} value={workers * iters}\n"
