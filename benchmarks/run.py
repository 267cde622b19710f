"""scoopc benchmark suite (DESIGN section 9): SCOOP/Qs programs on the runtime vs threading.

Three variants of each benchmark: `scoop` (hand-written Python calling the runtime API as
generated code does), `compiled` (the dialect version benchmarks/<name>/*.e, compiled once per
run by scoopc into a temporary folder, run by the launcher as `scoopc run` does) and `baseline`
(hand-written threading). `python benchmarks/run.py --help`. Each run is a fresh subprocess;
best (or median) of R runs.
"""

import argparse
import importlib
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BENCHMARKS = ["mutex", "condition", "prodcons", "threadring", "chameneos"]
VARIANTS = ("baseline", "scoop", "compiled")
API_VARIANTS = ("baseline", "scoop")
REPEATS = {"full": 3, "quick": 3, "smoke": 1}
TIMEOUTS = {"full": 120, "quick": 30, "smoke": 10}
STATS = {"best": min, "median": statistics.median}


class RunFailed(Exception):
    """A child run crashed, timed out or failed its result check."""


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Run the SCOOP/Qs concurrency benchmarks and micro costs: each benchmark "
        "against the scoopc runtime (hand-written as generated code calls it), as its dialect "
        "version compiled by scoopc, and as hand-written threading, with the time ratios "
        "scoop/baseline and compiled/scoop, then micro costs of separate calls. Each run is "
        "a fresh subprocess, pinned to one CPU unless --unpinned; the best (or, with --stat "
        "median, the median) of several runs is reported."
    )
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--quick", action="store_true", help="small sizes (well under 1 s each)")
    size.add_argument("--smoke", action="store_true", help="tiny sizes, one run: for tests")
    parser.add_argument("--unpinned", action="store_true", help="do not pin to one CPU (shows the multi-core picture)")
    parser.add_argument(
        "--no-unpinned-figure",
        action="store_true",
        help="after a pinned run, skip measuring the compiled versions against threading again on every CPU",
    )
    parser.add_argument(
        "--only",
        nargs="+",
        metavar="NAME",
        choices=BENCHMARKS + ["micro"],
        help="run only these benchmarks (names: %(choices)s)",
    )
    parser.add_argument("--repeat", type=int, metavar="R", help="runs per measurement")
    parser.add_argument(
        "--stat",
        choices=sorted(STATS),
        default="best",
        help="how runs are summarised (default: best, the least disturbed)",
    )
    parser.add_argument(
        "--assertions",
        choices=("none", "require", "all"),
        default="none",
        help="contracts the compiled versions check (default: none, as in a "
        "finalized build; wait conditions are always evaluated and the standard "
        "library keeps its preconditions)",
    )
    parser.add_argument("--no-compiled", action="store_true", help="skip the compiled dialect versions")
    parser.add_argument("--child", nargs=3, metavar=("NAME", "VARIANT", "SIZE"), help=argparse.SUPPRESS)
    parser.add_argument("--build", metavar="DIR", help=argparse.SUPPRESS)
    return parser.parse_args(argv)


def size_of(args):
    return "smoke" if args.smoke else "quick" if args.quick else "full"


# --- child side: one measurement in this process ------------------------------


def load(name):
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    from common import use_scoopc

    use_scoopc()
    return importlib.import_module("micro" if name == "micro" else "bench_" + name)


def runtime_kind():
    """Which runtime the runs use: the compiled one (docs/RUNTIME.md section 10) or pure Python."""
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    from common import use_scoopc

    use_scoopc()
    import scoopc.runtime as rt

    return f"runtime {'compiled to C' if rt.COMPILED else 'pure Python'} ({os.path.dirname(rt.__file__)})"


def child_main(name, variant, size, build=None):
    """Run one variant once; print its result as one JSON line on stdout."""
    module = load(name)
    params = module.SIZES[size]
    if name == "micro":
        result = getattr(module, variant)(**params)
    elif variant == "compiled":
        from common import run_compiled

        result = run_compiled(build, name, module, params)
    else:
        start, cpu = time.perf_counter(), time.process_time()
        getattr(module, variant)(**params)
        result = {"seconds": time.perf_counter() - start, "cpu": time.process_time() - cpu}
    print(json.dumps(result))


# --- parent side: orchestration and report ------------------------------------


ALL_CPUS = []  # the CPUs the run had before pinning, given back for the unpinned figure


