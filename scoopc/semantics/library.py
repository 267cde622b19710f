"""Checker, the standard library: its syntax trees and its prepared universe (feature tables and
signatures), parsed from stdlib/ or loaded from a cache keyed by the library's contents and the
compiler's version (so edits invalidate it).

Cache directory: $SCOOPC_CACHE_DIR, else $XDG_CACHE_HOME/scoopc, else ~/.cache/scoopc. A wheel
ships the cache file of its own library in scoopc/prebuilt/ (version.PREBUILT), read first.
"""

from __future__ import annotations

import gc
import hashlib
import os
import pickle
import sys
from dataclasses import replace
from pathlib import Path

from .. import syntax, version
from ..progress import Steps
from ..version import __version__
from .universe import stdlib_files

CACHE_FORMAT = 4
_PARSED: dict = {}  # the full trees of the last cold parse, by library key (one use)


def cache_dir() -> Path:
    explicit = os.environ.get("SCOOPC_CACHE_DIR")
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "scoopc"


def library_key() -> str:
    """The key of the current library's declarations cache (`stdlib-<key>.pickle`)."""
    return _key(stdlib_files())


def _key(files: list[Path]) -> str:
    digest = hashlib.sha256(f"{__version__}:{CACHE_FORMAT}".encode())
    for path in files:
        digest.update(str(path.name).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:32]


def load(parse_file, prepare=None, use_cache: bool = True, progress=None):
    """(units, prepared) for the stdlib: units are [(SourceFile, tree, diagnostics)] for every
    class file; prepared is `prepare(units)` (the library's universe, ready for user classes to be
    added), kept in the cache with the units. Without the cache, prepared is None. From the cache,
    the trees have no routine bodies and the SourceFile is None. `progress(text)` hears of the
    slow path (parsing the library: a few seconds, once per version)."""
    files = stdlib_files()
    key = _key(files)
    if not use_cache:
        full = _PARSED.pop(key, None)  # parsed moments ago to fill the cache: not again
        return (full if full is not None else [parse_file(path) for path in files]), None
    cached = _read(key)
    if cached is not None:
        return cached
    units, prepared = _parse_and_prepare(files, key, parse_file, prepare, progress)
    _write(key, (units, prepared))
    return units, prepared


def ship(parse_file, prepare, folder: Path, progress=None) -> Path:
    """A wheel's build: the library's declarations cache file written into `folder` (the trees
    are kept for compiling the library next). Fails loudly."""
    files = stdlib_files()
    key = _key(files)
    _write(key, _parse_and_prepare(files, key, parse_file, prepare, progress), folder)
    return folder / f"stdlib-{key}.pickle"


def _parse_and_prepare(files: list[Path], key: str, parse_file, prepare, progress) -> tuple:
    with Steps(progress, "reading the standard library (once per scoopc version)", ("parsing", "preparing")) as steps:
        steps.stage(len(files))
        parsed = []
        for path in files:
            parsed.append(parse_file(path))
            steps.advance()
        _PARSED.clear()
        _PARSED[key] = parsed  # compiling the library next needs the bodies too
        steps.stage()
        # Kept: the declarations; not kept: the source texts (a cached library reports nothing).
        units = [(None, declarations_only(tree), found) for _, tree, found in parsed]
        prepared = prepare(units) if prepare is not None else None
    return units, prepared


def declarations_only(tree):
    """The class without its routine bodies (instructions, locals, rescue clauses): what checking
    other classes against it needs, and half the size to load."""
    if tree is None:
        return None
    clauses = tuple(
        replace(clause, features=tuple(_without_body(f) for f in clause.features)) for clause in tree.feature_clauses
    )
    return replace(tree, feature_clauses=clauses)


def _without_body(feature):
    body = getattr(feature, "body", None)
    if body is None or not isinstance(body.body, (syntax.InternalBody, syntax.AttributeBody)):
        return feature
    inner = replace(body.body, instructions=())
    return replace(feature, body=replace(body, body=inner, locals=(), rescue=None))


def _read(key: str) -> list | None:
    name = f"stdlib-{key}.pickle"
    path = version.prebuilt(name) or cache_dir() / name
    enabled = gc.isenabled()
    gc.disable()  # a load creates many objects and no garbage: collections only cost time
    try:
        with open(path, "rb") as handle:
            return pickle.load(handle)
    except Exception:  # a damaged or foreign cache file: parse the library again
        return None
    finally:
        if enabled:
            gc.enable()


def _write(key: str, units, directory: Path | None = None) -> None:
    """Into the cache folder, or `directory` (a wheel's build, which must not fail quietly)."""
    shipping = directory is not None
    directory = cache_dir() if directory is None else directory
    try:
        directory.mkdir(parents=True, exist_ok=True)
        temporary = directory / f".stdlib-{key}.{os.getpid()}"
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(max(limit, 20000))
        try:
            with open(temporary, "wb") as handle:
                pickle.dump(units, handle, protocol=pickle.HIGHEST_PROTOCOL)
        finally:
            sys.setrecursionlimit(limit)
        os.replace(temporary, directory / f"stdlib-{key}.pickle")
        for stale in directory.glob("stdlib-*.pickle"):
            if stale.name != f"stdlib-{key}.pickle":
                stale.unlink(missing_ok=True)
    except OSError:
        if shipping:  # a wheel must not ship without it
            raise
        # else a read-only home: work without the cache
