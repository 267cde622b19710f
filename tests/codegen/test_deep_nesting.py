"""Programs nested up to 2,000 deep (parentheses, `not`, operator chains, calls, `if`; loops,
`across`, `inspect`, separate blocks, `check ... then`, inline agents, manifest tuples and arrays,
calls as arguments of calls, long `elseif` chains) check, compile and run (issue 25 item 6); one
level deeper is SYNTAX-DEPTH at its place, never an internal error. The generated Python stays
within CPython's limits (scoopc/codegen/shallow.py). A rescue clause retries from 2,000 deep."""

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
    runs_as_expected(tmp_path, *program(kind, n))


def runs_as_expected(tmp_path, source: str, expected: str) -> None:
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


# Compound instructions and expressions that nest, each `n` deep, in a class of their own; the
# routine `g` and the separate object `p` are there for them.
COMPOUND = """class DEEP
create make
feature
	make
		local
			i, x: INTEGER
			b, c: BOOLEAN
			t: ANY
			f: FUNCTION [INTEGER]
			p: separate ANY
		do
			i := 1
			c := True
			create p
"""
COMPOUND_END = """
	g (k: INTEGER): INTEGER
		do
			Result := k + 1
		end
end
"""


def compound(kind: str, n: int) -> tuple[str, str, str]:
    """(instructions, what to print, expected output) of `kind` nested `n` deep. An inline agent
    nests four constructs (the agent, the assignment to Result, the parentheses, the call of
    `item`): `n` deep has n // 4 - 1 agents."""
    if kind == "loop":
        return "from until b loop\n" * n + "x := 7\nb := True\n" + "end\n" * n, "x", "7"
    if kind == "across":
        return "".join(f"across 1 |..| 1 as c{k} loop\n" for k in range(n)) + "x := 7\n" + "end\n" * n, "x", "7"
    if kind == "across_is":
        return "".join(f"across << {k} >> is e{k} loop\n" for k in range(n)) + "x := e1\n" + "end\n" * n, "x", "1"
    if kind == "inspect":
        return "inspect i when 1 then\n" * n + "x := 7\n" + "end\n" * n, "x", "7"
    if kind == "separate":
        return "".join(f"separate p as q{k} do\n" for k in range(n)) + "x := 7\n" + "end\n" * n, "x", "7"
    if kind == "check":
        return "check c then\n" * n + "x := 7\n" + "end\n" * n, "x", "7"
    if kind == "elseif":
        chain = "".join(f"elseif i = {k - n + 2} then\nx := {k}\n" for k in range(n))
        return "if i = 0 then\nx := -1\n" + chain + "end\n", "x", str(n - 1)
    if kind == "feature_calls":
        return "x := " + "g (" * n + "1" + ")" * n, "x", str(n + 1)
    if kind == "qualified_calls":
        return "x := " + "Current.g (" * n + "1" + ")" * n, "x", str(n + 1)
    if kind == "agents":
        agents = n // 4 - 1
        inner = "agent: INTEGER do Result := 7 end"
        return "f := " + "agent: INTEGER do Result := (" * agents + inner + ").item end" * agents, "f.item", "7"
    if kind == "tuple":
        return "t := " + "[" * n + "7" + "]" * n, "t.generating_type.name.count", str(len("TUPLE [") * n + 10 + n)
    if kind == "array":
        shown = "ARRAY [" * n + "INTEGER_32" + "]" * n
        return "t := " + "<< " * n + "7" + " >>" * n, "t.generating_type.name.count", str(len(shown))
    raise KeyError(kind)


COMPOUNDS = ["loop", "across", "across_is", "inspect", "separate", "check", "elseif", "feature_calls"]
COMPOUNDS += ["qualified_calls", "agents", "tuple", "array", "rescue"]


RESCUE = """
	retried: INTEGER
			-- 7, the second time: the first raises, and the rescue clause retries {n} levels deep.
		local
			tried: BOOLEAN
		do
			if tried then
				Result := 7
			else
				(create {{DEVELOPER_EXCEPTION}}).raise
			end
		rescue
			{rescue}
		end
"""


def compound_program(kinds, n: int) -> tuple[str, str]:
    """A class doing each of `kinds` `n` deep, and the output it prints. `rescue`: a routine whose
    rescue clause retries inside `n` `if`s."""
    body, expected, features = "", "", ""
    for kind in kinds:
        if kind == "rescue":
            instructions, shown, value = "x := retried", "x", "7"
            features += RESCUE.format(n=n, rescue="if True then\n" * n + "tried := True\nretry\n" + "end\n" * n)
        else:
            instructions, shown, value = compound(kind, n)
        body += instructions + f'\n\t\t\tprint (({shown}).out + "%N")\n'
        expected += value + "\n"
    return COMPOUND + body + "\t\tend\n" + features + COMPOUND_END, expected


def run_compounds(tmp_path, kinds, n):
    runs_as_expected(tmp_path, *compound_program(kinds, n))


def test_every_compound_seventy_deep_runs(tmp_path):
    run_compounds(tmp_path, COMPOUNDS, 70)


@pytest.mark.slow
@pytest.mark.parametrize("kind", [k for k in COMPOUNDS if k != "agents"])
def test_two_thousand_deep_compounds_run(tmp_path, kind):
    run_compounds(tmp_path, [kind], MAX_NESTING)


@pytest.mark.slow
def test_agents_two_thousand_deep_compile_and_two_hundred_calls_deep_run(tmp_path):
    """499 inline agents in one another check and compile; run, each calls the next: 199 such calls
    run, 499 are past the run-time call depth (docs/GUARANTEES.md, Limits), a run-time failure
    with its message and exit 3, not an internal error."""
    source, _ = compound_program(["agents"], MAX_NESTING)
    (tmp_path / "deep").mkdir()
    (tmp_path / "deep" / "deep.e").write_text(source)
    assert scoopc.compile([tmp_path / "deep"], tmp_path / "out").status == 0
    err = io.StringIO()
    assert scoopc.run([tmp_path / "deep"], stdout=io.StringIO(), stderr=err).status == 3
    assert "stack overflow (recursion too deep)" in err.getvalue() and "in DEEP.inline agent (deep.e:" in err.getvalue()
    run_compounds(tmp_path, ["agents"], 800)


# Parsing 2,000 levels takes half a second: the quick selection checks the kinds whose levels are
# counted apart from their parts (inspect, across, the elseif chain) and the agents.
QUICK_DEEPER = ("inspect", "across", "elseif", "agents")


@pytest.mark.parametrize(
    "kind", [k if k in QUICK_DEEPER else pytest.param(k, marks=pytest.mark.slow) for k in COMPOUNDS]
)
def test_a_compound_one_level_deeper_is_a_coded_diagnostic(tmp_path, kind):
    """(An `elseif` chain does not nest: 2,001 branches check.)"""
    source, _ = compound_program([kind], MAX_NESTING + (4 if kind == "agents" else 1))
    path = tmp_path / "deep.e"
    path.write_text(source)
    result = scoopc.check([path])
    assert [d.code for d in result.diagnostics] == ([] if kind == "elseif" else ["SYNTAX-DEPTH"])


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