def pin(unpinned):
    if unpinned:
        return "unpinned"
    if not hasattr(os, "sched_setaffinity"):
        return "unpinned (no sched_setaffinity on this platform)"
    ALL_CPUS[:] = sorted(os.sched_getaffinity(0))
    cpu = ALL_CPUS[0]
    os.sched_setaffinity(0, {cpu})
    return f"pinned to cpu {cpu}"


def unpin():
    """Give back every CPU (children inherit it); False when the run was never pinned."""
    if not ALL_CPUS or len(ALL_CPUS) < 2:
        return False
    os.sched_setaffinity(0, set(ALL_CPUS))
    return True


def failure_line(stderr):
    """The runtime's own failure line if there is one, else the last line (the exception)."""
    lines = stderr.strip().splitlines() or ["(no output)"]
    ours = [line for line in lines if line.startswith("scoopc:")]
    return (ours or lines)[-1]


def run_child(name, variant, size, build=None):
    command = [sys.executable, os.path.abspath(__file__), "--child", name, variant, size]
    if build is not None:
        command += ["--build", build]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUTS[size])
    except subprocess.TimeoutExpired:
        raise RunFailed(f"{name} {variant}: timed out after {TIMEOUTS[size]} s") from None
    if done.returncode != 0:
        raise RunFailed(f"{name} {variant}: exit {done.returncode}: {failure_line(done.stderr)}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def summarise(runs, stat):
    """{variant: {key: [values]}} -> {variant: {key: stat(values)}}."""
    return {variant: {key: STATS[stat](values) for key, values in keys.items()} for variant, keys in runs.items()}


def measure(name, size, repeats, stat, variants=API_VARIANTS, build=None):
    """Run the variants `repeats` times, alternating them against drift; summarise."""
    runs = {variant: {} for variant in variants}
    for _ in range(repeats):
        for variant in variants:
            for key, value in run_child(name, variant, size, build).items():
                runs[variant].setdefault(key, []).append(value)
    return summarise(runs, stat)


def describe(params):
    return " ".join(f"{key}={value}" for key, value in params.items())


def report_benchmark(name, size, repeats, stat, build=None):
    """Print one benchmark line; return (scoop/baseline, compiled/scoop or None without a
    build), or None when it failed. `build`: the compiled versions' folder, or None, or the
    RunFailed that says why the dialect version could not be compiled."""
    module = load(name)
    params = module.SIZES[size]
    variants = VARIANTS if build is not None else API_VARIANTS
    try:
        if isinstance(build, RunFailed):
            raise build
        summary = measure(name, size, repeats, stat, variants, build)
    except RunFailed as failure:
        print(f"{name} {describe(params)} FAILED {failure}", flush=True)
        return None
    best = {variant: summary[variant]["seconds"] for variant in variants}
    cpu = {variant: summary[variant]["cpu"] for variant in variants}
    shown = [v for v in ("scoop", "compiled", "baseline") if v in variants]
    times = " ".join(f"{v}_s={best[v]:.3f}" for v in shown)
    per_op = "/".join(f"{1e6 * best[v] / module.ops(**params):.2f}" for v in shown)
    ratio = best["scoop"] / best["baseline"]
    line = f"{name} {describe(params)} {times} ratio={ratio:.2f}"
    compiled = against_threads = None
    if build is not None:
        compiled = best["compiled"] / best["scoop"]
        against_threads = best["compiled"] / best["baseline"]
        line += f" compiled_ratio={against_threads:.2f} compiled_vs_api={compiled:.2f}"
    line += f" us_per_op={per_op} cpu_ratio={cpu['scoop'] / max(cpu['baseline'], 1e-9):.2f}"
    print(line, flush=True)
    return ratio, compiled, against_threads


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


# The targets of compiled programs against hand-written threading, pinned to one core.
COMPILED_WORST_TARGET, COMPILED_GEOMEAN_TARGET = 1.5, 1.0


def report_geomean(ratios, failed):
    """ratios: {name: (scoop/baseline, compiled/scoop or None, compiled/baseline or None)} of the
    benchmarks that ran."""
    if failed or not ratios:
        print(f"geomean_ratio=nan failed={','.join(failed) or 'none run'}")
        return
    line = f"geomean_ratio={geomean([r[0] for r in ratios.values()]):.2f}"
    compiled = [r[1] for r in ratios.values() if r[1] is not None]
    if compiled:
        line += f" compiled_vs_api_geomean={geomean(compiled):.2f} compiled_vs_api_max={max(compiled):.2f}"
    print(line)
    against = {name: r[2] for name, r in ratios.items() if r[2] is not None}
    if against:
        print(compiled_summary("compiled against threads", against))


def compiled_summary(title, against):
    """One line: the geomean and the worst of compiled/threads ratios, and whether the targets hold."""
    mean = geomean(list(against.values()))
    worst = max(against, key=against.get)
    met = mean <= COMPILED_GEOMEAN_TARGET and against[worst] <= COMPILED_WORST_TARGET
    return (
        f"{title}: compiled_geomean={mean:.2f} compiled_worst={against[worst]:.2f} ({worst})  "
        f"target each <= {COMPILED_WORST_TARGET}, geomean <= {COMPILED_GEOMEAN_TARGET}: {'met' if met else 'MISSED'}"
    )


def report_unpinned(names, size, repeats, stat, builds):
    """The compiled versions against threading again on every CPU: the multi-core picture."""
    against = {}
    for name in names:
        build = builds.get(name)
        if build is None or isinstance(build, RunFailed):
            continue
        try:
            summary = measure(name, size, repeats, stat, ("baseline", "compiled"), build)
        except RunFailed as failure:
            print(f"unpinned {name} FAILED {failure}", flush=True)
            continue
        against[name] = summary["compiled"]["seconds"] / summary["baseline"]["seconds"]
    if against:
        detail = " ".join(f"{name}={ratio:.2f}" for name, ratio in against.items())
        print(f"{compiled_summary(f'unpinned, {len(ALL_CPUS)} cpus', against)}  [{detail}]", flush=True)


def compile_all(names, folder, assertions):
    """Compile each benchmark's dialect version once for this run: {name: the build folder, or
    the RunFailed that says why not}. The standard library is compiled first (once per
    compiler version, then taken from scoopc's cache), timed apart."""
    from common import compile_benchmark, compiled_library

    library = compiled_library()
    builds, total = {}, 0.0
    for name in names:
        try:
            total += compile_benchmark(name, folder, assertions)["seconds"]
        except Exception as problem:  # noqa: BLE001 - reported on the benchmark's line
            builds[name] = RunFailed(f"{name} compiled: {type(problem).__name__}: {problem}")
            continue
        builds[name] = folder
    done = sum(not isinstance(b, RunFailed) for b in builds.values())
    print(
        f"# compiled {done} dialect versions with scoopc in {total:.2f} s "
        f"(assertions={assertions}; the standard library: {library:.2f} s, compiled once or cached)",
        flush=True,
    )
    return builds


def report_micro(size, repeats, stat):
    """Print the micro costs; return False when they could not be measured."""
    micro = load("micro")
    try:
        best = measure("micro", size, repeats, stat)
    except RunFailed as failure:
        print(f"micro FAILED {failure}", flush=True)
        return False
    for key, baseline_key, note in micro.PAIRS:
        scoop_us, baseline_us = best["scoop"][key], best["baseline"][baseline_key]
        print(
            f"micro {key} scoop_us={scoop_us:.2f} baseline_us={baseline_us:.2f}"
            f" ratio={scoop_us / baseline_us:.2f}  ({note})",
            flush=True,
        )
    return True


def load_average():
    """The 1-minute load average before the run: a busy machine makes the figures noisy."""
    return f"{os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else "n/a"


def print_header(size, repeats, stat, pinning):
    gil = getattr(sys, "_is_gil_enabled", lambda: True)()
    print(
        f"# scoopc benchmarks: python {platform.python_version()} "
        f"({'GIL' if gil else 'free-threaded'}), {os.cpu_count()} cpus, {pinning}, "
        f"load {load_average()}, size={size}, {stat} of {repeats} runs, "
        f"each run a fresh subprocess, {runtime_kind()}",
        flush=True,
    )


def main(argv=None):
    args = parse_args(argv)
    if args.child:
        child_main(*args.child, build=args.build)
        return 0
    size = size_of(args)
    repeats = args.repeat or REPEATS[size]
    print_header(size, repeats, args.stat, pin(args.unpinned))
    selected = args.only or BENCHMARKS + ["micro"]
    names = [n for n in BENCHMARKS if n in selected]
    ratios, failed = {}, []
    with tempfile.TemporaryDirectory(prefix="scoopc-bench-") as folder:
        builds = {} if args.no_compiled or not names else compile_all(names, folder, args.assertions)
        for name in names:
            ratio = report_benchmark(name, size, repeats, args.stat, builds.get(name))
            if ratio is None:
                failed.append(name)
            else:
                ratios[name] = ratio
        if names:
            report_geomean(ratios, failed)
        if builds and not args.no_unpinned_figure and unpin():
            report_unpinned(names, size, repeats, args.stat, builds)
    if "micro" in selected and not report_micro(size, repeats, args.stat):
        failed.append("micro")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
