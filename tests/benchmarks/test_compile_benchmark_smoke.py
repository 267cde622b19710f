"""Smoke test of benchmarks/compile.py: a tiny generated program, the output's format (never timings),
including the full cold compile and the cached start-up of a sample."""

import os
import re
import subprocess
import sys

COMPILE = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "compile.py")


def test_compile_benchmark_reports_cold_and_cached_times_with_ratios():
    done = subprocess.run(
        [sys.executable, COMPILE, "--lines", "200", "--repeat", "1"], capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("# scoopc compile benchmark: stdlib ") and "program " in lines[0]
    assert re.search(r"^parse only \(baseline\): \d+\.\d+ s", done.stdout, re.M)
    assert re.search(r"^cold parse\+check: \d+\.\d+ s  ratio=\d+\.\d+  target < 2 s: (met|MISSED)$", done.stdout, re.M)
    assert re.search(
        r"^cached parse\+check: \d+\.\d+ s  ratio=\d+\.\d+  target < 0\.5 s: (met|MISSED)$", done.stdout, re.M
    )
    assert re.search(
        r"^full cold compile of the stdlib and producer_consumer \(scoopc compile, no caches\): "
        r"\d+\.\d+ s  target < 3 s: (met|MISSED)$",
        done.stdout,
        re.M,
    )
    assert re.search(
        r"^cached scoopc run producer_consumer: start-up to the first output line \d+\.\d+ s  "
        r"target < 0\.5 s: (met|MISSED)$",
        done.stdout,
        re.M,
    )
    assert re.search(
        r"^cached scoopc run of a trivial program \(whole run\): \d+\.\d+ s  "
        r"target < 0\.5 s: (met|MISSED)$",
        done.stdout,
        re.M,
    )
