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


@pytest.mark.xfail(strict=True, reason=(
    "VFFD(8) (scoopc/semantics/scoop.py, check_process_once) refuses a `once (\"PROCESS\")` function "
    "of the non-separate type MUTEX, the usual lock shared by every thread of a thread system; "
    "EiffelStudio accepts it when the .ecf's concurrency is `thread`"))
def test_a_process_wide_mutex_in_a_thread_system():
    out = io.StringIO()
    result = scoopc.run([str(LIBRARIES / "process_once")], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    assert out.getvalue() == "total: 2000\n"


def test_what_blocks_the_process_wide_mutex_is_vffd_8():
    result = scoopc.check([str(LIBRARIES / "process_once")])
    assert [(d.code, d.span.line) for d in result.diagnostics if d.is_error] == [("VFFD(8)", 32)]
