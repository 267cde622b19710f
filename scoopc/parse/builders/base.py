"""Parser stage, shared by the AST builders: spans, names and problem reporting.

Input: lark tokens and built nodes handed to the reduction callbacks. Output: Spans,
Identifiers and Diagnostics collected for the file being parsed.
"""

from __future__ import annotations

from typing import Any

from lark import Token

from ... import diagnostics
from ...source import Span
from ...syntax import Identifier

_new = object.__new__


def make_span(file: str, line: int, column: int, end_line: int, end_column: int) -> Span:
    """A Span built without the frozen-dataclass __init__ (the parser makes one per node)."""
    span = _new(Span)
    span.__dict__.update(file=file, line=line, column=column, end_line=end_line, end_column=end_column)
    return span


class Tag:
    """An assertion tag `name:` waiting for the expression that follows it."""

    __slots__ = ("name",)

    def __init__(self, name: Identifier):
        self.name = name


class Keyworded(tuple):
    """A tuple of parts that remembers the keyword token opening its clause (for spans and
    for finding unclosed constructs after a syntax error)."""

    keyword: Any = None

    @classmethod
    def of(cls, keyword: Any, items: Any) -> Keyworded:
        result = cls(items)
        result.keyword = keyword
        return result


class BuilderBase:
    """State of one parse (file, diagnostics) and the helpers every builder uses."""

    file: str = "<input>"

    def reset(self, file: str) -> None:
        self.file = file
        self.problems: list[diagnostics.Diagnostic] = []
        self.open_operands: dict[int, Any] = {}

    def tspan(self, token: Token) -> Span:
        return make_span(self.file, token.line, token.column, token.end_line, token.end_column)

    def span(self, first: Any, last: Any) -> Span:
        """From the start of `first` to the end of `last` (each a Token or a node)."""
        a = getattr(first, "span", first)
        b = getattr(last, "span", last)
        return make_span(self.file, a.line, a.column, b.end_line, b.end_column)

    def ident(self, token: Token) -> Identifier:
        value = token.value
        return Identifier(value, value.lower(), self.tspan(token))

    def report(self, code: str, where: Any, **arguments: object) -> None:
        span = where if isinstance(where, Span) else self.span(where, where)
        self.problems.append(diagnostics.make(code, span, **arguments))

    def obsolete_form(self, where: Any, what: str, instead: str) -> None:
        """A pre-ECMA form the parser accepts: an error at the `standard` syntax level, a warning
        at `transitional` and `obsolete` (the pipeline applies the project's level)."""
        self.report(
            "SYNTAX-OBSOLETE",
            where,
            what=what,
            instead=f'{instead}, or set the syntax level in the .ecf: <option syntax="transitional">',
        )

    def report_at_offset(self, token: Token, offset: int, length: int, reason: str) -> None:
        """A lexical problem `offset` characters into a token."""
        before = token.value[:offset]
        line = token.line + before.count("\n")
        column = (offset - before.rfind("\n")) if "\n" in before else token.column + offset
        self.report("SYNTAX-LEXICAL", make_span(self.file, line, column, line, column + length), reason=reason)
