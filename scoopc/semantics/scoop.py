"""Checker, SCOOP rules: every separateness rule in one module (EiffelStudio codes, Gobo's
aliases in comments). The walker calls these at calls, assignments, creations and separate blocks.

Controlled: a formal argument of the enclosing routine, a separate-block local, an object-test or
across local over a controlled expression, or the result of a query on a controlled target within
its expression (Value.handler names the controlling entity; "?" means not controlled).
"""

from __future__ import annotations

import re

from .. import syntax
from .types import Ty
from .values import UNCONTROLLED, Value
from .walk import children, describe


def check_target(ctx, target_node, value: Value) -> bool:
    """VUTA(3) (Gobo VUTA-4G): a call on a separate target needs the target controlled (in a
    SCOOP system; elsewhere a separate value from the library is an ordinary one)."""
    if value.controlled or not ctx.universe.scoop:
        return True
    ctx.report("VUTA(3)", target_node.span, target=describe(target_node), type=str(value.ty), fresh=fresh(target_node))
    return False


def fresh(target_node) -> str:
    """A name for the separate block's local in VUTA(3)'s hint: `x` -> `l_x`, not `x` itself
    (a separate block's name must be fresh: V1SE-G2)."""
    words = re.findall(r"[A-Za-z]\w*", describe(target_node))
    return f"l_{words[-1].lower()}" if words else "l_target"


def separate_by_constraint(ctx, ty: Ty | None) -> bool:
    """A formal generic type whose constraints are all separate (`G -> separate CELL`): its values
    may live on another processor, so a call on one needs it controlled, as a separate target."""
    if ty is None or not ty.is_formal or ty.separate:
        return False
    from .conformance import constraint_types  # deferred: a cycle (scoopc.semantics.conformance imports this module)

    bounds = constraint_types(ctx.universe, ty, ctx.info)
    return bool(bounds) and all(bound.separate for bound in bounds)


def check_actual(ctx, actual_node, actual: Value, formal: Ty) -> bool:
    """The separate-argument rules at a call on a separate target (Gobo VUAR-3G/4G):
    VUAR(4) expanded actual with non-separate references; VUAR(3) a non-separate reference
    passed to a non-separate reference formal (it would be a traitor on the supplier's side);
    VUAR(2) a separate actual passed to a non-separate formal, even one on the target's own
    processor (`x.f (x.g)`), as EiffelStudio's `argument_compatibility_error`: its conformance
    check knows no processors, only separateness."""
    if is_expanded(ctx.universe, formal) or is_expanded(ctx.universe, actual.ty):
        if has_non_separate_references(ctx.universe, actual.ty):
            ctx.report("VUAR(4)", actual_node.span, type=str(actual.ty))
            return False
        return True
    if formal.separate or actual.ty.is_none:
        return True
    if not actual.ty.separate:
        mark = _formal_mark(ctx.info, actual.ty.formal) if actual.ty.is_formal else None
        if mark == "expanded":
            return True
        if actual.ty.is_formal and mark != "reference":
            # EiffelStudio takes an unmarked formal generic as possibly expanded and accepts
            # the call (its partree example relies on it); an actual generic that is a reference
            # type would be a traitor, so we warn (docs/LANGUAGE.md).
            ctx.warn(
                "FORMAL-TRAITOR",
                actual_node.span,
                what=f"`{describe(actual_node)}`",
                formal=str(actual.ty),
                how=f"is passed in a call on a separate target to a formal of non-separate type {formal}",
                risk="the supplier would hold a reference into this processor",
            )
            return True
        ctx.report("VUAR(3)", actual_node.span, actual=describe(actual_node), type=str(formal))
        return False
    ctx.report(
        "VUAR(2)",
        actual_node.span,
        actual=str(actual.ty),
        formal=str(formal),
        reason="it is separate and the formal is not",
        **SEPARATE_ACTUAL,
    )
    return False


