"""Syntax levels: the .ecf's `syntax` option (`<option syntax="...">` of a target or a cluster:
EiffelStudio's obsolete, transitional, standard, provisional). At `standard`, the default, the
pre-ECMA forms (`indexing`, `is` before a body or a constant, `?T`, `!T`, `{x: T} e`) are errors
whose hint names the option; at `transitional` (and `obsolete`) they are warnings and the class
compiles and runs. A library's .ecf sets the level of its own clusters."""

import io
from pathlib import Path

import scoopc
from scoopc.exits import Exit
from scoopc.pipeline import parse_project
from scoopc.project import collect

FOLDER = Path(__file__).parent / "libraries" / "transitional"
OLD_FORMS = [(1, 1), (12, 7), (18, 9), (30, 9), (32, 8), (32, 16), (38, 17), (43, 17)]


def _obsolete(diagnostics):
    return [d for d in diagnostics if d.code == "SYNTAX-OBSOLETE"]


def test_a_transitional_class_compiles_and_runs_with_warnings():
    out = io.StringIO()
    result = scoopc.run([str(FOLDER / "transitional.ecf")], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    found = _obsolete(result.diagnostics)
    assert [(d.span.line, d.span.column) for d in found] == OLD_FORMS
    assert {d.severity for d in found} == {"warning"} and all("transitional" not in d.hint for d in found)
    assert out.getvalue() == "a string of 4 characters\nfound: True, limit: 10\nset\n"


def test_at_the_standard_level_each_old_form_is_an_error_naming_the_setting():
    parsed = parse_project(collect([str(FOLDER / "old_style.e")]))
    found = _obsolete(parsed.diagnostics)
    assert [(d.span.line, d.span.column) for d in found] == OLD_FORMS and parsed.has_errors
    assert all(d.is_error and '<option syntax="transitional">' in d.hint for d in found)
    messages = {d.message for d in found}
    assert "`?T` is the obsolete spelling of `detachable T`" in messages
    assert "`!T` is the obsolete spelling of `attached T`" in messages


def _library_project(tmp_path, library_syntax: str, schema: str = "") -> Path:
    library = tmp_path / "old"
    library.mkdir(parents=True)
    (library / "old_style.e").write_text((FOLDER / "old_style.e").read_text())
    (library / "old.ecf").write_text(
        f"""<?xml version="1.0" encoding="ISO-8859-1"?>
<system {schema}name="old" uuid="00000000-0000-0000-0000-000000000003" library_target="old">
	<target name="old">
		{library_syntax}
		<cluster name="old" location="."/>
	</target>
</system>
"""
    )
    app = tmp_path / "app"
    app.mkdir()
    (app / "app.e").write_text(
        "class\n\tAPP\ncreate\n\tmake\nfeature\n\tmake\n\t\tlocal\n\t\t\to: OLD_STYLE\n"
        "\t\tdo\n\t\t\tcreate o.make\n\t\tend\nend\n"
    )
    (app / "app.ecf").write_text(
        """<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="app" uuid="00000000-0000-0000-0000-000000000004">
	<target name="app">
		<root class="APP" feature="make"/>
		<library name="old" location="../old/old.ecf"/>
		<cluster name="app" location="."/>
	</target>
</system>
"""
    )
    return app / "app.ecf"


def test_a_library_s_own_syntax_level_applies_to_its_classes(tmp_path):
    ecf = _library_project(tmp_path, '<option syntax="transitional"/>')
    project = collect([str(ecf)])
    assert project.settings.syntax is None  # the application's level stays standard
    parsed = parse_project(project)
    assert not parsed.has_errors and len(_obsolete(parsed.diagnostics)) == len(OLD_FORMS)
    standard = parse_project(collect([str(_library_project(tmp_path / "s", ""))]))
    assert standard.has_errors and len(_obsolete(standard.diagnostics)) == len(OLD_FORMS)
    cluster = collect([str(_library_project(tmp_path / "c", ""))])  # a cluster's own option
    assert cluster.syntax_level(tmp_path / "c" / "old" / "old_style.e") == "standard"


def test_a_cluster_s_option_sets_the_level_of_its_files(tmp_path):
    (tmp_path / "old").mkdir()
    (tmp_path / "old" / "old_style.e").write_text((FOLDER / "old_style.e").read_text())
    ecf = tmp_path / "app.ecf"
    ecf.write_text(
        """<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="app" uuid="00000000-0000-0000-0000-000000000005">
	<target name="app">
		<root class="OLD_STYLE" feature="make"/>
		<cluster name="old" location="old"><option syntax="obsolete"/></cluster>
	</target>
</system>
"""
    )
    project = collect([str(ecf)])
    assert project.settings.syntax is None and project.syntax_level(tmp_path / "old" / "old_style.e") == "obsolete"
    parsed = parse_project(project)
    assert not parsed.has_errors and {d.severity for d in _obsolete(parsed.diagnostics)} == {"warning"}


def _schema(version: str) -> str:
    return f'xmlns="http://www.eiffel.com/developers/xml/configuration-{version}" '


def test_an_ecf_of_an_old_schema_without_the_option_has_that_release_s_default_level(tmp_path):
    # EiffelStudio gives an .ecf with no syntax option the defaults of the release that wrote its
    # schema: 1-0-0 to 1-4-0 obsolete, 1-5-0 to 1-8-0 transitional, later standard.
    old_file = tmp_path / "{}" / "old" / "old_style.e"
    for version, level in [
        ("1-4-0", "obsolete"),
        ("1-5-0", "transitional"),
        ("1-8-0", "transitional"),
        ("1-9-0", "standard"),
        ("1-22-0", "standard"),
    ]:
        project = collect([str(_library_project(tmp_path / version, "", _schema(version)))])
        assert project.syntax_level(Path(str(old_file).format(version))) == level, version
    parsed = parse_project(collect([str(_library_project(tmp_path / "t", "", _schema("1-5-0")))]))
    assert not parsed.has_errors and {d.severity for d in _obsolete(parsed.diagnostics)} == {"warning"}
    stated = collect([str(_library_project(tmp_path / "s", '<option syntax="standard"/>', _schema("1-5-0")))])
    assert stated.syntax_level(tmp_path / "s" / "old" / "old_style.e") == "standard"  # the option wins


def test_the_application_s_schema_gives_the_void_safety_default(tmp_path):
    # The same defaults: void safety none up to 1-10-0, transitional for 1-11-0 and 1-12-0, then
    # complete (None); an option in the .ecf sets it whatever the schema.
    for version, level in [("1-5-0", "none"), ("1-10-0", "none"), ("1-12-0", "transitional"), ("1-13-0", None)]:
        ecf = tmp_path / f"{version}.ecf"
        ecf.write_text(
            f'<?xml version="1.0"?>\n<system {_schema(version)}name="a" uuid="00000000-0000-0000-0000-000000000006">'
            '<target name="a"><root class="APP" feature="make"/><cluster name="a" location="app"/></target></system>'
        )
        (tmp_path / "app").mkdir(exist_ok=True)
        (tmp_path / "app" / "app.e").write_text("class\n\tAPP\ncreate\n\tmake\nfeature\n\tmake\n\t\tdo\n\t\tend\nend\n")
        assert collect([str(ecf)]).settings.void_safety == level, version
    stated = tmp_path / "stated.ecf"
    stated.write_text((tmp_path / "1-5-0.ecf").read_text().replace("<root", '<option void_safety="all"/><root'))
    assert collect([str(stated)]).settings.void_safety == "all"
