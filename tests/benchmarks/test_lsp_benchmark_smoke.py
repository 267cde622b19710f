"""Smoke test of benchmarks/lsp_recheck.py: a small class, two edits, the output's format (never
timings): the edits' diagnostics are checked by the benchmark itself."""

import os
import re
import subprocess
import sys

import pytest

pytestmark = pytest.mark.slow  # a server process and `scoopc check` runs: seconds

RECHECK = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "lsp_recheck.py")


def test_lsp_benchmark_reports_the_recheck_time_against_scoopc_check():
    done = subprocess.run(
        [sys.executable, RECHECK, "--lines", "100", "--repeat", "2"], capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert re.match(r"# scoopc lsp re-check: class of \d+ lines, repeat=2, server (pinned|unpinned)", lines[0])
    assert re.search(r"^first check after open \(stdlib loaded\): \d+\.\d+ s$", done.stdout, re.M)
    assert re.search(r"^baseline `scoopc check` in a fresh process: \d+\.\d+ s$", done.stdout, re.M)
    assert re.search(
        r"^re-check after an edit: median \d+\.\d+ s, min \d+\.\d+ s, max \d+\.\d+ s  ratio=\d+\.\d+  "
        r"target <= 0\.3 s: (met|MISSED)$",
        done.stdout,
        re.M,
    )
