"""Shared by the tests of scoopc/kernel/basic*.py: a fake STRING_8, and `ev`, which builds the
expression of a built-in with `inline` and evaluates it."""

import ast
import math

import pytest

from scoopc.kernel import basic as B, basic_ops


class Str:
    """Stands for a STRING_8 made by scoopc.kernel.strings.new_string_8."""

    def __init__(self, region, text):
        self.region, self.text = region, text

    def __eq__(self, other):
        return isinstance(other, Str) and other.text == self.text

    def __repr__(self):
        return f"Str({self.text!r})"


@pytest.fixture(autouse=True)
def fake_strings():
    saved = basic_ops._S8[0]
    basic_ops._S8[0] = Str
    yield
    basic_ops._S8[0] = saved


# --- Evaluating inline expressions ---------------------------------------------------------

SEMISTRICT = {"conjuncted_semistrict", "disjuncted_semistrict", "implication"}
_COMPILED = {}


def _load(name):
    return ast.Name(name, ast.Load())


def compiled(cls, feature, count, form):
    """A function (once, here, v0, v1, ...) evaluating the feature's expression on operands that
    are names (form "name") or calls `once (i, vi)` (form "call"); cached."""
    key = (cls, feature, count, form)
    fn = _COMPILED.get(key)
    if fn is None:
        params = [f"v{i}" for i in range(count)]
        if form == "name":
            nodes = [_load(p) for p in params]
        else:
            nodes = [ast.Call(_load("once"), [ast.Constant(i), _load(p)], []) for i, p in enumerate(params)]
        expr = B.inline(cls, feature, nodes[0], nodes[1:])
        args = ast.arguments(
            posonlyargs=[],
            args=[ast.arg(a) for a in ["once", "here", *params]],
            vararg=None,
            kwonlyargs=[],
            kw_defaults=[],
            kwarg=None,
            defaults=[],
        )
        tree = ast.fix_missing_locations(ast.Expression(ast.Lambda(args, expr)))
        fn = _COMPILED[key] = eval(compile(tree, "<test>", "eval"), {"_B": B})
    return fn


def ev(cls, feature, *values, form="name", region="HERE"):
    """`inline`'s expression for `values[0].feature (values[1:])`, evaluated; operands given as
    names, constants or calls (each must be evaluated once, semistrict operators: at most once)."""
    if form == "const":
        expr = B.inline(cls, feature, ast.Constant(values[0]), [ast.Constant(v) for v in values[1:]])
        code = compile(ast.fix_missing_locations(ast.Expression(expr)), "<test>", "eval")
        return eval(code, {"_B": B, "here": region})
    counter = [0] * len(values)

    def once(i, value):
        counter[i] += 1
        return value

    result = compiled(cls, feature, len(values), form)(once, region, *values)
    if form == "call":
        lazy = feature in SEMISTRICT
        assert all(n == 1 or (lazy and n == 0) for n in counter), f"{cls}.{feature}: evaluated {counter}"
    return result


def same_value(a, b):
    if type(a) is not type(b):
        return False
    if type(a) is float:
        return (a != a and b != b) or (a == b and math.copysign(1, a) == math.copysign(1, b))
    return a == b
