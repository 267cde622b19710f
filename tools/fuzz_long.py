"""The seeded long fuzzing run (docs/GUARANTEES.md): mutants of the golden and valid programs are checked; those
that check clean are compiled; the first --runs of the compiled ones are run. A crash of the checker or
the code generator, a clean mutant the compiler refuses, or a run that ends with an exit status other
than 0 or 3 (4 is an internal error) is a bug: each is kept under --keep as `<kind>-<index>/` (the
mutant's sources and a file WHAT saying what happened). Mutants that loop forever are stopped after
--timeout seconds and counted apart.

Usage: nice -n 19 python tools/fuzz_long.py [--seed 25] [--mutants 20000] [--runs 2000] [--minutes 60]
                                              [--jobs N] [--keep fuzz-findings]

Deterministic given --seed, whatever --jobs and the scheduling:
- mutant i (0 <= i < --mutants) is made from random.Random(f"{seed}/{i}") alone: its program, the file
  mutated and the one to three edits (the mutation operators of tests/semantics/test_checker_robustness.py);
- mutant i is run iff it compiled and fewer than --runs mutants of smaller index compiled (the first
  --runs compiled mutants in index order). The parent decides this once every mutant before i has
  been examined, so runs follow the examination closely.
The counts therefore depend on the seed alone (except a run near --timeout on a loaded machine).

Work: --jobs worker processes (default: the number of CPUs; 1 works in this process). Each loads the
standard library's declarations and the compiled library's facts once; a mutant is checked once and
that check is the compilation's (scoopc.driver.Compilation, as `scoopc compile` does); the compiled
package is written beside a link to the run's one copy of the compiled standard library
(`eiffel_base`, with its bytecode) instead of a copy of its own; a run is `python -m <package>` in a
process of its own, judged by its exit status.

--minutes is the budget: no mutant or run starts after it (those under way finish: one per worker,
each bounded by --timeout); the end line says how many mutants were examined when not all were.
Prints a progress line every 500 mutants and the counts at the end. Exit status 1 when a bug was found.
"""

from __future__ import annotations

import argparse
import gc
import multiprocessing
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
import traceback
from concurrent.futures import FIRST_COMPLETED, Executor, Future, ProcessPoolExecutor, wait
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "semantics"))

from test_checker_robustness import WORDS, mutate  # noqa: E402  (the suite's mutation operators)

from scoopc import pipeline  # noqa: E402
from scoopc.driver import compilation as compiling  # noqa: E402
from scoopc.driver.library import compiled_library  # noqa: E402
from scoopc.driver.packages import BASE_PACKAGE  # noqa: E402
from scoopc.exits import UsageError  # noqa: E402

SOURCES = sorted(p for p in (ROOT / "tests" / "golden").iterdir() if p.is_dir() and any(p.glob("*.e")))
SOURCES += sorted(p for p in (ROOT / "tests" / "semantics" / "valid").iterdir() if p.is_dir())
BUGS = ("checker crash", "compile crash", "compile refused", "run exit other")
PROGRESS_EVERY = 500


