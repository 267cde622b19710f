"""Untorn program output: one print call writes its text whole; with processor tracing,
every output line carries the tag of the processor that wrote it.

Text may carry bytes that are not UTF-8 as surrogate escapes (a program's 8-bit strings are
bytes, written as they are): on a stream over bytes they are written as those bytes."""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from .processor import Processor


class Output:
    partial: dict[Processor, str]

    def __init__(self, stream: TextIO, trace: bool) -> None:
        self.stream = stream
        self.trace = trace
        self.lock = threading.Lock()
        self.partial = {}  # [lock] processor -> unfinished line (trace mode only)
        self.broken = False  # [lock] the reader of the stream has gone

    def write(self, proc: Processor, text: str) -> None:
        if not self.trace:
            with self.lock:
                self._emit(text)
            return
        with self.lock:
            text = self.partial.pop(proc, "") + text
            lines = text.split("\n")
            tail = lines.pop()
            if lines:
                tag = f"[P{proc.id}] "
                self._emit("".join(tag + line + "\n" for line in lines))
            if tail:
                self.partial[proc] = tail

    def _emit(self, text: str) -> None:
        """[lock] Write to the stream; once its reader has gone (a pipe into `head`), output is
        dropped instead of failing the program's routines."""
        if self.broken:
            return
        try:
            write_text(self.stream, text)
        except BrokenPipeError:
            self.broken = True

    def write_other(self, stream: TextIO, text: str) -> None:
        """Write `text` whole on another stream (stderr) under the same lock, and flush it."""
        with self.lock:
            write_text(stream, text)
            try:
                stream.flush()
            except (OSError, ValueError):
                pass

    def flush_streams(self, *others: TextIO) -> None:
        """Flush the output stream and `others` now (unfinished traced lines stay held)."""
        with self.lock:
            for stream in (self.stream,) + others:
                try:
                    stream.flush()
                except (OSError, ValueError):
                    pass

    def flush(self) -> None:
        """At exit: write unfinished lines, then flush the stream."""
        with self.lock:
            for proc, tail in sorted(self.partial.items(), key=lambda kv: kv[0].id):
                self._emit(f"[P{proc.id}] {tail}\n")
            self.partial.clear()
            try:
                self.stream.flush()
            except (OSError, ValueError):
                pass


def write_text(stream: TextIO, text: str) -> None:
    """Write `text` on `stream`; surrogate escapes go out as the bytes they stand for, through
    the stream's byte buffer when it has one (its own error handler may be strict, or replace
    them)."""
    if not text.isascii():
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:
            buffer = getattr(stream, "buffer", None)
            if buffer is not None:
                stream.flush()
                buffer.write(text.encode("utf-8", "surrogateescape"))
                return
    stream.write(text)
