"""Whole programs through the parser: valid ones match their AST dump goldens, invalid ones
report exactly the diagnostics their `-- E:` markers name."""

from pathlib import Path

import pytest

from scoopc import diagnostics, syntax
from scoopc.parse import parser
from scoopc.source import SourceFile

from harness import assert_markers, case_id, check_golden

HERE = Path(__file__).resolve().parent
VALID = sorted((HERE / "valid").rglob("*.e"))
INVALID = sorted((HERE / "invalid").rglob("*.e"))


@pytest.mark.parametrize("path", VALID, ids=lambda p: case_id(p, HERE / "valid"))
def test_valid_program_parses_to_its_golden_tree(request, path):
    result = parser.parse(SourceFile.read(path))
    assert not result.diagnostics, "\n".join(diagnostics.short(d) for d in result.diagnostics)
    golden = HERE / "expected" / (case_id(path, HERE / "valid")[:-2] + ".dump")
    check_golden(request, golden, syntax.dump(result.tree))


@pytest.mark.parametrize("path", INVALID, ids=lambda p: case_id(p, HERE / "invalid"))
def test_invalid_program_reports_its_marked_errors(path):
    result = parser.parse(SourceFile.read(path))
    assert result.tree is None or result.diagnostics
    assert_markers([path], result.diagnostics)


def test_the_corpus_is_not_empty():
    assert len(VALID) >= 30 and len(INVALID) >= 25
