"""Checker, contracts: preconditions (recording each clause's wait-condition arguments),
postconditions (where `old` is allowed), class invariants (no `Result`). Every clause is BOOLEAN
(VWBE); `old` elsewhere is VAOL(1) (expressions.py).
"""

from __future__ import annotations

from .. import diagnostics, syntax
from . import scoop, walk
from .calls import export_gap


def assertions(ctx, clauses):
    """Check clauses in order, each under what the earlier ones established (`x /= Void` then
    `x.count > 0`); return what they all establish: (object-test entities, attached names)."""
    found = ((), frozenset())
    for clause in clauses:
        if clause.expression is None:
            continue
        with ctx.assuming(found):
            ctx.boolean(clause.expression)
            established, _ = ctx.branches(clause.expression)
        found = (found[0] + established[0], found[1] | established[1])
    return found


def check_precondition(ctx, precondition) -> None:
    if precondition is None:
        return
    ctx.in_precondition = True
    try:
        assertions(ctx, precondition.clauses)
    finally:
        ctx.in_precondition = False
    for clause in precondition.clauses:
        waits = scoop.wait_arguments(ctx, clause)
        if waits:
            ctx.tables.wait_args[clause] = waits


def check_postcondition(ctx, postcondition) -> None:
    if postcondition is None:
        return
    ctx.in_postcondition = True
    try:
        for clause in postcondition.clauses:
            if clause.expression is not None:
                ctx.boolean(clause.expression)
    finally:
        ctx.in_postcondition = False


def check_invariant(ctx, clauses) -> None:
    ctx.result_context = "a class invariant"
    for clause in clauses:
        if clause.expression is not None:
            ctx.boolean(clause.expression)


def check_inherited_preconditions(universe, info, tables, found: list) -> None:
    """VAPE in the preconditions a redeclared routine inherits: each feature they call must be
    available to every client of the redeclared version (EiffelStudio checks them in the heir,
    `process_inherited_assertions`). Reported where the inherited precondition calls it."""
    for feature in info.features.values():
        if feature.written_in != info.name or not feature.precursors:
            continue
        by_seed = {s: f for f in info.features.values() for s in f.seeds()}
        for version in _versions(feature):
            body = version.body
            owner = universe.get(version.written_in)
            if body is None or body.precondition is None or owner is None or owner.from_library:
                continue
            for clause in body.precondition.clauses:
                _check_clause(universe, feature, clause.expression, tables, by_seed, found)


def _versions(feature):
    pending, seen = [p for _, p in feature.precursors], []
    while pending:
        version = pending.pop()
        if all(version is not s for s in seen):
            seen.append(version)
            pending.extend(p for _, p in version.precursors)
    return seen


def _check_clause(universe, routine, node, tables, by_seed, found) -> None:
    if node is None or isinstance(node, (syntax.CreationExpression, syntax.InlineAgent)):
        return
    called = tables.features.get(node)
    if called is not None and isinstance(node, (syntax.UnqualifiedCall, syntax.QualifiedCall)):
        if isinstance(node, syntax.UnqualifiedCall):
            called = by_seed.get(called.seed, called)  # the heir's version, with the heir's exports
        client = export_gap(universe, routine, called)
        if client is not None:
            listed = ", ".join(sorted(called.exports)) or "NONE"
            found.append(
                diagnostics.make(
                    "VAPE", node.name.span, name=called.text, routine=routine.text, client=client, exports=listed
                )
            )
    for child in walk.children(node):
        _check_clause(universe, routine, child, tables, by_seed, found)
