"""Profile one benchmark variant across all its threads (cProfile per thread, merged).

Usage: python benchmarks/profile_bench.py NAME [--variant scoop|compiled|baseline] [--size quick]
       [--top 25] (compiled: the dialect version, compiled first into a temporary folder)
"""

import argparse
import cProfile
import io
import os
import pstats
import sys
import tempfile
import threading

from run import BENCHMARKS, load

PROFILES = []  # one cProfile.Profile per thread that ran
PROFILES_LOCK = threading.Lock()


def profiled_run(original):
    def run(self):
        profile = cProfile.Profile()
        with PROFILES_LOCK:
            PROFILES.append(profile)
        profile.enable()
        try:
            original(self)
        finally:
            profile.disable()

    return run


def merged_stats():
    out = io.StringIO()
    with PROFILES_LOCK:
        profiles = list(PROFILES)
    stats = pstats.Stats(profiles[0], stream=out)
    for profile in profiles[1:]:
        stats.add(profile)
    return stats, out


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("name", choices=BENCHMARKS + ["micro"])
    parser.add_argument("--variant", default="scoop", choices=("scoop", "compiled", "baseline"))
    parser.add_argument(
        "--assertions",
        default="none",
        choices=("none", "require", "all"),
        help="contracts the compiled variant checks (default: none)",
    )
    parser.add_argument("--size", default="quick", choices=("full", "quick", "smoke"))
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--sort", default="tottime", help="pstats sort key (tottime, cumtime)")
    return parser.parse_args()


def main():
    args = parse_args()
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
    module = load(args.name)
    params = module.SIZES[args.size]
    build = tempfile.mkdtemp(prefix="scoopc-profile-")
    if args.variant == "compiled":
        from common import compile_benchmark, run_compiled

        compile_benchmark(args.name, build, args.assertions)
        variant = lambda **p: run_compiled(build, args.name, module, p)  # noqa: E731
    else:
        variant = getattr(module, args.variant)
    threading.Thread.run = profiled_run(threading.Thread.run)
    main_profile = cProfile.Profile()
    PROFILES.append(main_profile)
    main_profile.enable()
    variant(**params)
    main_profile.disable()
    stats, out = merged_stats()
    stats.sort_stats(args.sort).print_stats(args.top)
    print(f"{len(PROFILES)} threads profiled")
    print(out.getvalue())


if __name__ == "__main__":
    sys.exit(main())
