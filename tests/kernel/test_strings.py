"""The `external "Python"` features of the string classes (scoopc/kernel/ext/*string*.py) and
scoopc/kernel/strings.py: construction, access, hashing, comparison, conversion, copy, share.
Called directly on fakes (tests/kernel/string_fakes.py). Numbers: test_string_numbers.py;
modifications: test_string_mutation.py."""

import re

import pytest
from hypothesis import given, strategies as st

from scoopc.kernel import strings as K
from scoopc.kernel.ext import (
    readable_string_8 as r8,
    readable_string_32 as r32,
    readable_string_general as g,
    string_8,
    string_general as sg,
)

from string_fakes import (
    I8,
    I32,
    ROOT,
    S8,
    S32,
    MyString,
    R,
    Region,
    created,
    ise_hash_reference,
    registered,
    twin,
)


@pytest.fixture(autouse=True)
def fake_classes():
    with registered():
        yield


# --- Construction -------------------------------------------------------------------------------


def test_manifest_and_new_strings():
    a = K.s8(R, "abc")
    b = K.s32(R, "ab\u20ac")
    assert type(a) is S8 and type(b) is S32 and a._region_ is R
    assert (K.text(a), a.count, a.capacity) == ("abc", 3, 3)
    assert K.text(b) == "ab\u20ac"
    assert type(K.new_string_8(R, "x")) is S8 and type(K.new_string_32(R, "x")) is S32
    assert type(K.new_immutable_8(R, "x")) is I8 and type(K.new_immutable_32(R, "x")) is I32
    assert K.new_string_8(R, "x", 10).capacity == 10


def test_creation_procedures():
    s = created(S8, g.make, 10)
    assert (s._s, s.count, s.capacity) == ("", 0, 10)
    f = created(S8, r8.make_filled, "z", 3)
    assert (f._s, f.capacity) == ("zzz", 3)
    c = created(S8, r8.make_from_string, K.s8(R, "hello"))
    assert c._s == "hello" and c.capacity == 5
    other = K.s32(R, "x\u0101")
    sep = created(S8, r8.make_from_separate, K.s8(Region(), "far"))
    assert sep._s == "far" and sep._region_ is R
    w = created(S32, r32.make_from_string_general, K.s8(R, "abc"))
    assert w._s == "abc"
    w2 = created(S32, r32.make_from_separate, other)
    assert w2._s == "x\u0101"
    w3 = created(S32, r32.make_filled, "\u0101", 2)
    assert w3._s == "\u0101\u0101" and w3.capacity == 2
    i = created(I8, r8.make_from_string, K.s8(R, "imm"))
    assert i.item(2) == "m"


# --- Access and search ------------------------------------------------------------------------


def test_access_and_search():
    s = K.s8(R, "hello world")
    assert s.item(1) == "h" and string_8.item(s, 11) == "d"
    assert r8.character_32_item(s, 5) == "o" and g.code(s, 1) == 104
    assert g.index_of(s, "o", 1) == 5 and g.index_of(s, "o", 6) == 8 and g.index_of(s, "z", 1) == 0
    assert r8.index_of(s, "o", 12) == 0
    assert g.last_index_of(s, "o", 11) == 8 and r8.last_index_of(s, "o", 7) == 5
    assert g.last_index_of(s, "h", 1) == 1 and g.last_index_of(s, "w", 5) == 0
    assert g.substring_index(s, K.s8(R, "o w"), 1) == 5
    assert g.substring_index(s, K.s8(R, "o"), 6) == 8
    assert g.substring_index(s, K.s8(R, ""), 4) == 4
    assert g.substring_index(s, s, 1) == 1 and g.substring_index(s, s, 2) == 0
    assert g.substring_index_in_bounds(s, K.s8(R, "o"), 6, 7) == 0
    assert g.substring_index_in_bounds(s, K.s8(R, "o"), 6, 8) == 8
    assert g.occurrences(s, "l") == 3 and r8.occurrences(s, "z") == 0
    assert g.has(s, "w") and not r8.has(s, "W")
    assert g.has_substring(s, K.s32(R, "lo w")) and g.has_substring(s, K.s8(R, ""))
    assert not g.has_substring(K.s8(R, "ab"), K.s8(R, "abc"))
    assert g.starts_with(s, K.s32(R, "hell")) and r8.starts_with(s, K.s8(R, ""))
    assert g.ends_with(s, K.s8(R, "world")) and not r8.ends_with(s, K.s8(R, "worl"))
    u = K.s32(R, "\u20acuro")
    assert r32.starts_with(u, K.s32(R, "\u20ac")) and r32.ends_with(u, K.s32(R, "ro"))


