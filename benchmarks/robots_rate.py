"""Controller rate: how many iterations per second each of 10 Roboscoop controllers sustains.

One iteration reserves two signalers (a STOP_SIGNALER and an ODOMETRY_SIGNALER) and the robot's
DIFFERENTIAL_DRIVE, evaluates a wait condition over the signalers and sends one velocity command;
the controllers run at once, without pausing, each for S seconds (3; 1 with --quick) after 200
untimed iterations, and each reports how many iterations it did and the time they took, up to the
drive having published every command (so a queue of commands the drive has not executed yet does
not count as done). Two layouts: `separate` (each
controller has its own stop signaler and drive: ten robots) and `shared` (one stop signaler and one
drive for all: ten controllers of one robot, as a behaviour's controllers are). Two transports: the
in-process bus (`--robot none`) and DDS on loopback (`--robot ros2`). Target: >= 100 Hz each.

Variants, measured in the same run, each run a fresh subprocess:
* `compiled`: benchmarks/programs/robots_rate compiled by scoopc, run with `scoopc run`;
* `baseline`: the same structure hand-written with Python threads (one lock per signaler and
  drive, taken in a fixed order; a condition checked under them; the Twist published at once).
The report gives per layout and transport the slowest controller's rate, the median, the total
(all iterations over the longest controller's time), and `ratio`: the baseline's median rate over
the compiled one's, i.e. compiled time per iteration / baseline time (as benchmarks/run.py's ratios:
above 1, the compiled controllers are slower). `python benchmarks/robots_rate.py --help`.
"""

import argparse
import json
import os
import platform
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PROGRAM = os.path.join(HERE, "programs", "robots_rate")
CONTROLLERS = 10
SIZES = {"full": 3.0, "quick": 1.0, "smoke": 0.2}  # timed seconds per controller
WARMUP = 200  # untimed iterations per controller first (DDS writers, caches, thread start)
REPEATS = {"full": 3, "quick": 1, "smoke": 1}
TARGET_HZ = 100.0


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Iterations per second of 10 concurrent Roboscoop controllers (reserve two signalers "
        "and the drive, evaluate a wait condition, send one command), compiled by scoopc, against the "
        "same structure hand-written with Python threads; in-process bus and loopback DDS."
    )
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--quick", action="store_true", help="1 s per controller, one run")
    size.add_argument("--smoke", action="store_true", help="0.2 s per controller: for tests")
    parser.add_argument("--seconds", type=float, metavar="S", help="timed seconds per controller (default 3)")
    parser.add_argument("--repeat", type=int, metavar="R", help="runs per measurement (best is kept)")
    parser.add_argument(
        "--domain", type=int, metavar="ID", help="the loopback DDS domain id (default: random in 100..200)"
    )
    parser.add_argument("--transport", choices=("bus", "dds", "both"), default="both")
    parser.add_argument("--layout", choices=("separate", "shared", "both"), default="both")
    parser.add_argument("--child", nargs=3, metavar=("TRANSPORT", "LAYOUT", "S"), help=argparse.SUPPRESS)
    return parser.parse_args(argv)


# --- the baseline: hand-written threads -----------------------------------------------------------


class Signaler:
    def __init__(self):
        self.lock = threading.Lock()
        self.stop_requested = False
        self.update_count = 0


class Drive:
    def __init__(self, bus, topic, max_linear=0.5, max_angular=1.0):
        from scoopc.robots import ros_messages

        self.lock = threading.Lock()
        self.bus, self.topic, self.messages = bus, topic, ros_messages
        self.max_linear, self.max_angular = max_linear, max_angular
        self.count = 0

    def send(self, v, w):
        v = max(-self.max_linear, min(self.max_linear, v))
        w = max(-self.max_angular, min(self.max_angular, w))
        new = self.messages.new
        self.bus.publish(
            self.topic,
            new(
                "geometry_msgs/msg/Twist",
                linear=new("geometry_msgs/msg/Vector3", x=v),
                angular=new("geometry_msgs/msg/Vector3", z=w),
            ),
        )
        self.count += 1


def baseline(transport, layout, seconds):
    """[(iterations, seconds)] per controller."""
    if transport == "dds":
        from scoopc.robots.dds import DdsBus

        bus = DdsBus()
    else:
        from scoopc.robots.bus import Bus

        bus = Bus()
    shared_stop, shared_drive = Signaler(), Drive(bus, "/robot1/cmd_vel")
    results = [None] * CONTROLLERS
    barrier = threading.Barrier(CONTROLLERS)

    def step(index, stop, odometry, drive):
        with stop.lock, odometry.lock, drive.lock:  # one order for all: no deadlock
            if not stop.stop_requested and odometry.update_count >= 0:  # (always true)
                drive.send(0.1, 0.05 * (index + 1))

    def controller(index, stop, odometry, drive):
        barrier.wait()
        for _ in range(WARMUP):
            step(index, stop, odometry, drive)
        count, start = 0, time.perf_counter()
        end = start + seconds
        while time.perf_counter() < end:
            step(index, stop, odometry, drive)
            count += 1
        results[index] = (count, time.perf_counter() - start)

    threads = []
    for i in range(CONTROLLERS):
        stop, drive = (
            (shared_stop, shared_drive) if layout == "shared" else (Signaler(), Drive(bus, f"/robot{i + 1}/cmd_vel"))
        )
        threads.append(threading.Thread(target=controller, args=(i, stop, Signaler(), drive)))
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    if transport == "dds":
        bus.close()
    return results


