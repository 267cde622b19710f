"""Driver, one program through the pipeline: a Compilation owns the phases (project, parsed,
checked, root, the library's package and facts, the program's modules, the package on disk) and
computes each once, on first use, so every caller (the command line, the Python API, the tests)
gets the same pipeline and no phase is built as a side effect of another. Long phases report
through the `progress` callback.
"""

from __future__ import annotations

import ast
import json
import keyword
import os
import re
import shutil
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

from .. import outdir, pipeline
from ..codegen.context import Options
from ..codegen.names import class_name, module_name
from ..codegen.program import generate
from ..depth import deeply
from ..exits import SourceErrors, UsageError
from ..kernel.link import LIBRARY_LEAVES_FILE
from ..project import Project, beside_program, collect
from ..semantics import Checked as SemanticsChecked
from ..semantics.library import cache_dir
from ..semantics.universe import stdlib_root
from ..version import __version__
from . import cache, externals
from .library import Library, compiled_library
from .packages import (
    BASE_PACKAGE,
    ensure_bytecode,
    is_whole,
    program_key,
    writable_cache,
    write_bytecode,
    write_manifest,
    write_modules,
)
from .roots import Root, choose_root

Progress = Callable[[str], None] | None
PathLike = str | Path
Modules = dict[str, tuple[ast.Module, str]]  # file name -> (module, its Eiffel source file)
ASSERTIONS = ("all", "require", "none")


@dataclass(frozen=True)
class CompiledProgram:
    """A program compiled into a package on disk, ready to run."""

    folder: Path  # holds the program's package
    package: str  # its name
    root: Root
    library: Path  # holds the compiled library's package, eiffel_base
    shadowed: dict[str, str] = field(default_factory=dict)  # user classes named like library classes
    roboscoop: bool = False  # does it use the Roboscoop library (then it runs with a robot)?

    def meta(self) -> dict[str, Any]:
        return {
            "package": self.package,
            "root": self.root.key,
            "creator": self.root.creator,
            "base": str(self.library),
            "shadowed": self.shadowed,
            "roboscoop": self.roboscoop,
        }

    @classmethod
    def from_meta(cls, folder: Path, meta: dict[str, Any]) -> CompiledProgram:
        return cls(
            folder,
            meta["package"],
            Root(meta["root"], meta["creator"]),
            Path(meta["base"]),
            meta["shadowed"],
            meta["roboscoop"],
        )


