"""Robustness: valid programs mutated token by token (delete, insert, swap) always get an answer
from the front end, as diagnostics or a tree, never an internal error, within 2 s per input.

The default profile runs 2,000 examples; SCOOPC_HYPOTHESIS_PROFILE=thorough runs ten times more.
"""

import os
import re

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from scoopc import messages
from scoopc.parse import parser
from scoopc.source import SourceFile

from harness import ROOT

TOKEN = re.compile(r'"(?:%.|[^"%\n])*"|\'(?:%.|[^\'%\n])*\'|--[^\n]*|\s+|\w+|[^\w\s]{1,3}')
EXTRA_TOKENS = [
    "end",
    "do",
    "if",
    "then",
    "loop",
    "(",
    ")",
    "[",
    "]",
    ":=",
    ";",
    ",",
    ".",
    '"',
    "'",
    "%",
    "separate",
    "create",
    "class",
    "feature",
    "attached",
    "agent",
    "<<",
    ">>",
    "|..|",
    "0x",
    "1_000",
    '"[',
    ']"',
    "?",
    "{",
    "}",
    "old",
    "Result",
    "across",
    "as",
    "@",
]
EXAMPLES = 20_000 if os.environ.get("SCOOPC_HYPOTHESIS_PROFILE") == "thorough" else 2_000


def _programs() -> list[list[str]]:
    files = sorted((ROOT / "tests" / "syntax" / "valid").rglob("*.e")) + sorted((ROOT / "samples").rglob("*.e"))
    return [TOKEN.findall(f.read_text(encoding="utf-8")) for f in files]


PROGRAMS = _programs()


@st.composite
def mutated_programs(draw):
    tokens = list(draw(st.sampled_from(PROGRAMS)))
    for _ in range(draw(st.integers(1, 4))):
        where = draw(st.integers(0, len(tokens) - 1))
        kind = draw(st.sampled_from(["delete", "insert", "swap"]))
        if kind == "delete":
            del tokens[where]
        elif kind == "insert":
            tokens.insert(where, draw(st.sampled_from(EXTRA_TOKENS + tokens[:200])))
        else:
            other = draw(st.integers(0, len(tokens) - 1))
            tokens[where], tokens[other] = tokens[other], tokens[where]
    return "".join(tokens)


@pytest.mark.slow
@settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=True,  # no deadline: a loaded machine is no bug
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(mutated_programs())
def test_mutated_programs_get_located_diagnostics_or_a_tree(text):
    source = SourceFile("fuzz.e", text)
    result = parser.parse(source)
    assert result.tree is not None or result.diagnostics
    for d in result.diagnostics:
        assert d.code in messages.MESSAGES
        assert d.span is not None and 1 <= d.span.line <= source.line_count + 1
        assert d.message


def test_the_fuzz_corpus_is_not_empty():
    assert len(PROGRAMS) >= 10


def test_deep_nesting_parses_and_dumps_without_exhausting_the_stack():
    depth = 2_000  # the limit (scoopc/parse/nesting.py)
    text = f"class DEEP feature f: INTEGER do Result := {'(' * depth}1{')' * depth} end end\n"
    result = parser.parse(SourceFile("deep.e", text))
    assert not result.diagnostics
    from scoopc import syntax

    assert syntax.dump(result.tree).count("Parenthesized") == depth
    deeper = (
        text.replace("(1)", "((1))")
        .replace("Result := ", "Result := " + "(" * 3000)
        .replace(" end end", ")" * 3000 + " end end")
    )
    found = parser.parse(SourceFile("deep.e", deeper)).diagnostics
    assert [(d.code, d.span.column) for d in found] == [("SYNTAX-DEPTH", 44 + depth + 1)]  # the 2,002nd `(`
