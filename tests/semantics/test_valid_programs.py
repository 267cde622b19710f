"""Whole SCOOP programs that must check without a single error: tests/semantics/valid/<program>/
and the runnable samples/<program>/, each checked as one cluster with `scoopc check`'s pipeline."""

from pathlib import Path

import pytest

from scoopc import diagnostics, pipeline
from scoopc.project import collect

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def _programs(base: Path) -> list[Path]:
    return sorted(p for p in base.glob("*") if p.is_dir() and any(p.glob("*.e")))


PROGRAMS = _programs(HERE / "valid") + _programs(ROOT / "samples")


@pytest.mark.parametrize("program", PROGRAMS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_program_checks_without_errors(program):
    checked = pipeline.check_project(collect([str(p) for p in program.glob("*.ecf")] or [str(program)]))
    errors = [d for d in checked.diagnostics if d.is_error]
    assert not errors, f"{program.relative_to(ROOT)} should be valid, but:\n" + "\n".join(
        diagnostics.short(d) for d in errors
    )


def test_every_program_is_there():
    assert len(_programs(HERE / "valid")) >= 6
