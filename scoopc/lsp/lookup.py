"""Language server, what a position names: a feature (of a call, a creation, a declaration), an
entity (argument, local, Result, object-test or separate-block local) or a class, read from the
checker's tables of the latest analysis in which the file checked."""

from __future__ import annotations

from dataclasses import dataclass

from .. import syntax
from ..semantics.features import Feature
from ..semantics.tables import Entity
from ..semantics.universe import ClassInfo
from .analysis import Analysis
from .nodes import path_to

_CALLS = (syntax.QualifiedCall, syntax.UnqualifiedCall, syntax.StaticCall, syntax.Agent)
_CREATIONS = (syntax.CreationInstruction, syntax.CreationExpression)
_DECLARATIONS = (syntax.Routine, syntax.Attribute, syntax.Constant)


@dataclass
class Found:
    """What a position names, and the nodes from the class down to it."""

    chain: list[object]
    feature: Feature | None = None
    entity: Entity | None = None
    class_info: ClassInfo | None = None
    node: object = None  # the call, creation or declaration naming it

    @property
    def empty(self) -> bool:
        return self.feature is None and self.entity is None and self.class_info is None


def at(analysis: Analysis, path: str, line: int, column: int) -> Found:
    tree = analysis.trees.get(path)
    chain = path_to(tree, line, column, inclusive=True) if tree is not None else []
    found = Found(chain)
    sem = analysis.semantics
    if not chain or sem is None:
        return found
    for index in range(len(chain) - 1, -1, -1):
        _name(found, chain, index, sem, analysis.class_info(path))
        if not found.empty:
            break
    return found


def _name(found: Found, chain: list[object], index: int, sem, current: ClassInfo | None) -> None:
    node = chain[index]
    parent = chain[index - 1] if index > 0 else None
    tables, universe = sem.tables, sem.universe
    found.node = node
    if isinstance(node, _CALLS + _CREATIONS + (syntax.Precursor,)):
        found.entity = tables.entities.get(node)
        found.feature = tables.features.get(node) or _member(node, tables, universe)
        if found.feature is None and found.entity is None and isinstance(node, syntax.UnqualifiedCall):
            found.feature = current.features.get(node.name.key) if current is not None else None
    elif isinstance(node, syntax.ClassType):
        found.class_info = universe.get(node.name.text)
    elif isinstance(node, syntax.Identifier) and isinstance(parent, syntax.ClassDeclaration):
        found.class_info = current
    elif isinstance(node, syntax.FeatureName) and current is not None:
        found.feature = current.features.get(node.name.key)
        found.node = parent
    elif isinstance(node, (syntax.EntityDeclaration, syntax.SeparateArgument)):
        found.entity = _declared_entity(node, tables)


def _member(node, tables, universe) -> Feature | None:
    """The feature a qualified call names when the checker stopped before recording it (a call on
    an uncontrolled separate target): looked up in the class of the target's type."""
    target = getattr(node, "target", None)
    ty = tables.types.get(target) if isinstance(node, syntax.QualifiedCall) else None
    info = universe.get(ty.name) if ty is not None else None
    return info.features.get(node.name.key) if info is not None else None


def _declared_entity(node, tables) -> Entity | None:
    """The entity an argument, local or separate-block declaration introduces (from a use of it)."""
    for entity in tables.entities.values():
        if entity.span == node.name.span or entity.span == node.span:
            return entity
    return None


def class_of(found: Found, universe) -> ClassInfo | None:
    """The class that declares the feature found (its version there)."""
    if found.feature is None:
        return found.class_info
    return universe.get(found.feature.written_in)
