"""READABLE_STRING_32's `external "Python"` features (stdlib/base/string/readable_string_32.e).

Bound for STRING_32 and IMMUTABLE_STRING_32 (and descendants). Characters are CHARACTER_32
(one-character Python strs). Storage: scoopc/kernel/strings.py.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

# --- Initialization ----------------------------------------------------------------------------


def make_filled(current, c, n):
    """`n` copies of `c`, capacity n."""
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


def make_from_string_general(current, s):
    """A copy of the characters of any string."""
    make_from_string(current, s)


def make_from_separate(current, other):
    """A copy of the characters of `other` (any string), which may belong to another region."""
    K.leave_group(current)
    t = other._s
    current._s = t
    current._cap = len(t)


# --- Status report -----------------------------------------------------------------------------


def is_valid_as_string_8(current):
    s = current._s
    if s.isascii():
        return True
    try:
        s.encode("latin-1")
        return True
    except UnicodeEncodeError:
        return False


def starts_with(current, s):
    return current._s.startswith(s._s)


def ends_with(current, s):
    return current._s.endswith(s._s)


# --- Comparison --------------------------------------------------------------------------------


def same_string(current, other):
    return current._s == other._s


def is_case_insensitive_equal(current, other):
    """Same characters up to CHARACTER_PROPERTY.to_lower (Unicode simple case mapping)."""
    a, b = current._s, other._s
    return len(a) == len(b) and (a == b or K.lower32(a) == K.lower32(b))
