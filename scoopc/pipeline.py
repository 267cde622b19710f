"""The compiler's stages in order, with a fixed name for each stage's data.

Project (project.py) -> Parsed (this module: one ParsedUnit per file) -> later stages.
Stages produce diagnostics; only the CLI renders them.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from . import diagnostics
from .diagnostics import Diagnostic
from .project import Project
from .source import SourceFile, Span


@dataclass
class ParsedUnit:
    source: SourceFile
    tree: Optional[object]          # syntax.ClassDeclaration, None when the file has syntax errors


@dataclass
class Parsed:
    units: list[ParsedUnit] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    sources: dict[str, SourceFile] = field(default_factory=dict)

    @property
    def has_errors(self) -> bool:
        return any(d.is_error for d in self.diagnostics)

    def line_text(self, path: str, line: int) -> str:
        source = self.sources.get(path)
        return source.line_text(line) if source is not None else ""


def read_source(path: str) -> tuple[Optional[SourceFile], Optional[Diagnostic]]:
    """A file's text, or a SOURCE diagnostic saying why it cannot be read."""
    try:
        return SourceFile.read(path), None
    except UnicodeDecodeError as problem:
        reason = f"not UTF-8 text (byte {problem.start})"
    except OSError as problem:
        reason = problem.strerror or str(problem)
    return None, diagnostics.make("SOURCE", Span(path, 1, 1, 1, 2), path=path, reason=reason)


def parse_project(project: Project) -> Parsed:
    """Parse every file of the project; syntax errors are collected, never raised."""
    from . import parser  # deferred: building the grammar is the costly part of start-up

    parsed = Parsed(diagnostics=list(project.errors) + list(project.notes))
    for path in project.files:
        source, problem = read_source(str(path))
        if problem is not None:
            parsed.diagnostics.append(problem)
            continue
        parsed.sources[source.path] = source
        result = parser.parse(source)
        parsed.diagnostics.extend(result.diagnostics)
        parsed.units.append(ParsedUnit(source, result.tree))
    parsed.diagnostics.sort(key=diagnostics.sort_key)
    return parsed


def check_project(project: Project) -> Parsed:
    """Everything `scoopc check` verifies. Today that is syntax; the semantic checker joins here."""
    return parse_project(project)
