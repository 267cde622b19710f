"""`scoopc check --explain CODE`: every code has its rule, a wrong example and a fix; Gobo's SCOOP
codes are aliases; the explanation table keeps up with the diagnostics and the error cases."""

import pytest

from scoopc import cli, messages
from scoopc.exits import Exit
from scoopc.explain import canonical_code
from scoopc.explanations import ALIASES, EXPLANATIONS

from harness import TESTS

PLAN_SCOOP_CODES = [
    "VUTA(3)",
    "VUAR(2)",
    "VJAR",
    "VUAR(3)",
    "VUAR(4)",
    "VUER",
    "FRESH_IDENTIFIER",
    "V1SE",
    "V1SE(3)",
    "VFFD(8)",
]


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def folder_codes():
    """The codes of tests/errors/<CODE>/ folders that hold at least one case."""
    folders = {case.parent.name for case in (TESTS / "errors").glob("*/*") if case.is_dir()}
    return sorted(canonical_code(name) for name in folders)


@pytest.mark.parametrize("code", sorted(EXPLANATIONS))
def test_every_code_is_explained(capsys, code):
    status, out, err = run(capsys, "check", "--explain", code)
    assert status == Exit.OK and err == ""
    assert out.startswith(f"{code}: ")
    assert "\nWrong:\n" in out and "\nFix:\n" in out


@pytest.mark.parametrize("code", sorted(EXPLANATIONS))
def test_every_explanation_is_complete(code):
    entry = EXPLANATIONS[code]
    example, _, sentence = entry.fix.rpartition("\n\n")
    assert entry.rule.strip() and entry.wrong.strip() and example.strip() and sentence.strip()
    assert entry.wrong != example, f"{code}: the fix must differ from the wrong example"


@pytest.mark.parametrize("code", sorted(messages.MESSAGES))
def test_every_registered_message_has_an_explanation(code):
    assert code in EXPLANATIONS


@pytest.mark.parametrize("code", PLAN_SCOOP_CODES)
def test_every_scoop_code_has_an_explanation(code):
    assert code in EXPLANATIONS


@pytest.mark.parametrize("code", folder_codes())
def test_every_code_with_error_cases_has_an_explanation(code):
    assert code in EXPLANATIONS, f"tests/errors has cases for {code}; add it to scoopc.explanations"


def test_the_message_template_is_shown_when_registered(capsys):
    status, out, _ = run(capsys, "check", "--explain", "SYNTAX-END")
    assert status == 0 and f"Message: {messages.MESSAGES['SYNTAX-END'].text}" in out
    assert f"Hint: {messages.MESSAGES['SYNTAX-END'].hint}" in out


def test_a_code_without_a_message_is_still_explained(capsys, monkeypatch):
    monkeypatch.delitem(messages.MESSAGES, "VEVI", raising=False)
    status, out, _ = run(capsys, "check", "--explain", "VEVI")
    assert status == 0 and out.startswith("VEVI: ") and "\nFix:\n" in out and "Message:" not in out


@pytest.mark.parametrize("spelled", ["vuar-2", "VUAR(2)", "Vuar-2", " vuar(2) "])
def test_dashes_parentheses_and_case_are_accepted(capsys, spelled):
    status, out, _ = run(capsys, "check", "--explain", spelled)
    assert status == 0 and out.startswith("VUAR(2): ")


@pytest.mark.parametrize("alias", sorted(ALIASES))
def test_gobo_aliases_resolve_to_our_code(capsys, alias):
    ours = ALIASES[alias]
    assert ours in EXPLANATIONS
    for spelled in (alias, alias.lower(), alias.replace("-", "(", 1) + ")"):
        status, out, _ = run(capsys, "check", "--explain", spelled)
        assert status == 0 and out.startswith(f"{ours} (Gobo: {alias}): "), spelled
        assert "\nWrong:\n" in out and "\nFix:\n" in out


def test_the_gobo_scoop_codes_are_aliases():
    assert ALIASES["VUTA-4G"] == "VUTA(3)"
    assert ALIASES["VUAR-3G"] == "VUAR(3)" and ALIASES["VUAR-4G"] == "VUAR(4)"
    assert {ALIASES[f"V1SE-G{n}"] for n in (1, 2, 3)} == {"FRESH_IDENTIFIER", "V1SE"}


@pytest.mark.parametrize("unknown", ["NO-SUCH-CODE", "VUTA(99)", "VXYZ", "VUTA-9G"])
def test_an_unknown_code_is_a_usage_error(capsys, unknown):
    status, out, err = run(capsys, "check", "--explain", unknown)
    assert status == Exit.USAGE and out == "" and "unknown diagnostic code" in err


# ---- spellings, the list, suggestions (issue 22) -----------------------------------------------
@pytest.mark.parametrize(
    "spelled", ["VUTA3", "vuta-3", "VUTA(3)", "vuta(3)", "VUTA-4G", "vuta4g", "VUTA(4G)", " vuta3 "]
)
def test_every_spelling_of_vuta_3_is_explained(capsys, spelled):
    status, out, err = run(capsys, "check", "--explain", spelled)
    assert status == Exit.OK and err == "" and out.startswith("VUTA(3)")


@pytest.mark.parametrize(
    "spelled, code", [("V1SE-G1", "FRESH_IDENTIFIER"), ("v1se3g", "V1SE"), ("syntax_end", "SYNTAX-END")]
)
def test_gobo_and_squeezed_spellings(spelled, code):
    assert canonical_code(spelled) == code


def test_explain_without_a_code_lists_every_code_with_one_line(capsys):
    status, out, err = run(capsys, "check", "--explain")
    assert status == Exit.OK and err == ""
    listed = {line.split()[0] for line in out.splitlines() if line and not line.startswith(("Gobo", "Details"))}
    assert listed == set(EXPLANATIONS) | set(messages.MESSAGES)
    assert "VUTA-4G = VUTA(3)" in out


def test_an_unknown_code_suggests_the_closest(capsys):
    status, _, err = run(capsys, "check", "--explain", "VUTB3")
    assert status == Exit.USAGE and "did you mean `VUTA(3)`" in err and "--explain` lists them all" in err


@pytest.mark.parametrize("code", ["VJAR", "VUAR(2)", "VUAR(4)"] + PLAN_SCOOP_CODES)
def test_every_scoop_code_has_a_scoop_example(code):
    entry = EXPLANATIONS[code]
    assert "separate" in entry.wrong or "separate" in entry.fix


def test_check_ends_with_one_summary_line_in_the_pretty_form(capsys, tmp_path):
    (tmp_path / "app.e").write_text("class APP\ncreate make\nfeature\n\tmake do print (1) end\nend\n")
    (tmp_path / "other.e").write_text("class OTHER\nend\n")
    status, out, err = run(capsys, "check", "--format", "pretty", str(tmp_path))
    assert status == Exit.OK and out == "" and err == "2 classes checked, no errors\n"
    status, _, err = run(capsys, "check", "--format", "short", str(tmp_path))
    assert status == Exit.OK and err == ""
    (tmp_path / "other.e").write_text("class OTHER\nfeature f do x := 1 end\nend\n")
    status, _, err = run(capsys, "check", "--format", "pretty", str(tmp_path))
    assert status == Exit.SOURCE and err.endswith("\n2 classes checked, 1 error\n")
