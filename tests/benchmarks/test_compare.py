"""benchmarks/compare.py: two revisions' ratios, alternating runs, a table of medians (never timings)."""

import os
import re
import subprocess
import sys

import pytest

COMPARE = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "compare.py")
NUMBER = r"\d+\.\d+"


def compare(*args):
    return subprocess.run([sys.executable, COMPARE, *args], capture_output=True, text=True, timeout=600)


def test_an_unknown_revision_is_a_clear_error():
    done = compare("no-such-revision-anywhere", "--rounds", "1")
    assert done.returncode == 2
    assert done.stderr.startswith("compare: cannot export 'no-such-revision-anywhere'")
    assert "Traceback" not in done.stderr


def test_rounds_must_be_positive():
    done = compare("HEAD", "--rounds", "0")
    assert done.returncode == 2 and "--rounds and --repeat must be at least 1" in done.stderr


@pytest.mark.slow
def test_head_against_the_working_tree():
    done = compare("HEAD", "--smoke", "--rounds", "1", "--repeat", "1", "--only", "threadring", "mutex")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert re.fullmatch(rf"round 1 before mutex={NUMBER} threadring={NUMBER}  \(\d+ s\)", lines[1]), lines
    assert re.fullmatch(rf"round 1 after  mutex={NUMBER} threadring={NUMBER}  \(\d+ s\)", lines[2]), lines
    table = {line.split()[0]: line.split()[1:] for line in lines[4:-1]}
    assert set(table) == {"benchmark", "mutex", "threadring", "geomean"}, lines
    for name in ("mutex", "threadring", "geomean"):
        before, after, change = table[name]
        assert re.fullmatch(NUMBER, before) and re.fullmatch(NUMBER, after) and change.endswith("%")
    assert lines[-1] == "before = HEAD; after = working tree"
