"""The run-time helpers of the basic classes' built-in features (INTEGER_8..64, NATURAL_8..64,
REAL_32/64, BOOLEAN, CHARACTER_8/32, POINTER): what generated code calls as `B.name(...)` and the
inline templates of scoopc/kernel/basic_inline.py name as `B.name`. Generated code imports them
through scoopc.kernel.basic, which adds the dynamic dispatch and the code generator's entry
points; semantics and sources are described there. This module imports no other module of
the kernel at load time, so scoopc.kernel.basic_dispatch can import it.
"""

import math
import struct
import unicodedata

from . import CLASSES

# --- Constants and builtins (templates never name a Python builtin directly) --------------

NAN = math.nan
POS_INF = math.inf
NEG_INF = -math.inf
HEX_DIGITS = "0123456789ABCDEF"
chr = chr  # `B.chr`, `B.ord`: a generated local may shadow the builtins
ord = ord


def seq(*values):
    """Evaluate operands left to right and give the last (an operand a template drops)."""
    return values[-1]


# --- Integers ------------------------------------------------------------------------------


def _sized(bits, signed):
    mask = (1 << bits) - 1
    half = 1 << (bits - 1)
    if signed:

        def wrap(x):
            return ((x + half) & mask) - half

        def idiv(a, b):
            """C `a / b`: truncated toward zero (ZeroDivisionError for 0); MIN // -1 wraps."""
            q = a // b
            if q < 0 and q * b != a:
                q += 1
            return q if q != half else -half

        def irem(a, b):
            """C `a % b`: the sign of the dividend."""
            r = a % b
            if r and (a < 0) != (b < 0):
                r -= b
            return r

        def iabs(x):
            return x if x >= 0 else ((half - x) & mask) - half
    else:

        def wrap(x):
            return x & mask

        idiv = irem = iabs = None

    def shift(x, n):
        """`bit_shift`: right by `n` if `n` > 0, left by -`n` otherwise."""
        return x >> n if n > 0 else wrap(x << -n)

    def set_bit(x, b, n):
        return wrap(x | (1 << n) if b else x & ~(1 << n))

    def set_bit_mask(x, b, m):
        return x | m if b else x & ~m

    return wrap, idiv, irem, iabs, shift, set_bit, set_bit_mask


def _ranged(bits):
    low, high = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    mask = (1 << bits) - 1

    def ranged(x):
        """The exact result `x` of integer arithmetic (a whole `+ - *` tree, computed with
        Python's unbounded integers) as a value of the type: itself when in range, else wrapped."""
        return x if low <= x <= high else ((x - low) & mask) + low

    return ranged


i8, i16, i32, i64 = _ranged(8), _ranged(16), _ranged(32), _ranged(64)

wrap_i8, idiv_i8, irem_i8, abs_i8, shift_i8, set_bit_i8, set_bit_mask_i8 = _sized(8, True)
wrap_i16, idiv_i16, irem_i16, abs_i16, shift_i16, set_bit_i16, set_bit_mask_i16 = _sized(16, True)
wrap_i32, idiv_i32, irem_i32, abs_i32, shift_i32, set_bit_i32, set_bit_mask_i32 = _sized(32, True)
wrap_i64, idiv_i64, irem_i64, abs_i64, shift_i64, set_bit_i64, set_bit_mask_i64 = _sized(64, True)
wrap_n8, _, _, _, shift_n8, set_bit_n8, set_bit_mask_n8 = _sized(8, False)
wrap_n16, _, _, _, shift_n16, set_bit_n16, set_bit_mask_n16 = _sized(16, False)
wrap_n32, _, _, _, shift_n32, set_bit_n32, set_bit_mask_n32 = _sized(32, False)
wrap_n64, _, _, _, shift_n64, set_bit_n64, set_bit_mask_n64 = _sized(64, False)


def imax(a, b):
    """COMPARABLE's max (integers, characters): `Current >= other`."""
    return a if a >= b else b


def imin(a, b):
    return a if a <= b else b


def cmp(a, b):
    """three_way_comparison of integers and characters."""
    return (a > b) - (a < b)


def isign(x):
    return (x > 0) - (x < 0)


def fquot(a, b):
    """INTEGER_64/NATURAL_64 `/`: C converts both operands to double first."""
    return fdiv(float(a), float(b))


def hex_string(region, x, bits):
    """`to_hex_string`: all bits/4 digits, upper case, two's complement."""
    return s8(region, format(x & ((1 << bits) - 1), f"0{bits // 4}X"))


