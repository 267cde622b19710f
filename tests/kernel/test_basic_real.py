"""REAL_32 and REAL_64 built-ins (scoopc/kernel/basic.py): `out` against the C library's printf
(EiffelStudio's out.c uses "%.17g" and "%g"), `^` against libm's pow, REAL_32 arithmetic
against numpy's float32, comparisons against eif_helpers.h (NaN is the smallest value)."""

import ctypes
import ctypes.util
import math
import struct

import numpy as np
import pytest
from hypothesis import given, strategies as st

from scoopc.kernel import basic as B

from basic_support import ev, fake_strings as _fake_strings, same_value

fake_strings = _fake_strings
NAN, INF = math.nan, math.inf
_libc = ctypes.CDLL(ctypes.util.find_library("c"))
_libm = ctypes.CDLL(ctypes.util.find_library("m"))
_libm.pow.restype = ctypes.c_double
_libm.pow.argtypes = [ctypes.c_double, ctypes.c_double]


def printf(fmt, x):
    buffer = ctypes.create_string_buffer(64)
    _libc.snprintf(buffer, 64, fmt.encode(), ctypes.c_double(x))
    return buffer.value.decode()


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


doubles = st.floats(allow_nan=True, allow_infinity=True)
singles = st.floats(width=32, allow_nan=True, allow_infinity=True)
REALS = ["REAL_32", "REAL_64"]


# --- out ---------------------------------------------------------------------------------

REAL_64_OUT = [
    (0.1, "0.10000000000000001"),
    (1.0, "1"),
    (0.0, "0"),
    (-0.0, "-0"),
    (100.0, "100"),
    (0.5, "0.5"),
    (-123.456, "-123.456"),
    (1 / 3, "0.33333333333333331"),
    (299792.458, "299792.45799999998"),
    (1.5e300, "1.5000000000000001e+300"),
    (1e-05, "1.0000000000000001e-05"),
    (2.5e-10, "2.5000000000000002e-10"),
    (1e16, "10000000000000000"),
    (1e17, "1e+17"),
    (1e21, "1e+21"),
    (123456789012345678.0, "1.2345678901234568e+17"),
    (5e-324, "4.9406564584124654e-324"),
    (1.7976931348623157e308, "1.7976931348623157e+308"),
    (-(2.0**60), "-1.152921504606847e+18"),
    (NAN, "NaN"),
    (-NAN, "NaN"),
    (INF, "Infinity"),
    (-INF, "-Infinity"),
]
REAL_32_OUT = [
    (0.1, "0.1"),
    (3.14159274, "3.14159"),
    (1e10, "1e+10"),
    (123456.0, "123456"),
    (1234567.0, "1.23457e+06"),
    (0.0001, "0.0001"),
    (0.00001, "1e-05"),
    (16777216.0, "1.67772e+07"),
    (2.5, "2.5"),
    (100000.0, "100000"),
    (999999.5, "1e+06"),
    (3.4028234663852886e38, "3.40282e+38"),
    (1.401298464324817e-45, "1.4013e-45"),
    (0.0, "0"),
    (-0.0, "-0"),
    (-1.5, "-1.5"),
    (NAN, "NaN"),
    (INF, "Infinity"),
    (-INF, "-Infinity"),
]


@pytest.mark.parametrize("value, text", REAL_64_OUT)
def test_real_64_out(value, text):
    assert ev("REAL_64", "out", value).text == text
    assert B.r64_text(value) == text
    if math.isfinite(value):
        assert printf("%.17g", value) == text


@pytest.mark.parametrize("value, text", REAL_32_OUT)
def test_real_32_out(value, text):
    assert ev("REAL_32", "out", f32(value)).text == text
    if math.isfinite(value):
        assert printf("%g", f32(value)) == text


@given(doubles)
def test_real_64_out_is_printf(x):
    expected = "NaN" if x != x else ("Infinity" if x == INF else ("-Infinity" if x == -INF else printf("%.17g", x)))
    assert B.r64_text(x) == expected


@given(singles)
def test_real_32_out_is_printf(x):
    if math.isfinite(x):
        assert B.r32_text(x) == printf("%g", x)


# --- Arithmetic --------------------------------------------------------------------------


