"""STRING_GENERAL's `external "Python"` features (stdlib/base/string/string_general.e): the
modifications common to STRING_8 and STRING_32 (and descendants).

Capacities follow EiffelBase's STRING_8/STRING_32: appending beyond `capacity` resizes to
new count + max (capacity // 2, 5); numbers are appended character by character as ISE does
(`append_character` grows to count + max (capacity // 2, 5) when full). Every change goes
through scoopc/kernel/strings.py (`set_text`, `append_text`) so that strings that `share`
see it.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

# --- Element change ----------------------------------------------------------------------------


def append(current, s):
    """Append the characters of any string (STRING_8: codes beyond 255 would violate the
    precondition; they become '%U')."""
    t = s._s
    if t:
        if K.is8(current) and not K.is8(s):
            t = K.to_8(t)
        cap = K.grown(K.cap_of(current), len(current._s) + len(t))
        K.append_text(current, t, cap)


def prepend(current, s):
    t = s._s
    if t:
        if K.is8(current) and not K.is8(s):
            t = K.to_8(t)
        old = current._s
        K.set_text_cap(current, t + old, K.grown(K.cap_of(current), len(old) + len(t)))


def append_code(current, c):
    """Append the character of code `c` (ISE: append_character)."""
    n = len(current._s)
    K.append_text(current, chr(c), K.grown_by_chars(K.cap_of(current), n, 1))


def put_code(current, v, i):
    s = current._s
    K.set_text(current, s[: i - 1] + chr(v) + s[i:])


def _append_digits(current, t):
    n = len(current._s)
    K.append_text(current, t, K.grown_by_chars(K.cap_of(current), n, len(t)))


def append_integer(current, i):
    _append_digits(current, str(i))


append_integer_8 = append_integer
append_integer_16 = append_integer
append_integer_64 = append_integer
append_natural_8 = append_integer
append_natural_16 = append_integer
append_natural_32 = append_integer
append_natural_64 = append_integer


def _append_out(current, t):
    cap = K.grown(K.cap_of(current), len(current._s) + len(t))
    K.append_text(current, t, cap)


def append_real(current, r):
    """Append `r.out` (K.real_32_out)."""
    _append_out(current, K.real_32_out(r))


def append_double(current, d):
    """Append `d.out` (K.real_64_out)."""
    _append_out(current, K.real_64_out(d))


def append_boolean(current, b):
    _append_out(current, "True" if b else "False")


def keep_head(current, n):
    s = current._s
    if n < len(s):
        K.set_text(current, s[:n])


def keep_tail(current, n):
    s = current._s
    if n < len(s):
        K.set_text(current, s[len(s) - n :])


def left_adjust(current):
    """Remove the leading white space (CHARACTER_8.is_space / CHARACTER_PROPERTY.is_space)."""
    s = current._s
    t = s.lstrip(K.ws_of(current))
    if len(t) != len(s):
        K.set_text(current, t)


def right_adjust(current):
    s = current._s
    t = s.rstrip(K.ws_of(current))
    if len(t) != len(s):
        K.set_text(current, t)


def to_lower(current):
    K.set_text(current, K.lower_of(current, current._s))


def to_upper(current):
    K.set_text(current, K.upper_of(current, current._s))


def mirror(current):
    K.set_text(current, current._s[::-1])


def multiply(current, n):
    """The characters n times (ISE: grow (n * count), then append)."""
    s = current._s
    K.set_text_cap(current, s * n, max(K.cap_of(current), n * len(s)))


def set_count(current, number):
    """`number` characters: cut, or extended with null characters."""
    s = current._s
    if number <= len(s):
        K.set_text(current, s[:number])
    else:
        K.set_text(current, s + "\x00" * (number - len(s)))


# --- Removal -----------------------------------------------------------------------------------


def remove(current, i):
    s = current._s
    K.set_text(current, s[: i - 1] + s[i:])


def remove_head(current, n):
    s = current._s
    K.set_text(current, s[n:] if n < len(s) else "")


def remove_tail(current, n):
    s = current._s
    K.set_text(current, s[: len(s) - n] if n < len(s) else "")


def remove_substring(current, start_index, end_index):
    if end_index - start_index + 1 > 0:
        s = current._s
        K.set_text(current, s[: start_index - 1] + s[end_index:])


def wipe_out(current):
    K.set_text(current, "")


# --- Resizing ----------------------------------------------------------------------------------


def resize(current, newsize):
    """Capacity := newsize (ISE's aliased_resized_area; never below count)."""
    s = current._s
    K.set_text_cap(current, s, max(newsize, len(s)))


def grow(current, newsize):
    if newsize > K.cap_of(current):
        K.set_text_cap(current, current._s, newsize)


def trim(current):
    s = current._s
    K.set_text_cap(current, s, len(s))
