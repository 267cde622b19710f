"""The seeded long fuzzing run of issue 25: mutants of the golden and valid programs are checked; those
that check clean are compiled; the first --runs of those are run. A crash of the checker or the code
generator, or a run that ends with exit 4 (an internal error), is a bug: each is kept under --keep
with what happened. Mutants that loop forever are stopped after --timeout seconds and counted apart.

Usage: nice -n 19 python tools/fuzz_long.py [--seed 25] [--mutants 20000] [--runs 2000] [--minutes 60]

Prints a progress line every 500 mutants and the counts at the end. Exit status 1 when a bug was found.
"""

from __future__ import annotations

import argparse
import random
import shutil
import subprocess
import sys
import tempfile
import time
import traceback
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "semantics"))

from test_checker_robustness import WORDS, mutate  # noqa: E402  (the suite's mutation operators)

from scoopc import api, pipeline  # noqa: E402
from scoopc.exits import UsageError  # noqa: E402
from scoopc.project import collect  # noqa: E402

SOURCES = sorted(p for p in (ROOT / "tests" / "golden").iterdir() if p.is_dir() and any(p.glob("*.e")))
SOURCES += sorted(p for p in (ROOT / "tests" / "semantics" / "valid").iterdir() if p.is_dir())


BUGS = ("checker crash", "compile crash", "compile refused", "run exit other")


def make_mutant(rng: random.Random, folder: Path) -> Path:
    program = rng.choice(SOURCES)
    target_dir = folder / program.name
    target_dir.mkdir()
    sources = sorted(program.glob("*.e"))
    for source in sources:
        shutil.copy(source, target_dir / source.name)
    target = target_dir / rng.choice(sources).name
    lines = target.read_text(encoding="utf-8").splitlines()
    for _ in range(rng.randint(1, 3)):
        edit = (
            rng.choice(["delete", "replace", "swap"]),
            rng.randrange(10**6),
            rng.randrange(10**6),
            rng.choice(WORDS),
        )
        mutate(lines, edit)
    target.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return target_dir


class Counts(dict):
    def add(self, key: str) -> None:
        self[key] = self.get(key, 0) + 1

    def line(self) -> str:
        return ", ".join(f"{k} {v}" for k, v in self.items())


def keep(where: Path, mutant: Path, kind: str, text: str, counts: Counts) -> None:
    counts.add(kind)
    place = where / f"{kind}-{counts[kind]}"
    shutil.copytree(mutant, place)
    (place / "WHAT").write_text(text, encoding="utf-8")


def run_one(program: Path, timeout: float) -> tuple[str, str]:
    try:
        done = subprocess.run(
            [sys.executable, "-m", program.name],
            cwd=program.parent,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return "run timeout", ""
    if done.returncode in (0, 3):
        return f"run exit {done.returncode}", ""
    return "run exit other", f"exit {done.returncode}\n{done.stderr[-3000:]}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=25)
    ap.add_argument("--mutants", type=int, default=20_000)
    ap.add_argument("--runs", type=int, default=2_000)
    ap.add_argument("--minutes", type=float, default=60.0)
    ap.add_argument("--timeout", type=float, default=5.0, help="seconds a mutant may run")
    ap.add_argument("--keep", type=Path, default=Path("fuzz-findings"))
    args = ap.parse_args(argv)
    rng = random.Random(args.seed)
    stdlib = pipeline.load_stdlib()
    counts = Counts(mutants=0, clean=0, compiled=0, ran=0)
    start, deadline = time.monotonic(), time.monotonic() + args.minutes * 60
    args.keep.mkdir(parents=True, exist_ok=True)
    print(f"fuzz_long: seed {args.seed}, {len(SOURCES)} programs, findings in {args.keep}", flush=True)
    while counts["mutants"] < args.mutants and time.monotonic() < deadline:
        with tempfile.TemporaryDirectory(prefix="scoopc-fuzz-") as tmp:
            mutant = make_mutant(rng, Path(tmp))
            counts.add("mutants")
            try:
                checked = pipeline.check_project(collect([str(mutant)]), stdlib=stdlib)
            except Exception:
                keep(args.keep, mutant, "checker crash", traceback.format_exc(), counts)
                continue
            if checked.has_errors:
                continue
            counts.add("clean")
            try:
                result = api.compile([str(mutant)], Path(tmp) / "out")
            except UsageError:
                counts.add("no root")  # the mutant lost its root class: the user's mistake, exit 2
                continue
            except Exception:
                keep(args.keep, mutant, "compile crash", traceback.format_exc(), counts)
                continue
            if result.status != 0:
                keep(args.keep, mutant, "compile refused", "\n".join(map(str, result.diagnostics)), counts)
                continue
            counts.add("compiled")
            if counts["ran"] < args.runs:
                counts.add("ran")
                kind, text = run_one(result.package, args.timeout)
                if text:
                    keep(args.keep, mutant, kind, text, counts)
                else:
                    counts.add(kind)
        if counts["mutants"] % 500 == 0:
            print(f"  {time.monotonic() - start:7.0f} s: {counts.line()}", flush=True)
    print(f"fuzz_long: {time.monotonic() - start:.0f} s, seed {args.seed}: {counts.line()}", flush=True)
    bugs = sum(
        v for k, v in counts.items() if k in ("checker crash", "compile crash", "compile refused", "run exit other")
    )
    return 1 if bugs else 0


if __name__ == "__main__":
    sys.exit(main())
