"""CHARACTER_8/32, BOOLEAN and POINTER built-ins, the dynamic dispatch on Python values and on
objects (`call`, `query`, `call_as`), and Eiffel `=` / `~` (`same`, `equal`) of
scoopc/kernel/basic.py."""

import ast
import math
import struct

import pytest
from hypothesis import given, strategies as st

from scoopc.kernel import basic as B
from scoopc.kernel.strings import bytes_text

from basic_support import Str, ev, fake_strings as _fake_strings

fake_strings = _fake_strings
NAN, INF = math.nan, math.inf

# --- CHARACTER_8: ELKS CHARACTER_8_REF's table (ASCII; codes 128..255 have no property) ----

UPPER, LOWER, DIGIT, WHITE, PUNCT, CONTROL, HEXA, SPACE = 1, 2, 4, 8, 16, 32, 64, 128


def elks_flags(code):
    if code < 32 or code == 127:
        return CONTROL | (WHITE if 9 <= code <= 13 else 0)
    if code == 32:
        return WHITE | SPACE
    if 48 <= code <= 57:
        return DIGIT
    if 65 <= code <= 90:
        return UPPER | (HEXA if code <= 70 else 0)
    if 97 <= code <= 122:
        return LOWER | (HEXA if code <= 102 else 0)
    return PUNCT if code < 127 else 0


PROPERTIES = {
    "is_alpha": UPPER | LOWER,
    "is_upper": UPPER,
    "is_lower": LOWER,
    "is_digit": DIGIT,
    "is_hexa_digit": HEXA | DIGIT,
    "is_space": WHITE,
    "is_punctuation": PUNCT,
    "is_alpha_numeric": UPPER | LOWER | DIGIT,
    "is_printable": UPPER | LOWER | DIGIT | PUNCT | SPACE,
    "is_graph": UPPER | LOWER | DIGIT | PUNCT,
    "is_control": CONTROL,
}


def test_character_8_classification_is_the_elks_table():
    for code in range(256):
        c = chr(code)
        for feature, mask in PROPERTIES.items():
            assert ev("CHARACTER_8", feature, c) is bool(elks_flags(code) & mask), (code, feature)
        upper = chr(code - 32) if 97 <= code <= 122 else c
        lower = chr(code + 32) if 65 <= code <= 90 else c
        assert ev("CHARACTER_8", "as_upper", c) == ev("CHARACTER_8", "upper", c) == upper
        assert ev("CHARACTER_8", "as_lower", c, form="call") == lower
        assert ev("CHARACTER_8", "code", c) == ev("CHARACTER_8", "hash_code", c) == code
        assert ev("CHARACTER_8", "out", c).text == c


def test_character_operations():
    assert ev("CHARACTER_8", "plus", "a", 2) == "c" and ev("CHARACTER_8", "minus", "c", 2) == "a"
    assert ev("CHARACTER_8", "next", "\xff") == "\x00"  # C cast to unsigned char
    assert ev("CHARACTER_8", "previous", "b", form="call") == "a"
    assert ev("CHARACTER_8", "difference", "a", "c") == -2
    assert ev("CHARACTER_32", "plus", "\u0416", 1) == "\u0417" and ev("CHARACTER_32", "next", "\xff") == "\u0100"
    assert [ev("CHARACTER_8", "to_hexa_digit", c) for c in "09afAF"] == [0, 9, 10, 15, 10, 15]
    assert ev("CHARACTER_8", "three_way_comparison", "a", "b", form="call") == -1
    assert ev("CHARACTER_32", "max", "a", "\u0416") == "\u0416" and ev("CHARACTER_8", "min", "a", "B") == "B"
    assert ev("CHARACTER_8", "is_less", "A", "a") is True and ev("CHARACTER_8", "is_equal", "a", "a") is True
    assert ev("CHARACTER_8", "to_character_32", "\xe9") == "\xe9"
    assert ev("CHARACTER_32", "to_character_8", "\u0141") == "A"  # C cast: low 8 bits
    assert ev("CHARACTER_32", "natural_32_code", "\U0001f600") == 0x1F600
    assert ev("CHARACTER_32", "is_character_8", "\xff") and not ev("CHARACTER_32", "is_character_8", "\u0100")


