"""Checker, signatures pass: the argument and result types of every feature, resolved in the
class that declares it; redeclarations checked against their precursors (VDRD(2)).

Input: flattened classes. Output: Feature.signature for every feature.
"""

from __future__ import annotations

from .. import syntax
from .conformance import conforms
from .features import CURRENT, Feature, Signature, member_signature
from .typeresolve import TypeResolver, constraint_old_name
from .types import Ty


def resolve_all(universe, info, report) -> None:
    for feature in info.features.values():
        if feature.written_in == info.name:
            signature_of(universe, info, feature, report)


def signature_of(universe, info, feature: Feature, report=None) -> Signature:
    """The signature of a feature declared in `info` (computed once, reported once)."""
    if feature.signature is not None:
        return feature.signature
    feature.signature = Signature((), None)  # guards against `like` cycles
    silent = report or (lambda *a, **k: None)
    arguments = {a.name.key: a for a in feature.arguments}

    def anchor(name: str) -> Ty | None:
        if name in arguments:
            return resolver.resolve(arguments[name].type)
        other = info.features.get(name)
        if other is None or not other.is_query:
            return None
        signature_of(universe, universe.get(other.written_in) or info, other)
        return member_signature(universe, info.own_type(), other).result

    resolver = TypeResolver(universe, info, silent, anchor, current_anchor=True)
    args = tuple(_resolve(resolver, a.type) for a in feature.arguments)
    result = _resolve(resolver, feature.decl.type) if feature.is_query else None
    declared = [a.type for a in feature.arguments] + [feature.decl.type if feature.is_query else None]
    anchors = tuple(_feature_anchor(node, arguments) for node in declared)
    feature.signature = Signature(args, result, anchors if any(anchors) else ())
    return feature.signature


def _feature_anchor(node, arguments) -> tuple | None:
    """(name, attachment mark) for a type `like name` where name is a feature (not an argument)."""
    if (
        isinstance(node, syntax.AnchoredType)
        and isinstance(node.anchor, syntax.UnqualifiedCall)
        and not node.anchor.arguments
        and node.anchor.name.key not in arguments
    ):
        return node.anchor.name.key, node.attachment
    return None


def _resolve(resolver, node) -> Ty | None:
    if isinstance(node, syntax.AnchoredType) and isinstance(node.anchor, syntax.Current):
        return CURRENT.with_marks(attached=node.attachment != "detachable", separate=node.separate)
    return resolver.resolve(node)


def feature_type_in(universe, base: Ty, name: str) -> Ty | None:
    info = universe.get(base.name)
    feature = info.features.get(name) if info is not None else None
    if feature is None or not feature.is_query:
        return None
    if feature.signature is None:
        signature_of(universe, universe.get(feature.written_in) or info, feature)
    return member_signature(universe, base, feature).result


def check_redeclarations(universe, info, report) -> None:
    """VDRD(2): a redeclaration keeps the number of arguments; its result and arguments conform
    to those of the version it redeclares (EiffelStudio's covariant rule)."""
    own = info.own_type()
    for feature in info.features.values():
        if feature.written_in != info.name or not feature.precursors:
            continue
        mine = member_signature(universe, own, feature)
        for parent, precursor in feature.precursors:
            theirs = member_signature(universe, own, precursor)
            problem = _mismatch(universe, info, feature, precursor, mine, theirs)
            if problem:
                report("VDRD(2)", feature.fname.name.span, name=feature.text, parent=parent, reason=problem)
                break


