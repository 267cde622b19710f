"""Dynamic dispatch on values whose static type is ANY, COMPARABLE, PART_COMPARABLE, HASHABLE,
NUMERIC, DEBUG_OUTPUT or a formal generic: a Python value (bool: BOOLEAN, int: INTEGER_32,
float: REAL_64, str: CHARACTER_8, or CHARACTER_32 above code 255) runs the basic class's
built-in by its seed name; an object of a generated class is asked by `getattr`.
Also Eiffel `=` (`same`) and `~` (`equal`).

The features of a basic value are the inline templates of scoopc/kernel/basic_inline.py
compiled to functions `(region, current, *arguments)`, plus ANY's features for values. The
templates' `B` is scoopc.kernel.basic_ops, the helpers (the templates of basic classes name
no dispatch function); scoopc.kernel.basic, which generated code imports, re-exports both.
"""

import ast

from . import basic_ops as B
from .basic_inline import specs
from .boxes import KINDS as BOXES
from .strings import bytes_text, text as string_text
from .types import of, t

_KINDS = {bool: "BOOLEAN", int: "INTEGER_32", float: "REAL_64", str: "CHARACTER_8"}
_KINDS.update(BOXES)  # values boxed on reattachment (scoopc/kernel/boxes.py)
_TABLES = {}  # basic class name -> {seed name: function (region, current, *arguments)}


def call(target, name, arguments=(), region=None):
    """`target.name (arguments)`: a routine of an object, or a feature of a basic value.
    `region`: the caller's processor (`here`), for results that are new objects (`out`)."""
    kind = _KINDS.get(type(target))
    if kind is None:
        return getattr(target, name)(*arguments)
    if kind == "CHARACTER_8" and target > "\xff":
        kind = "CHARACTER_32"
    return _feature(kind, name)(region, target, *arguments)


def query(target, name, region=None):
    """`target.name`, a query without arguments (an attribute or a property of an object)."""
    kind = _KINDS.get(type(target))
    if kind is None:
        return getattr(target, name)
    if kind == "CHARACTER_8" and target > "\xff":
        kind = "CHARACTER_32"
    return _feature(kind, name)(region, target)


def call_as(kind, target, name, arguments=(), region=None):
    """`call` when the basic class of `target` is known at run time (e.g. from a generic's
    TypeDesc key: "REAL_32", "NATURAL_8", ...), so REAL_32 prints as a REAL_32."""
    return _feature(kind, name)(region, target, *arguments)


def query_as(kind, target, name, region=None):
    return _feature(kind, name)(region, target)


def _feature(kind, name):
    table = _TABLES.get(kind)
    if table is None:
        table = _TABLES[kind] = _make_table(kind)
    try:
        return table[name]
    except KeyError:
        raise AttributeError(f"a {kind} value has no feature `{name}'") from None


def generating_type(region, value, kind=None):
    """ANY.generating_type of a basic value: the TYPE object of its basic class (`kind`, the
    static class when known: a NATURAL_8 is a Python int too)."""
    from .support import type_object  # deferred: a cycle (support imports this module's B)

    return type_object(region, t(kind) if kind is not None else of(value))


# --- Equality ------------------------------------------------------------------------------

_VALUES = (int, bool, str)
_NUMBERS = (int, float)


def same(a, b):
    """Eiffel `a = b`: identity for references; value equality for basic values of the same
    kind (INTEGER and REAL compare numerically; REAL as ISE: NaN = NaN); `~` for objects of
    an expanded class."""
    if a is b:
        return True
    ta, tb = type(a), type(b)
    if ta is tb:
        if ta is float or ta in BOXES:
            return a == b or (a != a and b != b)
        if ta in _VALUES:
            return a == b
        if getattr(ta, "_expanded_", False):
            return a.is_equal(b)
        return False
    if ta in _NUMBERS and tb in _NUMBERS:
        return a == b
    return False


