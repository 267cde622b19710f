"""Micro costs of separate calls (async command, sync query, reserving N processors).

Each is set beside a queue.Queue hand-off between threads measured in the same process kind.
"""

import queue
import threading
import time

from scoopc.runtime import leaf

SIZES = {
    "full": {"calls": 200_000, "reservations": 20_000},
    "quick": {"calls": 20_000, "reservations": 2_000},
    "smoke": {"calls": 500, "reservations": 50},
}
RESERVE_COUNTS = (1, 2, 4, 8)

# (scoop key, baseline key, what the baseline is)
PAIRS = [
    (
        "async_command",
        "handoff",
        "leaf command; baseline: queue.Queue put to a consumer thread that runs it, amortised",
    ),
    ("async_command_queued", "handoff", "non-leaf command, run by the supplier's thread; same baseline"),
    ("sync_query", "roundtrip", "baseline: queue.Queue request/reply round trip to a server thread"),
    (
        "reserve_1_wait_condition",
        "handoff_x1",
        "reserve+release 1 idle processor with a true wait condition (one query); same baseline",
    ),
] + [
    (
        f"reserve_{n}",
        f"handoff_x{n}",
        f"reserve+release {n} idle processors; baseline: one put to each of {n} consumer threads",
    )
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
    result = {
        "handoff": per_call_us(_time_fanout(1, calls), calls),
        "roundtrip": per_call_us(_time_roundtrips(calls), calls),
    }
    for n in RESERVE_COUNTS:
        result[f"handoff_x{n}"] = per_call_us(_time_fanout(n, reservations), reservations)
    return result


# --- SCOOP: the same through the runtime, from a root processor --------------------

W_MICRO = ("ROOT", "measure", "benchmarks/micro.e", 1)


class Sink:
    @leaf
    def make(self):
        self.count = 0

    @leaf
    def bump(self):
        self.count += 1

    def bump_queued(self):
        """Not marked leaf (as if it looped): always queued for the supplier's thread."""
        self.count += 1

    @leaf
    def get_count(self):
        return self.count


class Root:
    def make(self, calls, reservations, out):
        here = self._region_
        sinks = [here.new_separate(Sink, Sink.make) for _ in range(max(RESERVE_COUNTS))]
        self.sync_with(sinks)
        commands = (("async_command", Sink.bump), ("async_command_queued", Sink.bump_queued))
        for key, routine in commands:
            out[key] = per_call_us(self.time_commands(sinks[0], routine, calls), calls)
        out["sync_query"] = per_call_us(self.time_queries(sinks[0], calls), calls)
        seconds = self.time_guarded(sinks[0], reservations)
        out["reserve_1_wait_condition"] = per_call_us(seconds, reservations)
        for n in RESERVE_COUNTS:
            seconds = self.time_reservations(tuple(sinks[:n]), reservations)
            out[f"reserve_{n}"] = per_call_us(seconds, reservations)

    def sync_with(self, sinks):
        """Wait until every sink has run its creation (so no timing includes it)."""
        here = self._region_
        with here.reserve(tuple(sinks), where=W_MICRO):
            for sink in sinks:
                here.query(sink, Sink.get_count, (), W_MICRO)

    def time_commands(self, sink, routine, calls):
        """Log `calls` commands, then one query: it returns when all have run."""
        here = self._region_
        start = time.perf_counter()
        with here.reserve((sink,), where=W_MICRO):
            before = here.query(sink, Sink.get_count, (), W_MICRO)
            for _ in range(calls):
                here.call(sink, routine)
            done = here.query(sink, Sink.get_count, (), W_MICRO) - before
        elapsed = time.perf_counter() - start
        if done != calls:
            raise AssertionError(f"async commands: {done} of {calls} ran")
        return elapsed

    def time_queries(self, sink, calls):
        here = self._region_
        with here.reserve((sink,), where=W_MICRO):
            start = time.perf_counter()
            for _ in range(calls):
                here.query(sink, Sink.get_count, (), W_MICRO)
            return time.perf_counter() - start

    def time_guarded(self, sink, count):
        """`guarded (s: separate SINK) require s.count >= 0 do end`, called `count` times."""
        here = self._region_
        start = time.perf_counter()
        for _ in range(count):
            pre = ((lambda: here.query(sink, Sink.get_count, (), W_MICRO) >= 0, (0,), "non_negative", W_MICRO),)
            with here.reserve((sink,), pre=pre, where=W_MICRO):
                pass
        return time.perf_counter() - start

    def time_reservations(self, sinks, count):
        here = self._region_
        start = time.perf_counter()
        for _ in range(count):
            with here.reserve(sinks, where=W_MICRO):
                pass
        return time.perf_counter() - start


def scoop(calls, reservations):
    from common import run_program

    out = {}
    run_program(Root, (calls, reservations, out))
    return out