@pytest.mark.parametrize(
    "c, text",
    [
        ("a", "a"),
        ("~", "~"),
        ("\x7f", "\x7f"),
        ("\x80", "U+0080"),
        ("\xe9", "U+00E9"),
        ("\u0416", "U+0416"),
        ("\U0001f600", "U+1F600"),
        ("\U0010ffff", "U+10FFFF"),
    ],
)
def test_character_32_out(c, text):
    assert ev("CHARACTER_32", "out", c).text == text  # out.c eif_out__c4_s1


def test_character_32_classification_is_unicode():
    yes = {
        "is_alpha": "a\u0416\u00df\u4e2d",
        "is_upper": "A\u0416",
        "is_lower": "a\u0436\u00df",
        "is_digit": "09",
        "is_hexa_digit": "0aF",
        "is_space": " \t\n\xa0\u2028\u3000",
        "is_punctuation": "!,\u00bf\u3001",
        "is_alpha_numeric": "a5\u0663\u0416",
        "is_printable": "a \xa0\u0416",
        "is_graph": "a\u0416!",
        "is_control": "\x00\x1f\x85",
    }
    no = {
        "is_alpha": "5 _",
        "is_upper": "a\u01c5",
        "is_lower": "A",
        "is_digit": "\u0663a",
        "is_hexa_digit": "g\uff21",
        "is_space": "a\u200b",
        "is_punctuation": "+$a",
        "is_alpha_numeric": "_ ",
        "is_printable": "\x00\u200b\u2028",
        "is_graph": " \xa0\x00",
        "is_control": "a\u200b",
    }
    for feature, chars in yes.items():
        assert all(ev("CHARACTER_32", feature, c) for c in chars), feature
    for feature, chars in no.items():
        assert not any(ev("CHARACTER_32", feature, c) for c in chars), feature
    assert ev("CHARACTER_32", "as_upper", "\u0436") == "\u0416" and ev("CHARACTER_32", "lower", "\u0416") == "\u0436"
    assert ev("CHARACTER_32", "as_upper", "\u00df") == "\u00df"  # "SS" is not one character
    assert ev("CHARACTER_32", "hash_code", "\U0001f600") == 0x1F600


# --- BOOLEAN, POINTER -----------------------------------------------------------------------


def boolean(feature, left, right_node):
    expr = B.inline("BOOLEAN", feature, ast.Constant(left), [right_node])
    return eval(compile(ast.fix_missing_locations(ast.Expression(expr)), "<t>", "eval"), {"_B": B, "boom": boom})


def boom():
    raise RuntimeError("evaluated")


BOOM = ast.Call(ast.Name("boom", ast.Load()), [], [])


def test_boolean_operators():
    for a in (False, True):
        assert ev("BOOLEAN", "negated", a) is (not a)
        assert ev("BOOLEAN", "hash_code", a) == ev("BOOLEAN", "to_integer", a) == int(a)
        assert ev("BOOLEAN", "out", a).text == str(a)
        for b in (False, True):
            for form in ("name", "const", "call"):
                assert ev("BOOLEAN", "conjuncted", a, b, form=form) is (a and b)
                assert ev("BOOLEAN", "conjuncted_semistrict", a, b, form=form) is (a and b)
                assert ev("BOOLEAN", "disjuncted", a, b, form=form) is (a or b)
                assert ev("BOOLEAN", "disjuncted_semistrict", a, b, form=form) is (a or b)
                assert ev("BOOLEAN", "disjuncted_exclusive", a, b, form=form) is (a != b)
                assert ev("BOOLEAN", "implication", a, b, form=form) is ((not a) or b)
                assert ev("BOOLEAN", "is_equal", a, b, form=form) is (a == b)


def test_semistrict_operators_short_circuit():
    assert boolean("conjuncted_semistrict", False, BOOM) is False
    assert boolean("disjuncted_semistrict", True, BOOM) is True
    assert boolean("implication", False, BOOM) is True
    for strict, left in (
        ("conjuncted", False),
        ("disjuncted", True),
        ("disjuncted_exclusive", True),
        ("conjuncted_semistrict", True),
        ("implication", True),
    ):
        with pytest.raises(RuntimeError):
            boolean(strict, left, BOOM)


