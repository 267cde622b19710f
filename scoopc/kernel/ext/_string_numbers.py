"""Numbers in strings as EiffelBase reads them (STRING_TO_INTEGER_CONVERTOR,
INTEGER_OVERFLOW_CHECKER, STRING_TO_REAL_CONVERTOR, set up as READABLE_STRING_GENERAL's
`ctoi_convertor`/`ctor_convertor`: blanks (' ' only) accepted before and after).

Integers: [' '*] ['+'|'-'] digit+ [' '*], digits '0'..'9' only, no blank after the sign.
Ranges are checked digit by digit in NATURAL_64 arithmetic (wrapping), as ISE does; the fast
path (at most 18 digits, where nothing can wrap) gives the same answers.

Reals: the convertor's state machine, including its quirks ("1e" and "1e+" are valid doubles,
".5" and "5." are, "." and "1.5e" are not; no range check for `is_real`), and its arithmetic
(natural part accumulated in REAL_64, fraction / divider, times 10.0 ^ exponent).
"""

from __future__ import annotations

import re
import struct

_M64 = (1 << 64) - 1
_INT_RE = re.compile(r" *([+-]?)([0-9]+) *\Z")

# kind -> (signed, bits)
KINDS = {
    "i8": (True, 8),
    "i16": (True, 16),
    "i32": (True, 32),
    "i64": (True, 64),
    "n8": (False, 8),
    "n16": (False, 16),
    "n32": (False, 32),
    "n64": (False, 64),
}