def _formal_mark(info, formal: int):
    """The mark (`reference`, `expanded`, `frozen` or None) of formal generic `formal` of `info`'s class."""
    generics = info.decl.formal_generics
    return generics[formal].mark if formal < len(generics) else None


SEPARATE_ACTUAL = {
    "hint": "declare the formal argument `separate`, or pass a non-separate copy "
    "(for a STRING: `create s.make_from_separate (x)`)"
}


_WRITTEN = {
    "local": "the local",
    "attribute": "the attribute",
    "result": "the result type of",
    "argument": "the argument",
}


def separate_mismatch(ctx, code: str, node, source: Ty, target: Ty, written=None, **extra) -> None:
    """VJAR / VUAR(2) when only separateness stops conformance: a separate value cannot become
    non-separate (the object lives on another processor). The hint fits what is written: the
    entity `written` of an assignment (local, attribute, Result), else a formal argument."""
    hint = SEPARATE_ACTUAL
    if code != "VUAR(2)":
        hint = {"hint": _separate_target_hint(written, target, describe(node))}
    ctx.report(
        code,
        node.span,
        source=str(source),
        target=str(target),
        actual=str(source),
        formal=str(target),
        reason="it is separate and the formal is not" if code == "VUAR(2)" else "it is separate and the target is not",
        **hint,
        **extra,
    )


def _separate_target_hint(written, target: Ty, source: str) -> str:
    if written is not None and written.kind == "result":
        return (
            f"the value is on another processor: declare the result type `separate {target}`, or return a copy "
            f"made on this processor: `create Result.make_from_separate ({source})` (STRING has it)"
        )
    name = written.name if written is not None and written.kind in _WRITTEN else "x"
    declare = (
        f"{_WRITTEN[written.kind]} `{name}: separate {target}`" if name != "x" else f"the target `separate {target}`"
    )
    return (
        f"the value is on another processor: declare {declare}, or copy it to this processor: "
        f"`create {name}.make_from_separate ({source})` (STRING has it)"
    )


def lock_passing(ctx, call_node, actuals: list, formals) -> None:
    """Record, for a separate call, the arguments that can hand the client's locks to the
    supplier: references in a region the client holds (non-separate, or controlled separate).
    Whether they do is decided at run time (a Void one does not)."""
    passing = tuple(
        index
        for index, (actual, formal) in enumerate(zip(actuals, formals))
        if actual is not None
        and formal is not None
        and not is_expanded(ctx.universe, actual.ty)
        and not actual.ty.is_none
        and (not actual.ty.separate or actual.controlled)
    )
    if passing:
        ctx.tables.lock_passing[call_node] = passing


def adapt_result(ctx, call_node, result: Ty, target: Value) -> Value:
    """Result type adaptation: a query on a separate target returns a value on the target's
    processor (controlled within the expression when the target is); VUER for an expanded result
    holding non-separate references."""
    if is_expanded(ctx.universe, result):
        if has_non_separate_references(ctx.universe, result):
            ctx.report("VUER", call_node.span, type=str(result))
        return Value(result)
    if result.separate:
        return Value(result, UNCONTROLLED)
    if result.is_formal and _formal_mark(ctx.info, result.formal) != "reference":
        # EiffelStudio does not make an unmarked formal generic result separate (G may be
        # expanded); partree relies on it. We follow, and warn where the value is then used as
        # non-separate (`foreign_use`, docs/LANGUAGE.md).
        return Value(result, None, call_node) if _formal_mark(ctx.info, result.formal) != "expanded" else Value(result)
    return Value(result.with_marks(separate=True), target.handler)


def foreign_use(ctx, value: Value, how: str) -> None:
    """FORMAL-TRAITOR where a `G` result of a separate call is used as non-separate: attached to
    a non-separate entity or argument, or the target of a call (if an actual generic for G is a
    reference type, that is a reference to another processor's object)."""
    if value.foreign is None:
        return
    ctx.warn(
        "FORMAL-TRAITOR",
        value.foreign.span,
        what="this result",
        formal=str(value.ty),
        how=f"comes from a call on a separate target and {how}",
        risk="this processor would use a non-separate reference to an object of another one",
    )


