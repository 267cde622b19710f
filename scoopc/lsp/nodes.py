"""Language server, positions in syntax trees: the chain of nodes under a cursor, the text of a
span, and the conversions between our spans (1-based lines and columns) and LSP's 0-based ones."""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Iterator
from pathlib import Path

from lsprotocol import types as lsp

from ..semantics.universe import stdlib_root
from ..source import SourceFile, Span
from ..syntax import instructions as syntax_instructions


def children(node: object) -> Iterator[object]:
    """The syntax nodes directly inside `node`, in field order."""
    if not dataclasses.is_dataclass(node):
        return
    for item in dataclasses.fields(node):
        value = getattr(node, item.name, None)
        if isinstance(value, tuple):
            yield from (v for v in value if _is_node(v))
        elif _is_node(value):
            yield value


def _is_node(value: object) -> bool:
    return dataclasses.is_dataclass(value) and isinstance(getattr(value, "span", None), Span)


def contains(span: Span, line: int, column: int, inclusive: bool = False) -> bool:
    """Is (line, column) inside `span` (its end too when `inclusive`: a cursor just after a name)?"""
    if (line, column) < (span.line, span.column):
        return False
    end = (span.end_line, span.end_column)
    return (line, column) <= end if inclusive else (line, column) < end


def path_to(tree: object, line: int, column: int, inclusive: bool = False) -> list[object]:
    """The nodes from `tree` down to the innermost one at (line, column); empty when outside."""
    chain: list[object] = []
    node: object | None = tree
    while node is not None:
        chain.append(node)
        node = next((c for c in children(node) if contains(c.span, line, column, inclusive)), None)
    return chain if chain and contains(tree.span, line, column, True) else []


def walk(node: object) -> Iterator[object]:
    """`node` and every node inside it, depth first."""
    stack = [node]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(list(children(current))))


def is_instruction(node: object) -> bool:
    return type(node).__module__ == syntax_instructions.__name__ and type(node).__name__ not in _NOT_INSTRUCTIONS


_NOT_INSTRUCTIONS = {
    "AssertionClause",
    "Choice",
    "ElseifPart",
    "Iteration",
    "Postcondition",
    "Precondition",
    "SeparateArgument",
    "Variant",
    "WhenPart",
}


# ---- files ------------------------------------------------------------------------------------
def library_file(path: str) -> str:
    """A path of the standard library as this installation has it (the checker's cache may hold
    the paths of another copy of the same library)."""
    root = stdlib_root()
    if path.startswith(str(root)) or "/stdlib/" not in path:
        return path
    return str(root / path.rsplit("/stdlib/", 1)[1])


class Texts:
    """Source texts by path: the editor's buffers first, then the files on disk (read once)."""

    def __init__(self) -> None:
        self.buffers: dict[str, str] = {}
        self._disk: dict[str, tuple[int, SourceFile]] = {}  # path -> (modification time, text)

    def source(self, path: str) -> SourceFile | None:
        path = os.path.abspath(path)
        if path in self.buffers:
            return SourceFile(path, self.buffers[path])
        try:
            stamp = os.stat(path).st_mtime_ns
            known = self._disk.get(path)
            if known is None or known[0] != stamp:
                known = self._disk[path] = (stamp, SourceFile.read(path))
        except (OSError, UnicodeDecodeError):
            return None
        return known[1]

    def text(self, span: Span) -> str:
        source = self.source(library_file(span.file))
        if source is None:
            return ""
        start = source.offset(span.line, span.column)
        return source.text[start : source.offset(span.end_line, span.end_column)]


# ---- LSP positions ----------------------------------------------------------------------------
def to_range(span: Span) -> lsp.Range:
    return lsp.Range(
        lsp.Position(max(span.line - 1, 0), max(span.column - 1, 0)),
        lsp.Position(max(span.end_line - 1, 0), max(span.end_column - 1, 0)),
    )


def to_location(span: Span) -> lsp.Location:
    return lsp.Location(Path(os.path.abspath(library_file(span.file))).as_uri(), to_range(span))


def from_position(position: lsp.Position) -> tuple[int, int]:
    """An LSP position as our (line, column)."""
    return position.line + 1, position.character + 1
