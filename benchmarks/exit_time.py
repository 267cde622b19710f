"""Exit time: how long a run takes to end after Ctrl-C (SIGINT) while N processors are busy in a
computation that makes no runtime call (so none of them notices the stop by itself).

Variants, measured in the same run, each a fresh subprocess, alternating:
* `compiled`: benchmarks/programs/busy_exit compiled by scoopc and run with `scoopc run -- N`;
* `baseline`: the same with N hand-written Python daemon threads, whose main thread ends on
  KeyboardInterrupt (the least a Python program can do).
Each child says `busy` once every spinner has begun; the clock starts when SIGINT is sent and
stops when the child has exited. The report gives the median of R runs for each and `ratio`
(compiled over baseline). `python benchmarks/exit_time.py --help`.
"""

import argparse
import os
import platform
import signal
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PROGRAM = os.path.join(HERE, "programs", "busy_exit")
TIMEOUT = 120.0

BASELINE = """
import signal, sys, threading, time
signal.signal(signal.SIGINT, signal.default_int_handler)   # a background job starts with SIGINT ignored
def spin():
    n = 0
    while n >= 0:
        n += 1
try:   # the signal may come as soon as `busy` is out: everything after it is inside the `try`
    for _ in range(int(sys.argv[1])):
        threading.Thread(target=spin, daemon=True).start()
    print("busy", flush=True)
    while True:
        time.sleep(1)
except KeyboardInterrupt:
    sys.exit(130)
"""


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Seconds from Ctrl-C to the end of a run with N busy processors, "
        "compiled by scoopc, against N busy Python threads."
    )
    parser.add_argument("-n", type=int, default=50, metavar="N", help="busy processors (default 50)")
    parser.add_argument("-r", "--repeats", type=int, default=3, metavar="R", help="runs of each variant (default 3)")
    parser.add_argument("--smoke", action="store_true", help="N=3, one run each: for tests")
    return parser.parse_args(argv)


def command(variant, count):
    if variant == "compiled":
        return [sys.executable, "-m", "scoopc", "run", PROGRAM, "--", str(count)]
    return [sys.executable, "-c", BASELINE, str(count)]


def exit_seconds(variant, count):
    """Start the child, wait for `busy`, send SIGINT, time the exit."""
    env = dict(os.environ, PYTHONUNBUFFERED="1", PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    child = subprocess.Popen(
        command(variant, count), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env
    )
    try:
        line = child.stdout.readline()
        if line != "busy\n":
            raise RuntimeError(f"{variant}: expected 'busy', got {line!r}: {child.stderr.read()[-2000:]}")
        start = time.perf_counter()
        child.send_signal(signal.SIGINT)
        child.wait(TIMEOUT)
        return time.perf_counter() - start
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()


def main(argv=None):
    args = parse_args(argv)
    count, repeats = (3, 1) if args.smoke else (args.n, args.repeats)
    print(
        f"# exit_time: python {platform.python_version()}, {os.cpu_count()} cpus, load "
        f"{os.getloadavg()[0]:.1f}, {count} busy processors, median of {repeats}; seconds from SIGINT to exit"
    )
    times = {"compiled": [], "baseline": []}
    for _ in range(repeats):
        for variant in ("baseline", "compiled"):
            times[variant].append(exit_seconds(variant, count))
    compiled, baseline = (statistics.median(times[v]) for v in ("compiled", "baseline"))
    print(f"exit compiled_s={compiled:.3f} baseline_s={baseline:.3f} ratio={compiled / baseline:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
