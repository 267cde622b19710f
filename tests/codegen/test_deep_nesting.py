"""Programs nested up to 2,000 deep (parentheses, `not`, operator chains, calls, `if`) check,
compile and run (issue 25 item 6); one level deeper is SYNTAX-DEPTH at its place, never an
internal error. The generated Python stays within CPython's limits (scoopc/codegen/shallow.py)."""

import io

import pytest

import scoopc
from scoopc.parse.nesting import MAX_NESTING

HEADER = """class DEEP
create make
feature
	make
		local
			i, x: INTEGER
			s: STRING
			b, c: BOOLEAN
		do
			i := 1
			c := True
"""


def program(kind: str, n: int) -> tuple[str, str]:
    """(source, expected output) of `kind` nested `n` deep (parentheses around an operator count
    one level each, so `difference` and `and_or` nest n / 2 of both)."""
    shapes = {
        "parentheses": ("x := " + "(" * n + "i" + ")" * n, "x.out", "1"),
        "not": ("b := " + "not " * n + "c", "b.out", "True" if n % 2 == 0 else "False"),
        "sum": ("x := " + " + ".join(["i"] * (n + 1)), "x.out", str(n + 1)),
        "difference": ("x := " + "(i - " * (n // 2) + "i" + ")" * (n // 2), "x.out", str(1 - (n // 2) % 2)),
        "concatenation": ('s := "a"' + ' + "a"' * n, "s.count.out", str(n + 1)),
        "and": ("b := c" + " and c" * n, "b.out", "True"),
        "and_or": (
            "b := " + "".join("c and (" if k % 2 else "not c or (" for k in range(n // 2)) + "c" + ")" * (n // 2),
            "b.out",
            "True",
        ),
        "calls": ("x := " + "i.max (" * n + "1" + ")" * n, "x.out", "1"),
        "if": ("".join("if c then\n" for _ in range(n)) + "x := 7\n" + "end\n" * n, "x.out", "7"),
    }
    body, shown, expected = shapes[kind]
    return HEADER + body + f'\n\t\t\tprint ({shown} + "%N")\n\t\tend\nend\n', expected + "\n"


KINDS = ["parentheses", "not", "sum", "difference", "concatenation", "and", "and_or", "calls", "if"]


def run(tmp_path, kind, n):
    source, expected = program(kind, n)
    path = tmp_path / "deep.e"
    path.write_text(source)
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([path], stdout=out, stderr=err)
    assert result.status == 0, (result.diagnostics, err.getvalue()[-2000:])
    assert out.getvalue() == expected


@pytest.mark.parametrize("kind", KINDS)
def test_seventy_deep_runs(tmp_path, kind):
    run(tmp_path, kind, 70)


@pytest.mark.slow
@pytest.mark.parametrize("kind", KINDS)
def test_three_hundred_deep_runs(tmp_path, kind):
    run(tmp_path, kind, 300)


@pytest.mark.slow
@pytest.mark.parametrize("kind", KINDS)
def test_two_thousand_deep_runs(tmp_path, kind):
    run(tmp_path, kind, MAX_NESTING)


@pytest.mark.parametrize("kind", ["parentheses", "not", "sum", "concatenation", "and", "calls", "if"])
def test_one_level_deeper_is_a_coded_diagnostic(tmp_path, kind):
    source, _ = program(kind, MAX_NESTING + 1)
    path = tmp_path / "deep.e"
    path.write_text(source)
    result = scoopc.check([path])
    assert result.status == 1
    assert [d.code for d in result.diagnostics] == ["SYNTAX-DEPTH"]
    span = result.diagnostics[0].span
    assert span.file == str(path) and span.line >= 11


def test_nesting_limit_explained():
    from scoopc.explain import explain  # deferred: only this test needs it

    assert "2,000" in explain("SYNTAX-DEPTH")
