"""Thread systems (EiffelThread): programs that compile and run under today's (SCOOP) rules are
golden cases (tests/golden/threads_mutex); this file holds those today's checker still refuses,
each marked with the rule that blocks it, until the .ecf `concurrency` setting selects the rules
of a thread system."""

import io
from pathlib import Path

import pytest

import scoopc
from scoopc.exits import Exit

LIBRARIES = Path(__file__).parent / "libraries"


@pytest.mark.xfail(
    strict=True,
    reason=(
        'VFFD(8) (scoopc/semantics/scoop.py, check_process_once) refuses a `once ("PROCESS")` function '
        "of the non-separate type MUTEX, the usual lock shared by every thread of a thread system; "
        "EiffelStudio accepts it when the .ecf's concurrency is `thread`"
    ),
)
def test_a_process_wide_mutex_in_a_thread_system():
    out = io.StringIO()
    result = scoopc.run([str(LIBRARIES / "process_once")], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    assert out.getvalue() == "total: 2000\n"


def test_what_blocks_the_process_wide_mutex_is_vffd_8():
    result = scoopc.check([str(LIBRARIES / "process_once")])
    assert [(d.code, d.span.line) for d in result.diagnostics if d.is_error] == [("VFFD(8)", 32)]


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
