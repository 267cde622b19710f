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


def _compare_module():
    import importlib.util

    spec = importlib.util.spec_from_file_location("compare", COMPARE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_with_compiled_runtime_the_working_tree_is_copied_not_built_in(tmp_path):
    """--compiled-runtime builds in the tree it measures: for the working tree, a copy, so that
    no compiled module lands in the checkout (it would hide later edits of the source)."""
    module = _compare_module()
    assert module.export(None, str(tmp_path)) == module.ROOT
    copy = module.export(None, str(tmp_path), copy_working_tree=True)
    assert copy != module.ROOT
    for name in ("setup.py", "tools/build_runtime.py", "scoopc/runtime/processor.py", "benchmarks/run.py"):
        assert os.path.isfile(os.path.join(copy, name)), name
    assert not os.path.exists(os.path.join(copy, ".git"))


def test_a_tree_from_before_the_compiled_runtime_runs_pure_python(tmp_path):
    module = _compare_module()
    (tmp_path / "scoopc" / "runtime").mkdir(parents=True)
    (tmp_path / "scoopc" / "runtime" / "processor.py").write_text("")
    assert module.compile_runtime(str(tmp_path)) == "pure Python"
