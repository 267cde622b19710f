"""Unknown names get a "did you mean" and hints that fit what was named (issue 22): features,
classes, locals, arguments, Result; a feature that exists but is not exported; a feature of an
entity in scope; VJAR's hint fits the target written."""

import pytest
from test_checker import check

BUF = """\
    class BUF
    feature
        last: STRING = "x"
        is_full: BOOLEAN do end
    feature {NONE}
        secret_count: INTEGER do end
    end
"""


CASES = {
    # routine body -> the hint its one error gets
    "feature_of_separate_argument": ("if buffer.is_ful then end", "did you mean `is_full`?"),
    "not_exported": (
        "print (plain.secret_cont)",
        "did you mean `secret_count`? BUF has it but does not export it to APP",
    ),
    "far_from_any_name": (
        "print (plain.zzz)",
        "BUF has no feature of this name: check the spelling, or add the feature to class BUF",
    ),
    "local": ("print (countr)", "did you mean `counter` (a local)?"),
    "argument": ("print (bufer)", "did you mean `buffer` (an argument)?"),
    "attribute": ("print (cont)", "did you mean `count` (a feature of APP)?"),
    "feature_in_scope": ("print (is_full)", "`is_full` is a feature of BUF: call it on `buffer` (`buffer.is_full`)"),
    "undeclared_target": (
        "total := 3",
        "to keep a value in this routine, declare a local in the `local` clause (`total: TYPE`); "
        "to keep it in the object, declare an attribute in class APP",
    ),
    "vjar_local": (
        "s := buffer.last",
        "the value is on another processor: declare the local `s: separate STRING_8`, or copy it to this "
        "processor: `create s.make_from_separate (buffer.last)` (STRING has it)",
    ),
}


@pytest.fixture(scope="module")
def found(tmp_path_factory):
    """One program with one mistake per routine (one check for all cases): routine name -> (code, hint)."""
    routines = []
    for name, (body, _) in CASES.items():
        routines.append(
            f"case_{name} (buffer: separate BUF; plain: BUF) local s: STRING; counter: INTEGER do {body} end"
        )
    routines.append("case_result (buffer: separate BUF): INTEGER do Reslt := 1 end")
    routines.append("case_vjar_result (buffer: separate BUF): STRING do Result := buffer.last end")
    routines.append("case_unknown_class local b: BUFF do end")
    routines.append("case_vuta_local local b: separate BUF do create b; b.is_full.do_nothing end")
    app = "class APP\ncreate make\nfeature\n    make do end\n    count: INTEGER\n"
    app += "".join(f"    {r}\n" for r in routines) + "end\n"
    checked = check(tmp_path_factory.mktemp("hints"), {"BUF": BUF, "APP": app})
    lines = {
        i + 1: text.split()[0].removeprefix("case_")
        for i, text in enumerate(app.splitlines())
        if text.startswith("    ")
    }
    return {lines[d.span.line]: (d.code, d.hint) for d in checked.diagnostics if d.is_error}


@pytest.mark.parametrize("name", sorted(CASES))
def test_hint(found, name):
    code, hint = found[name]
    assert hint == CASES[name][1]
    assert code == ("VJAR" if name.startswith("vjar") else "VEEN")


def test_misspelt_result_in_a_function(found):
    assert found["result"] == ("VEEN", "did you mean `Result` (the function's result)?")


def test_vjar_hint_fits_result(found):
    code, hint = found["vjar_result"]
    assert code == "VJAR" and hint.startswith(
        "the value is on another processor: declare the result type `separate STRING_8`"
    )
    assert "formal argument" not in hint


def test_misspelt_class(found):
    assert found["unknown_class"] == ("VTCT", "did you mean BUF?")


def test_vuta_3_hint_names_a_fresh_separate_block_local(found):
    code, hint = found["vuta_local"]
    assert code == "VUTA(3)" and "`separate b as l_b do l_b.f end`" in hint  # `as b` would be V1SE-G2
