"""Checker, contracts: preconditions (recording each clause's wait-condition arguments),
postconditions (where `old` is allowed), class invariants (no `Result`). Every clause is BOOLEAN
(VWBE); `old` elsewhere is VAOL(1) (expressions.py).
"""

from __future__ import annotations

from . import scoop


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