# --- Hash codes ---------------------------------------------------------------------------------


def test_hash_code_is_ise():
    assert g.hash_code(K.s8(R, "")) == 0
    assert g.hash_code(K.s8(R, "a")) == 97
    assert g.hash_code(K.s8(R, "abc")) == ((((97 << 8) + 98) % 8388593) << 8) + 99
    long = "The quick brown fox jumps over the lazy dog" * 50
    assert g.hash_code(K.s8(R, long)) == ise_hash_reference(long)


@given(st.text(alphabet=st.characters(max_codepoint=255), max_size=60))
def test_hash_code_8_bit_matches_reference(text):
    h = K.ise_hash(text)
    assert h == ise_hash_reference(text) and h >= 0


@given(st.text(max_size=30))
def test_hash_code_wide_matches_reference_when_non_negative(text):
    h = K.ise_hash(text)
    ref = ise_hash_reference(text)
    assert h >= 0 and h == (ref if ref >= 0 else ref & 0x7FFFFFFF)


def test_hash_code_cache_follows_changes():
    s = K.s8(R, "key")
    first = s.hash_code
    assert s.hash_code == first
    string_8.append_character(s, "s")
    assert s.hash_code == ise_hash_reference("keys")
    assert g.case_insensitive_hash_code(K.s8(R, "KeY\xc9")) == ise_hash_reference("key\xe9")
    assert g.case_insensitive_hash_code(K.s32(R, "\u03a3A")) == ise_hash_reference("\u03c3a")


# --- Status ------------------------------------------------------------------------------------


def test_whitespace_and_booleans():
    assert g.is_whitespace(K.s8(R, "")) and g.is_whitespace(K.s8(R, " \t\r\n\x0b\x0c"))
    assert not g.is_whitespace(K.s8(R, "\xa0")) and g.is_whitespace(K.s32(R, "\xa0\u3000 "))
    assert not g.is_whitespace(K.s8(R, " x "))
    for text, ok in (("true", True), ("FaLsE", True), ("True ", False), ("tru", False), ("", False)):
        assert g.is_boolean(K.s8(R, text)) is ok
    assert g.to_boolean(K.s8(R, "TRUE")) is True and g.to_boolean(K.s32(R, "false")) is False
    assert r32.is_valid_as_string_8(K.s32(R, "caf\xe9")) and not r32.is_valid_as_string_8(K.s32(R, "\u20ac"))


# --- Comparison ---------------------------------------------------------------------------------


def test_comparisons():
    a, b = K.s8(R, "abc"), K.s8(R, "abd")
    assert g.is_less(a, b) and not g.is_less(b, a) and not g.is_less(a, a)
    assert g.is_less(K.s8(R, "ab"), a) and g.is_less(K.s8(R, ""), a)
    assert g.is_equal(a, K.s8(R, "abc")) and not g.is_equal(a, b)
    assert g.same_string(a, K.s32(R, "abc")) and r8.same_string(a, K.s8(R, "abc"))
    assert r32.same_string(K.s32(R, "\u20ac"), K.s32(R, "\u20ac"))
    assert r8.is_case_insensitive_equal(K.s8(R, "Caf\xc9"), K.s8(R, "cAF\xe9"))
    assert not r8.is_case_insensitive_equal(K.s8(R, "\xff"), K.s8(R, "\xdf"))
    assert r32.is_case_insensitive_equal(K.s32(R, "\u03a3\u0130"), K.s32(R, "\u03c3i"))
    assert g.is_case_insensitive_equal(K.s8(R, "ABC"), K.s32(R, "abc"))
    assert not g.is_case_insensitive_equal(K.s8(R, "ABC"), K.s32(R, "abcd"))


# --- Conversion ---------------------------------------------------------------------------------


