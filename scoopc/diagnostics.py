"""Diagnostics as data, and their two renderings.

A stage creates a Diagnostic with `make(code, span, **arguments)`; the wording comes from
`messages.MESSAGES`. Rendering happens in one place (the CLI): `short` gives the one-line form
`path:line:col: error CODE: message` for tools and tests, `pretty` adds the source line, an
underline and the hint.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from . import messages
from .source import Span

ERROR = "error"
WARNING = "warning"
NOTE = "note"


@dataclass(frozen=True)
class Note:
    """A secondary message, optionally located ("declared here")."""

    message: str
    span: Span | None = None


@dataclass(frozen=True)
class Diagnostic:
    code: str
    span: Span | None
    message: str
    notes: tuple[Note, ...] = ()
    severity: str = ERROR
    hint: str = ""

    @property
    def is_error(self) -> bool:
        return self.severity == ERROR


class InternalError(Exception):
    """A bug in scoopc, never the user's fault (reported as such, with the Python traceback)."""


def make(
    code: str, span: Span | None, notes: Iterable[Note] = (), severity: str = ERROR, **arguments: object
) -> Diagnostic:
    """A diagnostic whose message and hint are the templates of `code` filled with `arguments`
    (every argument of the message is required; those of the hint are optional)."""
    entry = messages.MESSAGES.get(code)
    if entry is None:
        raise InternalError(f"no message registered for diagnostic code {code!r}")
    try:
        text = entry.text.format(**arguments)
    except (KeyError, IndexError) as missing:
        raise InternalError(f"message {code} lacks argument {missing}") from None
    hint = entry.hint.format_map(_Optional(arguments))
    return Diagnostic(code, span, text, tuple(notes), severity, hint)


class _Optional(dict):
    """Hint arguments: a hint whose argument a raise site does not give is left empty."""

    def __missing__(self, key: str) -> str:
        return ""


def short(d: Diagnostic) -> str:
    """`path:line:col: error CODE: message`, then one indented line per note."""
    where = f"{d.span}: " if d.span is not None else ""
    lines = [f"{where}{d.severity} {d.code}: {d.message}"]
    for note in d.notes:
        located = f"{note.span}: " if note.span is not None else ""
        lines.append(f"    {located}note: {note.message}")
    return "\n".join(lines)


def pretty(d: Diagnostic, line_text: Callable[[str, int], str], color: bool = False) -> str:
    """The one-line form, then the source line with the span underlined, the notes and the hint.

    `line_text(path, line)` returns the text of a line (empty when unknown).
    """
    bold, red, cyan, reset = ("\x1b[1m", "\x1b[31m", "\x1b[36m", "\x1b[0m") if color else ("",) * 4
    where = f"{d.span}: " if d.span is not None else ""
    out = [f"{bold}{where}{red if d.is_error else cyan}{d.severity} {d.code}{reset}{bold}: {d.message}{reset}"]
    if d.span is not None:
        out.extend(_excerpt(d.span, line_text, red, reset))
    for note in d.notes:
        located = f"{note.span}: " if note.span is not None else ""
        out.append(f"  {cyan}note{reset}: {located}{note.message}")
    if d.hint:
        out.append(f"  {cyan}hint{reset}: {d.hint}")
    return "\n".join(out)


def _excerpt(span: Span, line_text: Callable[[str, int], str], red: str, reset: str) -> list[str]:
    text = line_text(span.file, span.line)
    if not text and span.line <= 0:
        return []
    gutter = str(span.line)
    width = (span.end_column - span.column) if span.end_line == span.line else len(text) - span.column + 1
    width = max(1, width)
    shown = text.expandtabs(1)
    marker = " " * (span.column - 1) + "^" + "~" * (width - 1)
    pad = " " * len(gutter)
    return [f"  {pad} |", f"  {gutter} | {shown}", f"  {pad} | {red}{marker}{reset}"]


def sort_key(d: Diagnostic) -> tuple:
    s = d.span
    return (s.file, s.line, s.column) if s is not None else ("", 0, 0)
