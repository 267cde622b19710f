"""prodcons (SCOOP/Qs): producers and consumers share a queue; consumers wait until it is non-empty.

Baseline: threads sharing one queue.Queue (unbounded, as the SCOOP queue is).
"""

import queue
from collections import deque

from scoopc.runtime import leaf

from common import check, join_all, run_program, start_all, where

SIZES = {
    "full": {"producers": 4, "consumers": 4, "items": 200_000},
    "quick": {"producers": 4, "consumers": 4, "items": 5_000},
    "smoke": {"producers": 2, "consumers": 2, "items": 100},
}


def ops(producers, consumers, items):
    """`items` is per producer; each item is produced once and consumed once."""
    return producers * items


def _check_split(producers, consumers, items):
    if producers * items % consumers:
        raise ValueError("producers * items must divide evenly among consumers")
    return producers * items // consumers


def _expected_sum(producers, items):
    return producers * items * (items - 1) // 2


# --- hand-written threading --------------------------------------------------


def _thread_producer(q, items):
    for i in range(items):
        q.put(i)


def _thread_consumer(q, count, totals):
    total = 0
    for _ in range(count):
        total += q.get()
    totals.append(total)


def baseline(producers, consumers, items):
    per_consumer = _check_split(producers, consumers, items)
    q, totals = queue.Queue(), []
    targets = [(_thread_producer, (q, items))] * producers
    targets += [(_thread_consumer, (q, per_consumer, totals))] * consumers
    join_all(start_all(targets))
    check("prodcons baseline sum", sum(totals), _expected_sum(producers, items))


# --- SCOOP, as generated code calls the runtime ----------------------------------
# (@leaf where codegen would put it: routines without loops, separate or blocking calls)
# class SHARED_QUEUE: is_empty, item, extend (v), remove (a LINKED_QUEUE)
# class PRODUCER: live do across 0 |..| (items - 1) as i loop put (queue, i) end end
#                 put (q: separate SHARED_QUEUE; v) do q.extend (v) end
# class CONSUMER: live do across 1 |..| count loop take (queue) end end
#                 take (q: separate SHARED_QUEUE) require not q.is_empty
#                 do total := total + q.item; q.remove end

W_PUT = where("PRODUCER", "put", 10)
W_TAKE = where("CONSUMER", "take", 20)
W_NOT_EMPTY = where("CONSUMER", "take", 21)
W_ITEM = where("CONSUMER", "take", 22)
W_LAUNCH = where("ROOT", "launch", 30)


class SharedQueue:
    @leaf
    def make(self):
        self.items = deque()

    @leaf
    def is_empty(self):
        return not self.items

    @leaf
    def item(self):
        return self.items[0]

    @leaf
    def extend(self, value):
        self.items.append(value)

    @leaf
    def remove(self):
        self.items.popleft()


class Producer:
    @leaf
    def make(self, q, items):
        self.queue, self.items = q, items

    def live(self):
        for i in range(self.items):
            self.put(self.queue, i)

    def put(self, q, value):
        here = self._region_
        here.command1(q, SharedQueue.extend, (value,), W_PUT)  # INTEGER: passes no lock


# Codegen's clause table for `take` (see bench_condition.PRE_CHANGE).
PRE_TAKE = (
    (lambda here, q: not here.leaf_query(q, SharedQueue.is_empty, (), W_NOT_EMPTY), (0,), "not_empty", W_NOT_EMPTY),
)


class Consumer:
    @leaf
    def make(self, q, count):
        self.queue, self.count, self.total = q, count, 0

    def live(self):
        for _ in range(self.count):
            self.take(self.queue)

    def take(self, q):
        here = self._region_
        with here.reserve1(q, W_TAKE, PRE_TAKE, (here, q)):
            self.total += here.leaf_query(q, SharedQueue.item, (), W_ITEM)
            here.leaf_call(q, SharedQueue.remove)


class Root:
    def make(self, producers, consumers, items, out):
        here = self._region_
        q = here.new_separate(SharedQueue, SharedQueue.make)
        count = _check_split(producers, consumers, items)
        out["consumers"] = [here.new_separate(Consumer, Consumer.make, (q, count)) for _ in range(consumers)]
        for c in out["consumers"]:
            self.launch(c, Consumer.live)
        for _ in range(producers):
            self.launch(here.new_separate(Producer, Producer.make, (q, items)), Producer.live)

    def launch(self, w, live):
        here = self._region_
        here.command1(w, live, (), W_LAUNCH)


def scoop(producers, consumers, items):
    out = {}
    run_program(Root, (producers, consumers, items, out))
    total = sum(c.total for c in out["consumers"])
    check("prodcons scoop sum", total, _expected_sum(producers, items))


# --- the dialect version (benchmarks/prodcons/*.e), compiled by scoopc ---------------


def program_args(producers, consumers, items):
    _check_split(producers, consumers, items)
    return [str(items), str(producers), str(consumers)]


def program_output(producers, consumers, items):
    return (
        f"prodcons: producers={producers} consumers={consumers} items={items} sum={_expected_sum(producers, items)}\n"
    )
