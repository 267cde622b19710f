"""Parse every .e file under a directory with scoopc's parser and report what it could not parse.

Usage: python tools/parse_corpus.py DIR [DIR...] [--quiet]

Prints one line per syntax diagnostic (`path:line:col: CODE: message`), then the summary
`parsed N/M files, L lines, T s`. A file counts as parsed when the parser returned a tree and
no error. An exception inside the parser is reported as `INTERNAL` with its type and message
(that is a parser bug, never the input's fault). Always exits 0: this is a survey, not a test.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from scoopc.parse import parser  # noqa: E402
from scoopc.source import SourceFile  # noqa: E402


def survey(paths: list[Path], quiet: bool = False) -> tuple[int, int, int, float]:
    """Parse each file; print failures; return (parsed, total, lines, seconds)."""
    parsed = total = lines = 0
    seconds = 0.0
    for path in paths:
        total += 1
        try:
            source = SourceFile.read(path)
        except (OSError, UnicodeDecodeError) as error:
            print(f"{path}:1:1: SOURCE: {error}")
            continue
        lines += source.line_count
        start = time.perf_counter()
        try:
            result = parser.parse(source)
        except Exception as error:  # a parser bug: report it and go on with the next file
            seconds += time.perf_counter() - start
            print(f"{path}:1:1: INTERNAL: {type(error).__name__}: {error}")
            continue
        seconds += time.perf_counter() - start
        errors = [d for d in result.diagnostics if getattr(d, "is_error", True)]
        if result.tree is not None and not errors:
            parsed += 1
            continue
        if not quiet:
            for d in errors or result.diagnostics:
                span = d.span
                where = f"{path}:{span.line}:{span.column}" if span else f"{path}:?:?"
                print(f"{where}: {d.code}: {d.message}")
            if result.tree is None and not result.diagnostics:
                print(f"{path}:?:?: NO-TREE: the parser returned neither a tree nor a diagnostic")
    return parsed, total, lines, seconds


def main(argv: list[str] | None = None) -> int:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("dirs", nargs="+", type=Path, help="directories (or .e files) to parse")
    options.add_argument("--quiet", action="store_true", help="print only the summary")
    args = options.parse_args(argv)
    paths: list[Path] = []
    for d in args.dirs:
        paths.extend([d] if d.is_file() else sorted(p for p in d.rglob("*.e") if p.is_file()))
    parsed, total, lines, seconds = survey(paths, args.quiet)
    print(f"parsed {parsed}/{total} files, {lines} lines, {seconds:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