class Compilation:
    """One program (the sources at `paths`) and the options that shape its compilation."""

    def __init__(
        self,
        paths: Sequence[PathLike],
        *,
        target: str | None = None,
        root: str | None = None,
        assertions: str | None = None,
        progress: Progress = None,
        overlay: Mapping[str, str] | None = None,
        stdlib: tuple[Any, Any] | None = None,
    ):
        """`overlay` ({absolute path: text}) stands for the files' text on disk (an editor's
        unsaved buffers); `stdlib` is pipeline.load_stdlib's result, shared by many compilations."""
        if not paths:
            raise UsageError("no PATH given: name a .e file, a directory or an .ecf project file")
        if assertions is not None and assertions not in ASSERTIONS:
            raise UsageError(f"assertions must be one of {', '.join(ASSERTIONS)}, not {assertions!r}")
        self.paths = [str(p) for p in paths]
        self.target, self.root_option, self.assertions_option = target, root, assertions
        self.progress = progress
        self.overlay, self.stdlib = dict(overlay or {}), stdlib
        self._modules: dict[str, tuple[Modules, list[str]]] = {}
        self.rebuild_library = False
        self._program: CompiledProgram | None = None

    # ---- the front end ------------------------------------------------------------------------
    @cached_property
    def project(self) -> Project:
        return collect(self.paths, self.target)

    @cached_property
    def parsed(self) -> pipeline.Parsed:
        return deeply(pipeline.parse_project, self.project, self.overlay)

    @cached_property
    def checked(self) -> pipeline.Checked:
        parsed = self.parsed
        return deeply(pipeline.check_project, self.project, parsed=parsed, progress=self.progress, stdlib=self.stdlib)

    @property
    def was_checked(self) -> bool:
        """Has this compilation checked the program (a cached run does not)?"""
        return "checked" in self.__dict__

    def require_clean(self) -> pipeline.Checked:
        """The checked program; SourceErrors when it has errors."""
        if self.checked.has_errors:
            raise SourceErrors(self.checked.diagnostics)
        try:
            self.c_modules  # noqa: B018 - built now: a build failure is the source's error
        except SourceErrors as failed:
            self.checked.diagnostics.extend(failed.diagnostics)
            raise SourceErrors(self.checked.diagnostics) from None
        return self.checked

    @cached_property
    def c_modules(self) -> list[Path]:
        """The extension modules of the program's C and C++ externals, built with cffi (or taken
        from the cache); SourceErrors naming what is missing when they cannot be built."""
        return externals.build_all(self.checked.externals, self.project)

    @property
    def semantics(self) -> SemanticsChecked:
        """What the checker proved of a program without errors (SourceErrors otherwise)."""
        found = self.require_clean().semantics
        assert found is not None  # no syntax errors: the checker ran
        return found

    @cached_property
    def root(self) -> Root:
        return choose_root(self.project, self.semantics.universe, self.root_option, self.paths)

    @property
    def program_folder(self) -> str:
        """The folder of the program's paths (a file's, a cluster's, an .ecf's): generated code
        names the program's source files relative to it."""
        folders = [p if os.path.isdir(p) else os.path.dirname(p) or "." for p in self.paths]
        try:
            return os.path.commonpath([os.path.abspath(f) for f in folders])
        except ValueError:  # folders on several drives (Windows)
            return os.path.abspath(folders[0])

    @property
    def assertions(self) -> str:
        return self.assertions_option or self.project.settings.assertions or "all"

    # ---- the back end -------------------------------------------------------------------------
    @cached_property
    def library(self) -> Library:
        return compiled_library(self.progress, rebuild=self.rebuild_library)

    def modules(self, package: str = "program") -> tuple[Modules, list[str]]:
        """The program's modules ({file name: (ast.Module, Eiffel file)}) as package `package`
        (they import each other by the package's name), and the library routines that are leaves
        in the program's closed world."""
        if package not in self._modules:
            sem = self.semantics
            leaves: list[str] = []
            c_modules = tuple(
                (plan.language, plan.name) for plan in externals.plans(self.checked.externals, self.project)
            )
            options = Options(
                assertions=self.assertions, package=package, c_modules=c_modules, source_root=self.program_folder
            )
            modules = deeply(
                generate,
                sem.universe,
                sem.tables,
                options,
                lambda info: not info.from_library,
                leaves,
                library_facts=self.library.facts,
            )
            self._modules[package] = (modules, leaves)
        return self._modules[package]

    def write_package(self, out: Path, package: str) -> CompiledProgram:
        """Write the program's package as `out/package` (a folder that must not exist yet, or
        that outdir.clear emptied), marked as written by scoopc."""
        sem = self.semantics
        modules, leaves = self.modules(package)
        folder = out / package
        doc = f"A program compiled by scoopc (root class {self.root.key})."
        deeply(write_modules, folder, modules, doc, (BASE_PACKAGE,), _no_scoopc(package))
        (folder / LIBRARY_LEAVES_FILE).write_text(json.dumps(leaves, separators=(",", ":")))
        compiled = CompiledProgram(
            out, package, self.root, self.library.path, dict(sem.universe.shadowed), uses_roboscoop(self.project.files)
        )
        (folder / "__main__.py").write_text(_main_text(compiled))
        externals.copy_python_modules(self.checked.externals, folder)
        for module in self.c_modules:
            shutil.copy2(module, folder / module.name)
        outdir.mark(folder)
        return compiled

    def compile_to(self, out: PathLike) -> CompiledProgram:
        """`scoopc compile -o OUT`: OUT/<root> and OUT/eiffel_base, replacing only what scoopc wrote
        there before (outdir)."""
        out = Path(out)
        package = package_name(self.root.key)
        library = out / BASE_PACKAGE
        outdir.prepare(out)
        for folder in (out / package, library):  # both checked before either is touched
            outdir.check(folder)
        for folder in (out / package, library):
            outdir.clear(folder)
        compiled = self.write_package(out, package)
        if compiled.roboscoop:  # its run looks for them beside the package, as `scoopc run` does beside the sources
            for name in ("world.yaml", "robot.yaml"):
                found = beside_program(self.paths, name)
                if found is not None:
                    shutil.copy2(found, out / package / name)
            outdir.mark(out / package)
        shutil.copytree(
            self.library.path / BASE_PACKAGE, library, ignore=shutil.ignore_patterns("__pycache__", outdir.MARKER)
        )
        outdir.mark(library)
        return compiled

    def cached_program(self, use_cache: bool = True) -> CompiledProgram:
        """The program compiled into scoopc's cache, keyed by the sources' contents and the options;
        an earlier compilation is used unless `use_cache` is false. Computed once per Compilation."""
        if self._program is None:
            self._program = self._cached_program(use_cache)
        return self._program

    def _cached_program(self, use_cache: bool) -> CompiledProgram:
        extra = json.dumps(
            [
                self.root_option,
                self.assertions_option,
                self.project.settings.assertions,
                self.project.root.class_name if self.project.root else None,
                self.project.concurrency,  # decides what `separate` compiles to
                externals.inputs_digest(self.project),
            ]
        )
        key = program_key([Path(p) for p in self.project.files], extra)
        folder = cache_dir() / "programs" / key
        found = _read_cached(folder) if use_cache else None
        if found is None:
            # The checked library stays in memory to the end: the collector's passes over it
            # would cost more than the whole compilation (pipeline.without_gc_pauses).
            with pipeline.without_gc_pauses():
                self.require_clean()
                self.rebuild_library |= not use_cache  # no cache at all: the library is compiled again too
                found = self._cache(folder, key)
            cache.tidy(keep=folder)
        else:
            cache.touch(folder / "program.json")
        if found.library.parent == cache_dir():
            cache.touch(found.library)
        ensure_bytecode(found.library)
        return found

    def _cache(self, folder: Path, key: str) -> CompiledProgram:
        writable_cache()
        staging = folder.with_name(f"{key}.{os.getpid()}.tmp")  # per process: runs may race
        if staging.exists():
            shutil.rmtree(staging)
        staging.mkdir(parents=True)
        compiled = self.write_package(staging, "program")
        write_manifest(staging / "program")
        (staging / "program.json").write_text(json.dumps(compiled.meta()))
        write_bytecode(staging / "program")
        if folder.exists():  # no cache wanted, or another process compiled it meanwhile
            old = folder.with_name(f"{key}.{os.getpid()}.old")
            try:
                folder.rename(old)
                shutil.rmtree(old, ignore_errors=True)
            except OSError:
                pass
        try:
            staging.rename(folder)
        except OSError:  # another process put its copy in place first: use it
            shutil.rmtree(staging, ignore_errors=True)
        return CompiledProgram.from_meta(folder, compiled.meta())


