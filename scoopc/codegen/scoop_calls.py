"""Codegen, SCOOP entry points: the runtime entry point chosen for each separate call and
reservation from the facts of scoop.py (docs/RUNTIME.md section 3, "Choosing an entry point"),
the `@_rt.leaf` decorations, and `across` over an integer interval as a Python range.

Every fast form is emitted only where its facts hold statically; otherwise the general form:
- a separate call is bound to `C.f` at compile time when the universe has one version of `f`
  for the target's static class and its heirs and the target is never Void (void-safe program,
  attached type); it is `leaf_call`/`leaf_query` when that version is a leaf and no actual
  argument can pass locks (basic types or Void only), else `call`/`query`. Otherwise the
  version is looked up on the target at run time (`_S.scall`, `_S.squery`).
- a routine (or separate block) with one separate argument `x`, no precondition clause left to
  evaluate and a body that is exactly one command on `x` whose arguments cannot pass locks is
  `command1` (`leaf_command1` when it is a leaf); one argument otherwise `claim1` when the body
  is a direct block (direct.py), else `reserve1`; several `reserve` (module-level clause
  tables).
"""

from __future__ import annotations

import ast

from .. import syntax
from ..semantics.types import BASIC
from . import direct, pyast as P
from .scoop import analysis, only_stored


# --- choosing the entry points (docs/RUNTIME.md section 3) --------------------------------------------
def _operands(node):
    """(target node, argument nodes) of a separate call node; (None, None) when unknown."""
    if isinstance(node, (syntax.QualifiedCall, syntax.BracketExpression)):
        return node.target, list(node.arguments)
    if isinstance(node, syntax.BinaryExpression):
        return node.left, [node.right]
    if isinstance(node, syntax.UnaryExpression):
        return node.operand, []
    return None, None


def cannot_pass_locks(gen, nodes) -> bool:
    """Every actual argument's static type is a basic (expanded, immutable) type, or Void."""
    for node in nodes:
        conversion = gen.tables.conversions.get(node)
        ty = conversion[1] if conversion is not None else gen.tables.types.get(node)
        if ty is None or ty.is_formal or not (ty.is_none or ty.name in BASIC):
            return False
    return True


def _statically_attached(gen, node, ty) -> bool:
    """The target is never Void at run time (the program is void-safe and its type attached)."""
    return (
        ty is not None
        and ty.attached
        and not ty.is_formal
        and gen.universe.void_safe
        and node not in gen.tables.conversions
    )


def routine_ref(gen, version) -> ast.expr:
    """The Python function of one version, callable as f(target, *args)."""
    name = gen.py_name(version)
    if version.kind in ("attribute", "constant"):
        return gen.module.constant("G", P.call("_S.getter", [P.const(name)]), key=("getter", name))
    function = P.attr(gen.class_ref(version.written_in), name)
    if version.is_query and not version.arguments:
        return P.attr(function, "fget")
    return function


def separate_call(gen, node, target, feature, args) -> ast.expr:
    """A call on a controlled separate target: statically bound to the one version the
    universe has when it can be (`leaf_call`/`leaf_query` when that version is a leaf and no
    argument can pass locks, else `call`/`query`); otherwise looked up at run time (_S.scall,
    _S.squery). Commands a `command1` could replace are remembered for `reserved`."""
    here = P.name("here")
    target_node, arg_nodes = _operands(node)
    ty = gen.tables.types.get(target_node) if target_node is not None else None
    values = arg_nodes is not None and cannot_pass_locks(gen, arg_nodes)
    attached = target_node is not None and _statically_attached(gen, target_node, ty)
    facts = analysis(gen.program)
    version = None
    if attached and not gen.info.from_library:  # the library is compiled in an open world
        known = gen.universe.get(ty.name)
        version = facts.single(known.name, feature) if known is not None else None
        if version is not None and "@" in version.written_in:
            version = None  # a library class whose name a program class took
    if version is None:
        passing = P.const(bool(gen.tables.lock_passing.get(node)))
        name = P.const(gen.py_name(feature))
        if feature.is_query:
            return P.call("_S.squery", [here, target, name, P.tup(args), passing, gen.where(node)])
        call = P.call("_S.scall", [here, target, name, P.tup(args), passing])
        if attached and values and isinstance(target, ast.Name):
            routine = P.call("_S.routine_of", [P.name(target.id), name])
            _commands(gen)[id(call)] = (target.id, routine, P.tup(args), False)
        return call
    routine = routine_ref(gen, version)
    leaf = values and facts.is_leaf(version)
    if feature.is_query:
        entry = "here.leaf_query" if leaf else "here.query"
        query_where = gen.where(node)
        call = P.call(entry, [target, routine, P.tup(args), query_where])
        if leaf:
            direct.note(gen, call, target, routine, args, arg_nodes, query_where)
        return call
    call = P.call("here.leaf_call" if leaf else "here.call", [target, routine, P.tup(args)])
    if leaf:
        direct.note(gen, call, target, routine, args, arg_nodes, None)
    if values and isinstance(target, ast.Name):
        _commands(gen)[id(call)] = (target.id, routine, P.tup(args), leaf)
    return call


