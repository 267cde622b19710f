"""Codegen, small constructors of Python `ast` nodes (the generator never builds Python text)."""

from __future__ import annotations

import ast


def name(identifier: str, store: bool = False) -> ast.Name:
    return ast.Name(identifier, ast.Store() if store else ast.Load())


def attr(value: ast.expr, attribute: str, store: bool = False) -> ast.Attribute:
    return ast.Attribute(value, attribute, ast.Store() if store else ast.Load())


def dotted(path: str) -> ast.expr:
    parts = path.split(".")
    node: ast.expr = name(parts[0])
    for part in parts[1:]:
        node = attr(node, part)
    return node


def const(value) -> ast.Constant:
    return ast.Constant(value)


def call(func, args=(), keywords=None) -> ast.Call:
    if isinstance(func, str):
        func = dotted(func)
    kws = [ast.keyword(k, v) for k, v in (keywords or {}).items()]
    return ast.Call(func, list(args), kws)


def tup(items) -> ast.Tuple:
    return ast.Tuple(list(items), ast.Load())


def lst(items) -> ast.List:
    return ast.List(list(items), ast.Load())


def assign(target: ast.expr, value: ast.expr) -> ast.Assign:
    target = _as_store(target)
    return ast.Assign([target], value)


def _as_store(node):
    if isinstance(node, ast.Name):
        return name(node.id, store=True)
    if isinstance(node, ast.Attribute):
        return ast.Attribute(node.value, node.attr, ast.Store())
    if isinstance(node, ast.Subscript):
        return ast.Subscript(node.value, node.slice, ast.Store())
    return node


def expr_stmt(value: ast.expr) -> ast.Expr:
    return ast.Expr(value)


def not_(value: ast.expr) -> ast.expr:
    if isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.Not):
        return value.operand
    return ast.UnaryOp(ast.Not(), value)


def compare(left, op, right) -> ast.Compare:
    return ast.Compare(left, [op], [right])


def is_none(value) -> ast.Compare:
    return compare(value, ast.Is(), const(None))


def is_not_none(value) -> ast.Compare:
    return compare(value, ast.IsNot(), const(None))


def boolop(op, values) -> ast.expr:
    """`a and b and c` as one n-ary node: a chain of 2,000 `and`s stays flat (`(a and b) and c`
    and `a and (b and c)` mean the same in Python)."""
    flat: list[ast.expr] = []
    for value in values:
        if isinstance(value, ast.BoolOp) and type(value.op) is type(op):
            flat.extend(value.values)
        else:
            flat.append(value)
    if len(flat) == 1:
        return flat[0]
    return ast.BoolOp(op, flat)


def if_(test, body, orelse=None) -> ast.If:
    return ast.If(test, list(body) or [ast.Pass()], list(orelse or []))


def function(fname: str, args: list[str], body: list, decorators=()) -> ast.FunctionDef:
    arguments = ast.arguments(
        posonlyargs=[],
        args=[ast.arg(a) for a in args],
        vararg=None,
        kwonlyargs=[],
        kw_defaults=[],
        kwarg=None,
        defaults=[],
    )
    return ast.FunctionDef(fname, arguments, list(body) or [ast.Pass()], list(decorators), None)


def lambda_(args: list[str], body: ast.expr) -> ast.Lambda:
    arguments = ast.arguments(
        posonlyargs=[],
        args=[ast.arg(a) for a in args],
        vararg=None,
        kwonlyargs=[],
        kw_defaults=[],
        kwarg=None,
        defaults=[],
    )
    return ast.Lambda(arguments, body)


def at(node, span):
    """Stamp `node` (and its children without a position) with an Eiffel span's line."""
    if span is None:
        return node
    line, column = span.line, max(span.column - 1, 0)
    pending = [node]
    while pending:
        child = pending.pop()
        if "lineno" in child._attributes:
            if getattr(child, "lineno", None) is not None:
                continue  # stamped already, and so is everything below it
            child.lineno, child.col_offset = line, column
            child.end_lineno, child.end_col_offset = line, column
        pending.extend(ast.iter_child_nodes(child))
    return node