class Worker:
    """What a worker process keeps from one mutant to the next: the programs' texts, the standard
    library's declarations, the compiled library, the folders it works and keeps findings in."""

    def __init__(self, work: Path, keep: Path, timeout: float):
        self.work, self.keep, self.timeout = work, keep, timeout
        self.programs = [
            (p.name, {f.name: f.read_text(encoding="utf-8") for f in sorted(p.glob("*.e"))}) for p in SOURCES
        ]
        self.stdlib = pipeline.load_stdlib()
        self.library = compiled_library()
        # The runs' eiffel_base: this run's own copy, with its bytecode (another scoopc may replace or prune
        # the cache's meanwhile); made once, by the first worker.
        self.base = work / "library" / BASE_PACKAGE
        if not self.base.exists():
            shutil.copytree(self.library.path / BASE_PACKAGE, self.base)
        compiling.Compilation([str(SOURCES[0])], stdlib=self.stdlib).checked  # noqa: B018 - the parser loaded, warm

    def make_mutant(self, seed: int, index: int) -> Path:
        """Mutant `index` of `seed`, written as work/<index>/<program>/."""
        rng = random.Random(f"{seed}/{index}")
        name, texts = self.programs[rng.randrange(len(self.programs))]
        folder = self.work / str(index) / name
        folder.mkdir(parents=True)
        files = sorted(texts)
        target = files[rng.randrange(len(files))]
        lines = texts[target].splitlines()
        for _ in range(rng.randint(1, 3)):
            mutate(
                lines,
                (
                    rng.choice(["delete", "replace", "swap"]),
                    rng.randrange(10**6),
                    rng.randrange(10**6),
                    rng.choice(WORDS),
                ),
            )
        for file, text in texts.items():
            (folder / file).write_text("\n".join(lines) + "\n" if file == target else text, encoding="utf-8")
        return folder

    def examine(self, seed: int, index: int) -> tuple[int, list[str], str | None]:
        """Check mutant `index`, and compile it when clean: (index, what to count, the compiled
        package's folder when it compiled). Its folder stays while it may be run."""
        mutant = self.make_mutant(seed, index)
        kinds = ["mutants"]
        try:
            compilation = compiling.Compilation([str(mutant)], stdlib=self.stdlib)
            checked = compilation.checked
        except Exception:
            return self._end(index, kinds, "checker crash", traceback.format_exc())
        if checked.has_errors:
            return self._end(index, kinds)
        kinds.append("clean")
        try:
            compilation.__dict__["library"] = self.library  # the cached_property, filled with what was read once
            package = compiling.package_name(compilation.root.key)
            out = mutant.parent / "out"
            out.mkdir()
            compilation.write_package(out, package)
        except UsageError:
            return self._end(index, kinds, "no root")  # the mutant lost its root class: exit 2
        except compiling.SourceErrors as refused:
            return self._end(index, kinds, "compile refused", "\n".join(map(str, refused.diagnostics)))
        except Exception:
            return self._end(index, kinds, "compile crash", traceback.format_exc())
        (out / BASE_PACKAGE).symlink_to(self.base, target_is_directory=True)
        return index, [*kinds, "compiled"], str(out / package)

    def run(self, index: int, package: str) -> tuple[int, list[str], None]:
        """Run a compiled mutant: `python -m <package>`, judged by its exit status."""
        program = Path(package)
        try:
            done = subprocess.run(
                [sys.executable, "-m", program.name],
                cwd=program.parent,
                stdin=subprocess.DEVNULL,
                capture_output=True,
                text=True,
                timeout=self.timeout,
            )
        except subprocess.TimeoutExpired:
            return self._end(index, ["ran"], "run timeout")
        if done.returncode in (0, 3):
            return self._end(index, ["ran"], f"run exit {done.returncode}")
        what = f"exit {done.returncode}\n{done.stderr[-3000:]}"
        return self._end(index, ["ran"], "run exit other", what)

    def _end(self, index: int, kinds: list[str], kind: str = "", what: str = "") -> tuple[int, list[str], None]:
        """Done with a mutant: `kind` counted, a bug kept as keep/<kind>-<index>/<program>/ with the
        file WHAT, the mutant's folder removed."""
        if what:
            place = self.keep / f"{kind.replace(' ', '-')}-{index}"
            shutil.copytree(self.work / str(index), place, ignore=shutil.ignore_patterns("out"), dirs_exist_ok=True)
            (place / "WHAT").write_text(what, encoding="utf-8")
        remove(self.work, index)
        return index, [*kinds, kind] if kind else kinds, None


def remove(work: Path, index: int) -> None:
    shutil.rmtree(work / str(index), ignore_errors=True)


_worker: Worker | None = None  # the worker of this process (a pool's process, or the parent with --jobs 1)


def _start(work: Path, keep: Path, timeout: float) -> None:
    global _worker
    _worker = Worker(work, keep, timeout)


def _examine(seed: int, index: int):
    assert _worker is not None
    return _worker.examine(seed, index)


def _run(index: int, package: str):
    assert _worker is not None
    return _worker.run(index, package)


class InProcess(Executor):
    """--jobs 1: each task done at once in this process (the same code as the workers')."""

    def submit(self, fn, /, *args, **kwargs):
        future: Future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as problem:
            future.set_exception(problem)
        return future


class Counts(dict):
    def add(self, key: str) -> None:
        self[key] = self.get(key, 0) + 1

    def line(self) -> str:
        """The counts, the four totals first and then the kinds in alphabetical order (the same
        line whatever the order of the events)."""
        first = ["mutants", "clean", "compiled", "ran"]
        return ", ".join(f"{k} {self[k]}" for k in first + sorted(set(self) - set(first)))


