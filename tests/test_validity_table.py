"""docs/LANGUAGE.md's table of validity codes stays honest: every row marked enforced names a
tests/errors folder that exists and holds cases, and every code the checker or the parser's
validity checks can report (scoopc/messages.py, syntax and input codes aside) has a row."""

import re
from pathlib import Path

from scoopc import messages

ROOT = Path(__file__).resolve().parents[1]
ROW = re.compile(r"^\| (?P<code>[A-Z0-9_()\-]+) \| (?P<status>enforced|warning|not enforced) \| (?P<rest>.*) \|$")
# not validity: syntax, files, .ecf projects, building C externals (tests/externals)
NOT_VALIDITY = re.compile(r"^(SYNTAX.*|SOURCE|ECF.*|EXTERNAL-BUILD)$")


def table_rows() -> dict:
    text = (ROOT / "docs" / "LANGUAGE.md").read_text(encoding="utf-8")
    section = text.split("### Validity codes", 1)[1].split("\n#", 1)[0]
    rows = {}
    for line in section.splitlines():
        match = ROW.match(line.strip())
        if match:
            assert match["code"] not in rows, f"{match['code']} has two rows"
            rows[match["code"]] = (match["status"], match["rest"])
    return rows


def test_the_table_is_there():
    assert len(table_rows()) >= 60


def test_every_enforced_row_names_an_existing_error_folder():
    for code, (status, rest) in table_rows().items():
        if status != "enforced":
            continue
        folder = re.match(r"tests/errors/([A-Za-z0-9_\-]+)", rest)
        assert folder, f"{code}: an enforced row must name its tests/errors folder"
        path = ROOT / "tests" / "errors" / folder[1]
        assert path.is_dir() and any(p.is_dir() for p in path.iterdir()), f"{code}: {path} has no cases"
        assert folder[1] == code.replace("(", "-").replace(")", ""), f"{code}: folder {folder[1]} is another code's"


def test_every_code_the_checker_reports_has_a_row():
    rows = table_rows()
    missing = [code for code in messages.MESSAGES if not NOT_VALIDITY.match(code) and code not in rows]
    assert not missing, f"docs/LANGUAGE.md's validity table lacks {missing}"


def test_codes_not_enforced_are_not_reported():
    rows = table_rows()
    reported = {code for code, (status, _) in rows.items() if status == "not enforced"} & set(messages.MESSAGES)
    assert not reported, f"{sorted(reported)} are marked not enforced but have messages"
