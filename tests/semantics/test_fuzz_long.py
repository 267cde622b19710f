"""tools/fuzz_long.py, the seeded long fuzzing run, on a few mutants: its counts depend on the seed
alone (not on --jobs), and a bug of the compiler or of a run is counted, kept and makes it fail."""

import importlib
import subprocess
import sys
from pathlib import Path

import pytest

TOOL = Path(__file__).resolve().parents[2] / "tools" / "fuzz_long.py"


@pytest.fixture(scope="module")
def fuzz_long():
    """The tool as the module `fuzz_long`: its workers' tasks are pickled by that name."""
    if str(TOOL.parent) not in sys.path:
        sys.path.insert(0, str(TOOL.parent))
    return importlib.import_module("fuzz_long")


def test_the_counts_are_the_same_with_one_job_and_with_two(fuzz_long, tmp_path):
    one = fuzz_long.fuzz(3, 16, 2, 5.0, 10.0, tmp_path / "one", jobs=1)
    two = fuzz_long.fuzz(3, 16, 2, 5.0, 10.0, tmp_path / "two", jobs=2)
    assert one == two
    # At most `runs` (2) mutants run; which ones (and whether one lost its root class) depends
    # on the seed and on the golden programs the mutants are made from.
    assert one["mutants"] == 16 and 1 <= one["ran"] <= 2 and one["compiled"] >= one["ran"]
    assert not any(one.get(kind) for kind in fuzz_long.BUGS)
    assert not any((tmp_path / "one").iterdir())


def test_a_crash_of_the_code_generator_is_counted_kept_and_fails_the_run(fuzz_long, tmp_path, monkeypatch, capsys):
    def crash(self, out, package):
        raise RuntimeError("planted")

    monkeypatch.setattr(fuzz_long.compiling.Compilation, "write_package", crash)
    status = fuzz_long.main(["--seed", "3", "--mutants", "8", "--jobs", "1", "--keep", str(tmp_path)])
    assert status == 1
    counts = capsys.readouterr().out.splitlines()[-1]
    crashes = sorted(tmp_path.glob("compile-crash-*"))
    assert crashes and f"compile crash {len(crashes)}" in counts
    assert "RuntimeError: planted" in (crashes[0] / "WHAT").read_text()
    assert any(crashes[0].glob("*/*.e"))  # the mutant's sources, to reproduce it


def test_a_run_ending_with_exit_4_is_counted_kept_and_fails_the_run(fuzz_long, tmp_path, monkeypatch):
    def internal_error(command, **options):
        return subprocess.CompletedProcess(command, 4, "", "Traceback: planted")

    monkeypatch.setattr(fuzz_long.subprocess, "run", internal_error)
    counts = fuzz_long.fuzz(3, 8, 1, 5.0, 10.0, tmp_path, jobs=1)
    assert counts["ran"] == 1 and counts["run exit other"] == 1
    (kept,) = tmp_path.glob("run-exit-other-*")
    assert "exit 4" in (kept / "WHAT").read_text()
