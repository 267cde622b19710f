"""The cost of the live view (`scoopc run --live`, docs/LIVE.md) to a running program: each compiled
benchmark run as `scoopc run` runs it, `off` (no view) and `on` (the live view's sampler attached:
the runtime's snapshot at most 20 times a second, changes only, each message JSON-encoded as the
Foxglove SDK encodes it, the server itself left out), alternating, each run a fresh subprocess
pinned to one CPU. Reports the best of R runs of each and the ratio on/off.
`python benchmarks/live_cost.py --help`."""

import argparse
import importlib
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
NAMES = ("mutex", "condition", "prodcons", "threadring", "chameneos")


class EncodingSink:
    """A sink of the sampler that encodes each message as the SDK's server would, and keeps a count."""

    def __init__(self):
        self.count = 0

    def attach(self, rt):
        pass

    def send(self, topic, message, wall_ns, sim_ns):
        json.dumps(message)
        self.count += 1

    def heard(self, topic, msg):
        pass

    def close(self):
        pass


def child(name, variant, size, build):
    for path in (HERE, ROOT):
        if path not in sys.path:
            sys.path.insert(0, path)
    from scoopc.driver.live import Sampler  # deferred: the child only
    from scoopc.driver.status import ClauseSource  # deferred: the child only

    from common import run_compiled  # deferred: after sys.path has the benchmarks

    module = importlib.import_module("bench_" + name)
    on_start, sink = None, EncodingSink()
    if variant == "on":
        sampler = Sampler(ClauseSource([os.path.join(HERE, name)]), [sink])
        on_start = sampler.attach
    result = run_compiled(build, name, module, module.SIZES[size], on_start=on_start)
    print(json.dumps({**result, "messages": sink.count}))


def run_child(name, variant, size, build):
    command = [sys.executable, os.path.abspath(__file__), "--child", name, variant, size, build]
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise SystemExit(f"{name} {variant}: exit {done.returncode}: {done.stderr.strip()[-400:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv=None):
    parser = argparse.ArgumentParser(description="The live view's cost to compiled benchmarks (on/off).")
    parser.add_argument("--size", choices=("quick", "full"), default="quick")
    parser.add_argument("--repeat", type=int, default=5, metavar="R")
    parser.add_argument("--only", nargs="+", choices=NAMES, default=list(NAMES))
    parser.add_argument("--child", nargs=4, metavar=("NAME", "VARIANT", "SIZE", "BUILD"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        return child(*args.child)
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
    sys.path.insert(0, HERE)
    from common import compile_benchmark  # deferred: after sys.path has the benchmarks

    with tempfile.TemporaryDirectory() as build:
        ratios = []
        for name in args.only:
            compile_benchmark(name, build)
            best = {"off": float("inf"), "on": float("inf")}
            messages = 0
            for _ in range(args.repeat):
                for variant in ("off", "on"):
                    result = run_child(name, variant, args.size, build)
                    best[variant] = min(best[variant], result["seconds"])
                    messages = max(messages, result["messages"])
            ratios.append(best["on"] / best["off"])
            print(
                f"{name:<11} off={best['off']:.3f}s on={best['on']:.3f}s ratio={ratios[-1]:.3f} "
                f"messages={messages} {time.strftime('%H:%M:%S')}",
                flush=True,
            )
        geomean = 1.0
        for r in ratios:
            geomean *= r
        print(f"geomean on/off {geomean ** (1 / len(ratios)):.3f}")


if __name__ == "__main__":
    main()
