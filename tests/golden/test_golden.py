"""Golden compile-and-run cases (tests/golden/README.md): for each tests/golden/<case>/, the
generated Python of the case's own classes equals expected/*.py and the run's output equals
expected.out (exactly, per processor or sorted, as case.toml says); the exit status and the first
lines of stderr (expected.err) are checked too, and neither stream may show a Python exception
(a built-in exception class's name, a traceback). `pytest --update-golden` rewrites expected/ and
the outputs from the current compiler: review the diff, the outputs are EiffelStudio's."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from golden_support import assert_no_host_exception, assert_output, compile_program, read_config, run_program  # noqa: E402

GOLDEN = Path(__file__).parent
CASES = sorted(p for p in GOLDEN.iterdir() if p.is_dir() and any(p.glob("*.e")))


def test_case_names_are_safe():
    """A case is imported as a package named like it: it must not shadow a Python module."""
    for case in CASES:
        assert case.name not in sys.stdlib_module_names, f"{case.name} shadows a standard module"
        assert (case / f"{case.name}.e").exists(), f"{case.name}: the root class file is missing"


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_golden(case: Path, tmp_path: Path, request):
    update = request.config.getoption("--update-golden")
    config = read_config(case)
    compiled, texts = compile_program(case, tmp_path, config.assertions)
    expected_dir = case / "expected"
    if update:
        if expected_dir.exists():
            shutil.rmtree(expected_dir)
        expected_dir.mkdir()
        for name, text in texts.items():
            (expected_dir / name).write_text(text)
    else:
        written = sorted(p.name for p in expected_dir.glob("*.py"))
        assert written == sorted(texts), f"{case.name}: generated modules differ: {sorted(texts)}"
        for name, text in texts.items():
            assert text == (expected_dir / name).read_text(), f"{case.name}: generated {name} differs"
    outcome = run_program(compiled, config)
    assert_no_host_exception(outcome.out, outcome.err, case.name)
    if update:
        out_path, err_path = case / "expected.out", case / "expected.err"
        out_path.write_text(outcome.out)
        if outcome.err:
            kept = len(err_path.read_text().splitlines()) if err_path.exists() else 1
            err_path.write_text("\n".join(outcome.err.splitlines()[:kept]) + "\n")
        elif err_path.exists():
            err_path.unlink()
    check_outcome(case, config, outcome)


def check_outcome(case: Path, config, outcome, label: str = "") -> None:
    """The run's exit status, output and first lines of stderr are the case's expected ones."""
    name = case.name + label
    out_path, err_path = case / "expected.out", case / "expected.err"
    assert outcome.status == config.exit, f"{name}: exit status {outcome.status}\n{outcome.err}"
    assert_output(config, out_path.read_text(), outcome.out, name)
    if err_path.exists():
        expected = err_path.read_text().splitlines()
        assert outcome.err.splitlines()[: len(expected)] == expected, f"{name}: stderr differs"
    else:
        assert outcome.err == "", f"{name}: unexpected stderr:\n{outcome.err}"


# Cases whose generated code has a direct block (runtime direct.py): compiled without them, every
# call goes through the general entry points, and the run must show exactly the same.
DIRECT = [c for c in CASES if any("here.claim1(" in p.read_text() for p in (c / "expected").glob("*.py"))]


def test_direct_blocks_are_covered():
    assert {"scoop_direct_blocks", "scoop_dirty_uncaught", "scoop_passive", "scoop_wait"} <= {c.name for c in DIRECT}


@pytest.mark.parametrize("case", DIRECT, ids=[c.name for c in DIRECT])
def test_general_path_agrees(case: Path, tmp_path: Path, monkeypatch):
    from scoopc.codegen import direct

    monkeypatch.setattr(direct, "block", lambda *args: None)
    config = read_config(case)
    compiled, texts = compile_program(case, tmp_path, config.assertions)
    assert not any("claim1" in text for text in texts.values())
    outcome = run_program(compiled, config)
    assert_no_host_exception(outcome.out, outcome.err, case.name)
    check_outcome(case, config, outcome, " (without direct blocks)")
