"""The cost of an external call through the runtime (scoopc.runtime.externals.call): one not
marked blocking (keeps the processor's run permit) against a blocking one (gives it up and takes
it back), on a processor alone and with another processor that computes meanwhile.

    python benchmarks/externals.py [--calls N] [--busy-calls M] [--repeat R]

Prints microseconds per call (best of R) and the ratio blocking / not blocking. With a computing
processor, a blocking call hands the permit over and waits for it back (the other processor
never blocks in the runtime: about two slices, docs/RUNTIME.md), hence fewer calls there.
Absolute figures are for reference only (DESIGN section 9).
"""

from __future__ import annotations

import argparse
import threading
import time

import scoopc.runtime as rt
from scoopc.runtime import externals


def host(x):
    return x


class Spinner:
    """Computes until told to stop: another processor that wants to run."""

    def make(self):
        self.stop = threading.Event()

    def spin(self):
        n = 0
        while not self.stop.is_set():
            n += 1


def per_call_us(root, calls: int, blocking: bool) -> float:
    start = time.perf_counter()
    for i in range(calls):
        externals.call(root, "APP.f", "Python f", host, (i,), blocking)
    return 1e6 * (time.perf_counter() - start) / calls


def measure(calls: int, busy: bool) -> dict[bool, float]:
    runtime, root = rt.start()
    try:
        spinner = None
        if busy:
            spinner = root.new_separate(Spinner, Spinner.make)
            with root.reserve((spinner,)):
                root.call(spinner, Spinner.spin, ())
            time.sleep(0.05)  # the spinner's thread is running (or waiting for a permit)
        found = {blocking: per_call_us(root, calls, blocking) for blocking in (False, True)}
        if spinner is not None:
            spinner.stop.set()  # the object itself: the runtime API hands out objects, not proxies
        return found
    finally:
        rt.finish(runtime, root)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calls", type=int, default=20_000, help="calls per measurement (default 20000)")
    parser.add_argument("--busy-calls", type=int, default=200, help="calls with a computing processor (default 200)")
    parser.add_argument("--repeat", type=int, default=3, help="measurements; the best is shown (default 3)")
    args = parser.parse_args()
    print(f"external calls: {args.calls} alone, {args.busy_calls} beside a computing processor, best of {args.repeat}")
    for busy in (False, True):
        runs = [measure(args.busy_calls if busy else args.calls, busy) for _ in range(args.repeat)]
        best = {blocking: min(r[blocking] for r in runs) for blocking in (False, True)}
        where = "with a computing processor" if busy else "alone"
        print(
            f"  {where:28} not blocking {best[False]:8.2f} us   blocking {best[True]:8.2f} us   "
            f"ratio {best[True] / best[False]:.2f}"
        )


if __name__ == "__main__":
    main()