def package_name(root_key: str) -> str:
    """The package `scoopc compile` writes for a root class: its name in lower case, unless that
    would shadow a module Python or scoopc needs (`json`, `threading`, `eiffel_base`, ...), then
    with `_program` after it."""
    name = module_name(root_key)
    taken = name in sys.stdlib_module_names or name in (BASE_PACKAGE, "scoopc", "program") or keyword.iskeyword(name)
    return f"{name}_program" if taken else name


def _read_cached(folder: Path) -> CompiledProgram | None:
    try:
        meta = json.loads((folder / "program.json").read_text())
        found = CompiledProgram.from_meta(folder, meta)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    whole = is_whole(found.library / BASE_PACKAGE) and is_whole(folder / found.package)
    return found if whole else None


def _main_text(program: CompiledProgram) -> str:
    """The `__main__` of a compiled program. A Roboscoop program is run by scoopc as `scoopc run`
    runs it, with a robot and the run and robot options (cli.run_compiled); any other program is
    started by the launcher alone (a faster start: the driver is not loaded), with its arguments."""
    root = program.root
    if program.roboscoop:
        facts = {"root": root.key, "creator": root.creator, "shadowed": program.shadowed, "version": __version__}
        return (
            f'"""Run the program: python -m {program.package} [OPTIONS] [-- ARGS] (the options: --help)."""\n'
            f"import sys\n\n"
            f"from scoopc.cli import run_compiled\n\n"
            f"if __name__ == '__main__':\n"
            f"    sys.exit(run_compiled(__file__, {facts!r}))\n"
        )
    return (
        f'"""Run the program: python -m {program.package} [ARGS]."""\n'
        f"import sys\n\n"
        f"from scoopc.kernel import launcher\n\n"
        f"if __name__ == '__main__':\n"
        f"    from {program.package}.{module_name(root.key)} import {class_name(root.key)}\n"
        f"    sys.exit(launcher.main({class_name(root.key)}, {root.creator!r}, sys.argv, "
        f"shadowed={program.shadowed!r}))\n"
    )


def _no_scoopc(package: str) -> str:
    """What a compiled program says when the Python that runs it cannot import scoopc."""
    return (
        f"{package}: error: this program was compiled by scoopc {__version__} and runs on scoopc's runtime, "
        "which this Python cannot import ({}); install scoopc (pip install scoopc) or run it with the Python "
        "that has scoopc\n"
    )


def uses_roboscoop(files: Sequence[PathLike]) -> bool:
    """Does a user class name a class of stdlib/roboscoop? (Comments do not count.)"""
    library = stdlib_root()
    names = {p.stem.upper() for p in (library / "roboscoop").rglob("*.e")}
    for name in files:
        path = Path(name).resolve()
        if library in path.parents:
            continue
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        code = re.sub(r"--[^\n]*", "", text)
        if names.intersection(re.findall(r"\b[A-Z][A-Z0-9_]*\b", code)):
            return True
    return False
