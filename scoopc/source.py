"""Source files and spans: the positions every later stage reports against.

Input: paths or text. Output: SourceFile (text plus line index) and Span values.
Lines and columns are 1-based; columns count characters, a tab counting as one.
"""

from __future__ import annotations

import bisect
import errno
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path

MAX_SOURCE_BYTES = 16 * 2**20  # no class text is this long; a larger file is a mistake


def _open_regular(path: str, flags: int) -> int:
    """os.open for regular files only: opened without blocking (a FIFO), then checked."""
    fd = os.open(path, flags | getattr(os, "O_NONBLOCK", 0))
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise OSError(errno.EINVAL, "not a regular file (a device, pipe or socket)")
    return fd


@dataclass(frozen=True)
class Span:
    """A region of one source file: start inclusive, end exclusive (end_column is one past)."""

    file: str
    line: int
    column: int
    end_line: int
    end_column: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"

    def to(self, other: Span) -> Span:
        """The span from the start of self to the end of other."""
        return Span(self.file, self.line, self.column, other.end_line, other.end_column)

    @staticmethod
    def point(file: str, line: int, column: int) -> Span:
        return Span(file, line, column, line, column + 1)


@dataclass(frozen=True, eq=False)
class SourceFile:
    """The text of one .e file with an index from offsets to lines."""

    path: str
    text: str
    _line_starts: list[int] = field(default_factory=list, repr=False)

    def __post_init__(self) -> None:
        starts = [0]
        find = self.text.find
        i = find("\n")
        while i >= 0:
            starts.append(i + 1)
            i = find("\n", i + 1)
        object.__setattr__(self, "_line_starts", starts)

    @classmethod
    def read(cls, path: str | Path) -> SourceFile:
        """Read a file as UTF-8 (a BOM is dropped; undecodable bytes raise UnicodeDecodeError).
        Only a regular file of at most MAX_SOURCE_BYTES is read (OSError otherwise): a FIFO would
        block, and a link to /dev/zero would never end."""
        with open(path, "rb", opener=_open_regular) as handle:
            data = handle.read(MAX_SOURCE_BYTES + 1)
        if len(data) > MAX_SOURCE_BYTES:
            raise OSError(errno.EFBIG, f"larger than {MAX_SOURCE_BYTES // 2**20} MiB: not a class text")
        text = data.decode("utf-8-sig")
        return cls(str(path), text.replace("\r\n", "\n").replace("\r", "\n"))

    @property
    def line_count(self) -> int:
        return len(self._line_starts)

    def line_text(self, line: int) -> str:
        """The text of a 1-based line, without its newline ('' when out of range)."""
        if not 1 <= line <= len(self._line_starts):
            return ""
        start = self._line_starts[line - 1]
        end = self.text.find("\n", start)
        return self.text[start:] if end < 0 else self.text[start:end]

    def position(self, offset: int) -> tuple[int, int]:
        """(line, column) of a 0-based character offset."""
        index = bisect.bisect_right(self._line_starts, offset) - 1
        return index + 1, offset - self._line_starts[index] + 1

    def offset(self, line: int, column: int) -> int:
        """The 0-based character offset of a 1-based (line, column), clamped to the text."""
        line = min(max(line, 1), len(self._line_starts))
        return min(self._line_starts[line - 1] + max(column, 1) - 1, len(self.text))

    def span(self, start: int, end: int) -> Span:
        """The span of the character offsets [start, end)."""
        line, column = self.position(start)
        end_line, end_column = self.position(max(end, start))
        return Span(self.path, line, column, end_line, end_column)
