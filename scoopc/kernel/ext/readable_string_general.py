"""READABLE_STRING_GENERAL's `external "Python"` features (stdlib/base/string/readable_string_general.e).

Bound for every string class (STRING_8/32, IMMUTABLE_STRING_8/32 and descendants); the storage
model is described in scoopc/kernel/strings.py. Characters are seen as CHARACTER_32 here: the
8-bit classes rename `item`, `has`, `index_of`, ... and give their own versions.
Indices are 1-based; preconditions are the Eiffel contracts' business.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

from . import _string_numbers as N

# --- Initialization ----------------------------------------------------------------------------


def make(current, n):
    """Empty, capacity n (a fresh area: a share group is left)."""
    K.leave_group(current)
    current._s = ""
    current._cap = n


# --- Access ------------------------------------------------------------------------------------


def code(current, i):
    if i < 1:  # refused (the caller reports `valid_index')
        raise IndexError(i)
    return ord(current._s[i - 1])


def index_of(current, c, start_index):
    return current._s.find(c, start_index - 1) + 1


def last_index_of(current, c, start_index_from_end):
    return current._s.rfind(c, 0, start_index_from_end) + 1


def substring_index(current, other, start_index):
    # ISE's searcher: an empty `other` is found at `start_index`, as str.find.
    return current._s.find(other._s, start_index - 1) + 1


def substring_index_in_bounds(current, other, start_pos, end_pos):
    return current._s.find(other._s, start_pos - 1, end_pos) + 1


def hash_code(current):
    """ISE's string hash, bit-identical (>= 0), cached for the current characters."""
    s = current._s
    if getattr(current, "_hk", None) is s:
        return current._hv
    h = K.ise_hash(s)
    current._hk = s
    current._hv = h
    return h


def case_insensitive_hash_code(current):
    """ISE: the hash of the characters mapped by CHARACTER_PROPERTY.to_lower (= as_lower.hash_code)."""
    return K.ise_hash(K.lower32(current._s))


# --- Measurement -------------------------------------------------------------------------------


def count(current):
    return len(current._s)


def capacity(current):
    return K.cap_of(current)


def occurrences(current, c):
    return current._s.count(c)


# --- Status report -----------------------------------------------------------------------------


def has(current, c):
    return c in current._s


def has_substring(current, other):
    return other._s in current._s


def starts_with(current, s):
    return current._s.startswith(s._s)


def ends_with(current, s):
    return current._s.endswith(s._s)


def is_whitespace(current):
    """Every character is a space (CHARACTER_8.is_space / CHARACTER_PROPERTY.is_space)."""
    return not current._s.lstrip(K.ws_of(current))


def is_boolean(current):
    s = current._s
    return len(s) in (4, 5) and s.isascii() and s.lower() in ("true", "false")


def is_integer(current):
    return N.is_int(current._s, "i32")


is_integer_32 = is_integer


def is_integer_8(current):
    return N.is_int(current._s, "i8")


def is_integer_16(current):
    return N.is_int(current._s, "i16")


def is_integer_64(current):
    return N.is_int(current._s, "i64")


def is_natural(current):
    return N.is_int(current._s, "n32")


is_natural_32 = is_natural


def is_natural_8(current):
    return N.is_int(current._s, "n8")


def is_natural_16(current):
    return N.is_int(current._s, "n16")


def is_natural_64(current):
    return N.is_int(current._s, "n64")


def is_real(current):
    return N.is_double(current._s)


is_real_32 = is_real


def is_double(current):
    return N.is_double(current._s)


is_real_64 = is_double


def is_number_sequence(current):
    return N.is_int(current._s, None)


def is_real_sequence(current):
    return N.is_double(current._s)


# --- Comparison --------------------------------------------------------------------------------


def is_equal(current, other):
    return current._s == other._s


def is_less(current, other):
    """Lexicographic order of character codes (ISE's str_strict_cmp)."""
    return current._s < other._s


