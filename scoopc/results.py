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
