"""Syntax tree, the text dump: a stable indented form for `scoopc parse --dump` and goldens.

Iterative (an explicit stack), so a deeply nested expression cannot exhaust Python's stack.
"""

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
    work: list[tuple[str, object, int, str]] = [("node", tree, 0, "")]
    while work:
        kind, value, depth, label = work.pop()
        produced = _node(value, depth, label, lines) if kind == "node" else _field(value, depth, label, lines)
        work.extend(reversed(produced))
    return "\n".join(lines) + "\n"


def _node(value: object, depth: int, label: str, lines: list[str]) -> list:
    pad = "  " * depth
    if isinstance(value, Identifier):
        lines.append(f"{pad}{label}{value.text!r} {where(value.span)}")
        return []
    span = getattr(value, "span", None)
    if span is None:
        lines.append(f"{pad}{label}{value!r}")
        return []
    lines.append(f"{pad}{label}{type(value).__name__} {where(span)}")
    return [
        ("field", getattr(value, f.name), depth + 1, f.name) for f in fields(value) if f.name not in ("span", "key")
    ]  # type: ignore[arg-type]


def _field(value: object, depth: int, name: str, lines: list[str]) -> list:
    if value is None or value == () or (value is False and name != "value"):
        return []
    pad = "  " * depth
    if isinstance(value, tuple):
        lines.append(f"{pad}{name}:")
        return [("node", item, depth + 1, "- ") for item in value]
    if isinstance(value, Span):
        lines.append(f"{pad}{name}: {where(value)}")
    elif hasattr(value, "span"):
        return [("node", value, depth, f"{name}: ")]
    else:
        lines.append(f"{pad}{name}: {value!r}")
    return []
