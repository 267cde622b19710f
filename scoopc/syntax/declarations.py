"""Syntax tree, declarations: features (routines, attributes, constants) and classes."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..source import Span
from .base import Identifier, node

if TYPE_CHECKING:  # names used only in annotations (strings at run time)
    from .expressions import Expression
    from .instructions import AssertionClause, Instruction, Postcondition, Precondition
    from .types import ClassType, FormalGeneric, Type


__all__ = [
    "Alias",
    "FeatureName",
    "EntityDeclaration",
    "Note",
    "InternalBody",
    "DeferredBody",
    "ExternalBody",
    "AttributeBody",
    "RoutineBody",
    "Routine",
    "Attribute",
    "Constant",
    "FeatureClause",
    "Rename",
    "ExportItem",
    "Parent",
    "InheritClause",
    "CreationClause",
    "Converter",
    "ClassDeclaration",
    "Feature",
]


@node
class Alias:
    """`alias "+"` (operator or bracket alias) with its `convert` mark."""

    name: str
    convert: bool
    span: Span


@node
class FeatureName:
    name: Identifier
    frozen: bool
    aliases: tuple[Alias, ...]
    span: Span


@node
class EntityDeclaration:
    """One formal argument or local: a group `a, b: T` gives one per name, sharing the type."""

    name: Identifier
    type: Type
    span: Span


@node
class Note:
    tag: Identifier
    values: tuple[Identifier | Expression, ...]
    span: Span


@node
class InternalBody:
    """`do` or `once [("KEY", ...)]` with its instructions."""

    once: bool
    once_keys: tuple[str, ...]
    instructions: tuple[Instruction, ...]
    span: Span


@node
class DeferredBody:
    span: Span


@node
class ExternalBody:
    language: str  # e.g. "C", "Python", "built_in"
    alias: str | None
    span: Span


@node
class AttributeBody:
    """`attribute` with the instructions that compute a self-initializing attribute."""

    instructions: tuple[Instruction, ...]
    span: Span


@node
class RoutineBody:
    """Everything from `obsolete`/`require` to `end` of a routine, attribute body or agent."""

    obsolete: str | None
    precondition: Precondition | None
    locals: tuple[EntityDeclaration, ...]
    body: InternalBody | DeferredBody | ExternalBody | AttributeBody
    postcondition: Postcondition | None
    rescue: tuple[Instruction, ...] | None
    span: Span


@node
class Routine:
    names: tuple[FeatureName, ...]
    arguments: tuple[EntityDeclaration, ...]
    type: Type | None  # None for a procedure
    assigner: Identifier | None
    notes: tuple[Note, ...]
    body: RoutineBody
    span: Span


@node
class Attribute:
    names: tuple[FeatureName, ...]
    type: Type
    assigner: Identifier | None
    notes: tuple[Note, ...]
    body: RoutineBody | None  # with an AttributeBody, or None for a plain attribute
    span: Span


@node
class Constant:
    names: tuple[FeatureName, ...]
    type: Type
    value: Expression  # a manifest constant, TypedConstant or Unique
    notes: tuple[Note, ...]
    span: Span


Feature = Routine | Attribute | Constant


@node
class FeatureClause:
    """`feature {A, B}`; clients None when unrestricted."""

    clients: tuple[Identifier, ...] | None
    features: tuple[Feature, ...]
    span: Span


@node
class Rename:
    old_name: Identifier
    new_name: FeatureName
    span: Span


@node
class ExportItem:
    """`{A, B} f, g`; features None for `all`."""

    clients: tuple[Identifier, ...]
    features: tuple[Identifier, ...] | None
    span: Span


@node
class Parent:
    type: ClassType
    renames: tuple[Rename, ...]
    exports: tuple[ExportItem, ...]
    undefines: tuple[Identifier, ...]
    redefines: tuple[Identifier, ...]
    selects: tuple[Identifier, ...]
    span: Span


@node
class InheritClause:
    """`inherit [{NONE}] parents`; conforming False for `inherit {NONE}`."""

    conforming: bool
    parents: tuple[Parent, ...]
    span: Span


@node
class CreationClause:
    """`create {A} make, make_from`; clients None when unrestricted."""

    clients: tuple[Identifier, ...] | None
    procedures: tuple[Identifier, ...]
    span: Span


@node
class Converter:
    """`make ({T})` (creation_mode) or `to_t: {T}`."""

    name: Identifier
    types: tuple[Type, ...]
    creation_mode: bool
    span: Span


@node
class ClassDeclaration:
    name: Identifier
    marks: tuple[str, ...]  # "deferred", "expanded", "frozen", "external"
    formal_generics: tuple[FormalGeneric, ...]
    obsolete: str | None
    inherit_clauses: tuple[InheritClause, ...]
    creation_clauses: tuple[CreationClause, ...]
    converters: tuple[Converter, ...]
    feature_clauses: tuple[FeatureClause, ...]
    invariant: tuple[AssertionClause, ...]
    notes: tuple[Note, ...]  # the leading and the trailing note clauses together
    span: Span

    @property
    def is_deferred(self) -> bool:
        return "deferred" in self.marks

    @property
    def is_expanded(self) -> bool:
        return "expanded" in self.marks