def test_pointer():
    assert ev("POINTER", "out", 0).text == "0x0" and ev("POINTER", "out", 0xDEADBEEF).text == "0xDEADBEEF"
    assert ev("POINTER", "plus", 4096, 8) == 4104 and ev("POINTER", "is_default_pointer", 0) is True
    assert ev("POINTER", "to_integer_32", 2**32 + 7) == 7 and ev("POINTER", "hash_code", 2**40 + 5) == 5
    assert ev("POINTER", "is_hashable", 0) is False and ev("POINTER", "is_equal", 3, 3) is True


# --- Dynamic dispatch -------------------------------------------------------------------------


class Region:
    def __init__(self):
        self.printed = []

    def print(self, text):
        self.printed.append(text)


class Obj:
    count = 3

    def put(self, v, i):
        return ("put", v, i)

    def is_equal(self, other):
        return self.count == other.count


def test_call_and_query_on_values():
    assert B.call(5, "plus", (3,)) == 8 and B.call(2147483647, "plus", (1,)) == -2147483648
    assert B.call(7, "quotient", (2,)) == 3 and B.call(-7, "quotient", (2,)) == -3  # NUMERIC's `/` on INTEGER
    assert B.call(-7, "integer_remainder", (2,)) == -1
    assert B.call(1.5, "quotient", (0.0,)) == INF and B.call(1.5, "opposite") == -1.5
    assert B.call(NAN, "is_less", (1.0,)) is True and B.call("a", "max", ("b",)) == "b"
    assert B.call(3, "three_way_comparison", (9,)) == -1 and B.call(2.0, "min", (NAN,)) != B.call(2.0, "min", (NAN,))
    assert B.query(5, "one") == 1 and B.query(5.0, "zero") == 0.0 and B.query(-3, "identity") == -3
    assert B.query(-5, "hash_code") == 0x7FFFFFFB and B.query(True, "hash_code") == 1
    assert B.query(True, "is_hashable") is True and B.query(0, "is_hashable") is False
    assert B.query("a", "is_hashable") is True


@pytest.mark.parametrize(
    "value, text, generator",
    [
        (5, "5", "INTEGER_32"),
        (-2.5, "-2.5", "REAL_64"),
        (0.1, "0.10000000000000001", "REAL_64"),
        (True, "True", "BOOLEAN"),
        (False, "False", "BOOLEAN"),
        ("a", "a", "CHARACTER_8"),
        ("\xe9", "\xe9", "CHARACTER_8"),
        ("\u0416", "U+0416", "CHARACTER_32"),
    ],
)
def test_any_features_of_values(value, text, generator):
    region = Region()
    for name in ("out", "tagged_out", "debug_output"):
        result = B.query(value, name, region)
        assert (result.text, result.region) == (text, region)
    assert B.query(value, "generator", region) == Str(region, generator)
    for name in ("twin", "standard_twin", "deep_twin"):
        assert B.query(value, name) is value
    assert B.call(value, "same_type", (value,)) is True and B.call(value, "conforms_to", (value,)) is True
    assert B.call(value, "is_equal", (value,)) is True and B.call(value, "standard_is_equal", (value,)) is True
    assert B.call(value, "copy", (value,)) is None and B.query(value, "do_nothing") is None
    assert B.query(value, "default") == {int: 0, float: 0.0, bool: False, str: "\x00"}[type(value)]
    assert type(B.query(value, "default")) is type(value)
    assert B.call(value, "print", (value,), region) is None
    assert region.printed == [bytes_text(text)]  # a CHARACTER_8 is a byte: 233 goes out as the byte 233


def test_types_of_values():
    assert B.call(1, "same_type", (1.0,)) is False and B.call(True, "same_type", (1,)) is False
    assert B.call("a", "same_type", ("\u0416",)) is False
    assert B.call(1, "conforms_to", (Obj(),)) is False
    any_class = type("ANY", (), {"_key_": "ANY"})
    assert B.call(1, "conforms_to", (any_class(),)) is True


