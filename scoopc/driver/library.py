"""Driver, the compiled standard library: stdlib/ checked with bodies and compiled once into the
package `eiffel_base`, cached by content ($SCOOPC_CACHE_DIR/base-<key>/), with the SCOOP facts of
its routines beside it (codegen.scoop), which programs' leaf analysis reads."""

from __future__ import annotations

import json
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..codegen.context import Options
from ..codegen.program import generate
from ..codegen.scoop import FACTS_FILE, FACTS_FORMAT, write_library_facts
from ..pipeline import check_project
from ..project import Project
from ..semantics.library import cache_dir
from ..semantics.universe import stdlib_root
from .packages import (
    BASE_PACKAGE,
    compiler_digest,
    is_whole,
    remove_cached,
    writable_cache,
    write_manifest,
    write_modules,
)

Progress = Callable[[str], None] | None


class LibraryError(Exception):
    """The standard library does not check: a bug of scoopc's (an internal error)."""


@dataclass(frozen=True)
class Library:
    path: Path  # the folder holding the package eiffel_base
    facts: dict[str, Any]  # {routine version key: [leaf verdict, callees]} (codegen.scoop.library_facts)


def compiled_library(progress: Progress = None, rebuild: bool = False) -> Library:
    """The compiled standard library, built on first use (a few seconds, once per scoopc version),
    and built again when it is damaged or `rebuild` is asked."""
    target = cache_dir() / f"base-{compiler_digest()}"
    if rebuild or not is_whole(target / BASE_PACKAGE):
        if target.exists():
            remove_cached(target)
        _build(target, progress)
    return Library(target, _read_facts(target / BASE_PACKAGE / FACTS_FILE))


def _build(target: Path, progress: Progress) -> None:
    if progress:
        progress("compiling the standard library (once per scoopc version)")
    checked = check_project(Project(), use_cache=False, library_bodies=True)
    if checked.has_errors:
        raise LibraryError("the standard library does not check: " + str(checked.diagnostics[0]))
    sem = checked.semantics
    assert sem is not None  # no errors: the checker ran
    options = Options(package=BASE_PACKAGE, source_root=str(stdlib_root().parent))
    modules = generate(sem.universe, sem.tables, options, lambda info: info.from_library)
    staging = Path(tempfile.mkdtemp(prefix="base-", dir=writable_cache()))
    write_modules(staging / BASE_PACKAGE, modules, "The standard library, compiled by scoopc.")
    write_library_facts(staging / BASE_PACKAGE, sem.universe, sem.tables, options)
    write_manifest(staging / BASE_PACKAGE)
    try:
        staging.rename(target)
    except OSError:  # another process won the race: use its copy
        shutil.rmtree(staging, ignore_errors=True)


def _read_facts(path: Path) -> dict[str, Any]:
    """The facts file's contents; {} when it is missing or of another format (library routines
    then count as non-leaves, which is always safe)."""
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    facts = data.get("facts") if isinstance(data, dict) and data.get("format") == FACTS_FORMAT else None
    return facts if isinstance(facts, dict) else {}
