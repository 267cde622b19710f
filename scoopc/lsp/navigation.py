"""Language server, go to definition and find references: a feature's declaration (in the
program or in the standard library's sources), an entity's declaration, a class's text; and
every use of them in the program's classes."""

from __future__ import annotations

from .. import syntax
from ..source import Span
from .analysis import Analysis
from .lookup import Found, class_of
from .nodes import walk


def definition(found: Found, analysis: Analysis) -> Span | None:
    if found.feature is not None:
        return found.feature.fname.name.span
    if found.entity is not None:
        return found.entity.span if isinstance(found.entity.span, Span) else None
    if found.class_info is not None:
        return found.class_info.decl.name.span
    return None


def references(found: Found, analysis: Analysis, declaration: bool) -> list[Span]:
    sem = analysis.semantics
    if sem is None or found.empty:
        return []
    if found.feature is not None:
        spans = _feature_uses(found, sem)
    elif found.entity is not None:
        key = found.entity.span
        spans = [_name_span(node) for node, entity in sem.tables.entities.items() if entity.span == key]
    else:
        spans = _class_uses(found, analysis)
    own = definition(found, analysis)
    if declaration and own is not None:
        spans.append(own)
    elif own is not None:
        spans = [s for s in spans if s != own]
    return sorted(set(spans), key=lambda s: (s.file, s.line, s.column))


def _feature_uses(found: Found, sem) -> list[Span]:
    seed = found.feature.seed or found.feature.name
    uses = [_name_span(node) for node, f in sem.tables.features.items() if (f.seed or f.name) == seed]
    for info in sem.universe.classes.values():  # redeclarations in the program's classes
        if info.from_library:
            continue
        for feature in info.features.values():
            if (feature.seed or feature.name) == seed and feature.written_in == info.name:
                uses.append(feature.fname.name.span)
    declaring = class_of(found, sem.universe)
    if declaring is not None and declaring.from_library:
        uses.append(found.feature.fname.name.span)
    return uses


def _class_uses(found: Found, analysis: Analysis) -> list[Span]:
    universe = analysis.semantics.universe
    target = found.class_info
    uses = []
    for tree in analysis.trees.values():
        for node in walk(tree):
            if isinstance(node, syntax.ClassType) and universe.get(node.name.text) is target:
                uses.append(node.name.span)
    return uses


def _name_span(node) -> Span:
    name = getattr(node, "name", None)
    if isinstance(name, syntax.Identifier):
        return name.span
    procedure = getattr(node, "procedure", None)
    return procedure.span if isinstance(procedure, syntax.Identifier) else node.span
