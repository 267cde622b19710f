"""Codegen, direct blocks: a reservation of one separate argument whose body the client runs
as plain calls of the supplier's routines (runtime direct.py, docs/RUNTIME.md section 3).

`separate_call` notes every statically bound leaf call whose target is a name and whose actual
arguments cannot fail or pass locks (`note`); `block` then turns a reservation body made only
of such calls on the reserved argument (commands, and queries assigned to a local, Result or
an attribute of Current) into

    with here.claim1(x, where, first_query_where, first_query, has_commands[, table, args]) as _block1:
        try:
            C.command(x, a)
        except BaseException as _failure2:
            raise _block1.failed(_failure2, where_of_the_next_query)  # None after the last one
        r = C.query(x, b)

when the body has a query; otherwise nothing changes.
"""

from __future__ import annotations

import ast

from .. import syntax
from . import pyast as P

_LITERALS = (
    syntax.ManifestInteger,
    syntax.ManifestReal,
    syntax.ManifestCharacter,
    syntax.ManifestBoolean,
)


def _plain(gen, node) -> bool:
    """An actual argument whose evaluation cannot fail and has no effect: a literal, a local,
    a formal argument, Result, or an attribute or constant of Current."""
    if node in gen.tables.conversions or node in gen.tables.rewrites:
        return False
    if isinstance(node, syntax.Parenthesized):
        return _plain(gen, node.expression)
    if isinstance(node, _LITERALS + (syntax.Result,)):
        return True
    if isinstance(node, syntax.UnaryExpression) and node.operator in ("-", "+"):
        return isinstance(node.operand, (syntax.ManifestInteger, syntax.ManifestReal))
    if not isinstance(node, syntax.UnqualifiedCall) or node.arguments or node in gen.tables.agent_calls:
        return False
    entity = gen.tables.entities.get(node)
    if entity is not None:
        return entity.kind in ("local", "argument", "result", "attribute")
    feature = gen.tables.features.get(node)
    if feature is None:
        return False
    if feature.kind == "constant":
        return True
    return feature.kind == "attribute" and feature.decl.body is None  # not self-initialising


def _notes(gen) -> dict:
    found = getattr(gen, "_direct_calls", None)
    if found is None:
        found = gen._direct_calls = {}
    return found


def note(gen, call: ast.Call, target: ast.expr, routine: ast.expr, args: list, arg_nodes, query_where) -> None:
    """Remember the leaf call `call` (`query_where` the position of a query, None for a
    command) if a direct block may make it directly."""
    if isinstance(target, ast.Name) and all(_plain(gen, n) for n in arg_nodes):
        _notes(gen)[id(call)] = (target.id, routine, list(args), query_where)


def _statement(notes: dict, stmt, target: str):
    """(note, assigned target or None) if `stmt` is a noted call on `target`, as a command
    statement or a query assigned to a name or an attribute of Current; else None."""
    if isinstance(stmt, ast.Expr):
        found = notes.get(id(stmt.value))
        if found is not None and found[0] == target and found[3] is None:
            return found, None
        return None
    if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1:
        to = stmt.targets[0]
        plain = isinstance(to, ast.Name) or (
            isinstance(to, ast.Attribute) and isinstance(to.value, ast.Name) and to.value.id == "self"
        )
        found = notes.get(id(stmt.value))
        if plain and found is not None and found[0] == target and found[3] is not None:
            return found, to
    return None


def block(gen, obj, table, pre_args, body, where) -> list | None:
    """The direct block of the reservation of `obj` around `body`, or None if `body` is not
    made only of noted calls on `obj` with at least one query."""
    if not isinstance(obj, ast.Name) or not body:
        return None
    notes = _notes(gen)
    shapes = [_statement(notes, stmt, obj.id) for stmt in body]
    if any(shape is None for shape in shapes):
        return None
    queries = [i for i, shape in enumerate(shapes) if shape[1] is not None]
    if not queries:
        return None
    first_query = shapes[queries[0]][0]
    has_commands = len(queries) < len(shapes)
    name = gen.temp("block") if has_commands else None
    out = []
    for index, (stmt, (noted, to)) in enumerate(zip(body, shapes)):
        direct = P.call(noted[1], [obj] + noted[2])
        if to is not None:
            out.append(ast.copy_location(ast.Assign([to], direct), stmt))
            continue
        failure = gen.temp("failure")
        later = [shape[0][3] for shape in shapes[index:] if shape[1] is not None]
        noticed = later[0] if later else P.const(None)  # where the next query would raise it
        handler = ast.ExceptHandler(
            P.dotted("BaseException"),
            failure,
            [ast.Raise(P.call(P.attr(P.name(name), "failed"), [P.name(failure), noticed]), None)],
        )
        out.append(ast.copy_location(ast.Try([ast.copy_location(ast.Expr(direct), stmt)], [handler], [], []), stmt))
    args = [obj, where, first_query[3], first_query[1], P.const(has_commands)]
    if table is not None:
        args += [table, pre_args]
    item = ast.withitem(P.call("here.claim1", args), P.name(name, store=True) if name else None)
    return [ast.With([item], out)]
