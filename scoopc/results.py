"""What the Python API returns (scoopc.check, scoopc.compile, scoopc.run): plain records, shared by
the driver and the robot runner, importing nothing of scoopc."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


@dataclass
class CheckResult:
    status: int  # exits.Exit: OK, or SOURCE when there are errors
    diagnostics: list = field(default_factory=list)  # diagnostics.Diagnostic, errors and warnings

    @property
    def errors(self) -> list:
        return [d for d in self.diagnostics if d.is_error]


@dataclass
class CompileResult(CheckResult):
    package: Path | None = None  # OUT/<root>, the program's package
    library: Path | None = None  # OUT/eiffel_base


@dataclass
class RunResult:
    status: int  # the program's exit status (exits.Exit, or 128 + signal)
    diagnostics: list = field(default_factory=list)  # what the check reported (a cached run: none)
    sim: Any = None  # the Simulator after a simulated run
    stopped_by: str | None = None  # "duration", "program", a signal's name, or None
    png: str | None = None  # pictures and recordings written
    gif: str | None = None
    record: str | None = None
    stopped_topics: list = field(default_factory=list)  # cmd_vel topics that got a zero velocity


@dataclass
class TestOutcome:
    """One test of `scoopc test`: a procedure of a test class (a descendant of EQA_TEST_SET)."""

    class_name: str  # the test class, upper case
    routine: str  # the test procedure, lower case
    status: str  # "passed", "failed" or "timeout"
    seconds: float = 0.0  # wall time of the test, runtime start to end
    message: str = ""  # a failure's first line: what failed
    report: str = ""  # a failure's whole report: what failed, where, the Eiffel trace
    output: str = ""  # what the test printed
    file: str = ""  # the test class's file
    line: int = 0  # the line of the test procedure

    @property
    def name(self) -> str:
        return f"{self.class_name}.{self.routine}"

    @property
    def passed(self) -> bool:
        return self.status == "passed"


@dataclass
class TestResult:
    status: int  # exits.Exit: OK when every test passed, SOURCE when one failed or the tests do not check
    diagnostics: list = field(default_factory=list)  # what the check reported
    tests: list = field(default_factory=list)  # TestOutcome, in the order they ran
    junit: str | None = None  # the JUnit XML file written, if any

    @property
    def failed(self) -> list:
        return [t for t in self.tests if not t.passed]

    def summary(self) -> str:
        """One line: how many tests passed and failed, and the time they took."""
        failed = len(self.failed)
        passed = len(self.tests) - failed
        seconds = sum(t.seconds for t in self.tests)
        parts = [f"{passed} passed"] + ([f"{failed} failed"] if failed else [])
        return f"{', '.join(parts)} ({len(self.tests)} test{'s' if len(self.tests) != 1 else ''}) in {seconds:.2f} s"
