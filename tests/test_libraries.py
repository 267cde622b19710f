"""Projects with libraries: an .ecf's <library> loads the stdlib's base, thread and time clusters
(by $ISE_LIBRARY location or by name), a user's library from its own .ecf (recursively), warns
about a cycle, and names a library we do not have in one error at the element's line:column."""

import io
from pathlib import Path

import scoopc
from scoopc.exits import Exit
from scoopc.project import collect

LIBRARIES = Path(__file__).parent / "libraries"

APP = """class
	APP

create
	make

feature

	make
		do
			print ("hello%N")
		end

end
"""


def _ecf(libraries: str, name: str = "app") -> str:
    return f"""<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="{name}" uuid="00000000-0000-0000-0000-000000000000">
	<target name="{name}">
		<root class="APP" feature="make"/>
{libraries}
		<cluster name="app" location="."/>
	</target>
</system>
"""


def _project(tmp_path, libraries: str) -> Path:
    (tmp_path / "app.e").write_text(APP)
    ecf = tmp_path / "app.ecf"
    ecf.write_text(_ecf(libraries))
    return ecf


def test_a_two_level_library_project_compiles_and_runs_from_its_ecf():
    ecf = LIBRARIES / "two_level" / "app" / "app.ecf"
    project = collect([str(ecf)])
    assert not project.errors
    assert sorted(p.name for p in project.files) == ["application.e", "length.e", "rectangle.e"]
    assert [p.name for p in project.ecf_files] == ["app.ecf", "shapes.ecf", "units.ecf"]
    assert project.root.class_name == "APPLICATION" and project.libraries == ["base"]
    # the libraries' own options (void_safety none in shapes.ecf) do not replace the application's
    assert project.settings.void_safety == "all" and project.settings.assertions == "all"
    assert not [n for n in project.notes if "console_application" in n.message]  # shapes' own setting
    out = io.StringIO()
    result = scoopc.run([str(ecf)], stdout=out)
    assert result.status == Exit.OK, result.diagnostics
    assert out.getvalue() == "width: 2 m 50 cm\nheight: 0 m 40 cm\nperimeter: 5 m 80 cm\n"


def test_a_library_cycle_is_reported_and_each_library_read_once():
    ecf = LIBRARIES / "cycle" / "app" / "app.ecf"
    project = collect([str(ecf)])
    cycles = [d for d in project.notes if d.code == "ECF-CYCLE"]
    assert len(cycles) == 1 and cycles[0].severity == "warning"
    assert cycles[0].message == "library `left` closes a cycle of libraries: left.ecf -> right.ecf -> left.ecf"
    assert cycles[0].span.file.endswith("right.ecf") and (cycles[0].span.line, cycles[0].span.column) == (5, 3)
    assert sorted(p.name for p in project.files) == ["application.e", "left_part.e", "right_part.e"]
    out = io.StringIO()
    result = scoopc.run([str(ecf)], stdout=out)
    assert result.status == Exit.OK and out.getvalue() == "left right\n"
    assert any(d.code == "ECF-CYCLE" for d in result.diagnostics)


def test_an_unknown_library_is_one_error_at_its_line_and_column(tmp_path):
    ecf = _project(
        tmp_path,
        '\t\t<library name="base" location="$ISE_LIBRARY/library/base/base.ecf"/>\n'
        '\t\t<library name="vision2" location="$ISE_LIBRARY\\library\\vision2\\vision2.ecf"/>',
    )
    result = scoopc.check([str(ecf)])
    errors = [d for d in result.diagnostics if d.is_error]
    assert result.status == Exit.SOURCE and [d.code for d in errors] == ["ECF-LIBRARY"]
    error = errors[0]
    assert (error.span.file, error.span.line, error.span.column) == (str(ecf), 6, 3)
    assert error.message == (
        "library `vision2` ($ISE_LIBRARY\\library\\vision2\\vision2.ecf): scoopc does not have this library"
    )
    assert "base, roboscoop, testing, thread, time" in error.hint


def test_a_missing_library_ecf_is_an_error(tmp_path):
    ecf = _project(tmp_path, '\t\t<library name="mine" location="../nowhere/mine.ecf"/>')
    result = scoopc.check([str(ecf)])
    errors = [d for d in result.diagnostics if d.is_error]
    assert [d.code for d in errors] == ["ECF-LIBRARY"] and errors[0].span.line == 5
    assert "no .ecf file" in errors[0].message and "nowhere" in errors[0].message


def test_ise_library_thread_time_and_testing(tmp_path, monkeypatch):
    # EiffelStudio's own installation, if any, is never read: $ISE_LIBRARY means ours
    monkeypatch.setenv("ISE_LIBRARY", str(tmp_path / "no-such-installation"))
    ecf = _project(
        tmp_path,
        '\t\t<library name="thread" location="$ISE_LIBRARY/library/thread/thread.ecf"/>\n'
        '\t\t<library name="time" location="$(ISE_LIBRARY)\\library\\time\\time.ecf"/>\n'
        '\t\t<library name="testing" location="$ISE_LIBRARY/library/testing/testing.ecf"/>\n'
        '\t\t<precompile name="base_pre" location="$ISE_PRECOMP\\base-scoop-safe.ecf"/>',
    )
    project = collect([str(ecf)])
    assert not project.errors and project.libraries == ["thread", "time", "testing", "base"]
    assert not [n for n in project.notes if "testing" in n.message]
    out = io.StringIO()
    assert scoopc.run([str(ecf)], stdout=out).status == Exit.OK and out.getvalue() == "hello\n"


def test_entity_declarations_are_refused(tmp_path):
    (tmp_path / "app.e").write_text(APP)
    ecf = tmp_path / "app.ecf"
    ecf.write_text(
        '<?xml version="1.0"?>\n<!DOCTYPE system [<!ENTITY big "xxxxxxxxxx">]>\n'
        '<system name="&big;"><target name="t"><cluster name="c" location="."/></target></system>\n'
    )
    result = scoopc.check([str(ecf)])
    assert result.status == Exit.SOURCE
    assert [d.code for d in result.diagnostics if d.is_error] == ["ECF"]
    assert "entity declarations are not accepted" in result.diagnostics[0].message
