"""Syntax tree, the text dump: a stable indented form for `scoopc parse --dump` and goldens."""
from __future__ import annotations

from dataclasses import fields

from ..source import Span
from .base import Identifier


def where(span: Span) -> str:
    return f"@{span.line}:{span.column}-{span.end_line}:{span.end_column}"


def dump(tree: object) -> str:
    """A deterministic indented text form: one node per line with its span, then its fields
    (None, False and empty fields are left out)."""
    lines: list[str] = []
    _dump_node(tree, 0, "", lines)
    return "\n".join(lines) + "\n"


def _dump_node(value: object, depth: int, label: str, lines: list[str]) -> None:
    pad = "  " * depth
    if isinstance(value, Identifier):
        lines.append(f"{pad}{label}{value.text!r} {where(value.span)}")
        return
    span = getattr(value, "span", None)
    if span is None:
        lines.append(f"{pad}{label}{value!r}")
        return
    lines.append(f"{pad}{label}{type(value).__name__} {where(span)}")
    for f in fields(value):  # type: ignore[arg-type]
        if f.name in ("span", "key"):
            continue
        _dump_field(getattr(value, f.name), depth + 1, f.name, lines)


def _dump_field(value: object, depth: int, name: str, lines: list[str]) -> None:
    if value is None or value == () or (value is False and name != "value"):
        return
    pad = "  " * depth
    if isinstance(value, tuple):
        lines.append(f"{pad}{name}:")
        for item in value:
            _dump_node(item, depth + 1, "- ", lines)
    elif isinstance(value, Span):
        lines.append(f"{pad}{name}: {where(value)}")
    elif hasattr(value, "span"):
        _dump_node(value, depth, f"{name}: ", lines)
    else:
        lines.append(f"{pad}{name}: {value!r}")
