"""Driver, scoopc's cache kept small: what it holds (`scoopc cache info`), entries of other
compiler versions removed, and the least recently used programs pruned past a size limit
($SCOOPC_CACHE_MAX, default 500 MB; suffixes K, M, G).

The cache folder (semantics.library.cache_dir) holds `stdlib-<key>.pickle` (the checked library's
declarations), `base-<digest>/` (the compiled library, driver.library) and `programs/<key>/` (one
compiled program each, driver.compilation). A program names its library's folder in its
`program.json`: it belongs to this compiler when that folder is this compiler's `base-<digest>`,
in the cache or shipped in the wheel (version.PREBUILT, never counted nor removed here).
A program's `program.json` is touched when it is used, so its time of last use is that file's.
"""

from __future__ import annotations

import os
import re
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from .. import version
from ..exits import UsageError
from ..semantics.library import cache_dir, library_key
from .packages import compiler_digest, remove_cached

DEFAULT_MAX = 500 * 1000 * 1000
OTHER_VERSIONS_GRACE = 86400.0  # seconds unused before `tidy` removes another compiler version's entry
STALE_STAGING = 3600.0  # seconds: a staging folder older than this was left by a process that died
_LIBRARY = re.compile(r"base-[0-9a-f]{24}")  # base-<compiler digest>; staging folders have other names
_UNITS = {"": 1, "B": 1, "K": 1000, "KB": 1000, "M": 1000**2, "MB": 1000**2, "G": 1000**3, "GB": 1000**3}


@dataclass(frozen=True)
class Entry:
    path: Path
    kind: str  # "library", "declarations", "program", "staging"
    size: int  # bytes
    used: float  # time of last use (seconds since the epoch)
    current: bool  # made by this compiler?


def cache_limit() -> int:
    """The size limit in bytes from $SCOOPC_CACHE_MAX (`500M`, `2G`, `100000`); a UsageError when
    it cannot be read."""
    text = os.environ.get("SCOOPC_CACHE_MAX", "").strip().upper()
    if not text:
        return DEFAULT_MAX
    number = text.rstrip("KMGB")
    unit = text[len(number) :]
    try:
        value = float(number)
    except ValueError:
        value = -1.0
    if value < 0 or unit not in _UNITS:
        raise UsageError(f"SCOOPC_CACHE_MAX={os.environ['SCOOPC_CACHE_MAX']}: expected a size such as 500M or 2G")
    return int(value * _UNITS[unit])


def entries(folder: Path | None = None) -> list[Entry]:
    """What the cache holds, oldest use first."""
    folder = cache_dir() if folder is None else folder
    if not folder.is_dir():
        return []
    base = f"base-{compiler_digest()}"
    found = []
    for path in _children(folder):
        name = path.name
        if _LIBRARY.fullmatch(name) and path.is_dir():
            found.append(_entry(path, "library", name == base))
        elif name.startswith("stdlib-") and name.endswith(".pickle"):
            found.append(_entry(path, "declarations", name == f"stdlib-{library_key()}.pickle"))
        elif name.startswith(".stdlib-") or name.startswith("base-"):
            found.append(_entry(path, "staging", False))
    for path in _children(folder / "programs"):
        if path.name.endswith((".tmp", ".old")):
            found.append(_entry(path, "staging", False))
        else:
            found.append(_entry(path, "program", _program_base(path) in (folder / base, version.PREBUILT / base)))
    return sorted(found, key=lambda e: e.used)


def clean(everything: bool = False, grace: float = 0.0, keep: Path | None = None) -> list[Entry]:
    """Remove the entries of other compiler versions unused for `grace` seconds and leftovers of
    interrupted runs (or, with `everything`, the whole cache); then the least recently used
    programs past the limit. The removed entries."""
    now = time.time()
    removed = [e for e in entries() if everything or _obsolete(e, now - grace)]
    for entry in removed:
        _remove(entry.path)
    return removed + prune(keep=keep)


