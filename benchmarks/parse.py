"""Parser speed: lines per second (every line counted) over a fixed corpus of our own Eiffel code
(the stdlib, the samples and the construct-covering test programs), repeated to at least 50,000 lines.

Usage: python benchmarks/parse.py [--lines N] [--repeat K]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from scoopc.parse import parser  # noqa: E402
from scoopc.source import SourceFile  # noqa: E402

CORPUS_DIRS = ("stdlib", "samples", "tests/syntax/valid")


def corpus(min_lines: int) -> list[tuple[str, str]]:
    files = [p for d in CORPUS_DIRS for p in sorted((ROOT / d).rglob("*.e"))]
    texts = [(str(p.relative_to(ROOT)), p.read_text(encoding="utf-8")) for p in files]
    if not texts:
        sys.exit("benchmarks/parse.py: no .e files found in " + ", ".join(CORPUS_DIRS))
    chosen, lines = [], 0
    while lines < min_lines:
        for name, text in texts:
            chosen.append((name, text))
            lines += text.count("\n") + 1
    return chosen


def one_pass(files: list[tuple[str, str]]) -> float:
    start = time.perf_counter()
    for name, text in files:
        result = parser.parse(SourceFile(name, text))
        if result.diagnostics:
            sys.exit(f"benchmarks/parse.py: {name} does not parse: {result.diagnostics[0]}")
    return time.perf_counter() - start


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=50_000, help="corpus size in lines (default 50,000)")
    options.add_argument("--repeat", type=int, default=5, help="timed passes; the median is reported")
    args = options.parse_args()
    files = corpus(args.lines)
    total = sum(text.count("\n") + 1 for _, text in files)
    start = time.perf_counter()
    parser.parse(SourceFile("warm-up.e", files[0][1]))
    print(f"grammar load and first parse: {time.perf_counter() - start:.3f} s")
    times = [one_pass(files) for _ in range(args.repeat)]
    median = statistics.median(times)
    print(
        f"corpus: {len(files)} files, {total} lines; {args.repeat} passes, median {median:.3f} s "
        f"(best {min(times):.3f} s)"
    )
    print(f"{total / median:.0f} lines/s")


if __name__ == "__main__":
    main()
