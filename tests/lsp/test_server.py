"""The language server as an editor sees it: LSP messages on its input and output (in this process,
on pipes: tests/lsp/conftest.py). The program (tests/lsp/program) has an uncontrolled separate call
(VUTA(3)) and a misspelt feature (VEEN)."""

from __future__ import annotations

from pathlib import Path
from urllib.parse import unquote, urlparse

from scoopc.semantics.universe import stdlib_root


def _file(uri: str) -> Path:
    return Path(unquote(urlparse(uri).path))


def _codes(diagnostics) -> list[tuple[str, int, int]]:
    return [(d["code"], d["range"]["start"]["line"] + 1, d["range"]["start"]["character"] + 1) for d in diagnostics]


def _apply(text: str, edits) -> str:
    """The text after LSP edits (applied last first, so earlier positions hold)."""
    lines = text.split("\n")
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line) + 1)

    def at(position) -> int:
        return offsets[position["line"]] + position["character"]

    for edit in sorted(edits, key=lambda e: at(e["range"]["start"]), reverse=True):
        text = text[: at(edit["range"]["start"])] + edit["newText"] + text[at(edit["range"]["end"]) :]
    return text


def test_diagnostics_on_open_have_codes_hints_and_explanations(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    found = lsp.diagnostics(uri)
    assert _codes(found) == [("VUTA(3)", 18, 4), ("VEEN", 34, 12)]
    uncontrolled = found[0]
    assert uncontrolled["message"] == "call on separate `motor` (type separate MOTOR) that is not controlled"
    assert uncontrolled["source"] == "scoopc" and uncontrolled["severity"] == 1
    hint = uncontrolled["relatedInformation"][0]
    assert hint["message"].startswith("hint: pass `motor` as an argument of a routine")
    explanation = _file(uncontrolled["codeDescription"]["href"]).read_text()
    assert explanation.startswith("# VUTA(3)") and "separate" in explanation


def test_a_change_is_checked_again_and_published_for_its_version(lsp, program):
    path = program / "robot_app.e"
    uri = lsp.open(path)
    lsp.diagnostics(uri)
    lsp.change(uri, path.read_text().replace("set_sped", "set_speed"), 2)
    assert _codes(lsp.diagnostics(uri, version=2)) == [("VUTA(3)", 18, 4)]
    lsp.change(uri, path.read_text().replace("\t\tdo\n\t\t\tcreate", "\t\tdo\n\t\t\tif create"), 3)
    assert [code for code, _, _ in _codes(lsp.diagnostics(uri, version=3))] == ["SYNTAX"]


def test_hover_shows_signature_comment_contracts_and_separateness(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    lsp.diagnostics(uri)
    feature = lsp.at("textDocument/hover", uri, 17, 11)["contents"]["value"]  # motor.set_speed (40)
    assert "set_speed (a_speed: INTEGER)" in feature and "Run at `a_speed'." in feature
    assert "in_range: a_speed >= -100 and a_speed <= 100" in feature and "speed_set: speed = a_speed" in feature
    assert "`MOTOR`" in feature
    uncontrolled = lsp.at("textDocument/hover", uri, 17, 4)["contents"]["value"]  # motor
    assert "motor: separate MOTOR" in uncontrolled and "**not controlled** here" in uncontrolled
    controlled = lsp.at("textDocument/hover", uri, 33, 5)["contents"]["value"]  # a_motor.set_sped
    assert "a_motor: separate MOTOR" in controlled and "is controlled here" in controlled


def test_definition_goes_into_the_program_and_the_library(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    lsp.diagnostics(uri)
    local = lsp.at("textDocument/definition", uri, 19, 4)  # count := ...
    assert _file(local["uri"]) == (program / "robot_app.e").resolve() and local["range"]["start"]["line"] == 14
    motor = lsp.at("textDocument/definition", uri, 17, 11)  # set_speed
    assert _file(motor["uri"]).name == "motor.e" and motor["range"]["start"] == {"line": 27, "character": 1}
    library = lsp.at("textDocument/definition", uri, 20, 4)  # print
    target = _file(library["uri"])
    assert target.is_relative_to(stdlib_root().resolve()) and target.name == "any.e"
    line = target.read_text().split("\n")[library["range"]["start"]["line"]]
    assert line.strip().startswith("print (")


def test_references_find_every_call_and_the_declaration(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    lsp.diagnostics(uri)
    found = lsp.at("textDocument/references", uri, 18, 4, context={"includeDeclaration": True})  # drive
    assert [(r["range"]["start"]["line"], r["range"]["start"]["character"]) for r in found] == [(18, 3), (30, 1)]
    without = lsp.at("textDocument/references", uri, 18, 4, context={"includeDeclaration": False})
    assert len(without) == 1


def _completion(lsp, uri: str, text: str, line: int, character: int) -> list[str]:
    lsp.change(uri, text, 2)
    lsp.diagnostics(uri, version=2)
    return [item["label"] for item in lsp.at("textDocument/completion", uri, line, character)["items"]]


def test_completion_after_a_dot_respects_exports(lsp, program):
    path = program / "robot_app.e"
    uri = lsp.open(path)
    lsp.diagnostics(uri)
    text = path.read_text().replace("\t\t\tdrive (motor, 60)", "\t\t\tdrive (motor, 60)\n\t\t\tmotor.sp")
    labels = _completion(lsp, uri, text, 19, 11)
    assert {"set_speed", "speed", "id", "out", "do_nothing"} <= set(labels)
    assert "calibrate" not in labels and "make" not in labels  # exported to MOTOR and to NONE only
    motor = program / "motor.e"
    own = lsp.open(motor)
    lsp.diagnostics(own)
    inside = motor.read_text().replace("\t\t\tspeed := 0", "\t\t\tspeed := 0\n\t\t\tCurrent.")
    assert "calibrate" in _completion(lsp, own, inside, 41, 11)  # MOTOR is a client of {MOTOR}


def test_completion_elsewhere_offers_keywords_classes_features_and_locals(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    lsp.diagnostics(uri)
    labels = {item["label"] for item in lsp.at("textDocument/completion", uri, 19, 3)["items"]}
    assert {"separate", "require", "across", "MOTOR", "ARRAYED_LIST", "drive", "motor", "count"} <= labels


def test_outline_and_folding(lsp, program):
    uri = lsp.open(program / "motor.e")
    lsp.diagnostics(uri)
    (whole,) = lsp.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}})
    assert whole["name"] == "MOTOR"
    outline = [(clause["name"], [f["name"] for f in clause["children"]]) for clause in whole["children"]]
    assert outline == [
        ("feature {NONE} -- Initialization", ["make"]),
        ("feature -- Access", ["id", "speed"]),
        ("feature -- Element change", ["set_speed"]),
        ("feature {MOTOR} -- Implementation", ["calibrate"]),
    ]
    folds = {
        (r["startLine"], r["endLine"]) for r in lsp.request("textDocument/foldingRange", {"textDocument": {"uri": uri}})
    }
    assert {(0, 45), (27, 35), (11, 15)} <= folds  # the class, set_speed, make


def _fixed(lsp, program, title_start: str) -> list:
    path = program / "robot_app.e"
    uri = lsp.open(path, path.read_text().replace("set_sped", "set_speed"))
    (uncontrolled,) = lsp.diagnostics(uri)
    context = {"diagnostics": [uncontrolled]}
    params = {"textDocument": {"uri": uri}, "range": uncontrolled["range"], "context": context}
    actions = lsp.request("textDocument/codeAction", params)
    (action,) = [a for a in actions if a["title"].startswith(title_start)]
    text = _apply(path.read_text().replace("set_sped", "set_speed"), action["edit"]["changes"][uri])
    lsp.change(uri, text, 2)
    return text, lsp.diagnostics(uri, version=2)


def test_quick_fix_wraps_the_call_in_a_separate_block(lsp, program):
    text, found = _fixed(lsp, program, "Wrap in `separate motor")
    assert "\t\t\tseparate motor as l_motor do\n\t\t\t\tl_motor.set_speed (40)\n\t\t\tend\n" in text
    assert found == []


def test_quick_fix_moves_the_call_into_a_routine_with_a_separate_argument(lsp, program):
    text, found = _fixed(lsp, program, "Move the call into a new routine `set_speed_on_motor`")
    assert "\t\t\tset_speed_on_motor (motor)\n" in text
    assert "\tset_speed_on_motor (a_motor: separate MOTOR)\n" in text and "\t\t\ta_motor.set_speed (40)\n" in text
    assert found == []


def test_a_file_changed_on_disk_is_checked_again(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    assert [code for code, _, _ in _codes(lsp.diagnostics(uri))] == ["VUTA(3)", "VEEN"]
    motor = program / "motor.e"
    motor.write_text(motor.read_text().replace("set_speed", "set_sped"))  # drive's call is right, make's not
    changes = {"changes": [{"uri": motor.resolve().as_uri(), "type": 2}]}
    lsp.notify("workspace/didChangeWatchedFiles", changes)
    assert _codes(lsp.diagnostics(uri)) == [("VEEN", 18, 10)]


def test_in_a_library_file_names_of_classes_and_own_features_are_known(lsp, program):
    uri = lsp.open(program / "robot_app.e")
    lsp.diagnostics(uri)
    any_e = lsp.at("textDocument/definition", uri, 20, 4)["uri"]  # print, in ANY
    path = _file(any_e)
    lsp.open(path)
    lines = path.read_text().split("\n")
    line = next(i for i, text in enumerate(lines) if "io.put_string (o.out)" in text or "print (o:" in text)
    column = lines[line].index("print") if "print (o:" in lines[line] else lines[line].index("io")
    hover = lsp.at("textDocument/hover", any_e, line, column + 1)["contents"]["value"]
    assert "*feature of class* `ANY`" in hover
    outline = lsp.request("textDocument/documentSymbol", {"textDocument": {"uri": any_e}})
    assert outline[0]["name"] == "ANY"


def test_wrapping_a_conditional_controls_its_condition_and_its_body(lsp, program):
    path = program / "robot_app.e"
    text = (
        path.read_text()
        .replace("set_sped", "set_speed")
        .replace(
            "\t\t\tmotor.set_speed (40)\n",
            '\t\t\tif motor.speed > 50 then\n\t\t\t\tprint ("fast%N")\n\t\t\tend\n',
        )
    )
    uri = lsp.open(path, text)
    (uncontrolled,) = lsp.diagnostics(uri)
    assert _codes([uncontrolled]) == [("VUTA(3)", 18, 7)]
    params = {"textDocument": {"uri": uri}, "range": uncontrolled["range"], "context": {"diagnostics": [uncontrolled]}}
    actions = lsp.request("textDocument/codeAction", params)
    assert [a["title"] for a in actions] == ["Wrap in `separate motor as ... do ... end`"]  # no routine for a condition
    fixed = _apply(text, actions[0]["edit"]["changes"][uri])
    assert "\t\t\tseparate motor as l_motor do\n\t\t\t\tif l_motor.speed > 50 then\n\t\t\t\t\tprint" in fixed
    lsp.change(uri, fixed, 2)
    assert lsp.diagnostics(uri, version=2) == []


def test_every_file_of_the_program_gets_its_diagnostics_and_a_save_checks_again(lsp, program):
    motor = program / "motor.e"
    motor.write_text(motor.read_text().replace("speed := 0", "speed := True"))
    uri = lsp.open(program / "robot_app.e")
    published = {}
    while len(published) < 2:
        message = lsp.notifications.get(timeout=60)
        if message.get("method") == "textDocument/publishDiagnostics":
            published[_file(message["params"]["uri"]).name] = [d["code"] for d in message["params"]["diagnostics"]]
    assert published == {"robot_app.e": ["VUTA(3)", "VEEN"], "motor.e": ["VJAR"]}
    lsp.notify("textDocument/didSave", {"textDocument": {"uri": uri}})
    assert [d["code"] for d in lsp.diagnostics(uri)] == ["VUTA(3)", "VEEN"]
