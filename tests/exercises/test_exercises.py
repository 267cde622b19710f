"""The graded exercises (exercises/): each one's `scoopc test` suite passes with its reference
solution (here, beside this file) and fails, every test of it, with its starting skeleton. A
solution file replaces the skeleton's file of the same name; the skeleton's other files stay."""

from pathlib import Path

import pytest

import scoopc
from scoopc.exits import Exit

ROOT = Path(__file__).resolve().parents[2]
EXERCISES = ROOT / "exercises"
SOLUTIONS = Path(__file__).parent
ROBOTS = pytest.mark.slow  # a robot exercise runs seconds of simulation per test

CASES = [
    pytest.param("1_signaler", id="1_signaler"),
    pytest.param("2_controller", id="2_controller", marks=ROBOTS),
    pytest.param("3_behavior", id="3_behavior", marks=ROBOTS),
    pytest.param("4_bounded_buffer", id="4_bounded_buffer"),
    pytest.param("5_tangent_bug", id="5_tangent_bug", marks=ROBOTS),
]


def _with_solution(name: str) -> list[Path]:
    solution = sorted((SOLUTIONS / name).glob("*.e"))
    replaced = {p.name for p in solution}
    kept = [p for p in sorted((EXERCISES / name / "skeleton").glob("*.e")) if p.name not in replaced]
    return [EXERCISES / name / "tests", *kept, *solution]


def test_every_exercise_is_here():
    found = sorted(p.name for p in EXERCISES.iterdir() if p.is_dir())
    assert found == [p.values[0] for p in CASES]
    for name in found:
        assert (EXERCISES / name / "README.md").is_file() and list((EXERCISES / name / "skeleton").glob("*.e"))
        assert list((EXERCISES / name / "tests").glob("*_tests.e")) and list((SOLUTIONS / name).glob("*.e"))


@pytest.mark.parametrize("name", CASES)
def test_the_solution_passes_and_the_skeleton_fails(name):
    solved = scoopc.test(_with_solution(name), timeout=60)
    assert solved.status == Exit.OK and solved.tests, [t.report for t in solved.failed] or solved.diagnostics
    started = scoopc.test([EXERCISES / name / "tests", EXERCISES / name / "skeleton"], timeout=60)
    assert started.status == Exit.SOURCE and not [d for d in started.diagnostics if d.is_error]  # it checks...
    assert [t.name for t in started.tests] == [t.name for t in solved.tests]
    assert not [t.name for t in started.tests if t.passed]  # ...and fails every test