def check_assigners(universe, info, report) -> None:
    """VFAC (ECMA-367 8.5.21, numbered as its conditions): the assigner mark of a query names a
    command of the class (1) with one argument more than the query (2), whose first argument has
    the query's type (3) and whose other arguments have the query's argument types (4). Types are
    compared without their attachment marks, as in EiffelBase's `item (k: K): detachable G assign
    force` with `force (v: G; k: K)`."""
    own = info.own_type()
    for feature in info.features.values():
        mark = getattr(feature.decl, "assigner", None)
        if mark is None or feature.written_in != info.name:
            continue
        command = info.features.get(mark.key)
        names = {"name": feature.text, "assigner": mark.text}
        if command is None or command.is_query:
            what = "no feature of the class" if command is None else f"a {command.kind}"
            report("VFAC(1)", mark.span, what=what, **names)
            continue
        if len(command.arguments) != len(feature.arguments) + 1:
            report("VFAC(2)", mark.span, count=len(command.arguments), needed=len(feature.arguments) + 1, **names)
            continue
        query, setter = member_signature(universe, own, feature), member_signature(universe, own, command)
        if not _same_type(setter.arguments[0], query.result):
            report("VFAC(3)", mark.span, type=str(setter.arguments[0]), result=str(query.result), **names)
            continue
        for index, (a, b) in enumerate(zip(setter.arguments[1:], query.arguments), start=2):
            if not _same_type(a, b):
                report("VFAC(4)", mark.span, index=index, type=str(a), expected=str(b), **names)
                break


def check_converters(universe, info, report) -> None:
    """VNCP, VYCP(2..3), VYCQ(2..3): the class's `convert` clause, checked as EiffelStudio's
    CONVERTIBILITY_CHECKER does (its VNCP carries a reason, in EiffelStudio's words). A
    conversion procedure `make ({T})` is a creation procedure of the class with one argument to
    which T conforms; a conversion query `to_t: {T}` is a query without arguments whose type
    conforms to T; a routine is named once and a type once per direction; a conversion type is
    no anchored type, and the class does not already conform to it (VYCQ) nor it to the class
    (VYCP), the subcode 3 when the class is generic. As in EiffelStudio, the first error ends the
    check of the class's clause."""
    seen: set[str] = set()
    known: dict[bool, list[Ty]] = {True: [], False: []}
    resolver = TypeResolver(universe, info, report)
    for converter in info.decl.converters:
        if not _converter_valid(universe, info, converter, seen, known, resolver, report):
            return


def _converter_valid(universe, info, converter, seen: set, known: dict, resolver, report) -> bool:
    """One entry of a convert clause (see `check_converters`); False after reporting its error."""
    name = converter.name
    if name.key in seen:
        report("VNCP", name.span, reason="Routine specified twice in Convert_clause.")
        return False
    seen.add(name.key)
    feature = info.features.get(name.key)
    if feature is None:
        report("VNCP", name.span, reason=f"Routine not found: {name.text}")
        return False
    if converter.creation_mode:
        if name.key not in (info.creators or {}):
            report("VNCP", name.span, reason="Not a creation procedure.")
            return False
        if feature.is_query or len(feature.arguments) != 1:
            report("VNCP", name.span, reason="Not just 1 argument.")
            return False
    elif not feature.is_query or feature.arguments:
        report("VNCP", name.span, reason="Not a query without argument.")
        return False
    own = info.own_type()
    signature = member_signature(universe, own, feature)
    for written in converter.types:
        if isinstance(written, syntax.AnchoredType):
            report("VNCP", written.span, reason="Invalid type: use of anchors.")
            return False
        ty = resolver.resolve(written)
        if ty is None:
            return False  # reported (VTCT, VTUG)
        bare = ty.with_marks(attached=True)
        if bare in known[converter.creation_mode]:
            report("VNCP", written.span, reason="Conversion type already specified.")
            return False
        known[converter.creation_mode].append(bare)
        if converter.creation_mode:
            target = signature.arguments[0]
            if target is not None and not conforms(universe, bare, target.with_marks(attached=True), info):
                report("VNCP", name.span, reason="SOURCE does not conform to argument type.")
                return False
            if not bare.is_formal and conforms(universe, bare, own, info):
                report("VYCP(3)" if info.formals else "VYCP(2)", written.span, name=name.text, type=str(ty))
                return False
        else:
            result = signature.result
            if result is not None and not conforms(universe, result.with_marks(attached=True), bare, info):
                report("VNCP", name.span, reason="Return type does not conform to SOURCE.")
                return False
            if not bare.is_formal and conforms(universe, own, bare, info):
                report("VYCQ(3)" if info.formals else "VYCQ(2)", written.span, name=name.text, type=str(ty))
                return False
    return True


