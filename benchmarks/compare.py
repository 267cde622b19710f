"""Compare the benchmarks of two revisions on this machine, in the same session.

`python benchmarks/compare.py BEFORE [AFTER]` exports each revision's tree (`git archive`,
nothing in the repository changes), then runs each tree's own `benchmarks/run.py` with that
tree's scoopc, alternating BEFORE and AFTER for several rounds, so that a drift of the
machine's load falls on both alike. AFTER defaults to the working tree as it is. Each
round prints its ratios; the end prints, per benchmark, the median ratio of each revision
and the change, and the geomean of each revision's median ratios.

The ratios are those run.py prints: compiled_ratio (the compiled dialect version against
hand-written threading), or with --api, ratio (the runtime API version against threading).
A ratio is taken within one run of run.py, so load that changes between rounds cancels
out; load that changes within a run does not, which is why rounds alternate.

The trees run the pure-Python runtime. With --compiled-runtime, each tree's runtime is first
compiled to C as a regular install compiles it (docs/RUNTIME.md section 10; about a minute per
tree; the working tree is copied first, so no compiled module lands in the checkout); a revision
from before the compiled runtime existed stays pure Python, and the report says so.
"""

import argparse
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BENCHMARKS = ["mutex", "condition", "prodcons", "threadring", "chameneos"]
WORKING_TREE = "working tree"


