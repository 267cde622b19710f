"""Checker, types pass: syntax types to Ty in the context of a class.

Input: a syntax type, the class it is written in, a way to resolve anchors. Output: Ty or None
(None after reporting VTCT, VTUG, VTCG or VTAT; callers then stay silent about that entity).
"""

from __future__ import annotations

from collections.abc import Callable

from .. import syntax
from . import suggest
from .types import Ty

Report = Callable[..., None]


class TypeResolver:
    """Resolves types written in one class. `anchor(name)` gives the type of `like name`."""

    def __init__(
        self,
        universe,
        info,
        report: Report,
        anchor: Callable[[str], Ty | None] | None = None,
        constraints: bool = True,
        current_anchor: bool = False,
    ):
        self.universe = universe
        self.info = info
        self.report = report
        self.anchor = anchor
        self.constraints = constraints
        self.current_anchor = current_anchor  # `like Current` stays open (features.CURRENT) for call sites

    def resolve(self, node) -> Ty | None:
        if isinstance(node, syntax.ClassType):
            return self._class_type(node)
        if isinstance(node, syntax.TupleType):
            return self._tuple_type(node)
        return self._anchored(node)

    def _separate(self, mark: bool) -> bool:
        """A `separate` mark as it counts here: in a system that is not a SCOOP one, EiffelStudio
        gives the program's `separate` no meaning (a separate type is an ordinary one; only the
        standard library keeps its SCOOP signatures, compiled once)."""
        return mark and (self.universe.scoop or self.info.from_library)

    def _marks(self, node, ty: Ty) -> Ty:
        expanded = (info := self.universe.get(ty.name)) is not None and info.is_expanded and not ty.is_formal
        attached = expanded or node.attachment != "detachable"
        return ty.with_marks(
            attached=attached, separate=self._separate(node.separate or (ty.separate and not expanded))
        )

    def _class_type(self, node: syntax.ClassType) -> Ty | None:
        key = node.name.key.upper()
        if key in self.info.formals:
            if node.generics:
                self.report("VTUG(1)", node.span, type=node.name.text, expected=0, given=len(node.generics))
                return None
            return self._marks(node, Ty(key, formal=self.info.formals.index(key)))
        if key == "NONE":
            if node.generics:
                self.report("VTUG(1)", node.span, type="NONE", expected=0, given=len(node.generics))
                return None
            return Ty("NONE", attached=node.attachment == "attached", separate=self._separate(node.separate))
        target = self.universe.get(self.universe.name_in(key, self.info))
        if target is None:
            library = self.universe.hidden_cluster(key, self.info)
            if library:
                hint = (
                    f"check the spelling, and that the file declaring {node.name.text} is in a cluster given to scoopc;"
                    f" it is a class of the library `{library}`, which this class's .ecf does not name"
                )
            else:
                hint = suggest.unknown_class(self.universe, node.name.text)
            self.report("VTCT", node.name.span, name=node.name.text, hint=hint)
            return None
        generics = tuple(self.resolve(g) for g in node.generics)
        if any(g is None for g in generics):
            return None
        if target.name in AGENT_CLASSES:
            generics = agent_generics(target.name, generics, self._tuple_formal)
        if len(generics) != len(target.formals):
            code = "VTUG(1)" if not target.formals else "VTUG(2)"
            self.report(code, node.span, type=target.name, expected=len(target.formals), given=len(generics))
            return None
        ty = Ty(target.name, generics)
        if self.constraints and not self._constraints_hold(target, ty, node):
            return None
        return self._marks(node, ty)

    def _tuple_formal(self, ty: Ty) -> bool:
        constraints = self.info.constraints[ty.formal] if ty.formal < len(self.info.constraints) else ()
        return any(c.name == "TUPLE" for c in constraints)

    def _constraints_hold(self, target, ty: Ty, node) -> bool:
        from .conformance import conforms  # deferred: a cycle (conformance needs this pass's ancestors)

        for index, (actual, actual_node) in enumerate(zip(ty.generics, node.generics)):
            for constraint in target.constraints[index] if index < len(target.constraints) else ():
                bound = _instantiate(constraint, ty.generics)
                if not conforms(
                    self.universe,
                    actual.with_marks(attached=True, separate=False),
                    bound.with_marks(attached=True, separate=False),
                    self.info,
                ):
                    self.report(
                        "VTCG",
                        actual_node.span,
                        actual=str(actual),
                        constraint=str(bound),
                        formal=target.formals[index],
                    )
                    return False
            missing = self._missing_creators(target, index, actual)
            if missing:
                self.report(
                    "VTCG",
                    actual_node.span,
                    actual=str(actual),
                    formal=target.formals[index],
                    constraint=f"`create {', '.join(missing)} end` (not creation procedures of {actual.name})",
                )
                return False
        return True

    def _missing_creators(self, target, index: int, actual: Ty) -> list:
        """Creation procedures a formal's `create ... end` constraint asks of the actual's class."""
        wanted = target.formal_creators[index] if index < len(target.formal_creators) else ()
        if not wanted or actual.is_formal:
            return []
        info = self.universe.get(actual.name)
        if info is None or info.is_expanded or not info.features:
            return []
        creators = info.creators if info.creators is not None else {"default_create": None}
        bounds = target.constraints[index] if index < len(target.constraints) else ()
        renames = target.constraint_renames[index] if index < len(target.constraint_renames) else {}
        missing = []
        for name in wanted:
            # the actual provides the constraint's own name of the procedure (before renaming);
            # a name no constraint has is the generic class's VTGC(3), not this actual's fault
            olds = {constraint_old_name(renames.get(b.name, {}), name) for b in bounds if not b.is_formal}
            known = {o for o in olds if o is not None and self._has(bounds, o)}
            if known and not known & set(creators):
                missing.append(name)
        return missing

    def _has(self, bounds, name: str) -> bool:
        return any((i := self.universe.get(b.name)) is not None and name in i.features for b in bounds)

    def _tuple_type(self, node: syntax.TupleType) -> Ty | None:
        generics = tuple(self.resolve(g) for g in node.generics)
        if any(g is None for g in generics):
            return None
        labels = tuple(label.key for label in node.labels)
        return self._marks(node, Ty("TUPLE", generics, labels=labels))

    def _anchored(self, node: syntax.AnchoredType) -> Ty | None:
        anchor = node.anchor
        found: Ty | None = None
        if isinstance(anchor, syntax.Current):
            from .features import CURRENT  # deferred: a cycle (scoopc.semantics.features imports this module)

            found = CURRENT if self.current_anchor else self.info.own_type()
        elif isinstance(anchor, syntax.UnqualifiedCall) and not anchor.arguments and self.anchor is not None:
            found = self.anchor(anchor.name.key)
        elif isinstance(anchor, syntax.QualifiedCall) and self.anchor is not None:
            found = self._qualified_anchor(anchor)
        elif isinstance(anchor, syntax.StaticCall):
            found = self._static_anchor(anchor)
        if found is None:
            self.report("VTAT(1)", node.span, anchor=_anchor_text(anchor))
            return None
        attached = found.attached if node.attachment is None else node.attachment != "detachable"
        return found.with_marks(attached=attached, separate=self._separate(found.separate or node.separate))

    def _static_anchor(self, anchor: syntax.StaticCall) -> Ty | None:
        """`like {T}.f`: the type of T's feature f."""
        from .conformance import (
            constraint_types,  # deferred: a cycle (scoopc.semantics.conformance imports this module)
        )
        from .signatures import feature_type_in  # deferred: a cycle (scoopc.semantics.signatures imports this module)

        base = self.resolve(anchor.type)
        if base is None:
            return None
        for bound in constraint_types(self.universe, base.with_marks(attached=True), self.info):
            found = feature_type_in(self.universe, bound, anchor.name.key)
            if found is not None:
                return found
        return None

    def _qualified_anchor(self, anchor: syntax.QualifiedCall) -> Ty | None:
        from .signatures import feature_type_in  # deferred: a cycle (scoopc.semantics.signatures imports this module)

        if isinstance(anchor.target, syntax.UnqualifiedCall):
            base = self.anchor(anchor.target.name.key) if self.anchor else None
        elif isinstance(anchor.target, syntax.QualifiedCall):
            base = self._qualified_anchor(anchor.target)
        else:
            base = None
        return None if base is None else feature_type_in(self.universe, base, anchor.name.key)


