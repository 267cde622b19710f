"""Syntax tree, types: class types, tuple types, anchored types, formal generics."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..source import Span
from .base import Identifier, node

if TYPE_CHECKING:  # names used only in annotations (strings at run time)
    from .declarations import Rename
    from .expressions import Expression


__all__ = [
    "ClassType",
    "TupleType",
    "AnchoredType",
    "FormalGeneric",
    "Constraint",
    "Type",
]


@node
class ClassType:
    """`NAME [generics]`; formal generic parameters are ClassTypes too (the checker tells)."""

    name: Identifier
    generics: tuple[Type, ...]
    attachment: str | None  # "attached", "detachable" or None
    separate: bool
    variance: str | None  # "frozen", "variant" or None
    span: Span


@node
class TupleType:
    """`TUPLE [...]`; `labels` is empty or has one label per generic (`TUPLE [a: X; b: Y]`)."""

    generics: tuple[Type, ...]
    labels: tuple[Identifier, ...]
    attachment: str | None
    separate: bool
    variance: str | None
    span: Span


@node
class AnchoredType:
    """`like anchor`: anchor is Current, an UnqualifiedCall, a QualifiedCall chain or a StaticCall."""

    anchor: Expression
    attachment: str | None
    separate: bool
    variance: str | None
    span: Span


Type = ClassType | TupleType | AnchoredType


@node
class FormalGeneric:
    name: Identifier
    mark: str | None  # "frozen", "expanded" or None
    constraints: tuple[Constraint, ...]
    creators: tuple[Identifier, ...] | None  # `create make end`; None when absent
    span: Span


@node
class Constraint:
    type: Type
    renames: tuple[Rename, ...]
    span: Span
