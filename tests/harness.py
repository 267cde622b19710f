"""Shared test machinery: golden files and `-- E: CODE` markers.

Markers: a line of an Eiffel test file that ends with `-- E: CODE` (several codes separated by
spaces; `CODE@COL` also pins the column) expects exactly those diagnostics on that line.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent

_MARKER = re.compile(r"--\s*E:\s*(?P<codes>[A-Za-z0-9_()\-@ ]+?)\s*$")


def expected_diagnostics(files: Iterable[Path]) -> Counter:
    """(file name, line, code, column or None) for every marker in the files."""
    found: Counter = Counter()
    for file in files:
        for number, line in enumerate(file.read_text(encoding="utf-8").splitlines(), start=1):
            match = _MARKER.search(line)
            if not match:
                continue
            for item in match.group("codes").split():
                code, _, column = item.partition("@")
                found[(file.name, number, code, int(column) if column else None)] += 1
    return found


def actual_diagnostics(found, expected: Counter) -> Counter:
    """The reported errors in the marker form; columns kept only where a marker pins them."""
    pinned = {(f, line, code) for (f, line, code, column) in expected if column is not None}
    actual: Counter = Counter()
    for d in found:
        if not d.is_error:
            continue
        name = Path(d.span.file).name if d.span else "?"
        line = d.span.line if d.span else 0
        column = d.span.column if d.span and (name, line, d.code) in pinned else None
        actual[(name, line, d.code, column)] += 1
    return actual


def describe(entries: Counter) -> str:
    return "\n".join(
        f"  {f}:{line}{':' + str(c) if c else ''}: {code}"
        for (f, line, code, c), n in sorted(entries.items(), key=str)
        for _ in range(n)
    )


def assert_markers(files: list[Path], found) -> None:
    """Fail on an unexpected diagnostic and on an expected one that did not appear."""
    expected = expected_diagnostics(files)
    actual = actual_diagnostics(found, expected)
    missing, unexpected = expected - actual, actual - expected
    if missing or unexpected:
        rendered = "\n".join(str(d.span) + ": " + d.code + ": " + d.message for d in found)
        pytest.fail(
            f"missing diagnostics:\n{describe(missing)}\nunexpected diagnostics:\n{describe(unexpected)}"
            f"\nall reported:\n{rendered}",
            pytrace=False,
        )


def check_golden(request, path: Path, actual: str) -> None:
    """Compare `actual` with the golden file; `--update-golden` rewrites it instead."""
    if request.config.getoption("--update-golden"):
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(actual, encoding="utf-8")
        return
    if not path.exists():
        pytest.fail(f"no golden file {path.relative_to(ROOT)}; run pytest with --update-golden", pytrace=False)
    expected = path.read_text(encoding="utf-8")
    assert actual == expected, f"{path.relative_to(ROOT)} differs (run with --update-golden if intended)"


def case_id(path: Path, base: Path) -> str:
    return path.relative_to(base).as_posix()


def run_on_simulator(
    paths,
    world=None,
    *,
    duration=None,
    argv=(),
    namespace=None,
    goal=None,
    png=None,
    gif=None,
    record=None,
    realtime=False,
    stdout=None,
    stderr=None,
    root=None,
):
    """Compile (cached) and run the program at `paths` on the in-process simulator, through the
    Python API. Returns the RunResult, whose `sim` is the Simulator after the run."""
    import scoopc

    paths = [str(paths)] if isinstance(paths, (str, Path)) else [str(p) for p in paths]
    return scoopc.run(
        paths,
        list(argv),
        robot="sim",
        world=world,
        duration=duration,
        namespace=namespace,
        goal=goal,
        png=png,
        gif=gif,
        record=record,
        realtime=realtime,
        stdout=stdout,
        stderr=stderr,
        root=root,
    )