def fuzz(seed: int, mutants: int, runs: int, minutes: float, timeout: float, keep: Path, jobs: int) -> Counts:
    """The run's counts ("mutants" below `mutants` when the budget ended it early)."""
    start = time.monotonic()
    keep.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="scoopc-fuzz-") as tmp:
        work = Path(tmp)
        forking = "fork" in multiprocessing.get_all_start_methods()
        if jobs == 1 or forking:  # forked workers start with this process's worker, ready
            _start(work, keep, timeout)
        if jobs == 1:
            pool: Executor = InProcess()
        elif forking:
            gc.freeze()  # the collector then leaves the pages the workers share alone
            pool = ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("fork"))
        else:
            context = multiprocessing.get_context("spawn")
            pool = ProcessPoolExecutor(jobs, mp_context=context, initializer=_start, initargs=(work, keep, timeout))
        try:
            with pool:
                return Drive(pool, seed, runs, work, start, start + minutes * 60).go(mutants, 2 * jobs)
        finally:
            gc.unfreeze()


class Drive:
    """The parent's loop: mutants handed out in index order, at most `window` being examined at a time;
    a compiled mutant is run once every mutant below it was examined (the rule of the module's doc)."""

    def __init__(self, pool: Executor, seed: int, runs: int, work: Path, start: float, deadline: float):
        self.pool, self.seed, self.runs, self.work = pool, seed, runs, work
        self.start, self.deadline = start, deadline
        self.counts = Counts(mutants=0, clean=0, compiled=0, ran=0)
        self.examined: dict[int, str | None] = {}  # examined mutants not yet decided on: their package
        self.decided = 0  # every mutant below it was examined, and run or not
        self.chosen = 0  # compiled mutants chosen to run
        self.flying: set[Future] = set()

    def go(self, mutants: int, window: int) -> Counts:
        submitted = examining = 0
        while True:
            while submitted < mutants and examining < window and time.monotonic() < self.deadline:
                self.flying.add(self.pool.submit(_examine, self.seed, submitted))
                submitted += 1
                examining += 1
            if not self.flying:
                return self.counts
            done, self.flying = wait(self.flying, return_when=FIRST_COMPLETED)
            for future in sorted(done, key=lambda f: f.result()[0]):
                index, kinds, package = future.result()
                for kind in kinds:
                    self.counts.add(kind)
                if "mutants" in kinds:
                    examining -= 1
                    self.examined[index] = package
                    if self.counts["mutants"] % PROGRESS_EVERY == 0:
                        print(f"  {time.monotonic() - self.start:7.0f} s: {self.counts.line()}", flush=True)
            self.decide()

    def decide(self) -> None:
        """Run or drop each compiled mutant all of whose predecessors were examined."""
        while self.decided in self.examined:
            package = self.examined.pop(self.decided)
            if package is not None and self.chosen < self.runs and time.monotonic() < self.deadline:
                self.chosen += 1
                self.flying.add(self.pool.submit(_run, self.decided, package))
            elif package is not None:
                remove(self.work, self.decided)
            self.decided += 1


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=25)
    ap.add_argument("--mutants", type=int, default=20_000)
    ap.add_argument("--runs", type=int, default=2_000)
    ap.add_argument("--minutes", type=float, default=60.0)
    ap.add_argument("--timeout", type=float, default=5.0, help="seconds a mutant may run")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes (1: this process)")
    ap.add_argument("--keep", type=Path, default=Path("fuzz-findings"))
    args = ap.parse_args(argv)
    jobs = max(1, args.jobs)
    start = time.monotonic()
    print(f"fuzz_long: seed {args.seed}, {len(SOURCES)} programs, {jobs} jobs, findings in {args.keep}", flush=True)
    counts = fuzz(args.seed, args.mutants, args.runs, args.minutes, args.timeout, args.keep, jobs)
    print(f"fuzz_long: {time.monotonic() - start:.0f} s, seed {args.seed}: {counts.line()}", flush=True)
    if counts["mutants"] < args.mutants:
        print(
            f"fuzz_long: the {args.minutes:g}-minute budget ended the run: "
            f"{counts['mutants']} of {args.mutants} mutants examined"
        )
    return 1 if any(counts.get(kind) for kind in BUGS) else 0


if __name__ == "__main__":
    sys.exit(main())
