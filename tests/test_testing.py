"""`scoopc test` (scoopc/driver/testing.py, junit.py) and the testing library (stdlib/testing/,
ROBOT_TEST_SET): AutoTest's discovery, a fresh runtime per test, reports, time limits, -k, JUnit
XML, exit codes. The programs are in tests/testing/."""

import io
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path
from xml.etree import ElementTree

import pytest

import scoopc
from scoopc import cli
from scoopc.driver import Compilation
from scoopc.driver.junit import junit_xml
from scoopc.exits import Exit
from scoopc.results import TestOutcome as Outcome  # not collected by pytest

PROGRAMS = Path(__file__).parent / "testing"
COUNTER = PROGRAMS / "counter"


def _cli(*argv):
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        try:
            status = cli.main([str(a) for a in argv])
        except SystemExit as stop:  # argparse's own usage errors
            status = stop.code
    return status, out.getvalue(), err.getvalue()


def test_three_tests_one_failing_exit_1_and_junit_with_3_tests_1_failure(tmp_path):
    junit = tmp_path / "out.xml"
    status, out, err = _cli("test", COUNTER, "--junit", junit)
    assert status == Exit.SOURCE, err
    assert "COUNTER_TESTS.test_twice ... FAILED" in out and "COUNTER_TESTS.test_starts_at_zero ... ok" in out
    assert "2 passed, 1 failed (3 tests)" in out.splitlines()[-1]
    top = ElementTree.parse(junit).getroot()
    assert (top.get("tests"), top.get("failures")) == ("3", "1")
    cases = {c.get("name"): c for c in top.iter("testcase")}
    assert sorted(cases) == ["test_equalities", "test_starts_at_zero", "test_twice"]  # not `helper`: not exported
    failure = cases["test_twice"].find("failure")
    assert failure is not None and failure.get("message") == "exception raised: DEVELOPER_EXCEPTION: two"
    assert "expected: 3\n   but  got: 2" in failure.text
    assert "called by COUNTER_TESTS.test_twice (counter_tests.e:42)" in failure.text  # the Eiffel trace
    assert cases["test_twice"].find("system-out").text == "prepared\ncleaned, failed: True\n"  # clean after a failure
    assert cases["test_starts_at_zero"].find("failure") is None
    assert cases["test_starts_at_zero"].get("line") == "31" and float(cases["test_starts_at_zero"].get("time")) >= 0


def test_the_api_selects_with_k_and_gives_each_test_its_outcome():
    seen = []
    result = scoopc.test([COUNTER], pattern="*test_[st]*", on_outcome=seen.append)  # a glob on CLASS.routine
    assert [t.routine for t in result.tests] == ["test_starts_at_zero", "test_twice"] == [t.routine for t in seen]
    assert result.status == Exit.SOURCE and [t.name for t in result.failed] == ["COUNTER_TESTS.test_twice"]
    result = scoopc.test([COUNTER], pattern="EQUAL")  # a part of the name, any case
    assert result.status == Exit.OK and [t.routine for t in result.tests] == ["test_equalities"]
    assert result.tests[0].output == "prepared\ncleaned, failed: False\n"
    with pytest.raises(scoopc.UsageError, match="no test matches -k 'nothing' \\(there are 3 tests\\)"):
        scoopc.test([COUNTER], pattern="nothing")


def test_a_program_without_tests_or_with_errors(tmp_path):
    (tmp_path / "counter.e").write_text((COUNTER / "counter.e").read_text())
    with pytest.raises(scoopc.UsageError, match="no tests in .*a test class inherits EQA_TEST_SET"):
        scoopc.test([tmp_path])
    (tmp_path / "broken_tests.e").write_text(
        "class BROKEN_TESTS inherit EQA_TEST_SET feature test_x do assert_integers_equal (1, 2, 3) end end\n"
    )
    result = scoopc.test([tmp_path])
    assert result.status == Exit.SOURCE and not result.tests
    assert [(d.span.line, d.is_error) for d in result.diagnostics] == [(1, True)]
    status, out, err = _cli("test", tmp_path, "--junit", tmp_path / "grades.xml")
    assert status == Exit.SOURCE and out == "" and "broken_tests.e:1:" in err
    top = ElementTree.parse(tmp_path / "grades.xml").getroot()  # for a grader: no test passed
    assert (top.get("tests"), top.get("errors")) == ("1", "1")
    error = top.find("testsuite/testcase/error")
    assert error.get("message") == "1 error in the source: no test ran" and "broken_tests.e:1:" in error.text