# --- the compiled program -------------------------------------------------------------------------


def compiled(transport, layout, seconds, env):
    robot = "ros2" if transport == "dds" else "none"
    args = [str(CONTROLLERS), str(seconds), layout, str(WARMUP)]
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", "run", PROGRAM, "--robot", robot, "--", *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )
    if done.returncode != 0:
        raise RuntimeError(f"compiled {transport} {layout}: exit {done.returncode}: {done.stderr.strip()[-400:]}")
    results = []
    for line in done.stdout.splitlines():
        words = line.split()  # controller I iterations N seconds T
        if words and words[0] == "controller":
            results.append((int(words[3]), float(words[5])))
    if len(results) != CONTROLLERS or any(n <= 0 or t < seconds for n, t in results):
        raise RuntimeError(f"compiled {transport} {layout}: unexpected output {done.stdout!r}")
    return results


def run_baseline(transport, layout, seconds, env):
    done = subprocess.run(
        [sys.executable, os.path.abspath(__file__), "--child", transport, layout, str(seconds)],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )
    if done.returncode != 0:
        raise RuntimeError(f"baseline {transport} {layout}: {done.stderr.strip()[-400:]}")
    return [tuple(r) for r in json.loads(done.stdout.strip().splitlines()[-1])]


def rates(results):
    """Per-controller rates (slowest, median) and the aggregate: all iterations over the longest time."""
    hz = sorted(n / s for n, s in results)
    return {
        "min": hz[0],
        "median": statistics.median(hz),
        "total": sum(n for n, _ in results) / max(s for _, s in results),
    }


def best(runs):
    return max(runs, key=lambda r: r["median"])


def main(argv=None):
    args = parse_args(argv)
    if args.child:
        transport, layout, seconds = args.child
        sys.path.insert(0, ROOT)
        print(json.dumps(baseline(transport, layout, float(seconds))))
        return 0
    size = "smoke" if args.smoke else "quick" if args.quick else "full"
    seconds = args.seconds or SIZES[size]
    repeats = args.repeat or REPEATS[size]
    sys.path.insert(0, ROOT)
    from scoopc.robots import dds

    settings = dds.loopback_environment(
        tempfile.mkdtemp(prefix="scoopc-rate-"), args.domain if args.domain is not None else random.randint(100, 200)
    )
    env = dict(os.environ, **settings, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    transports = ["bus", "dds"] if args.transport == "both" else [args.transport]
    layouts = ["separate", "shared"] if args.layout == "both" else [args.layout]
    print(
        f"# robots_rate: python {platform.python_version()}, {os.cpu_count()} cpus, load {os.getloadavg()[0]:.1f}, "
        f"{CONTROLLERS} controllers x {seconds:g} s after {WARMUP} warm-up iterations, best of {repeats}; "
        f"DDS on loopback "
        f"(domain {settings['ROS_DOMAIN_ID']}); rates in iterations/s per controller",
        flush=True,
    )
    failed = []
    for transport in transports:
        for layout in layouts:
            runs = {"baseline": [], "compiled": []}
            try:
                for _ in range(repeats):
                    runs["baseline"].append(rates(run_baseline(transport, layout, seconds, env)))
                    runs["compiled"].append(rates(compiled(transport, layout, seconds, env)))
            except (RuntimeError, subprocess.TimeoutExpired) as e:
                print(f"rate {transport} {layout} FAILED {e}", flush=True)
                failed.append(f"{transport}/{layout}")
                continue
            base, ours = best(runs["baseline"]), best(runs["compiled"])
            verdict = "met" if ours["min"] >= TARGET_HZ else "MISSED"
            print(
                f"rate {transport} {layout} compiled_min_hz={ours['min']:.0f} "
                f"compiled_median_hz={ours['median']:.0f} "
                f"compiled_total_hz={ours['total']:.0f} baseline_median_hz={base['median']:.0f} "
                f"baseline_total_hz={base['total']:.0f} ratio={base['median'] / ours['median']:.2f} "
                f"target_{TARGET_HZ:.0f}hz={verdict}",
                flush=True,
            )
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