@given(singles, singles)
def test_real_32_arithmetic_rounds_to_single_precision(a, b):
    fa, fb = np.float32(a), np.float32(b)
    with np.errstate(all="ignore"):
        expected = {"plus": fa + fb, "minus": fa - fb, "product": fa * fb, "quotient": fa / fb}
    for feature, value in expected.items():
        for form in ("name", "call"):
            assert same_value(ev("REAL_32", feature, a, b, form=form), float(value)), (feature, form)


@given(doubles, doubles)
def test_real_64_arithmetic_is_ieee(a, b):
    with np.errstate(all="ignore"):
        quotient = float(np.float64(a) / np.float64(b))
    for form in ("name", "call", "const"):
        assert same_value(ev("REAL_64", "quotient", a, b, form=form), quotient), form
    assert same_value(ev("REAL_64", "plus", a, b), a + b)
    assert same_value(ev("REAL_64", "opposite", a), -a)


def test_division_by_zero_gives_infinities():
    assert ev("REAL_64", "quotient", 1.0, 0.0) == INF
    assert ev("REAL_64", "quotient", 1.0, -0.0) == -INF
    assert ev("REAL_64", "quotient", -1.0, 0.0, form="call") == -INF
    assert math.isnan(ev("REAL_64", "quotient", 0.0, 0.0))
    assert math.isnan(ev("REAL_64", "quotient", NAN, 0.0, form="const"))
    assert ev("REAL_32", "quotient", 2.0, 0.0) == INF
    assert ev("REAL_32", "plus", 3.4028234663852886e38, 3.4028234663852886e38) == INF


@given(doubles, doubles)
def test_power_is_c_pow(x, y):
    assert same_value(ev("REAL_64", "power", x, y), _libm.pow(x, y))


@pytest.mark.parametrize(
    "x, y",
    [
        (0.0, -1.0),
        (-0.0, -1.0),
        (-0.0, -2.0),
        (-8.0, 1 / 3),
        (10.0, 400.0),
        (-10.0, 401.0),
        (-10.0, 400.0),
        (0.0, -INF),
        (NAN, 0.0),
        (1.0, NAN),
        (2.0, -2000.0),
    ],
)
def test_power_special_values(x, y):
    assert same_value(B.power(x, y), _libm.pow(x, y))
    assert same_value(ev("INTEGER_32", "power", 0, -1.0), INF)


# --- Comparisons (eif_helpers.h: NaN is the smallest value and equals itself) -------------


def c_equal(a, b):
    return a == b if a == a else b != b


def c_less(a, b):
    return a < b if a == a else b == b


def c_less_equal(a, b):
    return a <= b if a == a else True


def c_greater(a, b):
    return a > b if b == b else a == a


def c_greater_equal(a, b):
    return a >= b if b == b else True


REFERENCE = {
    "is_equal": c_equal,
    "is_less": c_less,
    "is_less_equal": c_less_equal,
    "is_greater": c_greater,
    "is_greater_equal": c_greater_equal,
}
SPECIAL = [NAN, INF, -INF, 0.0, -0.0, 1.0, -1.0]


@pytest.mark.parametrize("cls", REALS)
def test_comparisons_order_nan_first(cls):
    for a in SPECIAL:
        for b in SPECIAL:
            for feature, ref in REFERENCE.items():
                for form in ("name", "const", "call"):
                    assert ev(cls, feature, a, b, form=form) is ref(a, b), (feature, a, b, form)
            twc = -1 if c_less(a, b) else (1 if c_less(b, a) else 0)
            assert ev(cls, "three_way_comparison", a, b) == twc
            assert same_value(ev(cls, "max", a, b), a if c_greater_equal(a, b) else b)
            assert same_value(ev(cls, "min", a, b), a if c_less_equal(a, b) else b)
            assert ev(cls, "ieee_is_equal", a, b) is (a == b)


@given(doubles, doubles)
def test_comparisons_match_eif_helpers(a, b):
    for feature, ref in REFERENCE.items():
        assert ev("REAL_64", feature, a, b) is ref(a, b)
        assert ev("REAL_64", feature, a, b, form="call") is ref(a, b)
        assert ev("REAL_64", feature, a, 2.5, form="const") is ref(a, 2.5)


# --- Conversions ---------------------------------------------------------------------------