def exponentiable(x, other):
    """ELKS: `other >= 0 or Current /= 0` (for INTEGER_32, REAL_32 and REAL_64 `other`)."""
    return other >= 0 or x != 0


def interval(region, lower, upper):
    """`lower |..| upper`: a new INTEGER_INTERVAL (`make (lower, upper)`) in `region`."""
    cls = CLASSES.get("INTEGER_INTERVAL@BASE") or CLASSES["INTEGER_INTERVAL"]
    result = region.new(cls)
    result.make(wrap_i32(lower), upper)
    return result


# --- Reals ---------------------------------------------------------------------------------

_F32 = struct.Struct("f")
_pack, _unpack = _F32.pack, _F32.unpack


def r32(x):
    """Round a double to single precision (IEEE nearest-even; overflow gives an infinity)."""
    try:
        return _unpack(_pack(x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def i2r32(x):
    """An integer as a REAL_32, rounded once (C `(EIF_REAL_32) i`, also beyond 2^53)."""
    if -9007199254740992 <= x <= 9007199254740992:
        return r32(float(x))
    a = -x if x < 0 else x
    shift = a.bit_length() - 24
    q, r = divmod(a, 1 << shift)
    half = 1 << (shift - 1)
    if r > half or (r == half and q & 1):
        q += 1
    return r32(float(q << shift) if x > 0 else -float(q << shift))


def fdiv(a, b):
    """IEEE division: x / 0.0 is an infinity (sign of x and of the zero), 0/0 and NaN/0 NaN."""
    try:
        return a / b
    except ZeroDivisionError:
        if a != a or a == 0:
            return NAN
        return math.copysign(math.inf, a) * math.copysign(1.0, b)


def _odd_integer(y):
    return math.isfinite(y) and y == math.floor(y) and abs(y) < 9007199254740992.0 and int(y) & 1 == 1


def power(x, y):
    """C `pow (x, y)` (REAL_64 `^`): special values instead of Python exceptions."""
    try:
        return math.pow(x, y)
    except (ValueError, OverflowError):
        x = float(x)
        if x == 0.0:  # pow (±0, y < 0)
            return math.copysign(math.inf, x) if _odd_integer(y) else math.inf
        if x < 0.0 and y != math.floor(y):  # negative base, fractional exponent
            return NAN
        return -math.inf if x < 0.0 and _odd_integer(y) else math.inf  # overflow


def trunc32(x):
    """C `(EIF_INTEGER_32) d` on x86-64: toward zero; NaN, infinities, out of range: -2^31."""
    if -2147483649.0 < x < 2147483648.0:
        return int(x)
    return -2147483648


def trunc64(x):
    if -9223372036854775808.0 <= x < 9223372036854775808.0:
        return int(x)
    return -9223372036854775808


def fceil(x):
    """C `ceil`: a double, keeps the sign of zero (ceil (-0.5) = -0.0)."""
    try:
        return math.copysign(float(math.ceil(x)), x)
    except (OverflowError, ValueError):  # infinities, NaN
        return x


def ffloor(x):
    try:
        return math.copysign(float(math.floor(x)), x)
    except (OverflowError, ValueError):
        return x


def fabs(x):
    """eif_abs_real64: `d > 0 ? d : -d`."""
    return x if x > 0 else -x


def fsign(x):
    """REAL `sign` through ISE's comparisons: NaN is below zero, so its sign is -1."""
    return 1 if x > 0 else (-1 if x < 0 or x != x else 0)


def rounded(x):
    """REAL_32/REAL_64 `rounded`: sign * (abs + 0.5).floor (in double precision)."""
    return wrap_i32(fsign(x) * trunc32(ffloor(fabs(x) + 0.5)))


def rounded_real(x):
    """REAL_64 `rounded_real_64`: sign * (abs + 0.5).floor_real_64 (-0.3 gives -0.0)."""
    return fsign(x) * ffloor(fabs(x) + 0.5)


def rounded_real_32(x):
    """REAL_32 `rounded_real_32`: the sum is a REAL_32 (abs + {REAL_32} 0.5)."""
    return fsign(x) * ffloor(r32(fabs(x) + 0.5))


def isnan(x):
    return x != x


def feq(a, b):
    """REAL `=`/is_equal (eif_is_equal_real_64): NaN equals NaN, 0.0 equals -0.0."""
    return a == b or (a != a and b != b)


def flt(a, b):
    """eif_is_less_real_64: NaN is less than every number."""
    return a < b or (a != a and b == b)


def fle(a, b):
    return a <= b or a != a


def fgt(a, b):
    return a > b or (b != b and a == a)


def fge(a, b):
    return a >= b or b != b


def fmax(a, b):
    return a if a >= b or b != b else b


def fmin(a, b):
    return a if a <= b or a != a else b


def fcmp(a, b):
    return -1 if flt(a, b) else (1 if flt(b, a) else 0)


# --- Characters ----------------------------------------------------------------------------


def _c8_set(*ranges):
    return frozenset(chr(c) for lo, hi in ranges for c in range(lo, hi + 1))


# ELKS CHARACTER_8_REF.internal_character_types: ASCII only (128..255 have no property).
C8_UPPER = _c8_set((65, 90))
C8_LOWER = _c8_set((97, 122))
C8_ALPHA = C8_UPPER | C8_LOWER
C8_DIGIT = _c8_set((48, 57))
C8_HEXA = C8_DIGIT | _c8_set((65, 70), (97, 102))
C8_SPACE = _c8_set((9, 13), (32, 32))
C8_PUNCTUATION = _c8_set((33, 47), (58, 64), (91, 96), (123, 126))
C8_ALPHA_NUMERIC = C8_ALPHA | C8_DIGIT
C8_GRAPH = C8_ALPHA_NUMERIC | C8_PUNCTUATION
C8_PRINTABLE = C8_GRAPH | {" "}
C8_CONTROL = _c8_set((0, 31), (127, 127))
UPPER8 = {chr(c): chr(c - 32) if 97 <= c <= 122 else chr(c) for c in range(256)}
LOWER8 = {chr(c): chr(c + 32) if 65 <= c <= 90 else chr(c) for c in range(256)}

_category = unicodedata.category
_NOT_PRINTABLE = frozenset({"Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"})
_NOT_GRAPH = _NOT_PRINTABLE | {"Zs"}


def hexa_value(c):
    """`to_hexa_digit`: 0..15."""
    return int(c, 16)


def upper32(c):
    """CHARACTER_32 `as_upper` (Unicode; a character whose upper case is several is kept)."""
    u = c.upper()
    return u if len(u) == 1 else c


def lower32(c):
    u = c.lower()
    return u if len(u) == 1 else c


def is_alpha32(c):
    return c.isalpha()


def is_upper32(c):
    return _category(c) == "Lu"


def is_lower32(c):
    return _category(c) == "Ll"


def is_space32(c):
    return c in "\t\n\x0b\x0c\r\x85" or _category(c) in ("Zs", "Zl", "Zp")


def is_punctuation32(c):
    return _category(c)[0] == "P"


def is_alpha_numeric32(c):
    return c.isalpha() or _category(c) == "Nd"


def is_printable32(c):
    return _category(c) not in _NOT_PRINTABLE


def is_graph32(c):
    return _category(c) not in _NOT_GRAPH


def is_control32(c):
    return _category(c) == "Cc"


# --- Output --------------------------------------------------------------------------------

_S8 = [None]  # scoopc.kernel.strings.new_string_8, imported on first use (tests set it)


def s8(region, text):
    """A new STRING_8 holding `text`, in `region`."""
    make = _S8[0]
    if make is None:
        from .strings import new_string_8 as make  # deferred: start-up (loaded on first use only)

        _S8[0] = make
    return make(region, text)


def r64_text(x):
    if x != x:
        return "NaN"
    if x == POS_INF:
        return "Infinity"
    if x == NEG_INF:
        return "-Infinity"
    return "%.17g" % x


def r32_text(x):
    if x != x:
        return "NaN"
    if x == POS_INF:
        return "Infinity"
    if x == NEG_INF:
        return "-Infinity"
    return "%g" % x


def c32_text(c):
    return c if c < "\x80" else "U+%04X" % ord(c)


def pointer_text(p):
    return "0x%X" % (p & 0xFFFFFFFFFFFFFFFF)


def out_int(region, x):
    return s8(region, str(x))


def out_r64(region, x):
    return s8(region, r64_text(x))


def out_r32(region, x):
    return s8(region, r32_text(x))


def out_bool(region, x):
    return s8(region, "True" if x else "False")


def out_c8(region, c):
    return s8(region, c)


def out_c32(region, c):
    return s8(region, c32_text(c))


def out_pointer(region, p):
    return s8(region, pointer_text(p))


def out_text(value):
    """The text of `value.out` for a Python value (int: INTEGER_32, float: REAL_64, ...)."""
    kind = type(value)
    if kind is bool:
        return "True" if value else "False"
    if kind is int:
        return str(value)
    if kind is float:
        return r64_text(value)
    if kind is str:
        return value if value <= "\xff" else c32_text(value)
    raise TypeError(f"not a basic value: {value!r}")
