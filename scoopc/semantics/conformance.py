"""Checker, conformance and convertibility of types (ECMA-367 8.14, 8.15, with SCOOP's rule that
`T` conforms to `separate T` and never the reverse).

Input: the universe with ancestors computed. Output: yes/no answers and the reason for a no.
"""

from __future__ import annotations

from .types import RANGES, STRINGS, Ty, substitute


def ancestor(universe, ty: Ty, name: str) -> Ty | None:
    """`ty` seen as its ancestor class `name` (generics substituted), or None."""
    info = universe.get(ty.name)
    if info is None:
        return None
    found = info.ancestors.get(name)
    return None if found is None else substitute(found, ty.generics)


def _constraints(context, formal: int, visiting: frozenset = frozenset()) -> list:
    """The class-type constraints of formal generic `formal`, a constraint naming another formal
    replaced by that formal's own (`[G -> H, H -> STRING]`: G's bound is STRING); none when there
    is none, or when the constraints only lead round a cycle (`[G -> H, H -> G]`)."""
    constraints = context.constraints[formal] if formal < len(context.constraints) else ()
    found = []
    for c in constraints:
        if not c.is_formal:
            found.append(c)
        elif c.formal not in visiting and c.formal != formal:
            found.extend(
                b.with_marks(separate=b.separate or c.separate)
                for b in _constraints(context, c.formal, visiting | {formal})
            )
    return found


def _bounds(context, formal: int) -> list:
    return _constraints(context, formal) or [Ty("ANY")]


def base_type(universe, ty: Ty, context) -> Ty:
    """For a formal generic, the (first) constraint in `context`'s class; else ty itself."""
    if not ty.is_formal or context is None:
        return ty
    bound = _bounds(context, ty.formal)[0]
    return bound.with_marks(attached=ty.attached, separate=ty.separate or bound.separate)


def constraint_types(universe, ty: Ty, context) -> list:
    """For a formal generic, each of its constraints (ANY when unconstrained); else [ty]."""
    if not ty.is_formal or context is None:
        return [ty]
    bounds = _bounds(context, ty.formal)
    return [b.with_marks(attached=ty.attached, separate=ty.separate or b.separate) for b in bounds]


def conforms(universe, source: Ty, target: Ty, context=None) -> bool:
    return why_not(universe, source, target, context) is None


def why_not(universe, source: Ty, target: Ty, context=None) -> str | None:
    """None when `source` conforms to `target`; else "separate", "detachable", "separate-generic"
    (only the separateness of an actual generic parameter is in the way) or "type"."""
    if source.is_none:
        expanded = (info := universe.get(target.name)) is not None and info.is_expanded
        return (
            None
            if not expanded and (not target.attached or not universe.void_safe or target.is_formal)
            else ("type" if expanded else "detachable")
        )
    if source.separate and not target.separate and universe.scoop:  # EiffelStudio: is_processor_attachable_to
        return "separate" if _class_conforms(universe, source, target, context, generic_separateness=False) else "type"
    if not _class_conforms(universe, source, target, context):
        if universe.scoop and _class_conforms(universe, source, target, context, generic_separateness=False):
            return "separate-generic"
        return "type"
    if universe.void_safe and target.attached and not source.attached and not _is_expanded(universe, source):
        return "detachable"
    return None


def _is_expanded(universe, ty: Ty) -> bool:
    info = universe.get(ty.name)
    return info is not None and info.is_expanded and not ty.is_formal


def _class_conforms(
    universe, source: Ty, target: Ty, context, visiting: frozenset = frozenset(), generic_separateness: bool = True
) -> bool:
    """Whether the class of `source` conforms to that of `target` with conforming actual generic
    parameters; `generic_separateness` False: the parameters' separateness left aside."""
    if source is target:  # a type conforms to itself (not looked through: ARRAY [ARRAY [...]] 2,000 deep)
        return True
    if source.is_none:  # NONE conforms to every reference type
        return not _is_expanded(universe, target)
    if source.is_formal or target.is_formal:
        if source.is_formal and target.is_formal and source.formal == target.formal:
            return True
        if not source.is_formal:
            return False
        # A formal conforms to what its constraints conform to; constraints may name other
        # formals, even in a cycle (`[G -> H, H -> G]`), so each formal is followed once.
        if target.name == "ANY" and not target.generics:
            return True  # every type conforms to ANY, a cyclic constraint too
        if source.formal in visiting:
            return False
        return _constraint_conforms(universe, source, target, context, visiting | {source.formal})
    if target.name == "TUPLE" and source.name == "TUPLE":
        return len(source.generics) >= len(target.generics) and all(
            _generic_conforms(universe, s, t, context, generic_separateness)
            for s, t in zip(source.generics, target.generics)
        )
    seen = ancestor(universe, source, target.name)
    if seen is None:
        return False
    if not target.generics:
        return True
    if len(seen.generics) != len(target.generics):
        return False
    return all(
        _generic_conforms(universe, s, t, context, generic_separateness) for s, t in zip(seen.generics, target.generics)
    )


def _generic_conforms(universe, source: Ty, target: Ty, context, generic_separateness: bool = True) -> bool:
    if target.is_formal or source.is_formal:
        return _class_conforms(universe, source, target, context, generic_separateness=generic_separateness)
    if source.separate and not target.separate and universe.scoop and generic_separateness:
        return False  # EiffelStudio: GEN_TYPE_A.valid_generic, is_processor_attachable_to (SCOOP systems only)
    return _class_conforms(universe, source, target, context, generic_separateness=generic_separateness)


def _constraint_conforms(universe, source: Ty, target: Ty, context, visiting: frozenset) -> bool:
    if context is None:
        return target.name == "ANY" and not target.is_formal
    constraints = context.constraints[source.formal] if source.formal < len(context.constraints) else ()
    if not constraints:
        return target.name == "ANY" and not target.generics and not target.is_formal
    return any(_class_conforms(universe, c, target, context, visiting) for c in constraints)


def converts(universe, source: Ty, target: Ty) -> str | None:
    """The name of the feature that converts `source` to `target` (a `convert` clause of either
    class), or None."""
    if source.is_formal or target.is_formal or source.is_none:
        return None
    for owner, to_side in ((universe.get(source.name), True), (universe.get(target.name), False)):
        if owner is None:
            continue
        for converter in owner.decl.converters:
            if converter.creation_mode == to_side:
                continue
            for written in converter.types:
                name = universe.canonical(getattr(getattr(written, "name", None), "key", "") or "")
                other = target if to_side else source
                if name == other.name:
                    return converter.name.key
    return None


def manifest_fits(kind: str, value, target: Ty) -> bool:
    """Whether a manifest constant of `kind` ("integer", "real", "string", "character") may take
    the type `target` from its context, as EiffelStudio types manifest constants."""
    name = target.name
    if kind == "integer":
        if name in RANGES:
            low, high = RANGES[name]
            return low <= value <= high
        return name in ("REAL_32", "REAL_64")
    if kind == "real":
        return name in ("REAL_32", "REAL_64")
    if kind == "string":
        return name in STRINGS
    if kind == "character":
        return name in ("CHARACTER_8", "CHARACTER_32")
    return False