def test_truncation_and_rounding():
    assert [ev("REAL_64", "truncated_to_integer", v) for v in (2.9, -2.9, 0.5, -0.5)] == [2, -2, 0, 0]
    for bad in (NAN, INF, -INF, 2147483648.0, -2147483649.0, 1e300):
        assert ev("REAL_64", "truncated_to_integer", bad) == -2147483648  # x86-64 cvttsd2si
    assert ev("REAL_64", "truncated_to_integer", 2147483647.9) == 2147483647
    assert ev("REAL_64", "truncated_to_integer", -2147483648.9) == -2147483648
    assert ev("REAL_64", "truncated_to_integer_64", 9.3e18) == -(2**63)
    assert ev("REAL_64", "truncated_to_integer_64", -9.2e18) == -9200000000000000000
    assert ev("REAL_32", "truncated_to_integer_64", f32(1e10)) == 10000000000
    assert [ev("REAL_64", "ceiling", v) for v in (1.2, -1.2, 2.0)] == [2, -1, 2]
    assert [ev("REAL_64", "floor", v) for v in (1.2, -1.2, 2.0)] == [1, -2, 2]
    assert [ev("REAL_64", "rounded", v) for v in (2.5, -2.5, 1.4999, -0.5, 0.49999999999999994)] == [3, -3, 1, -1, 1]
    assert [ev("REAL_64", "rounded", v) for v in (NAN, INF, -INF)] == [-2147483648] * 3
    assert same_value(ev("REAL_64", "ceiling_real_64", -0.5), -0.0)
    assert same_value(ev("REAL_64", "floor_real_64", -0.5), -1.0)
    assert same_value(ev("REAL_64", "floor_real_64", INF), INF)
    assert same_value(ev("REAL_64", "rounded_real_64", -0.3), -0.0)  # sign * floor: -1 * 0.0
    assert same_value(ev("REAL_64", "rounded_real_64", 2.5), 3.0)
    assert same_value(ev("REAL_64", "rounded_real_64", NAN), NAN)
    assert same_value(ev("REAL_32", "rounded_real_32", f32(0.49999997)), 1.0)  # abs + {REAL_32} 0.5 rounds up
    assert ev("REAL_32", "rounded", f32(0.49999997)) == 0  # abs + 0.5 in double
    assert ev("REAL_64", "truncated_to_real", 0.1) == f32(0.1)
    assert ev("REAL_64", "truncated_to_real", 1e300) == INF
    assert ev("REAL_32", "to_double", f32(0.1)) == f32(0.1)


def test_other_real_queries():
    assert [ev("REAL_64", "sign", v) for v in (-2.0, -0.0, 0.0, 3.0, NAN)] == [-1, 0, 0, 1, -1]
    assert same_value(ev("REAL_64", "abs", -2.0), 2.0)
    assert same_value(ev("REAL_64", "abs", 0.0), -0.0)  # eif_abs_real64: d > 0 ? d : -d
    assert same_value(ev("REAL_64", "abs", -0.0, form="call"), 0.0)
    assert ev("REAL_64", "hash_code", -3.7) == 0x7FFFFFFD
    assert ev("REAL_64", "hash_code", NAN) == 0
    assert ev("REAL_32", "hash_code", 12.5) == 12
    assert ev("REAL_64", "is_nan", NAN) and not ev("REAL_64", "is_nan", INF, form="call")
    assert ev("REAL_64", "is_positive_infinity", INF) and ev("REAL_32", "is_negative_infinity", -INF)
    assert math.isnan(ev("REAL_64", "nan", 1.0)) and ev("REAL_32", "negative_infinity", 1.0) == -INF
    assert ev("REAL_64", "positive_infinity", 1.0, form="call") == INF
    assert ev("REAL_64", "divisible", 1.0, -0.0) is False and ev("REAL_64", "is_hashable", 0.0) is False
    assert ev("REAL_64", "exponentiable", 0.0, -0.5) is False and ev("REAL_64", "exponentiable", 0.0, 0.5) is True
    assert ev("REAL_32", "one", 7.0) == 1.0 and ev("REAL_64", "zero", 7.0) == 0.0


@given(st.integers(-(2**63), 2**64 - 1))
def test_integer_to_real_32_rounds_once(n):
    expected = np.float32(np.uint64(n)) if n >= 2**63 else np.float32(np.int64(n))
    assert B.i2r32(n) == float(expected)