AGENT_CLASSES = ("ROUTINE", "PROCEDURE", "FUNCTION", "PREDICATE")


def agent_generics(name: str, generics: tuple, tuple_formal=lambda ty: False) -> tuple:
    """The short and the pre-17.05 spellings of agent types, as EiffelStudio accepts them:
    `PROCEDURE` (no operands), `PROCEDURE [A, B]` (operand types), `PROCEDURE [ANY, TUPLE [A]]`
    (base type first), `FUNCTION [A, R]`; all mean the TUPLE form."""
    results = 1 if name == "FUNCTION" else 0
    second_is_tuple = len(generics) > 1 and (
        generics[1].name == "TUPLE" or (generics[1].is_formal and tuple_formal(generics[1]))
    )
    if len(generics) == results + 2 and second_is_tuple and generics[0].name != "TUPLE":
        generics = generics[1:]  # old style: the base type first
    operands, rest = generics[: len(generics) - results], generics[len(generics) - results :]
    if len(operands) == 1 and (operands[0].name == "TUPLE" or (operands[0].is_formal and tuple_formal(operands[0]))):
        return generics
    if name == "FUNCTION" and not generics:
        return generics
    return (Ty("TUPLE", tuple(operands)),) + tuple(rest)


def _instantiate(constraint: Ty, actuals: tuple[Ty, ...]) -> Ty:
    from .types import substitute  # deferred: a cycle (scoopc.semantics.types imports this module)

    return substitute(constraint, actuals)


def _anchor_text(anchor) -> str:
    if isinstance(anchor, syntax.Current):
        return "Current"
    if isinstance(anchor, syntax.UnqualifiedCall):
        return anchor.name.text
    if isinstance(anchor, syntax.QualifiedCall):
        return f"{_anchor_text(anchor.target)}.{anchor.name.text}"
    if isinstance(anchor, syntax.StaticCall):
        return f"{{...}}.{anchor.name.text}"
    return "?"


def constraint_old_name(renames: dict, key: str):
    """The constraint class's own name of `key` under a constraint's `rename` clause."""
    return renames.get(key, None if key in renames.values() else key)
