"""tests/errors/<CODE>/<case>/: each case is a small program checked as one cluster; its
`-- E: CODE` markers name exactly the errors `scoopc check` must report (codes with parentheses
are written with a dash in folder names: VUTA(3) -> VUTA-3). A case with an .ecf is checked
through it (the root rules need the root it names)."""

from pathlib import Path

import pytest

from scoopc import pipeline
from scoopc.project import collect

from harness import assert_markers, case_id

HERE = Path(__file__).resolve().parent
CASES = sorted(p for p in HERE.glob("*/*") if p.is_dir() and any(p.glob("*.e")))


@pytest.mark.parametrize("case", CASES, ids=lambda p: case_id(p, HERE))
def test_case_reports_exactly_its_marked_errors(case):
    checked = pipeline.check_project(collect(_paths(case)))
    assert_markers(sorted(case.glob("*.e")), checked.diagnostics)


@pytest.mark.parametrize("case", CASES, ids=lambda p: case_id(p, HERE))
def test_case_is_documented_and_filed_under_a_code_it_reports(case):
    assert (case / "README").is_file() or (case / "README.md").is_file(), f"{case} needs a one-line README"
    folder_code = case.parent.name
    marked = {code.replace("(", "-").replace(")", "") for code in _marked_codes(case)}
    assert folder_code in marked, f"{case}: no `-- E: {folder_code}` marker"


def _paths(case: Path) -> list[str]:
    """The case's .ecf when it has one (it names the root: VSRT, VSRP), else its folder."""
    return [str(p) for p in case.glob("*.ecf")] or [str(case)]


def _marked_codes(case: Path):
    from harness import expected_diagnostics

    return {code for (_, _, code, _) in expected_diagnostics(case.glob("*.e"))}