def _limits(signed, bits):
    """INTEGER_OVERFLOW_CHECKER's (part1, part2) bounds for sign 0 and sign 1 (Eiffel `//`
    and `\\\\` truncate toward zero)."""
    if signed:
        top = (1 << (bits - 1)) - 1
        low = 1 << (bits - 1)  # -(min_value)
        return (top // 10, top % 10), (low // 10, low % 10)
    top = (1 << bits) - 1
    return (top // 10, top % 10), None


_LIMITS = {kind: _limits(*spec) for kind, spec in KINDS.items()}


def _will_overflow(part1, part2, kind, sign):
    positive, negative = _LIMITS[kind]
    if negative is None:  # natural
        if sign == 1:
            return part1 > 0 or part2 > 0
        s1, s2 = positive
    else:
        s1, s2 = negative if sign == 1 else positive
    return part1 > s1 or (part1 == s1 and part2 > s2)


def _int_machine(s, kind):
    """STRING_TO_INTEGER_CONVERTOR.parse_string_with_type; kind None = no limitation.
    Returns (integral, sign, part1, part2)."""
    state = 0
    part1 = part2 = 0
    sign = 0
    overflowed = False
    for ch in s:
        if state >= 4:
            break
        code = ord(ch)
        if code > 255:
            state = 4
            continue
        digit = 48 <= code <= 57
        if state == 0:
            if digit:
                state, part1, part2 = 2, 0, code - 48
            elif ch == "-" or ch == "+":
                state = 1
                sign = 1 if ch == "-" else 0
            elif ch != " ":
                state = 4
        elif state == 1:
            if digit:
                part1, part2, state = 0, code - 48, 2
                if kind is not None and _will_overflow(part1, part2, kind, sign):
                    overflowed = True
                    part1 = part2 = 0
                    state = 5
            else:
                state = 4
        elif state == 2:
            if digit:
                t1, t2 = part1, part2
                part1 = (part1 * 10 + part2) & _M64
                part2 = code - 48
                if kind is not None:
                    overflowed = _will_overflow(part1, part2, kind, sign)
                    if overflowed and sign == 0:
                        part1, part2, state = t1, t2, 5
            elif ch == " ":
                state = 3
            else:
                state = 4
        elif state == 3:
            if ch != " ":
                state = 4
    return state in (2, 3) and not overflowed, sign, part1, part2


def is_int(s, kind):
    """`is_integer_8` ... `is_natural_64` (kind "i8".."n64"), `is_number_sequence` (None)."""
    m = _INT_RE.match(s)
    if m is None:
        return False
    if kind is None:
        return True
    digits = m.group(2)
    if len(digits) > 18:
        return _int_machine(s, kind)[0]
    value = int(digits)
    signed, bits = KINDS[kind]
    if m.group(1) == "-":
        value = -value
    if signed:
        return -(1 << (bits - 1)) <= value < (1 << (bits - 1))
    return 0 <= value < (1 << bits)


def to_int(s, kind):
    """`to_integer_8` ... `to_natural_64`: parsed without limitation, then converted as ISE
    (`as_integer_xx` of the NATURAL_64 magnitude, negated in the type)."""
    m = _INT_RE.match(s)
    if m is not None:
        magnitude = int(m.group(2)) & _M64
        sign = 1 if m.group(1) == "-" else 0
    else:  # precondition violated: what ISE's machine leaves
        _ok, sign, part1, part2 = _int_machine(s, None)
        magnitude = (part1 * 10 + part2) & _M64
    signed, bits = KINDS[kind]
    mask = (1 << bits) - 1
    value = magnitude & mask
    if not signed:
        return value
    if sign == 1:
        value = (-value) & mask
    return value - (1 << bits) if value >> (bits - 1) else value


# ---------------------------------------------------------------------------------------------
# Reals


def _real_machine(s):
    """STRING_TO_REAL_CONVERTOR.parse_string_with_type. Returns (is_integral_double, value)."""
    state = 0
    natural = fractional = divider = 0.0
    exponent = 0
    negative = negative_exponent = has_fraction = needs_digit = False
    for ch in s:
        if state == 9:
            break
        code = ord(ch)
        if code > 255:
            state = 9
            continue
        digit = 48 <= code <= 57
        if state == 0:
            if digit:
                state, natural = 2, float(code - 48)
            elif ch == "+":
                state = 1
            elif ch == "-":
                state, negative = 1, True
            elif ch == " ":
                pass
            elif ch == ".":
                state, needs_digit = 3, True
            else:
                state = 9
        elif state == 1:
            if digit:
                state, natural = 2, float(code - 48)
            elif ch == ".":
                state, needs_digit = 3, True
            else:
                state = 9
        elif state == 2:
            if digit:
                natural = (natural * 10.0 + float(code)) - 48.0
            elif ch == ".":
                state, needs_digit = 3, False
            elif ch == " ":
                state = 8
            elif ch == "e" or ch == "E":
                state = 5
            else:
                state = 9
        elif state == 3:
            if digit:
                state, has_fraction = 4, True
                fractional, divider, needs_digit = float(code - 48), 10.0, False
            elif (ch == "e" or ch == "E") and not needs_digit:
                state, needs_digit = 5, True
            elif ch == " ":
                state = 8
            else:
                state = 9
        elif state == 4:
            if digit:
                fractional = fractional * 10.0 + float(code - 48)
                divider = divider * 10.0
            elif ch == "e" or ch == "E":
                state, needs_digit = 5, True
            elif ch == " ":
                state = 8
            else:
                state = 9
        elif state == 5:
            if ch == "-":
                state, negative_exponent = 6, True
            elif ch == "+":
                state = 6
            elif digit:
                state, needs_digit, exponent = 7, False, code - 48
            else:
                state = 9
        elif state == 6:
            if digit:
                state, exponent, needs_digit = 7, code - 48, False
            else:
                state = 9
        elif state == 7:
            if digit:
                exponent = _wrap32(exponent * 10 + code - 48)
            elif ch == " ":
                state = 8
            else:
                state = 9
        elif state == 8:
            if ch != " ":
                state = 9
    ok = 1 < state < 9 and not needs_digit
    # parsed_double
    if negative_exponent:
        exponent = _wrap32(-exponent)
    if has_fraction:
        natural = natural + fractional / divider
    try:
        scale = 10.0**exponent
    except OverflowError:
        scale = float("inf")
    value = (-natural if negative else natural) * scale
    return ok, value


def _wrap32(v):
    v &= 0xFFFFFFFF
    return v - 0x100000000 if v >= 0x80000000 else v


def is_double(s):
    """`is_double`, `is_real` and `is_real_sequence` (ISE does no range check for REAL_32)."""
    return _real_machine(s)[0]


def to_double(s):
    return _real_machine(s)[1]


def to_real_32(x):
    """REAL_64 `truncated_to_real`: round to single precision (C conversion)."""
    try:
        return struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:
        return float("inf") if x > 0 else float("-inf")