def equal(a, b):
    """Eiffel `a ~ b`: both Void, or of the same dynamic type and `a.is_equal (b)`."""
    if a is None or b is None:
        return a is b
    ta = type(a)
    if ta is not type(b):
        return False
    if ta is float or ta in BOXES:
        return a == b or (a != a and b != b)
    if ta in _VALUES:
        return a == b
    return a.is_equal(b)


def standard_equal(a, b):
    if a is None or b is None:
        return a is b
    if type(a) is not type(b):
        return False
    if type(a) in _KINDS:
        return equal(a, b)
    return a.standard_is_equal(b)


def deep_equal(a, b):
    if a is None or b is None:
        return a is b
    if type(a) is not type(b):
        return False
    if type(a) in _KINDS:
        return equal(a, b)
    return a.is_deep_equal(b)


# --- Tables --------------------------------------------------------------------------------

_DEFAULTS = {"BOOLEAN": False, "REAL_32": 0.0, "REAL_64": 0.0, "CHARACTER_8": "\x00", "CHARACTER_32": "\x00"}
_SEEDS = {"integer_quotient": "quotient", "unapplicable_opposite": "opposite"}  # renamed NUMERIC features


def _compile(spec):
    names = ["R", "X", "Y", "Z"][: spec.arity + 2]
    body = spec.build(
        ast.Name("X", ast.Load()), [ast.Name(n, ast.Load()) for n in names[2:]], ast.Name("R", ast.Load())
    )
    args = ast.arguments(
        posonlyargs=[],
        args=[ast.arg(n) for n in names],
        vararg=None,
        kwonlyargs=[],
        kw_defaults=[],
        kwarg=None,
        defaults=[],
    )
    tree = ast.fix_missing_locations(ast.Expression(ast.Lambda(args, body)))
    return eval(compile(tree, "<scoopc.kernel.basic>", "eval"), {"_B": B})


def _make_table(kind):
    table = {feature: _compile(spec) for (cls, feature), spec in specs().items() if cls == kind}
    for own, seed in _SEEDS.items():
        if own in table:
            table[seed] = table[own]
    out = table["out"]
    py_type = {"BOOLEAN": bool, "REAL_32": float, "REAL_64": float, "CHARACTER_8": str, "CHARACTER_32": str}.get(
        kind, int
    )
    default = _DEFAULTS.get(kind, 0)
    for name, fn in {
        "tagged_out": out,
        "debug_output": out,
        "generator": lambda r, x: B.s8(r, kind),
        "generating_type": lambda r, x: generating_type(r, x, kind),
        "twin": lambda r, x: x,
        "standard_twin": lambda r, x: x,
        "deep_twin": lambda r, x: x,
        "copy": lambda r, x, other: None,
        "standard_copy": lambda r, x, other: None,
        "deep_copy": lambda r, x, other: None,
        "same_type": lambda r, x, other: type(other) is py_type and _wide(x) == _wide(other),
        "conforms_to": lambda r, x, other: _conforms(x, other, py_type),
        "standard_is_equal": table["is_equal"],
        "is_deep_equal": table["is_equal"],
        "is_equal": table["is_equal"],
        "equal": lambda r, x, a, b: equal(a, b),
        "standard_equal": lambda r, x, a, b: standard_equal(a, b),
        "deep_equal": lambda r, x, a, b: deep_equal(a, b),
        "is_hashable": lambda r, x: True,
        "default": lambda r, x: default,
        "default_pointer": lambda r, x: 0,
        "do_nothing": lambda r, x: None,
        "default_rescue": lambda r, x: None,
        "print": lambda r, x, o: _print(r, o),
    }.items():
        table.setdefault(name, fn)
    return table


def _wide(x):
    return type(x) is str and x > "\xff"


def _conforms(x, other, py_type):
    if type(other) in _KINDS:
        return type(other) is py_type and _wide(x) == _wide(other)
    return getattr(type(other), "_key_", None) == "ANY"  # an object of class ANY itself


def _print(region, o):
    """ANY.print: write `o.out` (if `o` is attached) through the region's untorn output."""
    if o is None:
        return
    if type(o) in _KINDS:
        text = B.out_text(o)
    else:
        text = string_text(o.out)
    region.print(text if text.isascii() else bytes_text(text))
