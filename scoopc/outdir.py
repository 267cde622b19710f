"""Output folders of `scoopc compile -o DIR`: scoopc replaces only what it wrote itself.

Every package folder scoopc writes carries a marker file that lists the files written into it.
Before a folder is written again, it must either not exist or carry that marker and hold nothing
else (bytecode caches aside); otherwise nothing is touched and the user gets a usage error. Only
the files the marker lists are removed, so a file scoopc did not write is never deleted or
overwritten, whatever `-o` names (a sources folder, the home directory, `.`).
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterable
from pathlib import Path

from .exits import UsageError
from .version import __version__

MARKER = ".scoopc-output"
_CACHES = "__pycache__"


def prepare(out: Path) -> None:
    """`-o OUT`: a folder that exists or can be made."""
    if out.exists() and not out.is_dir():
        raise UsageError(f"-o {out}: is a file, not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as problem:
        raise UsageError(f"-o {out}: cannot make the folder ({problem.strerror or problem})") from None


def check(folder: Path):
    """The files scoopc wrote in `folder` (None: there is no such folder yet). Raises UsageError
    when the folder holds anything else, or was not written by scoopc at all."""
    if not folder.exists() and not folder.is_symlink():
        return None
    if folder.is_symlink() or not folder.is_dir():
        raise UsageError(
            f"{folder} exists and is not a folder scoopc wrote: it is left as it is; "
            f"choose another -o folder or move it away"
        )
    written = _written(folder)
    if written is None:
        raise UsageError(
            f"{folder} exists and was not written by scoopc (it has no {MARKER} file): it is left "
            f"as it is; choose another -o folder, or remove it yourself"
        )
    foreign = sorted(str(p.relative_to(folder)) for p in _files(folder) if _relative(p, folder) not in written)
    if foreign:
        shown = ", ".join(foreign[:5]) + (", ..." if len(foreign) > 5 else "")
        raise UsageError(
            f"{folder} holds files scoopc did not write ({shown}): nothing was changed; move them "
            f"away or choose another -o folder"
        )
    return written


def clear(folder: Path) -> None:
    """Make room for a new output in `folder`: remove what scoopc wrote there before, after checking
    that nothing else is there. Raises UsageError, having removed nothing, otherwise."""
    written = check(folder)
    if written is None:
        return
    for name in written:
        (folder / name).unlink(missing_ok=True)
    for cache in folder.rglob(_CACHES):
        shutil.rmtree(cache, ignore_errors=True)
    (folder / MARKER).unlink(missing_ok=True)
    _remove_empty(folder)


def mark(folder: Path) -> None:
    """Record every file now in `folder` as written by scoopc (call right after writing it)."""
    files = sorted(_relative(p, folder) for p in _files(folder))
    (folder / MARKER).write_text(json.dumps({"written_by": f"scoopc {__version__}", "files": files}, indent=0))


def _written(folder: Path):
    """The files the marker lists, or None where there is no readable marker."""
    try:
        data = json.loads((folder / MARKER).read_text())
    except (OSError, ValueError):
        return None
    files = data.get("files") if isinstance(data, dict) else None
    if not isinstance(files, list) or not all(isinstance(f, str) for f in files):
        return None
    # a marker never names a path outside its folder
    return {f for f in files if not Path(f).is_absolute() and ".." not in Path(f).parts}


def _files(folder: Path) -> Iterable[Path]:
    """Every file below `folder` but the marker and bytecode caches (links count as files)."""
    for path in folder.rglob("*"):
        if _CACHES in path.relative_to(folder).parts or path.name == MARKER and path.parent == folder:
            continue
        if path.is_symlink() or not path.is_dir():
            yield path


def _relative(path: Path, folder: Path) -> str:
    return path.relative_to(folder).as_posix()


def _remove_empty(folder: Path) -> None:
    for path in sorted(folder.rglob("*"), key=lambda p: len(p.parts), reverse=True):
        if path.is_dir() and not path.is_symlink() and not any(path.iterdir()):
            path.rmdir()
    if not any(folder.iterdir()):
        folder.rmdir()