def test_generating_type_is_the_type_object_of_the_basic_class(monkeypatch):
    from scoopc.kernel import support

    monkeypatch.setattr(support, "type_object", lambda region, desc: ("TYPE", region, desc.name))
    assert B.query(5, "generating_type", "R") == ("TYPE", "R", "INTEGER_32")
    assert B.query(0.5, "generating_type", "R")[2] == "REAL_64"
    assert B.query_as("NATURAL_8", 5, "generating_type", "R")[2] == "NATURAL_8"


def test_call_as_a_known_basic_class():
    single = struct.unpack("f", struct.pack("f", 0.1))[0]
    assert B.query_as("REAL_32", single, "out").text == "0.1"
    assert B.query(single, "out").text == "0.10000000149011612"
    assert B.call_as("NATURAL_8", 255, "plus", (1,)) == 0 and B.call_as("NATURAL_8", 5, "opposite") == 5
    assert B.query_as("INTEGER_64", 2**40, "out").text == "1099511627776"


def test_call_and_query_on_objects():
    obj = Obj()
    assert B.query(obj, "count") == 3 and B.call(obj, "put", ("v", 2)) == ("put", "v", 2)
    with pytest.raises(AttributeError):
        B.call(5, "no_such_feature", (1,))
    with pytest.raises(AttributeError):
        B.query(obj, "no_such_feature")
    with pytest.raises(AttributeError):
        B.query(None, "count")


def test_equal_through_a_value_target():
    assert B.call(0, "equal", (1.0, 1.0)) is True and B.call(0, "equal", (None, None)) is True
    assert B.call(0, "standard_equal", (1, 1.0)) is False and B.call("a", "deep_equal", (Obj(), None)) is False


@given(st.integers(-(2**31), 2**31 - 1), st.integers(-(2**31), 2**31 - 1))
def test_dispatch_agrees_with_inline(a, b):
    for feature in (
        "plus",
        "minus",
        "product",
        "is_less",
        "is_greater_equal",
        "max",
        "three_way_comparison",
        "bit_xor",
    ):
        assert B.call(a, feature, (b,)) == ev("INTEGER_32", feature, a, b)
    if b:
        assert B.call(a, "quotient", (b,)) == ev("INTEGER_32", "integer_quotient", a, b)


@given(st.floats(), st.floats())
def test_real_dispatch_agrees_with_inline(a, b):
    for feature in ("is_less", "is_less_equal", "is_equal", "three_way_comparison"):
        assert B.call(a, feature, (b,)) == ev("REAL_64", feature, a, b)


# --- Eiffel `=` and `~` ---------------------------------------------------------------------


class Point:
    _expanded_ = False

    def __init__(self, x):
        self.x = x
        self.compared = 0

    def is_equal(self, other):
        self.compared += 1
        return self.x == other.x


class Exp(Point):
    _expanded_ = True


def test_same_is_eiffel_equality():
    assert B.same(1, 1) and B.same(1, 1.0) and B.same(2.0, 2) and not B.same(1, 2)
    assert not B.same(1, True) and not B.same(0, False) and B.same(True, True)
    assert B.same(NAN, NAN) and B.same(0.0, -0.0) and not B.same(NAN, 1.0) and not B.same(1, NAN)
    assert B.same("a", "a") and not B.same("a", 97) and not B.same("a", "b")
    assert B.same(None, None) and not B.same(None, 0) and not B.same(0, None)
    p, q = Point(1), Point(1)
    assert B.same(p, p) and not B.same(p, q) and p.compared == 0
    assert B.same(Exp(1), Exp(1)) and not B.same(Exp(1), Exp(2))


def test_equal_is_object_equality():
    assert B.equal(None, None) and not B.equal(None, Point(1)) and not B.equal(Point(1), None)
    assert B.equal(1, 1) and not B.equal(1, 1.0) and not B.equal(True, 1) and B.equal(NAN, NAN)
    p, q = Point(1), Point(1)
    assert B.equal(p, q) and p.compared == 1
    assert not B.equal(Point(1), Exp(1))  # different dynamic types: is_equal not called
    assert not B.equal(Point(1), Point(2))
