"""The programs that cover every construct of the grammar (tests/syntax/valid/) are valid
Eiffel: they check without a diagnostic."""

from pathlib import Path

import pytest

from scoopc import diagnostics, pipeline
from scoopc.project import collect

VALID = Path(__file__).resolve().parents[1] / "syntax" / "valid"
PROGRAMS = sorted(p for p in VALID.iterdir() if p.suffix == ".e" or p.is_dir())


@pytest.mark.parametrize("program", PROGRAMS, ids=lambda p: p.name)
def test_construct_program_checks_clean(program):
    checked = pipeline.check_project(collect([str(program)]))
    assert not checked.diagnostics, "\n".join(diagnostics.short(d) for d in checked.diagnostics)