def prune(limit: int | None = None, keep: Path | None = None) -> list[Entry]:
    """Remove the least recently used programs until the cache is under `limit` bytes (the
    current library and declarations are kept: every run needs them; so is `keep`, the program
    just compiled)."""
    limit = cache_limit() if limit is None else limit
    found = entries()
    total = sum(e.size for e in found)
    removed = []
    for entry in found:
        if total <= limit:
            break
        if entry.path != keep and (entry.kind == "program" or not entry.current and entry.kind != "staging"):
            _remove(entry.path)
            total -= entry.size
            removed.append(entry)
    return removed


def tidy(keep: Path) -> None:
    """After a compilation added to the cache: other versions' entries unused for a day removed
    (another scoopc sharing the cache may still be using its own), then pruned. Never fails a run
    (another process may be removing the same entries)."""
    try:
        clean(grace=OTHER_VERSIONS_GRACE, keep=keep)
    except (OSError, UsageError):
        pass


def touch(path: Path) -> None:
    """Record a use of a cached entry (a program's program.json, a library's folder): its place in
    the pruning order."""
    try:
        os.utime(path)
    except OSError:
        pass


def _obsolete(entry: Entry, unused_since: float) -> bool:
    if entry.kind == "staging":
        return entry.used < time.time() - STALE_STAGING
    return not entry.current and entry.used <= unused_since


def _children(folder: Path) -> Iterator[Path]:
    try:
        yield from sorted(folder.iterdir())
    except OSError:
        return


def _entry(path: Path, kind: str, current: bool) -> Entry:
    size, newest = _measure(path)
    used = _mtime(path / "program.json") if kind == "program" else max(newest, _mtime(path))
    return Entry(path, kind, size, used, current)


def _measure(path: Path) -> tuple[int, float]:
    """(bytes, latest modification) of a file or a folder's files."""
    try:
        if not path.is_dir():
            info = path.stat()
            return info.st_size, info.st_mtime
        size, newest = 0, path.stat().st_mtime
        for root, _, files in os.walk(path):
            for name in files:
                try:
                    info = os.stat(os.path.join(root, name))
                except OSError:
                    continue
                size += info.st_size
                newest = max(newest, info.st_mtime)
        return size, newest
    except OSError:
        return 0, 0.0


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0


def _program_base(path: Path) -> Path | None:
    try:
        text = (path / "program.json").read_text()
    except OSError:
        return None
    marker = '"base": "'
    start = text.find(marker)
    if start < 0:
        return None
    end = text.find('"', start + len(marker))
    return Path(text[start + len(marker) : end])


def _remove(path: Path) -> None:
    if path.is_dir():
        remove_cached(path)
    else:
        root = cache_dir().resolve()
        if root in path.resolve().parents:
            path.unlink(missing_ok=True)


def describe(found: list[Entry], folder: Path, limit: int) -> str:
    """The text of `scoopc cache info`."""
    lines = [f"cache folder: {folder}", f"limit: {size_text(limit)} (SCOOPC_CACHE_MAX)"]
    shipped = version.prebuilt(f"base-{compiler_digest()}")
    if shipped is not None:
        lines.append(f"standard library: the one installed with scoopc, outside the cache ({shipped})")
    total = sum(e.size for e in found)
    by_kind: dict[str, list[Entry]] = {}
    for entry in found:
        by_kind.setdefault(entry.kind, []).append(entry)
    for kind in ("library", "declarations", "program", "staging"):
        group = by_kind.get(kind, [])
        if group:
            old = sum(1 for e in group if not e.current)
            note = f", {old} of other compiler versions" if old and kind != "staging" else ""
            label = {"library": "libraries", "program": "programs", "staging": "unfinished"}.get(kind, kind)
            lines.append(f"{label}: {len(group)}, {size_text(sum(e.size for e in group))}{note}")
    lines.append(f"total: {size_text(total)}")
    return "\n".join(lines)


def size_text(count: int) -> str:
    for unit, scale in (("GB", 1000**3), ("MB", 1000**2), ("kB", 1000)):
        if count >= scale:
            return f"{count / scale:.1f} {unit}"
    return f"{count} B"