def test_a_world_that_cannot_be_read_names_the_test(tmp_path):
    (tmp_path / "w_tests.e").write_text(
        'class W_TESTS inherit ROBOT_TEST_SET feature\n\ttest_x note world: "nowhere.yaml" do run_for (1.0) end\nend\n'
    )
    with pytest.raises(scoopc.UsageError, match=r"W_TESTS.test_x \(.*w_tests.e:2\): no world file .*nowhere.yaml"):
        scoopc.test([tmp_path])


def test_usage_errors_exit_2(tmp_path):
    assert _cli("test", COUNTER, "--timeout", "0")[0] == Exit.USAGE
    assert _cli("test")[0] == Exit.USAGE
    status, _out, err = _cli("test", COUNTER, "--junit", tmp_path / "no-such-folder" / "x.xml")
    assert status == Exit.USAGE and "its folder does not exist" in err


def test_each_way_of_failing_gives_its_report():
    # a deadlock fails its test with the deadlock report (no hang); a contract violation, a lost
    # exception (the runtime is strict), a wait that can never end (a deadlock too)
    result = scoopc.test([PROGRAMS / "failures"], pattern="FAILURE_TESTS.test_[cdlw]*", timeout=20)
    found = {t.routine: t for t in result.tests}
    assert sorted(found) == ["test_contract", "test_deadlock", "test_lost_exception", "test_waits_forever"]
    assert all(t.status == "failed" for t in result.tests) and result.status == Exit.SOURCE
    deadlock = found["test_deadlock"]
    assert deadlock.message == "deadlock: a cycle of synchronous calls" and deadlock.seconds < 10
    assert "P2(WORKER) in WORKER.await" in deadlock.report and "waits for the result of get_done" in deadlock.report
    assert found["test_contract"].report.splitlines() == [
        "precondition violated: `positive` (in WORKER.needs_positive, worker.e:41)",
        "  in WORKER.needs_positive (worker.e:41)",
        "  called by FAILURE_TESTS.test_contract (failure_tests.e:32)",
    ]
    assert found["test_lost_exception"].message.startswith("lost exception on P2(WORKER): check violated: `never`")
    assert "none can make a wait condition true" in found["test_waits_forever"].message


def test_a_test_that_computes_forever_times_out():
    result = scoopc.test([PROGRAMS / "failures"], pattern="test_forever", timeout=0.5)
    [outcome] = result.tests
    assert outcome.status == "timeout" and outcome.message == "timed out after 0.5 s"
    assert "the test body was interrupted\n  in FAILURE_TESTS.test_forever (failure_tests.e:49)" in outcome.report
    assert "P1(FAILURE_TESTS): running" in outcome.report and result.status == Exit.SOURCE


def test_each_test_has_a_runtime_of_its_own():
    # a once value set by one test is not seen by the next (both pass only then)
    result = scoopc.test([PROGRAMS / "failures"], pattern="FRESH_TESTS")
    assert [t.routine for t in result.tests] == ["test_first", "test_second"]
    assert result.status == Exit.OK, [t.report for t in result.failed]


def test_a_damaged_cached_program_is_compiled_again():
    assert scoopc.test([COUNTER]).tests  # compiled into the cache
    compilation = Compilation([COUNTER], root="COUNTER_TESTS.default_create")  # what scoopc test caches
    module = compilation.cached_program().folder / "program" / "counter_tests.py"
    assert module.is_file()
    module.write_text("this is not Python (\n")
    for cached in module.parent.glob("__pycache__/counter_tests*"):
        cached.unlink()
    result = scoopc.test([COUNTER])
    assert [t.passed for t in result.tests] == [True, False, True]


def test_junit_xml_holds_what_xml_cannot():
    outcome = Outcome("A_TESTS", "test_x", "failed", 0.5, "bad \x01 byte", "bad \x01 byte\n  in A", "out\x1b[0m")
    top = ElementTree.fromstring(junit_xml([outcome]))
    case = top.find("testsuite/testcase")
    assert case.find("failure").get("message") == "bad \ufffd byte" and case.find("system-out").text == "out\ufffd[0m"


@pytest.mark.slow
def test_robot_tests_run_in_their_world_and_are_reproducible():
    runs = [scoopc.test([PROGRAMS / "robot"]) for _ in range(2)]
    for result in runs:
        found = {t.routine: t for t in result.tests}
        assert found["test_wanders_safely"].passed, found["test_wanders_safely"].report
        corner = found["test_reaches_corner"]
        assert corner.status == "failed" and "expected: within 0.100 m of (2.300, 1.800)" in corner.report
        assert "called by WANDER_TESTS.test_reaches_corner (wander_tests.e:52)" in corner.report
    first, second = ({t.routine: t.output for t in r.tests} for r in runs)
    assert first == second and first["test_wanders_safely"].startswith("x = ")  # the same run, to the last digit
