"""Language server, the programs behind open documents: which program a file belongs to (the
.ecf beside it, else its folder as a cluster), checked through the driver with the editor's
unsaved buffers and one standard library kept in memory for every check."""

from __future__ import annotations

import gc
import os
import threading
from dataclasses import dataclass, field
from pathlib import Path

from .. import diagnostics, pipeline
from ..diagnostics import Diagnostic
from ..driver import Compilation
from ..exits import UsageError
from ..parse import parser
from ..semantics import Checked as SemanticsChecked
from ..semantics.tables import Tables
from ..semantics.universe import ClassInfo, stdlib_root
from ..source import SourceFile, Span
from .nodes import Texts, library_file


@dataclass
class Analysis:
    """One check of one program: its diagnostics, syntax trees and, when it parsed, what the
    checker proved (universe, tables)."""

    paths: tuple[str, ...]
    checked: pipeline.Checked | None
    files: tuple[str, ...] = ()  # the program's own files (absolute)
    problem: Diagnostic | None = None  # the program could not be read (a bad .ecf, ...)
    trees: dict[str, object] = field(default_factory=dict)  # absolute path -> ClassDeclaration

    @property
    def semantics(self):
        return self.checked.semantics if self.checked is not None else None

    def class_info(self, path: str) -> ClassInfo | None:
        tree = self.trees.get(path)
        if tree is None or self.semantics is None:
            return None
        info = self.semantics.universe.get(tree.name.key)
        if info is None or not (info.decl is tree or library_file(info.decl.span.file) == path):
            return None
        return info

    def diagnostics_by_file(self) -> dict[str, list[Diagnostic]]:
        """Every file of the program with its diagnostics (an empty list clears old ones)."""
        found: dict[str, list[Diagnostic]] = {path: [] for path in self.files}
        everything = ([self.problem] if self.problem else []) + (self.checked.diagnostics if self.checked else [])
        for diagnostic in everything:
            where = os.path.abspath(diagnostic.span.file) if diagnostic.span else self.paths[0]
            found.setdefault(where, []).append(diagnostic)
        return found


def program_paths(path: str) -> tuple[str, ...]:
    """What a file is checked as: the nearest .ecf project above it (the only one in its folder or
    in a folder above, up to the repository's top, a folder with .git), else its own folder as a
    cluster (every .e file below it), as `scoopc check FOLDER` sees it."""
    folder = Path(path).parent
    for candidate in (folder, *folder.parents):
        ecfs = sorted(candidate.glob("*.ecf"))
        if len(ecfs) == 1:
            return (str(ecfs[0]),)
        if (candidate / ".git").exists() or candidate == Path.home():
            break
    return (str(folder),)


def in_library(path: str) -> bool:
    return Path(path).resolve().is_relative_to(stdlib_root().resolve())


_STDLIB: list[tuple] = []  # the standard library, loaded once per process (under _LOADING)
_LOADING = threading.Lock()
SERVER_PROCESS = {"freeze": False}  # set by server.serve: this process is the server's own


def stdlib() -> tuple:
    """The standard library, loaded once. In the server's own process it is then frozen out of the
    cyclic collector's way (its full passes over the library's objects would cost more than a
    check); a process that only hosts a server (the tests) keeps its collector as it was."""
    with _LOADING:
        if not _STDLIB:
            _STDLIB.append(pipeline.load_stdlib())
            if SERVER_PROCESS["freeze"]:
                gc.collect()
                gc.freeze()
        return _STDLIB[0]


def warm_up() -> None:
    """Load the standard library and build the parser before the first document needs them."""
    stdlib()
    parser.parse(SourceFile("warm_up.e", "class WARM_UP end"))


class Programs:
    """The programs of the open documents, each checked again when one of its files changes."""

    def __init__(self) -> None:
        self.texts = Texts()
        self.latest: dict[tuple[str, ...], Analysis] = {}
        self.good: dict[str, Analysis] = {}  # file -> the latest analysis in which it parsed and checked

    @property
    def stdlib(self) -> tuple:
        return stdlib()

    def check(self, path: str) -> Analysis:
        """Check the program of file `path` with the current buffers."""
        return self.check_program(program_paths(path), path)

    def check_program(self, key: tuple[str, ...], path: str) -> Analysis:
        try:
            compilation = Compilation(list(key), overlay=self.texts.buffers, stdlib=self.stdlib)
            checked = compilation.checked
        except UsageError as problem:
            problem_here = diagnostics.make("SOURCE", Span(path, 1, 1, 1, 1), path=key[0], reason=str(problem))
            found = Analysis(key, None, (path,), problem_here)
            self.latest[key] = found
            return found
        files = tuple(os.path.abspath(f) for f in compilation.project.files)
        trees = {os.path.abspath(u.source.path): u.tree for u in checked.units if u.tree is not None}
        analysis = Analysis(key, checked, files, None, trees)
        self.latest[key] = analysis
        if checked.semantics is not None:
            for name in trees:
                self.good[name] = analysis
        return analysis

    def library_analysis(self, path: str) -> Analysis | None:
        """A standard library file: its syntax tree against the library's prepared classes (no
        bodies are checked: names of classes and of the class's own features are known)."""
        source = self.texts.source(path)
        prepared = self.stdlib[1]
        tree = parser.parse(SourceFile(path, source.text)).tree if source is not None else None
        if tree is None or prepared is None:
            return None
        checked = pipeline.Checked(semantics=SemanticsChecked(prepared[0], Tables()))
        return Analysis((path,), checked, (path,), None, {path: tree})

    def analysis(self, path: str) -> Analysis | None:
        """The latest analysis in which `path` has a syntax tree and the program was checked."""
        path = os.path.abspath(path)
        if in_library(path):
            return self.library_analysis(path)
        found = self.good.get(path)
        if found is None and path not in self.texts.buffers:
            found = self.check(path)
        return found if found is not None and path in found.trees else None
