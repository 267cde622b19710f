"""Codegen, the last pass over a module's Python tree: code Python can compile however deeply the
Eiffel source nests. CPython refuses more than 200 nested parentheses, 100 levels of indentation
and 20 nested loops or `try` blocks, and its compiler recurses on deep trees; an Eiffel program may
nest 2,000 deep (docs/GUARANTEES.md). Two rewrites, applied only where the limits are near:

- an expression deeper than EXPRESSION_DEPTH is cut: a deep operand is computed first, into a
  temporary of the tuple around the expression (`(_h1 := <deep part>, <rest using _h1>)[-1]`),
  the operands evaluated before it too unless they are names or constants, so the source's order
  of evaluation is kept; a conditional operand (`and`, `or`, `if`, a lambda's or comprehension's
  body) is cut inside itself, never evaluated ahead;
- statements nested deeper than BLOCK_DEPTH move into a function of their own, defined beside
  them in the routine and called where they were (`_block_3()`), the names they assign declared
  `nonlocal`; a `break` or `continue` inside them returns a code the call site acts on.
"""

from __future__ import annotations

import ast
import itertools

from . import pyast as P

EXPRESSION_DEPTH = 60
LIMIT_CUT = EXPRESSION_DEPTH // 2  # the height of a part cut out
BLOCK_DEPTH = 12
_COMPOUND = (ast.If, ast.For, ast.While, ast.Try, ast.With)
_SCOPES = (ast.FunctionDef, ast.Lambda, ast.ClassDef)
_BREAK, _CONTINUE = 1, 2


