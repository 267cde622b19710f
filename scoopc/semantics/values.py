"""Checker, values: the static result of typing an expression (its type and, for a separate
value, which controlled entity's processor it lives on), and how a value meets a target type.
"""

from __future__ import annotations

from typing import NamedTuple

from .. import syntax
from .conformance import converts, manifest_fits, why_not
from .types import Ty

UNCONTROLLED = "?"


class Value(NamedTuple):
    ty: Ty
    handler: str | None = None  # None: not separate; a name: controlled through it; "?": not controlled
    foreign: object = None  # a `G` result of a separate call (its call node): a traitor if used as non-separate

    @property
    def controlled(self) -> bool:
        return not self.ty.separate or self.handler != UNCONTROLLED


def manifest_kind(node) -> tuple[str, object] | None:
    """The kind and value of a manifest constant whose type comes from its context."""
    if isinstance(node, syntax.ManifestInteger):
        return "integer", node.value
    if (
        isinstance(node, syntax.UnaryExpression)
        and node.operator in ("-", "+")
        and isinstance(node.operand, syntax.ManifestInteger)
    ):
        return "integer", -node.operand.value if node.operator == "-" else node.operand.value
    if isinstance(node, syntax.ManifestReal):
        return "real", node.value
    if (
        isinstance(node, syntax.UnaryExpression)
        and node.operator in ("-", "+")
        and isinstance(node.operand, syntax.ManifestReal)
    ):
        return "real", node.operand.value
    if isinstance(node, syntax.ManifestString):
        return "string", node.value
    if isinstance(node, syntax.ManifestCharacter):
        return "character", node.value
    if isinstance(node, syntax.Parenthesized):
        return manifest_kind(node.expression)
    return None


def meet(universe, node, value: Value, target: Ty, context, tables) -> str | None:
    """None when `value` (of expression `node`) may be attached to an entity of type `target`:
    conformance, a manifest constant typed by context, or a conversion (recorded); else the
    reason: "separate", "detachable", "separate-generic" or "type"."""
    reason = why_not(universe, value.ty, target, context)
    if reason is None:
        return None
    if reason == "type":
        kind = manifest_kind(node)
        if kind is not None and manifest_fits(kind[0], kind[1], target):
            tables.types[node] = target.with_marks(attached=True, separate=False)
            return None
        converter = converts(universe, value.ty, target)
        if converter is not None and not (value.ty.separate and not target.separate):
            tables.conversions[node] = (converter, target)
            return None
    return reason
