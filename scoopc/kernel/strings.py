"""String objects at run time: construction helpers and the storage model shared by the
`external "Python"` features of the string classes (scoopc/kernel/ext/*string*.py).

Storage model (every STRING_8, STRING_32, IMMUTABLE_STRING_8, IMMUTABLE_STRING_32 object):
- `_s`   : a Python `str`, exactly the characters (`count` = len(_s)); never mutated in place by
           anyone who can observe it (see `append_text`), so reading `_s` is one attribute load.
           An 8-bit string's characters are bytes (codes 0..255), as EiffelStudio's: text from
           outside (a UTF-8 source's manifest string, a file, the console, a ROS message) is
           kept as its UTF-8 bytes, so `"é"` has count 2, and output writes those bytes as they
           are (`utf8_bytes` in, `shown` out). A 32-bit string's characters are code points.
- `_cap` : `capacity`, kept as EiffelBase computes it (make (n) gives n, appends grow by
           `max (capacity // 2, 5)`, `resize`/`grow`/`trim` set it); always >= len(_s) when read
           through `capacity`.
- `_grp` : only on strings that took part in `share`: the Python list of the objects that use one
           buffer. Every mutation of a member writes `_s`/`_cap` through to all members
           (`set_text`), so a change through either is seen by both, `count` included
           (codegen_spec.md; EiffelBase shares the area but not `count`). A copy of the object
           made outside this module (standard_twin, deep_twin copying the instance dictionary)
           may carry a `_grp` it is not a member of: membership is checked by identity and such
           a stale link is dropped on the first mutation, so a twin never writes into the group.
- `_hk`, `_hv`: cache of `hash_code` (`_hk` is the `_s` it was computed for).
Immutable strings only have `_s` and `_cap`.
"""

from __future__ import annotations

from . import CLASSES

# ---------------------------------------------------------------------------------------------
# Construction


def _new(key, region, text, cap=None):
    pycls = CLASSES[key]
    obj = pycls.__new__(pycls)
    obj._region_ = region
    obj._s = text
    obj._cap = len(text) if cap is None else cap
    return obj


def new_string_8(region, text, cap=None):
    """A new STRING_8 in `region` holding `text` (capacity `cap`, default len(text))."""
    return _new("STRING_8", region, text, cap)


def new_string_32(region, text, cap=None):
    """A new STRING_32 in `region` holding `text`."""
    return _new("STRING_32", region, text, cap)


def new_immutable_8(region, text, cap=None):
    """A new IMMUTABLE_STRING_8 in `region` holding `text`."""
    return _new("IMMUTABLE_STRING_8", region, text, cap)


def new_immutable_32(region, text, cap=None):
    """A new IMMUTABLE_STRING_32 in `region` holding `text`."""
    return _new("IMMUTABLE_STRING_32", region, text, cap)


def s8(region, text):
    """Manifest STRING_8 (generated code: `K.s8(here, "abc")`); capacity = count, as ISE."""
    pycls = CLASSES["STRING_8"]
    obj = pycls.__new__(pycls)
    obj._region_ = region
    obj._s = text
    obj._cap = len(text)
    return obj


def s32(region, text):
    """Manifest STRING_32."""
    pycls = CLASSES["STRING_32"]
    obj = pycls.__new__(pycls)
    obj._region_ = region
    obj._s = text
    obj._cap = len(text)
    return obj


def text(obj) -> str:
    """The characters of any string object, each code as a Python character (a STRING_8's
    bytes as U+0000..U+00FF): EiffelBase's view of a READABLE_STRING_GENERAL as "a sequence of
    Unicode characters" (PATH.make_from_string: file names, environment variables)."""
    return obj._s


def utf8_bytes(t: str) -> str:
    """Python text as an 8-bit string holds it: its UTF-8 bytes, one character each (what
    EiffelStudio's scanner keeps of a manifest string, EIFFEL_SCANNER_SKELETON's
    `append_code_point_to_utf8`). Bytes smuggled in as surrogates (surrogateescape) are
    restored; a lone surrogate code is encoded as EiffelStudio does, in three bytes."""
    if t.isascii():
        return t
    try:
        return t.encode("utf-8").decode("latin-1")
    except UnicodeEncodeError:  # surrogates
        return _mixed(t)


def _mixed(t: str) -> str:
    out = []
    for c in t:
        code = ord(c)
        if 0xDC80 <= code <= 0xDCFF:  # a byte that was not UTF-8 (surrogateescape)
            out.append(chr(code - 0xDC00))
        else:
            out.append(c.encode("utf-8", "surrogatepass").decode("latin-1"))
    return "".join(out)


def bytes_text(s: str) -> str:
    """The Python text of 8-bit characters read as UTF-8 bytes; a byte that is no part of a
    UTF-8 sequence becomes a surrogate (surrogateescape), so `utf8_bytes` and the output
    streams (scoopc.runtime.output) give the same bytes back. A character beyond 255 (none
    should be in an 8-bit string) is kept as it is."""
    if s.isascii():
        return s
    try:
        data = s.encode("latin-1")
    except UnicodeEncodeError:
        return s
    return data.decode("utf-8", "surrogateescape")


