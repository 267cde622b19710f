"""Driver, `scoopc test --junit FILE`: the outcomes of a test run as JUnit XML, the format graders
and CI servers read: one <testsuite> per test class, one <testcase> per test with its time, a
<failure> (its message, the whole report) when it failed, and what it printed in <system-out>."""

from __future__ import annotations

import datetime
import re
from collections.abc import Sequence
from pathlib import Path
from xml.etree import ElementTree

from ..diagnostics import Diagnostic, short
from ..exits import UsageError
from ..results import TestOutcome

# XML 1.0 cannot hold these characters, not even escaped: a test may print them.
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def junit_xml(outcomes: Sequence[TestOutcome]) -> str:
    """The JUnit XML text of `outcomes`."""
    top = ElementTree.Element("testsuites", _counts(outcomes))
    top.set("name", "scoopc test")
    stamp = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    for class_key in dict.fromkeys(o.class_name for o in outcomes):
        mine = [o for o in outcomes if o.class_name == class_key]
        suite = ElementTree.SubElement(top, "testsuite", {"name": class_key, **_counts(mine), "timestamp": stamp})
        for outcome in mine:
            _testcase(suite, outcome)
    ElementTree.indent(top)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ElementTree.tostring(top, encoding="unicode") + "\n"


def source_errors_xml(diagnostics: Sequence[Diagnostic]) -> str:
    """The JUnit XML of a program that does not check: one test, `check`, in error, whose text is
    the diagnostics (a grader then counts no test passed rather than finding no file)."""
    errors = [d for d in diagnostics if d.is_error]
    top = ElementTree.Element("testsuites", {"name": "scoopc test", "tests": "1", "failures": "0", "errors": "1"})
    suite = ElementTree.SubElement(top, "testsuite", {"name": "scoopc", "tests": "1", "failures": "0", "errors": "1"})
    case = ElementTree.SubElement(suite, "testcase", {"classname": "scoopc", "name": "check", "time": "0"})
    message = f"{len(errors)} error{'s' if len(errors) != 1 else ''} in the source: no test ran"
    error = ElementTree.SubElement(case, "error", {"message": message, "type": "source"})
    error.text = _clean("\n".join(short(d) for d in diagnostics))
    ElementTree.indent(top)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ElementTree.tostring(top, encoding="unicode") + "\n"


def write_source_errors(diagnostics: Sequence[Diagnostic], path: str | Path) -> str:
    """Write `source_errors_xml` to `path`."""
    return _write(source_errors_xml(diagnostics), path)


def write_junit(outcomes: Sequence[TestOutcome], path: str | Path) -> str:
    """Write `outcomes` as JUnit XML to `path`; UsageError when it cannot be written."""
    return _write(junit_xml(outcomes), path)


def _write(text: str, path: str | Path) -> str:
    target = Path(path)
    try:
        target.write_text(text, encoding="utf-8")
    except OSError as error:
        raise UsageError(f"cannot write the JUnit file {target}: {error.strerror or error}") from None
    return str(target)


def _counts(outcomes: Sequence[TestOutcome]) -> dict[str, str]:
    failed = sum(1 for o in outcomes if not o.passed)
    seconds = sum(o.seconds for o in outcomes)
    return {"tests": str(len(outcomes)), "failures": str(failed), "errors": "0", "time": f"{seconds:.3f}"}


def _testcase(suite: ElementTree.Element, outcome: TestOutcome) -> None:
    case = ElementTree.SubElement(
        suite,
        "testcase",
        {
            "classname": outcome.class_name,
            "name": outcome.routine,
            "time": f"{outcome.seconds:.3f}",
            "file": outcome.file,
            "line": str(outcome.line),
        },
    )
    if not outcome.passed:
        failure = ElementTree.SubElement(case, "failure", {"message": _clean(outcome.message), "type": outcome.status})
        failure.text = _clean(outcome.report)
    if outcome.output:
        ElementTree.SubElement(case, "system-out").text = _clean(outcome.output)


def _clean(text: str) -> str:
    return _NOT_XML.sub("\ufffd", text)
