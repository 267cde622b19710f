"""Driver, the compiled standard library: stdlib/ checked with bodies and compiled once into the
package `eiffel_base`, with the SCOOP facts of its routines beside it (codegen.scoop), which
programs' leaf analysis reads. A wheel ships it (scoopc/prebuilt/base-<digest>/, made by
build_prebuilt when the wheel is built); otherwise, or when the compiler's digest differs from the
one it was built with, it is compiled on first use into the cache ($SCOOPC_CACHE_DIR/base-<digest>/)."""

from __future__ import annotations

import functools
import json
import py_compile
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .. import version
from ..codegen.context import Options
from ..codegen.program import generate
from ..codegen.scoop import FACTS_FILE, FACTS_FORMAT, write_library_facts
from ..parse.parser import save_parser
from ..pipeline import check_project, ship_stdlib
from ..progress import Steps
from ..project import Project
from ..semantics.library import cache_dir
from ..semantics.universe import stdlib_root
from .packages import (
    BASE_PACKAGE,
    BYTECODE_DONE,
    compiler_digest,
    is_whole,
    remove_cached,
    writable_cache,
    write_manifest,
    write_modules,
)

Progress = Callable[[str], None] | None
STAGES = ("checking", "generating Python", "writing eiffel_base", "byte-compiling")


class LibraryError(Exception):
    """The standard library does not check: a bug of scoopc's (an internal error)."""


@dataclass(frozen=True)
class Library:
    path: Path  # the folder holding the package eiffel_base
    facts: dict[str, Any]  # {routine version key: [leaf verdict, callees]} (codegen.scoop.library_facts)


def compiled_library(progress: Progress = None, rebuild: bool = False) -> Library:
    """The compiled standard library: the cache's copy, else the one the wheel ships, when made
    by this compiler (its digest in the folder's name); else compiled into the cache (a few
    seconds, once per compiler), as it is when it is damaged or `rebuild` is asked."""
    name = f"base-{compiler_digest()}"
    target = cache_dir() / name
    if not rebuild and is_whole(target / BASE_PACKAGE):
        return Library(target, _read_facts(target / BASE_PACKAGE / FACTS_FILE))
    shipped = version.prebuilt(name)
    if not rebuild and shipped is not None and is_whole(shipped / BASE_PACKAGE):
        return Library(shipped, _read_facts(shipped / BASE_PACKAGE / FACTS_FILE))
    if target.exists():
        remove_cached(target)
    staging = Path(tempfile.mkdtemp(prefix="base-", dir=writable_cache()))
    _build(staging, progress, bytecode=True)
    try:
        staging.rename(target)
    except OSError:  # another process won the race: use its copy
        shutil.rmtree(staging, ignore_errors=True)
    return Library(target, _read_facts(target / BASE_PACKAGE / FACTS_FILE))


def build_prebuilt(folder: Path, progress: Progress = None) -> Path:
    """A wheel's build (tools/build_stdlib.py): the parser's tables, the library's declarations
    and the compiled library written into `folder` (the package's `prebuilt`), for the compiler
    this process runs. No bytecode: the installer writes it. The compiled library's folder."""
    folder.mkdir(parents=True, exist_ok=True)
    save_parser(folder)
    ship_stdlib(folder, progress)
    target = folder / f"base-{compiler_digest()}"
    _build(target, progress, bytecode=False)
    return target


def _build(target: Path, progress: Progress, bytecode: bool) -> None:
    title = "compiling the standard library (once per compiler)"
    with Steps(progress, title, STAGES if bytecode else STAGES[:-1]) as steps:
        steps.stage()
        checked = check_project(Project(), use_cache=False, library_bodies=True)
        if checked.has_errors:
            raise LibraryError("the standard library does not check: " + str(checked.diagnostics[0]))
        sem = checked.semantics
        assert sem is not None  # no errors: the checker ran
        options = Options(package=BASE_PACKAGE, source_root=str(stdlib_root().parent))
        steps.stage(sum(1 for info in sem.universe.classes.values() if info.from_library))
        modules = generate(sem.universe, sem.tables, options, lambda info: info.from_library, on_class=steps.advance)
        steps.stage()
        package = target / BASE_PACKAGE
        write_modules(package, modules, "The standard library, compiled by scoopc.")
        write_library_facts(package, sem.universe, sem.tables, options)
        if bytecode:
            sources = sorted(package.glob("*.py"))
            steps.stage(len(sources))
            for source in sources:  # what packages.write_bytecode does, one module at a time
                py_compile.compile(str(source), doraise=True)
                steps.advance()
            (package / BYTECODE_DONE).touch()
        write_manifest(package)


def _read_facts(path: Path) -> dict[str, Any]:
    """The facts file's contents; {} when it is missing or of another format (library routines
    then count as non-leaves, which is always safe). Read once per process while the file is
    unchanged (a few megabytes of JSON: a third of a second per compilation otherwise); callers
    only read the dictionary."""
    try:
        stat = path.stat()
    except OSError:
        return {}
    return _facts_of(path, stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=4)
def _facts_of(path: Path, mtime_ns: int, size: int) -> dict[str, Any]:
    """The facts of the file at `path` as it was at (mtime_ns, size): the key of the memo."""
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    facts = data.get("facts") if isinstance(data, dict) and data.get("format") == FACTS_FORMAT else None
    return facts if isinstance(facts, dict) else {}
