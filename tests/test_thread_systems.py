"""Thread systems (EiffelThread) and the .ecf `concurrency` setting: SCOOP's rules apply only
under `scoop` (the default, also without an .ecf); under `thread` and `none` the program's
`separate` means nothing, as in EiffelStudio, and a library that does not support the system's
concurrency is named in a warning. Programs that run under either rules are golden cases
(tests/golden/threads_mutex)."""

import io
from pathlib import Path

import pytest

import scoopc
from scoopc.exits import Exit
from scoopc.project import collect

LIBRARIES = Path(__file__).parent / "libraries"


def test_a_process_wide_mutex_in_a_thread_system():
    """process_once.ecf says `concurrency` `thread`: VFFD(8), a SCOOP rule, does not apply."""
    out = io.StringIO()
    result = scoopc.run([str(LIBRARIES / "process_once" / "process_once.ecf")], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    assert out.getvalue() == "total: 2000\n"


def test_without_an_ecf_the_system_is_a_scoop_one_and_vffd_8_applies():
    result = scoopc.check(
        [str(LIBRARIES / "process_once" / "process_once.e"), str(LIBRARIES / "process_once" / "tally_thread.e")]
    )
    assert [(d.code, d.span.line) for d in result.diagnostics if d.is_error] == [("VFFD(8)", 32)]


BOX = """class
	BOX

create
	make

feature

	make (a_name: STRING)
		do
			name := a_name
			print ("made " + a_name + "%N")
		end

	name: STRING

	show
		do
			print ("box " + name + "%N")
		end

end
"""

# Under SCOOP: VUAR(3) (a non-separate STRING to a separate object), VUTA(3) (`b.show` on an
# attribute), VJAR (`plain := b`, and `boxes := many`: an actual generic parameter keeps its
# separateness), V1SE (a separate block over a non-separate local), VFFD(8); under thread and
# none, none of them.
SEPARATE_APP = """class
	APP

create
	make

feature

	make
		local
			plain: BOX
			many: ARRAYED_LIST [separate BOX]
			boxes: ARRAYED_LIST [BOX]
		do
			create b.make ("one")
			b.show
			plain := b
			create many.make (1)
			boxes := many
			separate plain as p do
				p.show
			end
			print ("shared: " + shared.name + "%N")
		end

	b: separate BOX

	shared: BOX
		once ("PROCESS")
			create Result.make ("two")
		end

end
"""


def _concurrency_project(tmp_path, capability: str) -> Path:
    (tmp_path / "box.e").write_text(BOX)
    (tmp_path / "app.e").write_text(SEPARATE_APP)
    ecf = tmp_path / "app.ecf"
    ecf.write_text(
        f"""<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="app" uuid="00000000-0000-0000-0000-000000000000">
	<target name="app">
		<root class="APP" feature="make"/>
		{capability}
		<library name="base" location="$ISE_LIBRARY/library/base/base.ecf"/>
		<cluster name="app" location="."/>
	</target>
</system>
"""
    )
    return ecf


@pytest.mark.parametrize(
    "capability, concurrency",
    [
        ("", "scoop"),  # the default since ECF 1.16
        ('<capability><concurrency support="none"/></capability>', "none"),
        ('<capability><concurrency support="scoop" use="thread"/></capability>', "thread"),
        ('<setting name="concurrency" value="none"/>', "none"),  # ECF 1.7 to 1.15
        ('<setting name="multithreaded" value="true"/>', "thread"),  # before ECF 1.7
    ],
)
def test_the_system_concurrency_comes_from_the_ecf(tmp_path, capability, concurrency):
    project = collect([str(_concurrency_project(tmp_path, capability))])
    assert project.concurrency == concurrency and not project.notes


@pytest.mark.parametrize(
    "capability",
    ['<capability><concurrency support="none"/></capability>', '<setting name="multithreaded" value="true"/>'],
)
def test_separate_means_nothing_in_a_thread_or_none_system(tmp_path, capability):
    """Every call is a plain call: the output comes in program order, from one processor."""
    out = io.StringIO()
    result = scoopc.run([str(_concurrency_project(tmp_path, capability))], stdout=out, trace_processors=True)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    lines = out.getvalue().splitlines()
    assert [line.split("] ", 1)[1] for line in lines] == ["made one", "box one", "box one", "made two", "shared: two"]
    assert len({line.split("]", 1)[0] for line in lines}) == 1  # no processor besides the root's


def test_the_same_program_as_a_scoop_system_breaks_scoop_rules(tmp_path):
    ecf = _concurrency_project(tmp_path, '<capability><concurrency support="scoop"/></capability>')
    result = scoopc.check([str(ecf)])
    codes = sorted(d.code for d in result.diagnostics if d.is_error)
    assert codes == ["V1SE", "VFFD(8)", "VJAR", "VJAR", "VUAR(3)", "VUTA(3)"]


def test_a_library_that_does_not_support_the_system_concurrency_is_named_in_a_warning(tmp_path):
    library = tmp_path / "tools"
    library.mkdir()
    (library / "box.e").write_text(BOX)
    (library / "tools.ecf").write_text(
        """<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="tools" uuid="00000000-0000-0000-0000-000000000001" library_target="tools">
	<target name="tools">
		<capability>
			<concurrency support="thread"/>
		</capability>
		<cluster name="tools" location="."/>
	</target>
</system>
"""
    )
    app = tmp_path / "app"
    app.mkdir()
    (app / "app.e").write_text(
        SEPARATE_APP.replace("b: separate BOX", "b: BOX").replace(
            "separate plain as p do", "if attached plain as p then"
        )
    )
    (app / "app.ecf").write_text(
        """<?xml version="1.0" encoding="ISO-8859-1"?>
<system name="app" uuid="00000000-0000-0000-0000-000000000002">
	<target name="app">
		<root class="APP" feature="make"/>
		<capability>
			<concurrency support="none"/>
		</capability>
		<library name="tools" location="../tools/tools.ecf"/>
		<cluster name="app" location="."/>
	</target>
</system>
"""
    )
    result = scoopc.check([str(app / "app.ecf")])
    warnings = [d for d in result.diagnostics if d.code == "ECF-CAPABILITY"]
    assert [(w.severity, w.message, w.span.line) for w in warnings] == [
        ("warning", "library `tools` supports concurrency `thread`, not the system's `none`", 5)
    ]
    assert not [d for d in result.diagnostics if d.is_error]


def test_an_exception_in_a_thread_ends_the_program_with_its_eiffel_trace():
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([str(LIBRARIES / "thread_failure")], stdout=out, stderr=err)
    assert result.status == Exit.RUNTIME and out.getvalue() == ""  # the root stops in `join'
    report = err.getvalue()
    assert report.startswith(
        "scoopc: run-time failure: precondition violated: `locked_by_caller` (in MUTEX.unlock, mutex.e:"
    )
    assert "called by BAD.execute (bad.e:9)" in report and "Traceback" not in report


def test_read_write_lock_sleep_attributes_and_join_all():
    out = io.StringIO()
    result = scoopc.run([str(LIBRARIES / "rw_lock")], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    lines = out.getvalue().splitlines()
    # each reader ran after the root's write (1 item) and before or after the writer's (2)
    assert len(lines) == 5 and all(line in ("reader saw 1 item(s)", "reader saw 2 item(s)") for line in lines[:3])
    assert lines[3:] == ["store: 2 items, writer terminated: True", "priority: 0, detached: False"]


def _externals(cluster):
    """(class file, feature) of every `external "Python"` feature of a stdlib cluster."""
    import re

    from scoopc.semantics.universe import stdlib_root

    root = stdlib_root() / cluster  # the installed library (a checkout's stdlib/ when editable)
    for path in sorted(root.rglob("*.e")):
        external = r"\n\t(\w+)[^\n]*\n(?:\t\t\t--[^\n]*\n)*\t\texternal\n\t\t\t\"Python\""
        for match in re.finditer(external, path.read_text()):
            yield path, match.group(1)


def test_every_external_of_the_thread_and_time_libraries_is_implemented():
    import importlib
    import keyword

    missing = []
    for cluster in ("thread", "time"):
        for path, name in _externals(cluster):
            module = importlib.import_module(f"scoopc.kernel.ext.{path.stem}")
            if not hasattr(module, name + "_" if keyword.iskeyword(name) else name):
                missing.append(f"{path.name}: {name}")
    assert not missing
    assert sum(1 for _ in _externals("thread")) > 30
