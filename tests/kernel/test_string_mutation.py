"""STRING_GENERAL's, STRING_8's and STRING_32's modifications (scoopc/kernel/ext/string_general.py,
string_8.py, string_32.py), with EiffelBase's capacities."""

import pytest

from scoopc.kernel import strings as K
from scoopc.kernel.ext import (
    immutable_string_32,
    readable_string_32 as r32,
    readable_string_general as g,
    string_8,
    string_32,
    string_general as sg,
)

from string_fakes import S8, S32, R, created, ise_hash_reference, registered


@pytest.fixture(autouse=True)
def fake_classes():
    with registered():
        yield


# --- STRING_GENERAL ------------------------------------------------------------------------------


def test_append_family_and_capacity():
    s = created(S8, g.make, 0)
    caps = []
    for c in "abcdefghijklmnopqrstuvw":
        string_8.append_character(s, c)
        caps.append(s.capacity)
    assert s._s == "abcdefghijklmnopqrstuvw"
    assert caps[:6] == [5, 5, 5, 5, 5, 10] and caps[10] == 15 and caps[15] == 22 and caps[22] == 33
    t = created(S8, g.make, 4)
    string_8.append(t, K.s8(R, "abcdef"))  # 6 > 4: 6 + max (4 // 2, 5)
    assert t.capacity == 11
    sg.append(t, K.s32(R, "gh"))
    assert t._s == "abcdefgh" and t.capacity == 11
    sg.append(t, K.s32(R, "\u20ac"))  # precondition violated: '%U'
    assert t._s.endswith("\x00")
    u = created(S32, g.make, 0)
    sg.append(u, K.s32(R, "\u20ac"))
    string_32.append_character(u, "\u0101")
    string_32.extend(u, "!")
    assert u._s == "\u20ac\u0101!"
    string_8.append_substring(t, K.s8(R, "0123456"), 2, 4)
    assert t._s.endswith("123")
    string_8.append_substring(t, K.s8(R, "0123456"), 3, 2)
    assert t._s.endswith("123")


def test_numbers_and_booleans_appended():
    s = K.s8(R, "")
    sg.append_integer(s, -2147483648)
    sg.append_natural_64(s, 18446744073709551615)
    sg.append_boolean(s, True)
    sg.append_integer_8(s, -5)
    sg.append_code(s, 65)
    assert s._s == "-214748364818446744073709551615True-5A"
    r = K.s8(R, "")
    sg.append_double(r, 1.5)
    sg.append_real(r, 0.25)
    assert r._s == "1.50.25"
    n = created(S8, g.make, 0)
    sg.append_integer(n, 123456)  # character by character as ISE
    assert n.capacity == 10


def test_prepend_insert_replace():
    s = K.s8(R, "world")
    sg.prepend(s, K.s32(R, "hello "))
    assert s._s == "hello world"
    string_8.prepend(s, K.s8(R, ">"))
    string_8.prepend_character(s, "[")
    string_8.precede(s, "(")
    assert s._s == "([>hello world"
    string_8.insert_string(s, K.s8(R, "__"), 4)
    assert s._s == "([>__hello world"
    string_8.insert_character(s, "!", s.count + 1)
    assert s._s.endswith("world!")
    string_8.replace_substring(s, K.s8(R, "HELLO"), 6, 10)
    assert s._s == "([>__HELLO world!"
    string_8.replace_substring(s, K.s8(R, ""), 1, 5)
    assert s._s == "HELLO world!"
    string_8.replace_substring_all(s, K.s8(R, "l"), K.s8(R, "LL"))
    assert s._s == "HELLO worLLd!" and s.capacity == s.count
    string_8.replace_substring_all(s, K.s8(R, "LL"), K.s8(R, "l"))
    assert s._s == "HElO world!"
    a = K.s8(R, "aaa")
    string_8.replace_substring_all(a, K.s8(R, "aa"), K.s8(R, "b"))
    assert a._s == "ba"
    sg.put_code(a, 0x63, 1)
    assert a._s == "ca"