class Shallow:
    """The rewrites of one module; temporaries are numbered per module."""

    def __init__(self):
        self.counter = itertools.count(1)

    def module(self, module: ast.Module) -> ast.Module:
        for node in list(ast.walk(module)):
            if isinstance(node, ast.FunctionDef):
                self.function(node)
        for node in list(ast.walk(module)):
            for field in ("body", "orelse", "finalbody"):
                body = getattr(node, field, None)
                if isinstance(body, list) and body and isinstance(body[0], ast.stmt):
                    self.statements(body)
            for handler in getattr(node, "handlers", None) or ():
                self.statements(handler.body)
        return module

    # --- expressions ---------------------------------------------------------------------------
    def statements(self, body: list) -> None:
        index = 0
        while index < len(body):
            self.before: list[ast.stmt] = []
            self.statement(body[index])
            body[index:index] = [_located(s, body[index]) for s in self.before]
            index += len(self.before) + 1

    def statement(self, stmt: ast.stmt) -> None:
        for field in ("value", "test", "iter", "exc"):
            value = getattr(stmt, field, None)
            if isinstance(value, ast.expr) and _height(value) > EXPRESSION_DEPTH:
                setattr(stmt, field, self.region(value, scoped=False))

    def region(self, root: ast.expr, scoped: bool) -> ast.expr:
        """`root` with no path deeper than EXPRESSION_DEPTH; it is evaluated as a whole where
        `root` was (a statement's expression, or a conditional operand). `scoped`: inside a
        lambda or a comprehension, whose names a function defined before the statement cannot see."""
        first: list[ast.expr] = []  # `_h1 := ...`, evaluated in this order before the rest
        height = _height(root)
        while height + 2 > EXPRESSION_DEPTH:
            first += self.cut(root, scoped)
            height, before = _height(root), height
            if height >= before:
                break  # nothing more to cut here (a conditional operand binding names)
        if not first:
            return root
        return ast.Subscript(P.tup(first + [root]), P.const(-1), ast.Load())

    def cut(self, root: ast.expr, scoped: bool) -> list[ast.expr]:
        """One cut along the deepest path of `root`: what must be computed before it. Below a
        conditional operand, the cut is made in that operand's own region."""
        heights: dict[int, int] = {}
        _height(root, heights)
        hoisted: list[ast.expr] = []
        node, condition = root, None
        while True:
            children = _ordered_children(node)
            deepest = max(children, key=lambda c: heights[id(c[2])])
            holder, field, child, conditional = deepest
            if conditional:
                inner_scoped = scoped or not isinstance(node, (ast.BoolOp, ast.IfExp, ast.Compare))
                if inner_scoped or (heights[id(child)] <= LIMIT_CUT and _binds(child)):
                    _put(holder, field, self.region(child, inner_scoped))
                    return hoisted
                if heights[id(child)] <= LIMIT_CUT:
                    _put(holder, field, self.define(child))
                    return hoisted
                condition = (holder, field, child, inner_scoped)
                node = child
                continue
            # a strict operand: what is evaluated before it is computed ahead too
            strict_first = [e for e in children[: children.index(deepest)] if not e[3] and not _pure(e[2])]
            if condition is not None and (strict_first or heights[id(child)] <= LIMIT_CUT):
                _put(condition[0], condition[1], self.region(condition[2], condition[3]))
                return hoisted
            hoisted += [self.hoist(e) for e in strict_first]
            if heights[id(child)] <= LIMIT_CUT:
                hoisted.append(self.hoist(deepest))
                return hoisted
            node = child

    def define(self, operand: ast.expr) -> ast.expr:
        """A conditional operand as a function defined before the statement (`_h3 = lambda: ...`),
        called in its place: the definition evaluates nothing, so the order is kept."""
        name = f"_h{next(self.counter)}"
        self.before.append(P.assign(P.name(name), P.lambda_([], operand)))
        return P.call(name, [])

    def hoist(self, place) -> ast.expr:
        holder, field, child, _ = place
        name = f"_h{next(self.counter)}"
        _put(holder, field, P.name(name))
        return ast.NamedExpr(P.name(name, store=True), child)

    # --- statements ----------------------------------------------------------------------------
    def function(self, func: ast.FunctionDef) -> None:
        """Move blocks nested deeper than BLOCK_DEPTH into functions defined at the top of `func`."""
        helpers: list[ast.stmt] = []
        self.blocks(func.body, 0, helpers)
        if helpers:
            assigned = set()
            for helper in helpers:
                assigned |= _nonlocals(helper)
            bound = _bound(func)
            initial = [P.assign(P.name(n), P.const(None)) for n in sorted(assigned - bound)]
            func.body[:0] = initial + helpers

    def blocks(self, body: list, depth: int, helpers: list) -> None:
        index = 0
        while index < len(body):
            stmt = body[index]
            index += 1
            if not isinstance(stmt, _COMPOUND):
                continue
            if depth >= BLOCK_DEPTH:
                # The call and the tests of its code (`if _flow3 == 2: continue`) are not moved again:
                # one level past BLOCK_DEPTH, and moving them would make another, without end.
                replacement = self.extract(stmt, helpers)
                body[index - 1 : index] = replacement
                index += len(replacement) - 1
                continue
            for field in ("body", "orelse", "finalbody"):
                self.blocks(getattr(stmt, field, []), depth + 1, helpers)
            for handler in getattr(stmt, "handlers", []):
                self.blocks(handler.body, depth + 1, helpers)

    def extract(self, stmt: ast.stmt, helpers: list) -> list:
        name = f"_block{next(self.counter)}"
        self.blocks_inside(stmt, helpers)
        flows = _loop_exits(stmt)
        body: list[ast.stmt] = [stmt]
        func = P.function(name, [], body)
        names = _assigned(stmt)
        if names:
            func.body.insert(0, ast.Nonlocal(sorted(names)))
        helpers.append(_located(func, stmt))
        call = P.call(name, [])
        if not flows:
            return [_located(P.expr_stmt(call), stmt)]
        code = f"_flow{next(self.counter)}"
        out: list[ast.stmt] = [P.assign(P.name(code), call)]
        if _BREAK in flows:
            out.append(P.if_(P.compare(P.name(code), ast.Eq(), P.const(_BREAK)), [ast.Break()]))
        if _CONTINUE in flows:
            out.append(P.if_(P.compare(P.name(code), ast.Eq(), P.const(_CONTINUE)), [ast.Continue()]))
        return [_located(s, stmt) for s in out]

    def blocks_inside(self, stmt: ast.stmt, helpers: list) -> None:
        for field in ("body", "orelse", "finalbody"):
            self.blocks(getattr(stmt, field, []), 1, helpers)
        for handler in getattr(stmt, "handlers", []):
            self.blocks(handler.body, 1, helpers)


# --- helpers -------------------------------------------------------------------------------------


def _height(node: ast.AST, memo: dict | None = None) -> int:
    """The depth of the expression tree below `node` (iterative: it may be deep)."""
    memo = {} if memo is None else memo
    stack = [(node, False)]
    while stack:
        current, done = stack.pop()
        if id(current) in memo:
            continue
        children = [c for c in ast.iter_child_nodes(current) if isinstance(c, ast.expr)]
        if done or not children:
            memo[id(current)] = 1 + max((memo[id(c)] for c in children), default=0)
            continue
        stack.append((current, True))
        stack.extend((c, False) for c in children)
    return memo[id(node)]


