"""prodcons (SCOOP/Qs): producers and consumers over a shared queue; consumers wait until it is non-empty.

Baseline: threads sharing one queue.Queue (unbounded, as the SCOOP queue is).
"""
import queue

from common import check, join_all, start_all

SIZES = {
    "full": {"producers": 4, "consumers": 4, "items": 100_000},
    "quick": {"producers": 4, "consumers": 4, "items": 10_000},
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