class CompareFailed(Exception):
    """A revision could not be exported, or its run.py failed."""


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Compare the benchmark ratios of two revisions, alternating their runs on this machine."
    )
    parser.add_argument("before", help="the revision measured first (a commit, tag or branch)")
    parser.add_argument("after", nargs="?", help="the revision to compare with it (default: the working tree)")
    parser.add_argument("--rounds", type=int, default=4, help="alternating rounds (default: 4)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per measurement within run.py (default: 3)")
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--full", action="store_true", help="full sizes (default: run.py's --quick sizes)")
    size.add_argument("--smoke", action="store_true", help="run.py's tiny sizes: for tests")
    parser.add_argument(
        "--only", nargs="+", metavar="NAME", choices=BENCHMARKS, help="these benchmarks only (%(choices)s)"
    )
    parser.add_argument(
        "--api", action="store_true", help="compare the runtime API versions (ratio=) instead of the compiled ones"
    )
    parser.add_argument(
        "--compiled-runtime",
        action="store_true",
        help="compile each tree's runtime to C first, as a regular install does (about a minute per tree)",
    )
    args = parser.parse_args(argv)
    if args.rounds < 1 or args.repeat < 1:
        parser.error("--rounds and --repeat must be at least 1")
    return args


def export(revision, into, copy_working_tree=False):
    """The tree of `revision` (None: the working tree, itself or, with `copy_working_tree`, a copy
    of its files that git knows or would add) as a folder under `into`."""
    if revision is None:
        if not copy_working_tree:
            return ROOT
        listed = subprocess.run(
            ["git", "-C", ROOT, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            capture_output=True,
            text=True,
        )
        if listed.returncode != 0:
            raise CompareFailed(f"cannot list the working tree: {listed.stderr.strip() or 'git ls-files failed'}")
        folder = os.path.join(into, "working-tree")
        for name in filter(None, listed.stdout.split("\0")):
            source = os.path.join(ROOT, name)
            if os.path.isfile(source):
                os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
                shutil.copy2(source, os.path.join(folder, name))
        return folder
    folder = os.path.join(into, re.sub(r"[^A-Za-z0-9_.-]", "_", revision))
    archive = os.path.join(into, "tree.tar")
    done = subprocess.run(
        ["git", "-C", ROOT, "archive", "--format=tar", "-o", archive, revision], capture_output=True, text=True
    )
    if done.returncode != 0:
        raise CompareFailed(f"cannot export {revision!r}: {done.stderr.strip() or 'git archive failed'}")
    safe = {"filter": "data"} if hasattr(tarfile, "data_filter") else {}  # Python 3.10.12+ and 3.11.4+
    with tarfile.open(archive) as tar:
        tar.extractall(folder, **safe)
    os.remove(archive)
    if not os.path.exists(os.path.join(folder, "benchmarks", "run.py")):
        raise CompareFailed(f"{revision} has no benchmarks/run.py")
    return folder


def compile_runtime(tree):
    """Compile `tree`'s runtime to C in place, as its own setup.py does for a regular install.
    Returns how the tree's runtime runs: "compiled" or, for a tree without that build step
    (older revisions), "pure Python"."""
    if not os.path.exists(os.path.join(tree, "tools", "build_runtime.py")):
        return "pure Python"
    done = subprocess.run(
        [sys.executable, "setup.py", "--quiet", "build_ext", "--inplace"], capture_output=True, text=True, cwd=tree
    )
    compiled = [n for n in os.listdir(os.path.join(tree, "scoopc", "runtime")) if n.startswith("processor.")]
    if done.returncode != 0 or not any(not n.endswith(".py") for n in compiled):
        last = (done.stderr.strip() or done.stdout.strip() or "no output").splitlines()[-1]
        raise CompareFailed(f"{tree}: compiling the runtime failed: {last}")
    return "compiled"


def command(tree, args):
    run_py = os.path.join(tree, "benchmarks", "run.py")
    line = [sys.executable, run_py, "--repeat", str(args.repeat)]
    with open(run_py, encoding="utf-8") as f:
        if "--no-unpinned-figure" in f.read():  # not compared: skip its runs (older run.py: none)
            line.append("--no-unpinned-figure")
    if args.smoke:
        line.append("--smoke")
    elif not args.full:
        line.append("--quick")
    line += ["--only", *(args.only or BENCHMARKS)]
    if args.api:
        line.append("--no-compiled")
    return line


def run_once(tree, args):
    """{benchmark: ratio} from one run of the tree's run.py, with the tree's scoopc first on the path."""
    env = dict(os.environ, PYTHONPATH=tree + os.pathsep + os.environ.get("PYTHONPATH", ""))
    done = subprocess.run(command(tree, args), capture_output=True, text=True, cwd=tree, env=env)
    if done.returncode != 0:
        last = (done.stderr.strip() or done.stdout.strip() or "no output").splitlines()[-1]
        raise CompareFailed(f"{tree}: run.py exited {done.returncode}: {last}")
    key = "ratio" if args.api else "compiled_ratio"
    found = {}
    for line in done.stdout.splitlines():
        name = line.split(" ", 1)[0]
        match = re.search(rf"(?:^| ){key}=([0-9.]+)", line)
        if name in BENCHMARKS and match:
            found[name] = float(match.group(1))
    if not found:
        raise CompareFailed(f"{tree}: run.py printed no {key}=")
    return found


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def report(label_before, label_after, rounds):
    names = [n for n in BENCHMARKS if all(n in r for side in rounds.values() for r in side)]
    print(f"\n{'benchmark':<12} {'before':>8} {'after':>8} {'change':>8}   (median of {len(rounds['before'])} rounds)")
    medians = {side: {n: statistics.median(r[n] for r in rounds[side]) for n in names} for side in rounds}
    for n in names:
        b, a = medians["before"][n], medians["after"][n]
        print(f"{n:<12} {b:>8.2f} {a:>8.2f} {(a / b - 1) * 100:>+7.1f}%")
    gb, ga = geomean(list(medians["before"].values())), geomean(list(medians["after"].values()))
    print(f"{'geomean':<12} {gb:>8.2f} {ga:>8.2f} {(ga / gb - 1) * 100:>+7.1f}%")
    print(f"before = {label_before}; after = {label_after}")


def main(argv=None):
    args = parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="scoopc-compare-") as tmp:
        try:
            trees = {
                "before": export(args.before, tmp),
                "after": export(args.after, tmp, copy_working_tree=args.compiled_runtime),
            }
        except CompareFailed as e:
            print(f"compare: {e}", file=sys.stderr)
            return 2
        labels = {"before": args.before, "after": args.after or WORKING_TREE}
        if args.compiled_runtime:
            for side in ("before", "after"):
                print(f"# compiling the runtime of {labels[side]} ...", flush=True)
                try:
                    labels[side] += f" ({compile_runtime(trees[side])} runtime)"
                except CompareFailed as e:
                    print(f"compare: {e}", file=sys.stderr)
                    return 1
        rounds = {"before": [], "after": []}
        load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
        print(f"# {len(args.only or BENCHMARKS)} benchmarks, {args.rounds} rounds, load {load:.1f}", flush=True)
        for i in range(args.rounds):
            for side in ("before", "after"):
                start = time.perf_counter()
                try:
                    found = run_once(trees[side], args)
                except CompareFailed as e:
                    print(f"compare: {e}", file=sys.stderr)
                    return 1
                rounds[side].append(found)
                shown = " ".join(f"{n}={v:.2f}" for n, v in found.items())
                print(f"round {i + 1} {side:<6} {shown}  ({time.perf_counter() - start:.0f} s)", flush=True)
        report(labels["before"], labels["after"], rounds)
    return 0


if __name__ == "__main__":
    sys.exit(main())