def test_removals():
    s = K.s8(R, "abcdefgh")
    sg.remove(s, 1)
    assert s._s == "bcdefgh"
    sg.remove_head(s, 2)
    assert s._s == "defgh"
    sg.remove_tail(s, 1)
    assert s._s == "defg"
    sg.remove_substring(s, 2, 3)
    assert s._s == "dg"
    sg.remove_substring(s, 2, 1)
    assert s._s == "dg"
    sg.remove_head(s, 10)
    assert s._s == ""
    t = K.s8(R, "xyz")
    sg.remove_tail(t, 5)
    assert t._s == ""
    k = K.s8(R, "abcdef")
    sg.keep_head(k, 4)
    sg.keep_tail(k, 3)
    assert k._s == "bcd"
    sg.keep_tail(k, 0)
    assert k._s == ""
    p = K.s8(R, "xxaxbxx")
    string_8.prune(p, "x")
    assert p._s == "xaxbxx"
    string_8.prune_all_leading(p, "x")
    string_8.prune_all_trailing(p, "x")
    assert p._s == "axb"
    string_8.prune_all(p, "x")
    assert p._s == "ab"
    string_8.prune(p, "z")
    assert p._s == "ab"


def test_adjust_and_justify():
    s = K.s8(R, " \t hi \xa0\n")
    sg.left_adjust(s)
    sg.right_adjust(s)
    assert s._s == "hi \xa0"  # NBSP is not CHARACTER_8.is_space
    w = K.s32(R, "\u3000 hi \xa0\n")
    sg.left_adjust(w)
    sg.right_adjust(w)
    assert w._s == "hi"
    j = K.s8(R, "  ab")
    string_8.left_justify(j)
    assert j._s == "ab  "
    string_8.right_justify(j)
    assert j._s == "  ab"
    for text, expected in (
        ("ab   ", "  ab "),
        ("   ab", "  ab "),
        ("ab", "ab"),
        ("  ab  ", "  ab  "),
        ("\tab", "\tab"),
        ("ab\t\t", " ab\t"),
        ("   ", "   "),
        ("", ""),
    ):
        c = K.s8(R, text)
        string_8.center_justify(c)
        assert c._s == expected, text
    c32 = K.s32(R, "\u3000\u3000ab")
    string_32.center_justify(c32)
    assert c32._s == "\u3000ab "
    string_32.left_justify(c32)
    assert c32._s == "ab  "
    string_32.right_justify(c32)
    assert c32._s == "  ab"


def test_fill_multiply_set_count_resize():
    s = created(S8, g.make, 4)
    string_8.fill_character(s, "*")
    assert s._s == "****"
    string_8.fill_with(s, "-")
    assert s._s == "----"
    sg.wipe_out(s)
    assert s._s == "" and s.capacity == 4
    sg.set_count(s, 3)
    assert s._s == "\x00\x00\x00"
    sg.set_count(s, 1)
    assert s._s == "\x00"
    m = K.s8(R, "ab")
    sg.multiply(m, 3)
    assert m._s == "ababab" and m.capacity == 6
    sg.mirror(m)
    assert m._s == "bababa"
    sg.resize(m, 20)
    assert m.capacity == 20
    sg.grow(m, 10)
    assert m.capacity == 20
    sg.grow(m, 30)
    assert m.capacity == 30
    sg.trim(m)
    assert m.capacity == 6
    f = created(S32, r32.make_filled, "\u0101", 0)
    string_32.fill_character(f, "x")
    assert f._s == ""


def test_set_and_item_put_32():
    s = K.s32(R, "old")
    string_32.set(s, K.s32(R, "\u20acuros"), 1, 4)
    assert s._s == "\u20acuro" and s.capacity == 4
    string_32.set(s, K.s32(R, "abc"), 3, 1)
    assert s._s == ""
    t = K.s32(R, "abc")
    string_32.put(t, "\u0101", 2)
    assert t.item(2) == "\u0101" and immutable_string_32.item(K.new_immutable_32(R, "q"), 1) == "q"


def test_codegen_style_binding():
    s = K.s8(R, "abc")
    s.put("X", 1)
    s.append(K.s8(R, "d"))
    assert (s.item(1), s.count, s.capacity) == ("X", 4, 9)
    assert s.is_equal(K.s8(R, "Xbcd")) and s.hash_code == ise_hash_reference("Xbcd")


def test_a_string_appended_or_inserted_into_itself():
    s = K.s8(R, "ab")
    string_8.append(s, s)
    assert s._s == "abab"
    string_8.prepend(s, s)
    assert s._s == "abababab"
    string_8.insert_string(s, K.s8(R, "|"), 5)
    string_8.append_substring(s, s, 1, 2)
    assert s._s == "abab|ababab"
    sg.append(s, s)
    assert s._s == "abab|ababab" * 2
