"""The compiler's stages in order, with a fixed name for each stage's data.

Project (project.py) -> Parsed (this module: one ParsedUnit per file) -> later stages.
Stages produce diagnostics; only the CLI renders them.
"""

from __future__ import annotations

import gc
import os
from collections.abc import Callable, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from . import diagnostics
from .diagnostics import Diagnostic
from .project import Project
from .source import SourceFile, Span

if TYPE_CHECKING:
    from .semantics import Checked as semantics_checked


@dataclass
class ParsedUnit:
    source: SourceFile
    tree: object | None  # syntax.ClassDeclaration, None when the file has syntax errors


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


def read_source(path: str) -> tuple[SourceFile | None, Diagnostic | None]:
    """A file's text, or a SOURCE diagnostic saying why it cannot be read."""
    try:
        return SourceFile.read(path), None
    except UnicodeDecodeError as problem:
        reason = f"not UTF-8 text (byte {problem.start})"
    except OSError as problem:
        reason = problem.strerror or str(problem)
    return None, diagnostics.make("SOURCE", Span(path, 1, 1, 1, 2), path=path, reason=reason)


def parse_project(project: Project, overlay: Mapping[str, str] | None = None) -> Parsed:
    """Parse every file of the project; syntax errors are collected, never raised. `overlay`
    ({absolute path: text}) replaces the text on disk of those files (an editor's unsaved buffers)."""
    from .parse import parser  # deferred: building the grammar is the costly part of start-up

    parsed = Parsed(diagnostics=list(project.errors) + list(project.notes))
    for path in project.files:
        text = overlay.get(os.path.abspath(path)) if overlay else None
        source, problem = (SourceFile(str(path), text), None) if text is not None else read_source(str(path))
        if problem is not None:
            parsed.diagnostics.append(problem)
            continue
        parsed.sources[source.path] = source
        result = parser.parse(source)
        parsed.diagnostics.extend(_at_level(result, project.syntax_level(path)))
        parsed.units.append(ParsedUnit(source, result.tree))
    parsed.diagnostics.sort(key=diagnostics.sort_key)
    return parsed


def _at_level(result, level: str) -> list[Diagnostic]:
    """A file's syntax diagnostics at its syntax level: at `transitional` and `obsolete` the
    pre-ECMA forms the parser accepted (all of a file that parsed: the others stop the parser)
    are warnings, as EiffelStudio's parser reports them there; at `standard` they are errors."""
    if level not in ("transitional", "obsolete") or result.tree is None:
        return list(result.diagnostics)
    return [
        replace(d, severity=diagnostics.WARNING, hint=d.hint.split(", or set")[0]) if d.code == "SYNTAX-OBSOLETE" else d
        for d in result.diagnostics
    ]


@dataclass
class Checked(Parsed):
    """Parsed plus what the checker proved (None when syntax errors stopped it)."""

    semantics: semantics_checked | None = None
    externals: object = None  # semantics.externals.ProgramExternals: the program's externals


def _parse_library_file(path) -> tuple:
    from .parse import parser  # deferred, as in parse_project

    source, problem = read_source(str(path))
    if problem is not None:
        return None, None, [problem]
    result = parser.parse(source)
    return source, result.tree, list(result.diagnostics)


@contextmanager
def without_gc_pauses():
    """The compiler builds large, long-lived trees and little garbage: the cyclic collector's
    full passes over them would cost more than the whole check, so it waits until the end."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def check_project(
    project: Project,
    use_cache: bool = True,
    library_bodies: bool | None = None,
    parsed: Parsed | None = None,
    progress=None,
    stdlib: tuple | None = None,
) -> Checked:
    """Everything `scoopc check` verifies: syntax (unless `parsed` is given), then the semantic
    checker over the project's classes and the standard library. Library bodies are checked unless
    they come from the cache. `progress(text)` hears of slow steps. `stdlib`: what `load_stdlib`
    returned, kept by a caller that checks many times (the language server); else it is loaded."""
    with without_gc_pauses():
        if stdlib is None:
            stdlib = load_stdlib(use_cache, progress)
        return _check_project(project, use_cache, library_bodies, parsed or parse_project(project), stdlib)


def load_stdlib(use_cache: bool = True, progress=None) -> tuple:
    """The standard library for the checker: (units, prepared universe), from the cache when it
    can. Checking a program adds its classes to a copy of the universe's table and leaves the
    library's classes as they were, so one load serves any number of checks."""
    from .semantics import library  # deferred: start-up (scoopc.semantics.library loads only when this is used)

    return library.load(_parse_library_file, _prepare_library, use_cache, progress)


def ship_stdlib(folder: Path, progress: Callable[[str], None] | None = None) -> Path:
    """A wheel's build: the library's declarations written into `folder` (load_stdlib reads them
    there first), its full trees kept for compiling it next."""
    from .semantics import library  # deferred: start-up, as in load_stdlib

    return library.ship(_parse_library_file, _prepare_library, folder, progress)


def _check_project(project: Project, use_cache: bool, library_bodies: bool | None, parsed: Parsed, stdlib) -> Checked:
    from . import semantics  # deferred: the checker is not needed by `scoopc parse` (start-up)
    from .semantics import externals  # deferred: start-up, as the checker

    checked = Checked(parsed.units, parsed.diagnostics, parsed.sources)
    library_units, prepared = stdlib
    trees = [(unit.tree, False) for unit in parsed.units if unit.tree is not None]
    base = prepared[0] if prepared is not None else None
    for source, _tree, found in library_units:
        if source is not None:
            checked.sources.setdefault(source.path, source)
        checked.diagnostics.extend(found)
    if prepared is not None:
        checked.diagnostics.extend(prepared[1])
    user_names = {tree.name.key.upper() for tree, _ in trees}
    if base is None or any(base.get(name) is not None for name in user_names):
        base = None
        trees += [(tree, True) for _, tree, _ in library_units if tree is not None]
    if library_bodies is None:
        library_bodies = not use_cache
    root = (project.root.class_name, project.root.creation) if project.root is not None else None
    result = semantics.check(
        trees,
        project.settings.void_safety,
        library_bodies=library_bodies,
        base=base,
        root=root,
        concurrency=project.concurrency,
        visible=project.visibility(),
    )
    checked.semantics = result
    checked.diagnostics.extend(result.diagnostics)
    problems, checked.externals = externals.check(result.universe, project)
    checked.diagnostics.extend(problems)
    checked.diagnostics.sort(key=diagnostics.sort_key)
    return checked


def _prepare_library(units) -> tuple:
    """The library's universe with feature tables and signatures, and what preparing it reported."""
    from . import semantics  # deferred: start-up (scoopc.semantics loads only when this is used)

    found: list = []
    universe, _ = semantics.prepare([(tree, True) for _, tree, _ in units if tree is not None], found)
    return universe, found