def raw_bytes(s: str) -> bytes:
    """The bytes of 8-bit characters, for a file or a C external (a character beyond 255,
    which no 8-bit string should hold, as its UTF-8 bytes)."""
    try:
        return s.encode("latin-1")
    except UnicodeEncodeError:
        return b"".join(c.encode("latin-1") if c <= "\xff" else c.encode("utf-8", "surrogatepass") for c in s)


def shown(obj) -> str:
    """The Python text that writing `obj` shows: an 8-bit string's bytes read as UTF-8, a
    32-bit string's characters (for messages: exception descriptions, names of ROS topics)."""
    s = obj._s
    if s.isascii():
        return s
    return bytes_text(s) if is8(obj) else s


def new_string_8_of(region, t: str):
    """A new STRING_8 holding Python text `t` as its UTF-8 bytes."""
    return _new("STRING_8", region, utf8_bytes(t))


def like(cur, s, cap=None):
    """A new object of `cur`'s dynamic class (`like Current`) in `cur`'s region."""
    pycls = type(cur)
    obj = pycls.__new__(pycls)
    obj._region_ = cur._region_
    obj._s = s
    obj._cap = len(s) if cap is None else cap
    return obj


# ---------------------------------------------------------------------------------------------
# Kinds (8-bit or 32-bit characters; conformance to STRING_8 / STRING_32)

_KIND8: dict = {}


def is8(obj) -> bool:
    """Is `obj` a READABLE_STRING_8 (characters are CHARACTER_8)? Cached per Python class."""
    kind = type(obj)
    found = _KIND8.get(kind)
    if found is None:
        conforms = getattr(kind, "_conforms_", None)
        if conforms is not None:
            found = bool({"READABLE_STRING_8", "STRING_8", "IMMUTABLE_STRING_8"} & set(conforms))
        else:
            found = bool(getattr(obj, "is_string_8", False))
        _KIND8[kind] = found
    return found


def conforms(obj, key) -> bool:
    """Does `obj`'s dynamic class conform to the class `key` ("STRING_8", ...)?"""
    kind = type(obj)
    found = getattr(kind, "_conforms_", None)
    if found is not None:
        return key in found
    return kind is CLASSES.get(key)


def to_8(s: str) -> str:
    """`s` with every character beyond 255 replaced by the null character (as `as_string_8`)."""
    try:
        s.encode("latin-1")
        return s
    except UnicodeEncodeError:
        return "".join(c if ord(c) < 256 else "\x00" for c in s)


# ---------------------------------------------------------------------------------------------
# Mutation (write-through to a share group) and capacity


def sync_group(cur):
    group = cur._grp
    for member in group:
        if member is cur:
            break
    else:  # stale link copied by a twin: not a member, never write into the group
        cur._grp = None
        return
    s = cur._s
    cap = cur._cap
    for member in group:
        if member is not cur:
            member._s = s
            member._cap = cap


def set_text(cur, s):
    """Make `cur` hold `s` (capacity unchanged unless set before)."""
    cur._s = s
    if getattr(cur, "_grp", None) is not None:
        sync_group(cur)


def set_text_cap(cur, s, cap):
    cur._cap = cap
    cur._s = s
    if getattr(cur, "_grp", None) is not None:
        sync_group(cur)


def cap_of(cur) -> int:
    cap = getattr(cur, "_cap", 0)
    n = len(cur._s)
    return cap if cap >= n else n