def test_as_string_8_and_32():
    a = K.s8(R, "x")
    assert g.as_string_8(a) is a and g.as_string_32(K.s32(R, "y"))._s == "y"
    w = K.s32(R, "a\u20acb\xe9")
    n = g.as_string_8(w)
    assert type(n) is S8 and n._s == "a\x00b\xe9" and n.capacity == 4
    up = g.as_string_32(a)
    assert type(up) is S32 and up._s == "x" and up is not a
    assert g.to_string_32(w) is w
    imm = K.new_immutable_8(R, "i")
    assert type(g.as_string_8(imm)) is S8 and type(g.as_string_32(imm)) is S32
    mine = MyString.__new__(MyString)
    mine._region_, mine._s, mine._cap = R, "m", 1
    assert g.as_string_8(mine) is mine


def test_case_conversions():
    s = K.s8(R, "Hello \xe9\xff\xdf\xb5")
    low, up = g.as_lower(s), g.as_upper(s)
    assert type(low) is S8 and low is not s and s._s == "Hello \xe9\xff\xdf\xb5"
    assert low._s == "hello \xe9\xff\xdf\xb5" and up._s == "HELLO \xc9\xff\xdf\xb5"
    w = K.s32(R, "\xff\xdf\u03a3a\u0130\u1fb3")
    assert g.as_upper(w)._s == "\u0178\xdf\u03a3A\u0130\u1fbc"
    assert g.as_lower(w)._s == "\xff\xdf\u03c3ai\u1fb3"
    assert g.as_lower(K.s32(R, "A\u03a3"))._s == "a\u03c3"  # no final-sigma rule
    imm = K.new_immutable_32(R, "AbC")
    assert type(g.as_lower(imm)) is I32 and g.as_lower(imm)._s == "abc"
    t = K.s8(R, "MiXeD")
    sg.to_lower(t)
    assert t._s == "mixed"
    sg.to_upper(t)
    assert t._s == "MIXED"


def test_mirrored_plus_substring_keep_dynamic_class():
    mine = MyString.__new__(MyString)
    mine._region_, mine._s, mine._cap = R, "abc", 3
    for made in (
        g.mirrored(mine),
        g.plus(mine, K.s8(R, "d")),
        g.substring(mine, 1, 2),
        g.as_lower(mine),
        g.as_upper(mine),
    ):
        assert type(made) is MyString and made._region_ is R and made.extra == 7
    assert g.mirrored(mine)._s == "cba" and g.plus(mine, K.s32(R, "d"))._s == "abcd"
    s = K.s8(R, "hello")
    assert g.substring(s, 2, 4)._s == "ell" and g.substring(s, 2, 4).capacity == 3
    for bad in ((0, 2), (3, 2), (4, 6), (-1, -1)):
        empty = g.substring(s, *bad)
        assert empty._s == "" and type(empty) is S8
    assert s.substring(5, 5)._s == "o"
    imm = K.new_immutable_8(R, "abc")
    assert type(g.plus(imm, K.s8(R, "!"))) is I8 and type(g.substring(imm, 1, 1)) is I8
    assert g.plus(K.s8(R, "a"), K.s32(R, "\u20ac"))._s == "a\x00"  # precondition violated


def test_out_is_a_new_string_8():
    s = K.s8(R, "text")
    o = g.out(s)
    assert type(o) is S8 and o is not s and o._s == "text" and o._region_ is R
    assert g.out(K.s32(R, "\u20ac1"))._s == "\xe2\x82\xac1"  # READABLE_STRING_32.out: its UTF-8 bytes, as EiffelStudio
    assert type(g.out(K.new_immutable_32(R, "i"))) is S8


# --- copy, twin, share ----------------------------------------------------------------------------


def test_copy_and_twin():
    a = K.s8(R, "abc")
    t = twin(a)
    assert t._s == "abc" and t is not a and t.capacity == 3
    string_8.append_character(t, "d")
    assert a._s == "abc" and t._s == "abcd"
    big = created(S8, g.make, 50)
    g.copy(big, a)
    assert big._s == "abc" and big.capacity == 50  # ISE keeps the larger area
    small = K.s8(R, "x")
    g.copy(small, K.s8(R, "longer"))
    assert small._s == "longer" and small.capacity == 6
    g.copy(small, small)
    assert small._s == "longer"
    fresh = S8.__new__(S8)
    fresh._region_ = R
    g.copy(fresh, a)
    assert fresh._s == "abc" and fresh.capacity == 3