def same_string(current, other):
    return current._s == other._s


def is_case_insensitive_equal(current, other):
    """Same characters up to CHARACTER_PROPERTY.to_lower (Unicode simple case mapping)."""
    a, b = current._s, other._s
    return len(a) == len(b) and (a == b or K.lower32(a) == K.lower32(b))


# --- Conversion --------------------------------------------------------------------------------


def as_string_8(current):
    """Current if it is a STRING_8, else a new STRING_8; codes beyond 255 become '%U'."""
    if K.conforms(current, "STRING_8"):
        return current
    return K.new_string_8(current._region_, K.to_8(current._s))


def as_string_32(current):
    """Current if it is a STRING_32, else a new STRING_32."""
    if K.conforms(current, "STRING_32"):
        return current
    return K.new_string_32(current._region_, current._s)


to_string_32 = as_string_32


def as_lower(current):
    """New string of Current's dynamic class (ISE: twin, then to_lower)."""
    return K.like(current, K.lower_of(current, current._s))


def as_upper(current):
    return K.like(current, K.upper_of(current, current._s))


def to_integer(current):
    return N.to_int(current._s, "i32")


to_integer_32 = to_integer


def to_integer_8(current):
    return N.to_int(current._s, "i8")


def to_integer_16(current):
    return N.to_int(current._s, "i16")


def to_integer_64(current):
    return N.to_int(current._s, "i64")


def to_natural(current):
    return N.to_int(current._s, "n32")


to_natural_32 = to_natural


def to_natural_8(current):
    return N.to_int(current._s, "n8")


def to_natural_16(current):
    return N.to_int(current._s, "n16")


def to_natural_64(current):
    return N.to_int(current._s, "n64")


def to_real(current):
    """`to_double.truncated_to_real` (rounded to single precision)."""
    return N.to_real_32(N.to_double(current._s))


to_real_32 = to_real


def to_double(current):
    return N.to_double(current._s)


to_real_64 = to_double


def to_boolean(current):
    return len(current._s) == 4


def mirrored(current):
    return K.like(current, current._s[::-1])


# --- Element change ----------------------------------------------------------------------------


def plus(current, s):
    """New string of Current's dynamic class: Current's characters then `s`'s (ISE gives a
    mutable result capacity count + s.count, an immutable one just the characters)."""
    t = s._s
    if K.is8(current) and not K.is8(s):
        t = K.to_8(t)
    return K.like(current, current._s + t)


# --- Duplication -------------------------------------------------------------------------------


def substring(current, start_index, end_index):
    """New string (Current's dynamic class) with positions start_index..end_index, empty
    unless 1 <= start_index <= end_index <= count."""
    s = current._s
    if 1 <= start_index <= end_index <= len(s):
        return K.like(current, s[start_index - 1 : end_index])
    return K.like(current, "")


def copy(current, other):
    """Make Current hold `other`'s characters. As ISE: when Current's old area is too small,
    is `other`'s, or Current is new (twin), Current gets an area of its own with capacity =
    count (so a twin never shares a buffer); otherwise the characters go into the old area,
    which stays shared with whoever shared it, and the capacity is kept."""
    if current is other:
        return
    s = other._s
    state = current.__dict__
    old = state.get("_cap")
    if old is None or old <= len(s) or state.get("_s") is s or K.in_group_with(current, other):
        # (a twin made by copying the fields first holds `other`'s very str: "old_area =
        # other.area" in ISE's terms)
        K.leave_group(current)
        current._s = s
        current._cap = len(s)
    else:
        K.set_text(current, s)


# --- Output ------------------------------------------------------------------------------------


def out(current):
    """New STRING_8: a copy of an 8-bit string's characters; a 32-bit string's UTF-8 encoding, as
    EiffelStudio's READABLE_STRING_32.out (UTF_CONVERTER.string_32_to_utf_8_string_8)."""
    s = current._s
    return K.new_string_8(current._region_, s if K.is8(current) else K.utf8_bytes(s))