def check_separate_argument(ctx, argument: syntax.SeparateArgument, value: Value | None, clashes: bool) -> bool:
    """FRESH_IDENTIFIER (EiffelStudio's code; Gobo V1SE-G1/G2): the block's local must not clash
    with another name; V1SE (Gobo V1SE-G3): the expression must be of a separate type, so an
    expanded value or a non-separate reference is rejected as EiffelStudio 21.11+ does."""
    if clashes:
        ctx.report("FRESH_IDENTIFIER", argument.name.span, name=argument.name.text)
        return False
    if (
        value is not None
        and ctx.universe.scoop  # not a SCOOP system: the program's separate types are ordinary ones
        and (is_expanded(ctx.universe, value.ty) or not (value.ty.separate or separate_by_constraint(ctx, value.ty)))
    ):
        expanded = is_expanded(ctx.universe, value.ty)
        ctx.report(
            "V1SE",
            argument.expression.span,
            type=str(value.ty),
            hint="values of expanded types are copied anyway: use them directly"
            if expanded
            else "a non-separate object needs no reservation: use it directly, or declare it `separate`",
        )
        return False
    return True


def assign_to_separate_local(ctx, target_node, name: str) -> None:
    """V1SE(3): a separate block's local is read-only, like a formal argument."""
    ctx.report("V1SE(3)", target_node.span, name=name)


def check_process_once(ctx, feature, result: Ty | None) -> None:
    """VFFD(8): a `once ("PROCESS")` function is shared by all processors, so its result must be
    separate (or expanded): a non-separate reference would be reachable from other processors."""
    if result is None or not ctx.universe.scoop or not any(k.upper() == "PROCESS" for k in feature.once_keys):
        return  # EiffelStudio checks VFFD(8) only in a SCOOP system (FEATURE_I, `system.is_scoop`)
    if not result.separate and not is_expanded(ctx.universe, result):
        ctx.report("VFFD(8)", feature.fname.name.span, name=feature.text, type=str(result))


def wait_arguments(ctx, clause: syntax.AssertionClause) -> tuple[str, ...]:
    """The separate formal arguments used as call targets in a precondition clause: the runtime
    makes the clause a wait condition when one of them was newly reserved by the call."""
    names: set[str] = set()
    separate_formals = {
        e.name
        for e in ctx.scopes.frames[0].values()
        if e.kind == "argument" and e.ty is not None and (e.ty.separate or separate_by_constraint(ctx, e.ty))
    }

    def visit(node):
        if isinstance(node, (syntax.QualifiedCall, syntax.BracketExpression)):
            target = node.target
            while isinstance(target, syntax.Parenthesized):
                target = target.expression
            if (
                isinstance(target, syntax.UnqualifiedCall)
                and not target.arguments
                and target.name.key in separate_formals
            ):
                names.add(target.name.key)
        for child in children(node):
            visit(child)

    if clause.expression is not None:
        visit(clause.expression)
    return tuple(sorted(names))


def is_expanded(universe, ty: Ty) -> bool:
    info = universe.get(ty.name)
    return info is not None and info.is_expanded and not ty.is_formal


def has_non_separate_references(universe, ty: Ty, seen=None) -> bool:
    """Whether an expanded type holds (directly or through expanded attributes) a non-separate
    reference attribute."""
    info = universe.get(ty.name)
    if info is None or not info.is_expanded or info.from_library:
        return False
    seen = seen or set()
    if info.name in seen:
        return False
    seen.add(info.name)
    for feature in info.features.values():
        if feature.kind != "attribute" or feature.signature is None or feature.signature.result is None:
            continue
        attr = feature.signature.result
        if is_expanded(universe, attr):
            if has_non_separate_references(universe, attr, seen):
                return True
        elif not attr.separate:
            return True
    return False
