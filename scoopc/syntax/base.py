"""Syntax tree, the base: the node decorator and names (Identifier)."""

from __future__ import annotations

from dataclasses import dataclass

from ..source import Span

__all__ = [
    "node",
    "Identifier",
]


node = dataclass(frozen=True, eq=False)


@node
class Identifier:
    text: str
    key: str
    span: Span