def _ordered_children(node: ast.expr) -> list:
    """(holder, field, child, conditional) in the order Python evaluates them; `conditional`:
    evaluated only sometimes, or in a scope of its own (never computed ahead)."""
    out: list = []

    def add(holder, field, child, conditional=False):
        if isinstance(child, ast.expr):
            out.append((holder, field, child, conditional))

    if isinstance(node, ast.BoolOp):
        for i, value in enumerate(node.values):
            add(node.values, i, value, i > 0)
    elif isinstance(node, ast.IfExp):
        add(node, "test", node.test)
        add(node, "body", node.body, True)
        add(node, "orelse", node.orelse, True)
    elif isinstance(node, ast.Compare):
        add(node, "left", node.left)
        for i, value in enumerate(node.comparators):
            add(node.comparators, i, value, i > 0)
    elif isinstance(node, ast.Lambda):
        add(node, "body", node.body, True)
    elif isinstance(node, (ast.GeneratorExp, ast.ListComp, ast.SetComp, ast.DictComp)):
        for i, generator in enumerate(node.generators):
            add(generator, "iter", generator.iter, i > 0)
            for j, condition in enumerate(generator.ifs):
                add(generator.ifs, j, condition, True)
        for field in ("elt", "key", "value"):
            add(node, field, getattr(node, field, None), True)
    elif isinstance(node, ast.Call):
        add(node, "func", node.func)
        for i, arg in enumerate(node.args):
            add(node.args, i, arg)
        for keyword in node.keywords:
            add(keyword, "value", keyword.value)
    elif isinstance(node, ast.Dict):
        for i, (key, value) in enumerate(zip(node.keys, node.values)):
            add(node.keys, i, key)
            add(node.values, i, value)
    else:
        for field, value in ast.iter_fields(node):
            if isinstance(value, list):
                for i, item in enumerate(value):
                    add(value, i, item)
            else:
                add(node, field, value)
    return out


def _binds(node: ast.expr) -> bool:
    """Does `node` bind a name other than the cut's own temporaries (an object test's local)?"""
    return any(isinstance(n, ast.NamedExpr) and not n.target.id.startswith("_h") for n in _walk_scope(node)) or (
        isinstance(node, ast.NamedExpr)
    )


def _put(holder, field, value) -> None:
    if isinstance(holder, list):
        holder[field] = value
    else:
        setattr(holder, field, value)


def _pure(node: ast.expr) -> bool:
    """May `node` be evaluated after what follows it (a constant, or a name read)?"""
    return isinstance(node, ast.Constant) or (isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load))


def _walk_scope(node: ast.AST):
    """The nodes below `node` in its own scope (not inside nested functions or lambdas)."""
    stack = list(ast.iter_child_nodes(node))
    while stack:
        current = stack.pop()
        yield current
        if not isinstance(current, _SCOPES):
            stack.extend(ast.iter_child_nodes(current))


def _assigned(stmt: ast.stmt) -> set:
    """The names a block binds (assignments, `:=`, loop variables, exception names, functions)."""
    found = set()
    for node in itertools.chain([stmt], _walk_scope(stmt)):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            found.add(node.id)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            found.add(node.name)
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)) and node is not stmt:
            found.add(node.name)
        elif isinstance(node, ast.Nonlocal):
            found.update(node.names)
    return found


def _nonlocals(helper: ast.FunctionDef) -> set:
    first = helper.body[0] if helper.body else None
    return set(first.names) if isinstance(first, ast.Nonlocal) else set()


def _bound(func: ast.FunctionDef) -> set:
    """The names bound in `func`'s own scope (its arguments included)."""
    found = {a.arg for a in func.args.args}
    for stmt in func.body:
        found |= _assigned(stmt)
    return found


def _loop_exits(stmt: ast.stmt) -> set:
    """The `break`/`continue` in `stmt` that leave it (not those of its own loops), each turned
    into `return` of its code."""
    found = set()
    stack: list = [(stmt, False)]
    while stack:
        node, in_loop = stack.pop()
        for field, value in ast.iter_fields(node):
            items = value if isinstance(value, list) else [value]
            for i, child in enumerate(items):
                if not isinstance(child, ast.AST) or isinstance(child, _SCOPES):
                    continue
                if isinstance(child, (ast.Break, ast.Continue)) and not in_loop:
                    code = _BREAK if isinstance(child, ast.Break) else _CONTINUE
                    found.add(code)
                    replacement = _located(ast.Return(P.const(code)), child)
                    if isinstance(value, list):
                        value[i] = replacement
                    else:
                        setattr(node, field, replacement)
                    continue
                loop_body = isinstance(node, (ast.For, ast.While)) and field in ("body", "orelse")
                stack.append((child, in_loop or (loop_body and field == "body")))
    return found


def _located(node: ast.stmt, like: ast.stmt) -> ast.stmt:
    line = getattr(like, "lineno", None)
    if line is not None:
        for child in ast.walk(node):
            if "lineno" in child._attributes and getattr(child, "lineno", None) is None:
                child.lineno, child.col_offset = line, 0
                child.end_lineno, child.end_col_offset = line, 0
    return node
