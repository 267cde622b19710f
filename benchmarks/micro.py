"""Micro costs of separate calls (async command, sync query, reserving N processors).

Each is set beside a queue.Queue hand-off between threads measured in the same process kind.
"""
import queue
import threading
import time

SIZES = {
    "full": {"calls": 200_000, "reservations": 20_000},
    "quick": {"calls": 20_000, "reservations": 2_000},
    "smoke": {"calls": 500, "reservations": 50},
}
RESERVE_COUNTS = (1, 2, 4, 8)

# (scoop key, baseline key, what the baseline is)
PAIRS = [
    ("async_command", "handoff",
     "baseline: queue.Queue put to a consumer thread that runs it, amortised"),
    ("sync_query", "roundtrip",
     "baseline: queue.Queue request/reply round trip to a server thread"),
] + [
    (f"reserve_{n}", f"handoff_x{n}",
     f"reserve+release {n} idle processors; baseline: one put to each of {n} consumer threads")
    for n in RESERVE_COUNTS
]

STOP = object()


def per_call_us(seconds, count):
    return 1e6 * seconds / count


# --- baseline: queue.Queue hand-offs between threads --------------------------

def _consume(inbox):
    while True:
        item = inbox.get()
        if item is STOP:
            return
        item()


def _serve(inbox, outbox):
    while True:
        item = inbox.get()
        if item is STOP:
            return
        outbox.put(item())


def _nothing():
    return 0


def _time_fanout(consumers, rounds):
    """Seconds to put `rounds` items to each of `consumers` threads and see them all run."""
    inboxes = [queue.Queue() for _ in range(consumers)]
    threads = [threading.Thread(target=_consume, args=(box,)) for box in inboxes]
    for thread in threads:
        thread.start()
    start = time.perf_counter()
    for _ in range(rounds):
        for box in inboxes:
            box.put(_nothing)
    for box in inboxes:
        box.put(STOP)
    for thread in threads:
        thread.join()
    return time.perf_counter() - start


def _time_roundtrips(count):
    inbox, outbox = queue.Queue(), queue.Queue()
    server = threading.Thread(target=_serve, args=(inbox, outbox))
    server.start()
    start = time.perf_counter()
    for _ in range(count):
        inbox.put(_nothing)
        outbox.get()
    elapsed = time.perf_counter() - start
    inbox.put(STOP)
    server.join()
    return elapsed


def baseline(calls, reservations):
    result = {"handoff": per_call_us(_time_fanout(1, calls), calls),
              "roundtrip": per_call_us(_time_roundtrips(calls), calls)}
    for n in RESERVE_COUNTS:
        result[f"handoff_x{n}"] = per_call_us(_time_fanout(n, reservations), reservations)
    return result
