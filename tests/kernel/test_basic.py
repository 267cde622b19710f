"""Built-ins of the basic classes (scoopc/kernel/basic.py, basic_inline.py): the expressions
`inline` builds, evaluated, against straightforward references (C's printf and pow through
ctypes, numpy's float32, table-driven integer arithmetic). Dynamic dispatch and equality:
test_basic_dispatch.py."""

import ast
import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, strategies as st

from scoopc.kernel import basic as B
from scoopc.kernel.basic_inline import INTEGER_CLASSES

from basic_support import Str, ev, fake_strings as _fake_strings, same_value

fake_strings = _fake_strings

KERNEL = Path(__file__).resolve().parents[2] / "stdlib" / "base" / "kernel"
BASIC = [*INTEGER_CLASSES, "REAL_32", "REAL_64", "BOOLEAN", "CHARACTER_8", "CHARACTER_32", "POINTER"]
NAN, INF = math.nan, math.inf


# --- The feature list: every built-in of stdlib/base/kernel has a template --------------------

DECL = re.compile(
    r'^\t(?:frozen )?([a-z][a-z0-9_]*(?:, *[a-z][a-z0-9_]*)*)(?: alias "[^"]*")?'
    r"(?: \(([^)]*)\))?(?:: ([^=]+?))?\s*$"
)


def declared_builtins(cls):
    """{feature: (arity, result type)} of the `external "built_in"` features of `cls`."""
    found, current = {}, None
    text = (KERNEL / f"{cls.lower()}.e").read_text()
    for line in text[text.index("\nfeature") :].splitlines():
        m = DECL.match(line)
        if m:
            args = m.group(2) or ""
            arity = sum(len(part.split(":")[0].split(",")) for part in args.split(";") if part.strip())
            current = [(name.strip(), arity, m.group(3)) for name in m.group(1).split(",")]
        elif '"built_in"' in line and current:
            for name, arity, result in current:
                found[name] = (arity, result)
            current = None
    return found


@pytest.mark.parametrize("cls", BASIC)
def test_every_builtin_has_a_template(cls):
    declared = declared_builtins(cls)
    assert len(declared) >= 8
    specs = {f: s for (c, f), s in B.specs().items() if c == cls}
    missing = sorted(set(declared) - set(specs))
    assert not missing, f"{cls}: no template for {missing}"
    extra = sorted(set(specs) - set(declared))
    assert not extra, f"{cls}: templates for undeclared features {extra}"
    for name, (arity, _) in declared.items():
        assert specs[name].arity == arity, f"{cls}.{name}"


def test_any_builtins_and_unknown_features():
    assert set(declared_builtins("ANY")) <= {f for (c, f) in B.specs() if c == "ANY"}
    with pytest.raises(KeyError):
        B.inline("INTEGER_32", "no_such_feature", ast.Name("x", ast.Load()), [])
    with pytest.raises(KeyError):
        B.inline("STRING_8", "count", ast.Name("x", ast.Load()), [])


SAMPLES = {
    "int": [-7, 0, 1, 7, 200],
    "real": [1.5, -2.5, 0.0, -0.0, NAN, INF, 3.0],
    "BOOLEAN": [True, False],
    "CHARACTER_8": ["a", "Z", "5", " ", "\xe9", "%"],
    "CHARACTER_32": ["a", "\xe9", "\u0416", "\u00df", "9"],
    "POINTER": [0, 4096],
}
PY_TYPES = {
    "BOOLEAN": bool,
    "REAL_32": float,
    "REAL_64": float,
    "CHARACTER_8": str,
    "CHARACTER_32": str,
    "STRING_8": Str,
}


def samples(cls, feature, arity):
    kind = "int" if cls in INTEGER_CLASSES else ("real" if cls.startswith("REAL") else cls)
    xs = SAMPLES[kind]
    if cls in INTEGER_CLASSES:
        low, high = (0, 255) if cls.startswith("NATURAL") else (-128, 127)
        xs = [x for x in xs if low <= x <= high]
    ys = {0: [()], 1: [(y,) for y in xs[:4]], 2: [(True, 3), (False, 2)]}[arity]
    if feature in ("plus", "minus") and cls.startswith("CHARACTER"):
        ys = [(1,), (2,)]
    return [(x, *y) for x in xs for y in ys]