def _commands(gen) -> dict:
    found = getattr(gen, "_scoop_commands", None)
    if found is None:
        found = gen._scoop_commands = {}
    return found


def reserved(gen, objs, table, pre_args, body, where, names=None) -> list:
    """The reservation of a routine's (or separate block's) separate arguments around `body`:
    `command1` when the body is exactly one command on the one argument with no precondition,
    `reserve1` for one argument, `reserve` for several; `table` the clause table or None;
    `names` the Eiffel names of a routine's separate arguments (None for a separate block).
    An argument the routine only stores in attributes is not reserved (_unobservable)."""
    if table is None and names is not None:
        objs = [o for o, n in zip(objs, names) if not _unobservable(gen, o, n, body)]
        if not objs:
            return body or [ast.Pass()]
    if (
        len(objs) == 1
        and table is None
        and len(body) == 1
        and isinstance(body[0], ast.Expr)
        and isinstance(objs[0], ast.Name)
    ):
        command = _commands(gen).get(id(body[0].value))
        if command is not None and command[0] == objs[0].id:
            _, routine, args, leaf = command
            call = P.call("here.leaf_command1" if leaf else "here.command1", [objs[0], routine, args, where])
            return [ast.copy_location(ast.Expr(call), body[0])]
    if len(objs) == 1:
        claimed = direct.block(gen, objs[0], table, pre_args, body, where)
        if claimed is not None:
            return claimed
        call = P.call("here.reserve1", [objs[0], where] + ([table, pre_args] if table is not None else []))
    else:
        keywords = {"where": where}
        if table is not None:
            keywords.update(pre=table, pre_args=pre_args)
        call = P.call("here.reserve", [P.tup(objs)], keywords)
    return [ast.With([ast.withitem(call, None)], body or [ast.Pass()])]


def _unobservable(gen, obj, name, body) -> bool:
    """Whether reserving the separate argument `name` could not be observed: the routine only
    stores it in attributes of Current (`a := name`: no call on it, no argument passing, no
    test) and makes no call that could reserve its processor meanwhile (the routine is a leaf,
    or the body calls nothing). Reserving never blocks, and a private queue released with no
    call in it changes nothing. The leaf analysis (scoop.only_stored) uses the same rule."""
    feature = gen.feature
    if feature is None or not feature.is_routine or not isinstance(obj, ast.Name):
        return False
    facts = analysis(gen.program)
    if not only_stored(facts, feature.decl.body, name):
        return False
    if not gen.info.from_library and facts.is_leaf(feature):
        return True  # the leaf analysis relied on this very rule
    return _only_stored(obj, body) and not any(_real_call(node) for s in body for node in ast.walk(s))


_HARMLESS = {("_S", "assertion_failed")}


def _real_call(node) -> bool:
    """A Python call in generated code other than an assertion failure or integer wrapping."""
    if not isinstance(node, ast.Call):
        return False
    func = node.func
    if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name):
        if (func.value.id, func.attr) in _HARMLESS or (func.value.id == "_B" and func.attr.startswith("wrap_")):
            return False
    return True


def _only_stored(obj, body) -> bool:
    """Whether the generated body uses `obj` only in `self.a = obj`."""
    stored, seen = 0, 0
    for stmt in body:
        for node in ast.walk(stmt):
            if isinstance(node, ast.Name) and node.id == obj.id:
                seen += 1
            elif (
                isinstance(node, ast.Assign)
                and isinstance(node.value, ast.Name)
                and node.value.id == obj.id
                and all(
                    isinstance(t, ast.Attribute) and isinstance(t.value, ast.Name) and t.value.id == "self"
                    for t in node.targets
                )
            ):
                stored += 1
    return seen == stored


def finish_module(program, info, module: ast.Module) -> None:
    """The last touches on a class's module: `@_rt.leaf` on its leaves; no `here = ...` in a
    function that does not use it (a leaf command runs in a few hundred nanoseconds)."""
    for stmt in module.body:
        functions = stmt.body if isinstance(stmt, ast.ClassDef) else [stmt]
        for function in functions:
            if isinstance(function, ast.FunctionDef):
                _drop_unused_here(function)
    decorate_leaves(program, info, module)


def _drop_unused_here(function: ast.FunctionDef) -> None:
    first = function.body[0] if function.body else None
    if not (
        isinstance(first, ast.Assign)
        and len(first.targets) == 1
        and isinstance(first.targets[0], ast.Name)
        and first.targets[0].id == "here"
    ):
        return
    uses = sum(1 for node in ast.walk(function) if isinstance(node, ast.Name) and node.id == "here")
    if uses == 1:
        function.body = function.body[1:] or [ast.copy_location(ast.Pass(), first)]


