"""Numbers in strings as EiffelBase reads them (scoopc/kernel/ext/_string_numbers.py through
READABLE_STRING_GENERAL's is_integer*, to_integer*, is_real*, to_double ...)."""

import math
import struct

import pytest
from hypothesis import given, strategies as st

from scoopc.kernel import strings as K
from scoopc.kernel.ext import _string_numbers as N, readable_string_general as g

from string_fakes import R, registered


@pytest.fixture(autouse=True)
def fake_classes():
    with registered():
        yield


INTEGER_CASES = [
    ("0", "i32", True),
    ("  42  ", "i32", True),
    ("+7", "i8", True),
    ("- 5", "i32", False),
    ("-128", "i8", True),
    ("128", "i8", False),
    ("-129", "i8", False),
    ("127", "i8", True),
    ("255", "n8", True),
    ("256", "n8", False),
    ("-0", "n8", True),
    ("-1", "n32", False),
    ("", "i32", False),
    (" ", "i32", False),
    ("1 2", "i32", False),
    ("\t1", "i32", False),
    ("1\t", "i32", False),
    ("\u0661", "i32", False),
    ("1_000", "i32", False),
    ("0x10", "i32", False),
    ("2147483647", "i32", True),
    ("2147483648", "i32", False),
    ("-2147483648", "i32", True),
    ("9223372036854775807", "i64", True),
    ("9223372036854775808", "i64", False),
    ("-9223372036854775808", "i64", True),
    ("-9223372036854775809", "i64", False),
    ("18446744073709551615", "n64", True),
    ("18446744073709551616", "n64", False),
    ("0000000000000000000000000042", "i8", True),
    ("-00000000000000000000000128", "i8", True),
    ("+", "i32", False),
    ("-", "n8", False),
    ("12a", "i64", False),
]


@pytest.mark.parametrize("text,kind,ok", INTEGER_CASES)
def test_is_integer_family(text, kind, ok):
    assert N.is_int(text, kind) is ok
    assert N.is_int(text, kind) is N._int_machine(text, kind)[0]


def test_is_integer_features():
    s = K.s8(R, " -300 ")
    assert g.is_integer(s) and g.is_integer_32(s) and g.is_integer_16(s) and g.is_integer_64(s)
    assert not g.is_integer_8(s) and not g.is_natural(s) and not g.is_natural_64(s)
    assert g.is_number_sequence(s) and g.is_number_sequence(K.s8(R, "99999999999999999999999"))
    n = K.s32(R, "65535")
    assert g.is_natural_16(n) and g.is_natural_32(n) and not g.is_natural_8(n) and not g.is_integer_16(n)


@given(st.text(alphabet="0123456789 +-", max_size=24), st.sampled_from(sorted(N.KINDS)))
def test_integer_fast_path_equals_ise_machine(text, kind):
    assert N.is_int(text, kind) == N._int_machine(text, kind)[0]


def test_to_integer_family():
    assert g.to_integer(K.s8(R, " -42 ")) == -42 and g.to_integer_32(K.s8(R, "+17")) == 17
    assert g.to_integer_8(K.s8(R, "-128")) == -128 and g.to_integer_16(K.s8(R, "32767")) == 32767
    assert g.to_integer_64(K.s8(R, "-9223372036854775808")) == -(1 << 63)
    assert g.to_natural_8(K.s8(R, "255")) == 255 and g.to_natural_16(K.s8(R, "0")) == 0
    assert g.to_natural(K.s8(R, "4294967295")) == 4294967295 == g.to_natural_32(K.s8(R, "4294967295"))
    assert g.to_natural_64(K.s8(R, "18446744073709551615")) == (1 << 64) - 1
    # beyond the type (precondition violated): ISE's truncation of the NATURAL_64 magnitude
    assert N.to_int("300", "i8") == 44 and N.to_int("-129", "i8") == 127
    assert N.to_int("4294967296", "n32") == 0


REAL_CASES = [
    ("1.5e3", True, 1500.0),
    (" 1.5 ", True, 1.5),
    (".5", True, 0.5),
    ("5.", True, 5.0),
    ("-2.25", True, -2.25),
    ("+3", True, 3.0),
    ("1e", True, 1.0),
    ("1e+", True, 1.0),
    ("1E2", True, 100.0),
    ("2.5E-1", True, 0.25),
    ("1.e", False, None),
    ("1.5e", False, None),
    (".", False, None),
    ("-", False, None),
    ("e5", False, None),
    ("1 e5", False, None),
    ("nan", False, None),
    ("inf", False, None),
    ("", False, None),
    (" ", False, None),
    ("1.5.2", False, None),
    ("- 1", False, None),
    ("1e5 ", True, 100000.0),
    ("-.5", True, -0.5),
    ("0.1", True, 0.1),
    ("123.456", True, 123 + 456 / 1000.0),
    ("\u0661", False, None),
]


@pytest.mark.parametrize("text,ok,value", REAL_CASES)
def test_reals(text, ok, value):
    s = K.s8(R, text)
    assert g.is_double(s) is ok and g.is_real(s) is ok and g.is_real_sequence(s) is ok
    assert g.is_real_64(s) is ok and g.is_real_32(s) is ok
    if ok:
        assert g.to_double(s) == value and g.to_real_64(s) == value


def test_real_conversions_and_edges():
    assert g.to_real(K.s8(R, "0.1")) == struct.unpack("f", struct.pack("f", 0.1))[0]
    assert g.to_real_32(K.s8(R, "1e300")) == math.inf
    assert g.is_real(K.s8(R, "1e300"))  # ISE does not check REAL_32's range
    assert g.to_double(K.s8(R, "1e400")) == math.inf
    assert math.isnan(g.to_double(K.s8(R, "0e400")))  # 0 * (10.0 ^ 400) as ISE computes it
    minus_zero = g.to_double(K.s8(R, "-0"))
    assert minus_zero == 0.0 and math.copysign(1.0, minus_zero) == -1.0