@pytest.mark.parametrize("cls", BASIC)
def test_operand_forms_agree_and_results_have_the_declared_type(cls):
    """Names, constants and calls (evaluated once each) give the same results, of the type
    the feature declares."""
    for feature, (arity, result_type) in declared_builtins(cls).items():
        if feature == "interval":
            continue
        for values in samples(cls, feature, arity):
            outcomes = []
            for form in ("name", "const", "call"):
                try:
                    outcomes.append(ev(cls, feature, *values, form=form))
                except (ZeroDivisionError, ValueError, TypeError, KeyError, IndexError, OverflowError) as e:
                    outcomes.append(type(e))
            first = outcomes[0]
            assert all(same_value(first, o) for o in outcomes), (cls, feature, values, outcomes)
            if not isinstance(first, type):
                expected = PY_TYPES.get(result_type, int)
                assert type(first) is expected, (cls, feature, values, first)


# --- Integers ------------------------------------------------------------------------------


def ref_wrap(x, bits, signed):
    return int.from_bytes((x % (1 << bits)).to_bytes(bits // 8, "little"), "little", signed=signed)


def bounds(cls):
    bits, signed = INTEGER_CLASSES[cls]
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)


def values_of(cls):
    low, high = bounds(cls)
    return st.one_of(st.integers(low, high), st.sampled_from([low, high, low + 1, high - 1, 0, 1, max(low, -1)]))


@pytest.mark.parametrize("cls", list(INTEGER_CLASSES))
def test_limits_wrap_around(cls):
    low, high = bounds(cls)
    assert ev(cls, "plus", high, 1) == low
    assert ev(cls, "minus", low, 1) == high
    assert ev(cls, "product", high, 2) == ref_wrap(high * 2, *INTEGER_CLASSES[cls])
    assert ev(cls, "bit_shift_left", 1, INTEGER_CLASSES[cls][0] - 1) == (low if low else high // 2 + 1)
    if low:
        assert ev(cls, "opposite", low) == low
        assert ev(cls, "abs", low) == low
        assert ev(cls, "abs", low + 1) == high
        assert ev(cls, "integer_quotient", low, -1) == low
        assert ev(cls, "integer_remainder", low, -1) == 0
        assert ev(cls, "bit_not", 0) == -1
    else:
        assert ev(cls, "bit_not", 0) == high
        assert ev(cls, "unapplicable_opposite", 5) == 5


@pytest.mark.parametrize("cls", list(INTEGER_CLASSES))
@given(data=st.data())
def test_arithmetic_wraps_like_the_reference(cls, data):
    bits, signed = INTEGER_CLASSES[cls]
    a, b = data.draw(values_of(cls)), data.draw(values_of(cls))
    for feature, exact in (
        ("plus", a + b),
        ("minus", a - b),
        ("product", a * b),
        ("bit_and", a & b),
        ("bit_or", a | b),
        ("bit_xor", a ^ b),
    ):
        assert ev(cls, feature, a, b) == ref_wrap(exact, bits, signed), feature
        assert ev(cls, feature, a, b, form="call") == ref_wrap(exact, bits, signed), feature
    assert ev(cls, "bit_not", a) == ref_wrap(~a, bits, signed)
    if signed:
        assert ev(cls, "opposite", a) == ref_wrap(-a, bits, signed)
        assert ev(cls, "abs", a, form="call") == ref_wrap(abs(a), bits, signed)
    for target, (tbits, tsigned) in INTEGER_CLASSES.items():
        name = target.lower()
        assert ev(cls, "as_" + name, a) == ref_wrap(a, tbits, tsigned)
    assert ev(cls, "hash_code", a) == ref_wrap(a, 32, True) & 0x7FFFFFFF
    assert ev(cls, "three_way_comparison", a, b, form="call") == (a > b) - (a < b)
    assert ev(cls, "max", a, b, form="call") == max(a, b) and ev(cls, "min", a, b) == min(a, b)
    assert ev(cls, "to_double", a) == float(a)
    assert ev(cls, "to_real_32", a) == float(np.float32(np.int64(a) if a < 2**63 else np.uint64(a)))


def c_div(a, b):
    q = abs(a) // abs(b)
    return q if (a >= 0) == (b > 0) else -q


SIGNS = [
    (7, 2, 3, 1),
    (-7, 2, -3, -1),
    (7, -2, -3, 1),
    (-7, -2, 3, -1),
    (6, 3, 2, 0),
    (-6, 3, -2, 0),
    (1, 7, 0, 1),
    (-1, 7, 0, -1),
    (0, -5, 0, 0),
]


@pytest.mark.parametrize("cls", [c for c in INTEGER_CLASSES if c.startswith("INTEGER")])
@pytest.mark.parametrize("form", ["name", "const", "call"])
def test_division_truncates_toward_zero(cls, form):
    for a, b, q, r in SIGNS:
        assert ev(cls, "integer_quotient", a, b, form=form) == q, (a, b)
        assert ev(cls, "integer_remainder", a, b, form=form) == r, (a, b)
    for feature in ("integer_quotient", "integer_remainder"):
        with pytest.raises(ZeroDivisionError):
            ev(cls, feature, 5, 0, form=form)
    # `/` converts both operands to REAL_64 (C: (double) a / (double) b): IEEE, no trap.
    assert ev(cls, "quotient", 5, 0, form=form) == math.inf
    assert ev(cls, "quotient", -5, 0, form=form) == -math.inf
    assert math.isnan(ev(cls, "quotient", 0, 0, form=form))


@pytest.mark.parametrize("cls", list(INTEGER_CLASSES))
@given(data=st.data())
def test_division_matches_c(cls, data):
    bits, signed = INTEGER_CLASSES[cls]
    a, b = data.draw(values_of(cls)), data.draw(values_of(cls).filter(lambda v: v != 0))
    for form in ("name", "call"):
        q = ev(cls, "integer_quotient", a, b, form=form)
        assert q == ref_wrap(c_div(a, b), bits, signed)
        assert ev(cls, "integer_remainder", a, b, form=form) == a - c_div(a, b) * b
    assert ev(cls, "quotient", a, b) == float(a) / float(b)


@pytest.mark.parametrize("cls", list(INTEGER_CLASSES))
@given(data=st.data())
def test_shifts(cls, data):
    bits, signed = INTEGER_CLASSES[cls]
    a, n = data.draw(values_of(cls)), data.draw(st.integers(0, bits))
    unsigned = a % (1 << bits)
    assert ev(cls, "bit_shift_left", a, n) == ref_wrap(unsigned << n, bits, signed)
    right = (a >> n) if signed else (unsigned >> n)
    assert ev(cls, "bit_shift_right", a, n) == right
    assert ev(cls, "bit_shift", a, n) == (right if n else a)
    assert ev(cls, "bit_shift", a, -n) == ref_wrap(unsigned << n, bits, signed)
    if n < bits:
        assert ev(cls, "bit_test", a, n) is bool(unsigned >> n & 1)
        assert ev(cls, "set_bit", a, True, n) == ref_wrap(unsigned | 1 << n, bits, signed)
        assert ev(cls, "set_bit", a, False, n) == ref_wrap(unsigned & ~(1 << n), bits, signed)
    m = data.draw(values_of(cls))
    assert ev(cls, "set_bit_with_mask", a, True, m) == ref_wrap(unsigned | m, bits, signed)
    assert ev(cls, "set_bit_with_mask", a, False, m) == ref_wrap(unsigned & ~m, bits, signed)


def test_shifts_by_the_whole_width():
    assert ev("INTEGER_32", "bit_shift_right", -5, 32) == -1
    assert ev("INTEGER_32", "bit_shift_left", -5, 32) == 0
    assert ev("NATURAL_64", "bit_shift_right", 2**64 - 1, 64) == 0
    assert ev("INTEGER_8", "bit_shift_right", -128, 7) == -1
    assert ev("NATURAL_8", "bit_shift_right", 128, 7) == 1
    assert ev("INTEGER_16", "bit_shift", 1, -15) == -32768


def test_integer_conversions_and_queries():
    assert ev("INTEGER_32", "to_integer_8", 200) == -56  # precondition off: C cast
    assert ev("INTEGER_64", "to_integer_32", 2**31) == -(2**31)
    assert ev("NATURAL_32", "to_integer_32", 4294967295) == -1
    assert ev("INTEGER_8", "to_natural_8", -1) == 255
    assert ev("INTEGER_8", "to_integer_64", -1) == -1
    assert ev("INTEGER_64", "to_real_32", 2**62 + 2**38 + 1) == float(
        np.float32(np.int64(2**62 + 2**38 + 1))
    )  # once, not via double
    assert ev("NATURAL_64", "to_real_64", 2**64 - 1) == 18446744073709551616.0
    assert ev("NATURAL_64", "quotient", 2**64 - 1, 2**53 + 1) == float(2**64 - 1) / float(2**53 + 1)
    assert ev("INTEGER_32", "to_character_8", 65) == "A" and ev("INTEGER_32", "to_character_32", 0x416) == "\u0416"
    assert ev("INTEGER_32", "is_valid_character_8_code", 256) is False
    assert ev("INTEGER_32", "is_valid_character_32_code", -1) is False
    assert ev("NATURAL_8", "is_valid_character_8_code", 255) is True
    assert ev("INTEGER_32", "to_boolean", -3) is True and ev("INTEGER_32", "is_hashable", 0) is False
    assert [ev("INTEGER_32", "sign", v) for v in (-9, 0, 9)] == [-1, 0, 1]
    assert ev("NATURAL_16", "sign", 0) == 0 and ev("NATURAL_16", "sign", 9) == 1
    assert ev("INTEGER_32", "to_hex_character", 11) == "B"
    assert ev("INTEGER_32", "to_hex_string", -1).text == "FFFFFFFF"
    assert ev("INTEGER_8", "to_hex_string", 10).text == "0A"
    assert ev("NATURAL_64", "to_hex_string", 255).text == "00000000000000FF"
    assert ev("INTEGER_16", "to_hex_string", -2).text == "FFFE"
    assert ev("INTEGER_32", "power", 2, 10.0) == 1024.0 and ev("INTEGER_32", "quotient", 7, 2) == 3.5
    assert ev("INTEGER_32", "exponentiable", 0, -1) is False and ev("INTEGER_32", "exponentiable", 0, 2) is True
    assert ev("INTEGER_32", "divisible", 3, 0) is False
    assert ev("INTEGER_32", "one", 5) == 1 and ev("NATURAL_8", "zero", 5, form="call") == 0
    assert ev("INTEGER_64", "hash_code", -2) == 0x7FFFFFFE and ev("INTEGER_8", "hash_code", -1) == 0x7FFFFFFF
    assert ev("NATURAL_64", "hash_code", 2**64 - 1) == 0x7FFFFFFF


@pytest.mark.parametrize("cls", list(INTEGER_CLASSES))
def test_integer_out_is_decimal(cls):
    low, high = bounds(cls)
    for v in (low, high, 0, 1, 42):
        assert ev(cls, "out", v).text == str(v)
    assert ev(cls, "out", 5).region == "HERE"


def test_interval_creates_an_integer_interval(monkeypatch):
    import scoopc.kernel as kernel

    class Interval:
        def make(self, lower, upper):
            self.lower, self.upper = lower, upper

    class Region:
        def new(self, cls):
            obj = cls.__new__(cls)
            obj._region_ = self
            return obj

    monkeypatch.setitem(kernel.CLASSES, "INTEGER_INTERVAL", Interval)
    region = Region()
    r = ev("INTEGER_8", "interval", -3, 4, region=region)
    assert (type(r), r.lower, r.upper, r._region_) == (Interval, -3, 4, region)
    assert ev("INTEGER_64", "interval", 2**32 + 5, 9, region=region).lower == 5


@given(st.lists(st.integers(-(2**31), 2**31 - 1), min_size=4, max_size=4))
def test_nested_signed_arithmetic_wraps_each_step(v):
    """(a + b) * (c - d) + -a built from the templates: each operation brought into the type."""

    def node(i):
        return ast.Name(f"v{i}", ast.Load())

    left = B.inline("INTEGER_32", "plus", node(0), [node(1)])
    right = B.inline("INTEGER_32", "minus", node(2), [node(3)])
    expr = B.inline(
        "INTEGER_32",
        "plus",
        B.inline("INTEGER_32", "product", left, [right]),
        [B.inline("INTEGER_32", "opposite", node(0), [])],
    )
    tree = ast.fix_missing_locations(
        ast.Expression(
            ast.Lambda(
                ast.arguments(
                    posonlyargs=[],
                    args=[ast.arg(f"v{i}") for i in range(4)],
                    vararg=None,
                    kwonlyargs=[],
                    kw_defaults=[],
                    kwarg=None,
                    defaults=[],
                ),
                expr,
            )
        )
    )
    fn = eval(compile(tree, "<t>", "eval"), {"_B": B})
    a, b, c, d = v
    assert fn(a, b, c, d) == ref_wrap((a + b) * (c - d) - a, 32, True)
    assert ev("INTEGER_64", "plus", 2**63 - 1, 1) == -(2**63)
    assert ev("INTEGER_16", "minus", -32768, 1, form="const") == 32767
    assert ev("INTEGER_8", "plus", -128, -1, form="const") == 127