def grown(cap, new_count):
    """Capacity after EiffelBase's `if new > capacity then resize (new + additional_space)`."""
    if new_count > cap:
        return new_count + (cap // 2 if cap >= 10 else 5)
    return cap


def grown_by_chars(cap, count, k):
    """Capacity after `k` calls of `append_character` (`if count = capacity then
    resize (count + additional_space)`)."""
    for _ in range(k):
        if count >= cap:
            cap = count + (cap // 2 if cap >= 10 else 5)
        count += 1
    return cap


def append_text(cur, t, cap):
    """Append `t` to `cur` with new capacity `cap`. The attribute is cleared while appending so
    that, when nobody else holds the str, CPython extends it in place (linear-time loops of
    `append_character`); anyone holding it keeps an unchanged value (CPython copies then)."""
    cur._cap = cap
    s = cur._s
    cur._s = ""
    s += t
    cur._s = s
    if getattr(cur, "_grp", None) is not None:
        sync_group(cur)


def leave_group(cur):
    """`cur` gets a buffer of its own again (make, set, copy into a fresh area)."""
    group = getattr(cur, "_grp", None)
    if group is None:
        return
    cur._grp = None
    for i, member in enumerate(group):
        if member is cur:
            del group[i]
            if len(group) == 1:  # the last one left alone: an ordinary string again
                group[0]._grp = None
                group.clear()
            return


def share(cur, other):
    """`cur` and `other` use one buffer from now on."""
    if cur is other:
        return
    leave_group(cur)
    group = getattr(other, "_grp", None)
    if group is None or not any(m is other for m in group):
        group = [other]
        other._grp = group
    group.append(cur)
    cur._grp = group
    cur._s = other._s
    cur._cap = cap_of(other)


def in_group_with(cur, other) -> bool:
    group = getattr(cur, "_grp", None)
    return group is not None and group is getattr(other, "_grp", None)


# ---------------------------------------------------------------------------------------------
# Characters: case mappings and white space as EiffelBase

# CHARACTER_8 `as_lower`/`as_upper` (Latin-1 tables of EiffelBase's CHARACTER_8_REF): A-Z and
# U+00C0..U+00DE except U+00D7 have a lower case 32 codes further; ÿ, ß, µ stay unchanged.
LOWER8 = {c: c + 32 for c in list(range(0x41, 0x5B)) + list(range(0xC0, 0xDF)) if c != 0xD7}
UPPER8 = {c: c - 32 for c in list(range(0x61, 0x7B)) + list(range(0xE0, 0xFF)) if c != 0xF7}
# CHARACTER_8 `is_space`; CHARACTER_32 (CHARACTER_PROPERTY.is_space) adds Unicode White_Space.
WS8 = " \t\n\x0b\x0c\r"
WS32 = (
    WS8 + "\x85\xa0\u1680\u2000\u2001\u2002\u2003\u2004\u2005\u2006\u2007\u2008\u2009\u200a"
    "\u2028\u2029\u202f\u205f\u3000"
)

_LOWER32: dict = {}
_UPPER32: dict = {}


def _lower_char(c):
    found = _LOWER32.get(c)
    if found is None:
        low = c.lower()
        if len(low) != 1:  # U+0130: simple lower case mapping is 'i'
            low = "i" if c == "\u0130" else c
        found = _LOWER32[c] = low
    return found


def _upper_char(c):
    found = _UPPER32.get(c)
    if found is None:
        up = c.upper()
        if len(up) != 1:  # only a full (multi-character) mapping: the simple one is
            title = c.title()  # the title case when that is one character, else none
            up = title if len(title) == 1 else c
        found = _UPPER32[c] = up
    return found


def lower8(s):
    return s.lower() if s.isascii() else s.translate(LOWER8)


def upper8(s):
    return s.upper() if s.isascii() else s.translate(UPPER8)


def lower32(s):
    """Unicode simple lower case mapping, character by character (no Final_Sigma rule)."""
    return s.lower() if s.isascii() else "".join(map(_lower_char, s))


def upper32(s):
    return s.upper() if s.isascii() else "".join(map(_upper_char, s))


def lower_of(cur, s):
    return lower8(s) if is8(cur) else lower32(s)


def upper_of(cur, s):
    return upper8(s) if is8(cur) else upper32(s)


def ws_of(cur):
    return WS8 if is8(cur) else WS32


# ---------------------------------------------------------------------------------------------
# ISE's hash: Result := ((Result \\ 8388593) |<< 8) + item (i).code over the characters, in
# INTEGER_32 arithmetic. With codes <= 255 it never overflows, and it equals
# ((P mod 8388593) << 8) + last code where P is all characters but the last read as a base-256
# number, which Python computes in C.

_PRIME = 8388593


def ise_hash(s: str) -> int:
    try:
        b = s.encode("latin-1")
    except UnicodeEncodeError:
        return _ise_hash_wide(s)
    if not b:
        return 0
    return ((int.from_bytes(b[:-1], "big") % _PRIME) << 8) + b[-1]


def _ise_hash_wide(s):
    """Characters beyond 255: emulate INTEGER_32 wrap-around and C remainders exactly."""
    h = 0
    for c in s:
        r = h % _PRIME if h >= 0 else -((-h) % _PRIME)
        h = ((r << 8) + ord(c)) & 0xFFFFFFFF
        if h >= 0x80000000:
            h -= 0x100000000
    # ISE can end negative here (its postcondition `Result >= 0` would fail): keep HASHABLE's
    # contract by clearing the sign bit.
    return h & 0x7FFFFFFF


# ---------------------------------------------------------------------------------------------
# Output of reals for `append_real`/`append_double`: the basic types' `out` texts
# (scoopc/kernel/basic.py r32_text/r64_text); the classic ISE runtime's c_outr32 ("%g") and
# c_outr64 ("%.17g") if that module is not there.


def real_32_out(r) -> str:
    try:
        from .basic import r32_text  # deferred: optional (its absence is handled below)
    except ImportError:
        return "%g" % r
    return r32_text(r)


def real_64_out(d) -> str:
    try:
        from .basic import r64_text  # deferred: optional (its absence is handled below)
    except ImportError:
        return "%.17g" % d
    return r64_text(d)