def test_share_sees_changes_both_ways():
    a, b = K.s8(R, "abc"), K.s8(R, "zz")
    string_8.share(b, a)
    assert b._s == "abc" and b.count == a.count
    string_8.append(a, K.s8(R, "def"))
    assert b._s == "abcdef" and b.count == 6 and b.capacity == a.capacity
    string_8.put(b, "X", 1)
    assert a._s == "Xbcdef"
    sg.wipe_out(b)
    assert a._s == "" and a.count == 0
    c = K.s8(R, "")
    string_8.share(c, b)  # a group of three
    string_8.append_character(a, "q")
    assert b._s == c._s == "q"
    t = twin(c)  # a twin has a buffer of its own
    string_8.append_character(t, "!")
    assert (a._s, b._s, c._s, t._s) == ("q", "q", "q", "q!")
    string_8.append_character(c, "r")
    assert t._s == "q!" and a._s == "qr"
    g.make(c, 5)  # make: a fresh area
    string_8.append_character(a, "s")
    assert c._s == "" and b._s == "qrs"
    string_8.set(b, K.s8(R, "hello"), 2, 3)  # set: the area of a substring
    assert b._s == "el" and a._s == "qrs"
    sg.remove(a, 1)
    assert a._s == "rs" and b._s == "el"
    string_8.share(a, a)
    assert a._s == "rs"


def test_share_with_a_stale_link_copied_by_standard_twin():
    a, b = K.s8(R, "ab"), K.s8(R, "")
    string_8.share(b, a)
    clone = S8.__new__(S8)
    clone.__dict__.update(b.__dict__)  # standard_twin: fields only
    string_8.append_character(clone, "c")
    assert clone._s == "abc" and a._s == "ab" and b._s == "ab"


def test_share_then_copy_keeps_or_leaves_the_group_as_ise():
    a, b = K.s8(R, "abcdef"), K.s8(R, "")
    string_8.share(b, a)
    g.copy(b, K.s8(R, "xy"))  # fits in the shared area
    assert a._s == "xy"
    g.copy(b, K.s8(R, "a much longer text"))  # needs a new area
    assert a._s == "xy" and b._s == "a much longer text"


def test_text_held_by_others_does_not_change():
    s = K.s8(R, "")
    for c in "abc":
        string_8.append_character(s, c)
    held = K.text(s)
    string_8.append_character(s, "d")
    sg.append_integer(s, 5)
    assert held == "abc" and s._s == "abcd5"


# --- Every external of the .e files has its function ----------------------------------------------

_DECL = re.compile(r"^\t((?:frozen\s+)?[a-z][a-z0-9_]*(?:\s*,\s*[a-z][a-z0-9_]*)*)\b")


def _python_externals(path):
    """{feature name: ...} for every `external "Python"` feature declared in the .e file."""
    names, current, lines = set(), None, path.read_text(encoding="utf-8").splitlines()
    in_features = False
    for i, line in enumerate(lines):
        if line.startswith("feature"):
            in_features = True
            continue
        if not in_features or line.startswith(("invariant", "end")):
            continue
        m = _DECL.match(line)
        if m and not line.startswith("\t\t"):
            current = [n.strip() for n in m.group(1).replace("frozen", "").split(",")]
        if line.strip() == "external" and current and lines[i + 1].strip() == '"Python"':
            names.update(current)
    return names


@pytest.mark.parametrize(
    "module",
    [
        "readable_string_general",
        "readable_string_8",
        "readable_string_32",
        "string_general",
        "string_8",
        "string_32",
        "immutable_string_8",
        "immutable_string_32",
    ],
)
def test_every_python_external_has_a_function(module):
    import importlib

    path = ROOT / "stdlib" / "base" / "string" / f"{module}.e"
    names = _python_externals(path)
    assert names, path
    ext = importlib.import_module(f"scoopc.kernel.ext.{module}")
    missing = sorted(n for n in names if not callable(getattr(ext, n, None)))
    assert not missing, f"{module}: {missing}"


def test_no_external_in_other_string_classes():
    for name in ("immutable_string_general", "string_8_iteration_cursor", "string_32_iteration_cursor"):
        assert not _python_externals(ROOT / "stdlib" / "base" / "string" / f"{name}.e")


def test_white_space_table_is_unicode_white_space():
    import sys

    wide = {chr(c) for c in range(128, sys.maxunicode + 1, 1) if chr(c).isspace()}
    assert wide == set(K.WS32) - set(K.WS8)
