"""STRING_8's `external "Python"` features (stdlib/base/string/string_8.e).

STRING_32 binds the same functions (scoopc/kernel/ext/string_32.py) except the justifications,
whose notion of white space differs. Storage and capacity rules: scoopc/kernel/strings.py,
scoopc/kernel/ext/string_general.py.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

# --- Access ------------------------------------------------------------------------------------


def item(current, i):
    if i < 1:  # refused (the caller reports `valid_index')
        raise IndexError(i)
    return current._s[i - 1]


# --- Element change ----------------------------------------------------------------------------


def share(current, other):
    """From now on Current and `other` use one buffer: a change through either (count
    included) is seen by both, until one of them gets an area of its own again (make,
    make_from_string, set, copy of a longer string)."""
    K.share(current, other)


def put(current, c, i):
    s = current._s
    K.set_text(current, s[: i - 1] + c + s[i:])


def append(current, s):
    t = s._s
    if t:
        K.append_text(current, t, K.grown(K.cap_of(current), len(current._s) + len(t)))


def append_substring(current, s, start_index, end_index):
    if end_index - start_index + 1 > 0:
        t = s._s[start_index - 1 : end_index]
        K.append_text(current, t, K.grown(K.cap_of(current), len(current._s) + len(t)))


def append_character(current, c):
    """Append `c` (hot: one-character appends extend the str in place, see K.append_text)."""
    s = current._s
    n = len(s)
    cap = getattr(current, "_cap", 0)
    if n >= cap:
        current._cap = n + (cap // 2 if cap >= 10 else 5)
    current._s = ""
    s += c
    current._s = s
    if getattr(current, "_grp", None) is not None:
        K.sync_group(current)


extend = append_character


def prepend(current, s):
    """ISE: insert_string (s, 1)."""
    t = s._s
    if t:
        old = current._s
        K.set_text_cap(current, t + old, K.grown(K.cap_of(current), len(old) + len(t)))


def prepend_character(current, c):
    s = current._s
    n = len(s)
    cap = K.cap_of(current)
    if n >= cap:
        cap = n + (cap // 2 if cap >= 10 else 5)
    K.set_text_cap(current, c + s, cap)


precede = prepend_character


def insert_string(current, s, i):
    t = s._s
    if t:
        old = current._s
        cap = K.grown(K.cap_of(current), len(old) + len(t))
        K.set_text_cap(current, old[: i - 1] + t + old[i - 1 :], cap)


def insert_character(current, c, i):
    old = current._s
    cap = K.grown(K.cap_of(current), len(old) + 1)
    K.set_text_cap(current, old[: i - 1] + c + old[i - 1 :], cap)


def replace_substring(current, s, start_index, end_index):
    """Positions start_index..end_index replaced by `s` (ISE: grow (new count) when longer)."""
    old = current._s
    new = old[: start_index - 1] + s._s + old[end_index:]
    cap = K.cap_of(current)
    K.set_text_cap(current, new, len(new) if len(new) > cap else cap)


def replace_substring_all(current, original, new):
    """Every occurrence of `original` (non-overlapping, left to right) replaced by `new`. ISE
    reallocates to exactly the new count when the string grows and there was an occurrence."""
    old = current._s
    o, n = original._s, new._s
    if not old or o not in old:
        return
    result = old.replace(o, n)
    cap = K.cap_of(current)
    K.set_text_cap(current, result, len(result) if len(n) > len(o) else cap)


def set(current, t, n1, n2):
    """Current's characters := t.substring (n1, n2) (an area of its own, capacity = count)."""
    s = t._s
    sub = s[n1 - 1 : n2] if 1 <= n1 <= n2 <= len(s) else ""
    K.leave_group(current)
    current._s = sub
    current._cap = len(sub)


def fill_with(current, c):
    n = len(current._s)
    if n:
        K.set_text(current, c * n)


def fill_character(current, c):
    """Fill up to `capacity` with `c` (count := capacity)."""
    cap = K.cap_of(current)
    if cap:
        K.set_text_cap(current, c * cap, cap)


def _left_justify(current, ws):
    s = current._s
    t = s.lstrip(ws)
    if len(t) < len(s):
        K.set_text(current, t + " " * (len(s) - len(t)))


def _right_justify(current, ws):
    s = current._s
    t = s.rstrip(ws)
    if len(t) < len(s):
        K.set_text(current, " " * (len(s) - len(t)) + t)


def _center_justify(current, ws):
    """ISE's algorithm, including which white space characters it keeps or blanks."""
    s = current._s
    nb = len(s)
    left = nb - len(s.lstrip(ws))
    right = nb - len(s.rstrip(ws))
    total = left + right
    offset = left - total // 2 if total % 2 == 0 else left - total // 2 - 1
    if offset == 0:
        return
    a = list(s)
    core = nb - left - right
    a[left - offset : left - offset + core] = s[left : left + core]
    if offset < 0:
        a[left : left - offset] = " " * (-offset)
    else:
        a[nb - right - offset : nb] = " " * (right + offset)
    K.set_text(current, "".join(a))


def left_justify(current):
    """Leading white space (CHARACTER_8.is_space) moved after the characters, as blanks."""
    _left_justify(current, K.WS8)


def right_justify(current):
    _right_justify(current, K.WS8)


def center_justify(current):
    _center_justify(current, K.WS8)


# --- Removal -----------------------------------------------------------------------------------


def prune(current, c):
    s = current._s
    i = s.find(c)
    if i >= 0:
        K.set_text(current, s[:i] + s[i + 1 :])


def prune_all(current, c):
    s = current._s
    if c in s:
        K.set_text(current, s.replace(c, ""))


def prune_all_leading(current, c):
    s = current._s
    t = s.lstrip(c)
    if len(t) != len(s):
        K.set_text(current, t)


def prune_all_trailing(current, c):
    s = current._s
    t = s.rstrip(c)
    if len(t) != len(s):
        K.set_text(current, t)
