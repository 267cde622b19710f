"""READABLE_STRING_8's `external "Python"` features (stdlib/base/string/readable_string_8.e).

Bound for STRING_8 and IMMUTABLE_STRING_8 (and descendants). Characters are CHARACTER_8
(one-character Python strs with code <= 255). Storage: scoopc/kernel/strings.py.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

# --- Initialization ----------------------------------------------------------------------------


def make_filled(current, c, n):
    """`n` copies of `c`, capacity n (ISE: make (n); fill_character (c))."""
    K.leave_group(current)
    current._s = c * n
    current._cap = n


def make_from_string(current, s):
    """A copy of `s`'s characters, capacity = count (nothing happens when `s` is Current)."""
    if s is current:
        return
    K.leave_group(current)
    t = s._s
    current._s = t
    current._cap = len(t)


def make_from_separate(current, other):
    """A copy of the characters of `other`, which may belong to another region (the caller
    holds it: reading its characters is safe)."""
    K.leave_group(current)
    t = K.to_8(other._s)
    current._s = t
    current._cap = len(t)


# --- Access ------------------------------------------------------------------------------------


def character_32_item(current, i):
    return current._s[i - 1]


def index_of(current, c, start_index):
    return current._s.find(c, start_index - 1) + 1


def last_index_of(current, c, start_index_from_end):
    return current._s.rfind(c, 0, start_index_from_end) + 1


# --- Measurement -------------------------------------------------------------------------------


def occurrences(current, c):
    return current._s.count(c)


# --- Status report -----------------------------------------------------------------------------


def has(current, c):
    return c in current._s


def starts_with(current, s):
    return current._s.startswith(s._s)


def ends_with(current, s):
    return current._s.endswith(s._s)


# --- Comparison --------------------------------------------------------------------------------


def same_string(current, other):
    return current._s == other._s


def is_case_insensitive_equal(current, other):
    """Same characters up to CHARACTER_8.as_lower (ASCII and Latin-1 letters)."""
    a, b = current._s, other._s
    return len(a) == len(b) and (a == b or K.lower8(a) == K.lower8(b))