def decorate_leaves(program, info, module: ast.Module) -> None:
    """`@_rt.leaf` on every routine of a program's class (not the library's) that is a leaf."""
    if info.from_library:
        return
    facts = analysis(program)
    if not facts.closed:
        return
    leaves = set()
    for feature in info.features.values():
        if (
            feature.written_in == info.name
            and feature.is_routine
            and not feature.deferred
            and not feature.is_once
            and facts.is_leaf(feature)
        ):
            leaves.add(program.naming.primary(feature))
    if not leaves:
        return
    for stmt in module.body:
        if isinstance(stmt, ast.ClassDef):
            for member in stmt.body:
                if isinstance(member, ast.FunctionDef) and member.name in leaves:
                    member.decorator_list.append(P.dotted("_rt.leaf"))


# --- `across a |..| b as i`: a Python range --------------------------------------------------------
def interval_across(gen, node):
    """`across a |..| b as i loop ... i.item ... end` (INTEGER_32 bounds, `i` used only as
    `i.item`) or `across a |..| b is k`: `for i in range(a, b + 1)`, the same values in the
    same order without an INTEGER_INTERVAL and its cursor. None when the shape differs."""
    iteration = node.iteration
    expr = iteration.expression
    if (node.invariant or node.variant) and gen.assertions == "all":
        return None
    if not isinstance(expr, syntax.BinaryExpression) or expr.operator != "|..|":
        return None
    feature = gen.tables.features.get(expr)
    if (
        feature is None
        or feature.written_in != "INTEGER_32"
        or not gen.is_builtin_basic(feature)
        or expr in gen.tables.separate_calls
        or any(n in gen.tables.conversions for n in (expr, expr.left, expr.right))
    ):
        return None
    var = gen.local_name(iteration.name.key)
    out = gen.block(node.initialization)
    body = gen.block(node.body)
    if node.until is not None:
        body = [P.if_(gen.x(node.until), [ast.Break()])] + body
    if iteration.cursor_mode and not _items_only(body, var):
        source = gen.iteration_source(iteration)
    else:
        upper = ast.BinOp(gen.x(expr.right), ast.Add(), P.const(1))
        source = P.call("range", [gen.x(expr.left), upper])
    loop = ast.For(P.name(var, store=True), source, body or [ast.Pass()], [], None)
    setattr(loop, USES, _uses([loop.target, loop.iter, *loop.body]))
    return out + [mark_names(loop)]


def _items_only(body, var: str) -> bool:
    """Whether `var` occurs in `body` only as `var.item` (read); if so, each becomes `var`. The
    loops made here carry what names they use (USES): acrosses nested 2,000 deep are not each
    looked through to the bottom."""
    bare, items = _uses(body)
    if var in bare:
        return False
    if var in items:
        replace = _ItemToValue(var)
        body[:] = [replace.visit(stmt) for stmt in body]
    return True


NAMES = "_scoopc_names"  # on a loop of an `across`: the names (ast.Name ids) inside it


def mark_names(loop: ast.For) -> ast.For:
    """`loop` with the names inside it noted (NAMES): a rewrite of one name's uses in a loop around
    it (instrs._ItemReads) skips it when it does not hold that name. The rewrites of this module
    and of instrs change how a name is used, never which names occur."""
    found: set = set()
    pending: list = [loop]
    while pending:
        node = pending.pop()
        known = getattr(node, NAMES, None)
        if known is not None and node is not loop:
            found |= known
        elif isinstance(node, ast.Name):
            found.add(node.id)
        else:
            pending.extend(ast.iter_child_nodes(node))
    setattr(loop, NAMES, frozenset(found))
    return loop


USES = "_scoopc_uses"  # on a loop of interval_across: (names used other than as `name.item`, names used as `name.item`)


def _uses(nodes) -> tuple[frozenset, frozenset]:
    """(the names used other than as `name.item`, the names used as `name.item`) in `nodes`."""
    bare: set = set()
    items: set = set()
    pending = list(nodes)
    while pending:
        node = pending.pop()
        known = getattr(node, USES, None)
        if known is not None:
            bare |= known[0]
            items |= known[1]
        elif _is_item(node, None):
            items.add(node.value.id)
        elif isinstance(node, ast.Name):
            bare.add(node.id)
        else:
            pending.extend(ast.iter_child_nodes(node))
    return frozenset(bare), frozenset(items)


def _is_item(node, var: str | None) -> bool:
    """Is `node` `var.item` read (any name's when `var` is None)?"""
    return (
        isinstance(node, ast.Attribute)
        and node.attr == "item"
        and isinstance(node.ctx, ast.Load)
        and isinstance(node.value, ast.Name)
        and (var is None or node.value.id == var)
    )


class _ItemToValue(ast.NodeTransformer):
    def __init__(self, var: str):
        self.var = var

    def visit_Attribute(self, node):
        if _is_item(node, self.var):
            return ast.copy_location(P.name(self.var), node)
        return self.generic_visit(node)

    def visit_For(self, node):
        known = getattr(node, USES, None)
        if known is None:
            return self.generic_visit(node)
        if self.var in known[1]:  # a loop of interval_across using `var.item`: what it uses changes
            self.generic_visit(node)
            setattr(node, USES, (known[0] | {self.var}, known[1] - {self.var}))
        return node