def _same_type(a: Ty | None, b: Ty | None) -> bool:
    """The same type up to attachment marks (an unresolved one is reported elsewhere)."""
    return a is None or b is None or a.with_marks(attached=True) == b.with_marks(attached=True)


def _mismatch(universe, info, feature, precursor, mine: Signature, theirs: Signature) -> str:
    if feature.is_query != precursor.is_query:
        return "a query and a procedure cannot redeclare each other"
    if len(mine.arguments) != len(theirs.arguments):
        return f"it has {len(mine.arguments)} arguments where the parent's version has {len(theirs.arguments)}"
    if mine.result is not None and theirs.result is not None and not _loose(universe, mine.result, theirs.result, info):
        return f"its type {mine.result} does not conform to {theirs.result}"
    for index, (a, b) in enumerate(zip(mine.arguments, theirs.arguments), start=1):
        if a is not None and b is not None and not _loose(universe, a, b, info):
            return f"argument {index} has type {a}, which does not conform to {b}"
    return ""


def _loose(universe, source: Ty, target: Ty, info) -> bool:
    """Conformance for redeclarations: attachment marks may be strengthened either way, as
    EiffelStudio allows a detachable argument to become attached in a redeclaration."""
    if source.name == CURRENT.name or target.name == CURRENT.name:
        return True
    return conforms(universe, source.with_marks(attached=True), target.with_marks(attached=True), info)


def check_joins(universe, info, report) -> None:
    """VDJR: deferred versions joined into one feature must have the same signature. An effective
    version joined with deferred ones effects them: as EiffelStudio, its signature need only
    conform to theirs, like a redeclaration's (VDRD(2))."""
    own = info.own_type()
    for name, versions in info.joins:
        effective = [f for f in versions if not f.deferred]
        if effective:
            mine = member_signature(universe, own, effective[0])
            for feature in versions:
                if feature.deferred:
                    theirs = member_signature(universe, own, feature)
                    problem = _mismatch(universe, info, effective[0], feature, mine, theirs)
                    if problem:
                        report("VDRD(2)", info.decl.name.span, name=name, parent=feature.written_in, reason=problem)
                        break
            continue
        signatures = [member_signature(universe, own, f) for f in versions]
        first = signatures[0]
        for other, feature in zip(signatures[1:], versions[1:]):
            if len(other.arguments) != len(first.arguments) or not _same(universe, info, first, other):
                report("VDJR", info.decl.name.span, name=name, first=versions[0].written_in, second=feature.written_in)
                break


def _same(universe, info, a: Signature, b: Signature) -> bool:
    pairs = list(zip(a.arguments, b.arguments)) + [(a.result, b.result)]
    return all(
        (x is None) == (y is None) and (x is None or (_loose(universe, x, y, info) and _loose(universe, y, x, info)))
        for x, y in pairs
    )


def check_constraint_creators(universe, info, report) -> None:
    """VTGC(3) (ECMA-367-2's Generic Constraint rule, condition 3, as EiffelStudio numbers it):
    each name in a formal's creation constraint (`G -> A create make end`) is the final name, after
    the constraint's renaming, of a feature of exactly one of its constraining types."""
    for index, formal in enumerate(info.decl.formal_generics):
        bounds = info.constraints[index] if index < len(info.constraints) else ()
        if not formal.creators or not bounds or any(b.is_formal for b in bounds):
            continue  # a constraint that is another formal: its own constraint decides
        renames = info.constraint_renames[index] if index < len(info.constraint_renames) else {}
        for name in formal.creators:
            having = [b for b in bounds if _constraint_has(universe, b, renames.get(b.name, {}), name.key)]
            if len(having) != 1:
                listed = ", ".join(str(b) for b in (having or bounds))
                how = f"a feature of several of its constraints ({listed})" if having else f"not a feature of {listed}"
                report("VTGC(3)", name.span, name=name.text, formal=formal.name.text, how=how)


def _constraint_has(universe, bound: Ty, renames: dict, key: str) -> bool:
    """Has the constraint type `bound` a feature named `key` once its renaming is applied?"""
    info = universe.get(bound.name)
    if info is None:
        return True  # an unknown class is reported elsewhere
    old = constraint_old_name(renames, key)
    return old is not None and old in info.features
