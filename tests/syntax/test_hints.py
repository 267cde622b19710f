"""Syntax errors students make most carry a hint in plain words (shown by the pretty form)."""

from pathlib import Path

import pytest

from scoopc.parse import parser
from scoopc.source import SourceFile

INVALID = Path(__file__).resolve().parent / "invalid"

HINTS = {
    "assignment_in_condition.e": "to compare two values write `=`",
    "assignment_in_precondition.e": "to compare two values write `=`",
    "double_equals.e": "Eiffel compares with a single `=`",
    "missing_do.e": "is the `do` of this routine missing?",
    "equality_as_instruction.e": "to assign a value write `:=`",
    "semicolon_in_condition.e": "a condition ends with `then`",
    "missing_then.e": "a condition ends with `then`",
    "missing_loop_keyword.e": "ends with `loop`",
    "missing_end_if.e": "every `if` needs its own `end`",
    "reserved_loop_local.e": "choose another name",
}


@pytest.mark.parametrize("name, hint", sorted(HINTS.items()))
def test_common_mistakes_get_a_hint(name, hint):
    (d,) = parser.parse(SourceFile.read(INVALID / name)).diagnostics
    assert hint in d.hint


def test_other_syntax_errors_get_no_made_up_hint():
    (d,) = parser.parse(SourceFile.read(INVALID / "extra_close_paren.e")).diagnostics
    assert d.code == "SYNTAX" and d.hint == ""
