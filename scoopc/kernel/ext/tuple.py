"""TUPLE's `external "Python"` features (stdlib/base/structures/storage/tuple.e).

Representation (docs codegen_spec.md): `_items`, a Python list of the items (index `i` of Eiffel
is `_items[i - 1]`); `_gen_`, the TypeDescs of the declared item types; `_object_comparison`
(absent means False: `is_equal` compares items with `=`).

Type codes are TUPLE's `..._code` constants. The declared type of item `i` is `_gen_[i - 1]`
(its `.key`, e.g. "INTEGER_32"); when `_gen_` is shorter than the tuple (a tuple value of a
longer tuple type seen through a shorter one), the code comes from the item's Python value.

The value checks shared with ROUTINE.valid_operands (`value_fits`) are loose, by Python type:
BOOLEAN needs a `bool`; INTEGER_xx / NATURAL_xx an `int` (not a `bool`) within the type's range;
POINTER an `int`; REAL_32/64 a `float` (an `int` is accepted too); CHARACTER_8 a one-character
`str` below 256, CHARACTER_32 any one-character `str`. For a reference type, Void is refused
where the TypeDesc says `attached`, and a basic value or an object of a generated class (one with
`_conforms_`) must satisfy `TypeDesc.accepts` (scoopc/kernel/types.py); any other host object is
let through.
"""

from ..tuples import items_of

_BASIC = (bool, int, float, str)

REFERENCE_CODE = 0
BOOLEAN_CODE = 1
CHARACTER_8_CODE = 2
REAL_64_CODE = 3
REAL_32_CODE = 4
POINTER_CODE = 5
INTEGER_8_CODE = 6
INTEGER_16_CODE = 7
INTEGER_32_CODE = 8
INTEGER_64_CODE = 9
NATURAL_8_CODE = 10
NATURAL_16_CODE = 11
NATURAL_32_CODE = 12
NATURAL_64_CODE = 13
CHARACTER_32_CODE = 14

CODES = {
    "BOOLEAN": BOOLEAN_CODE,
    "CHARACTER_8": CHARACTER_8_CODE,
    "CHARACTER": CHARACTER_8_CODE,
    "REAL_64": REAL_64_CODE,
    "DOUBLE": REAL_64_CODE,
    "REAL_32": REAL_32_CODE,
    "REAL": REAL_32_CODE,
    "POINTER": POINTER_CODE,
    "INTEGER_8": INTEGER_8_CODE,
    "INTEGER_16": INTEGER_16_CODE,
    "INTEGER_32": INTEGER_32_CODE,
    "INTEGER": INTEGER_32_CODE,
    "INTEGER_64": INTEGER_64_CODE,
    "NATURAL_8": NATURAL_8_CODE,
    "NATURAL_16": NATURAL_16_CODE,
    "NATURAL_32": NATURAL_32_CODE,
    "NATURAL": NATURAL_32_CODE,
    "NATURAL_64": NATURAL_64_CODE,
    "CHARACTER_32": CHARACTER_32_CODE,
    "WIDE_CHARACTER": CHARACTER_32_CODE,
}

# Value ranges of the integer codes.
RANGES = {
    INTEGER_8_CODE: (-(2**7), 2**7 - 1),
    INTEGER_16_CODE: (-(2**15), 2**15 - 1),
    INTEGER_32_CODE: (-(2**31), 2**31 - 1),
    INTEGER_64_CODE: (-(2**63), 2**63 - 1),
    NATURAL_8_CODE: (0, 2**8 - 1),
    NATURAL_16_CODE: (0, 2**16 - 1),
    NATURAL_32_CODE: (0, 2**32 - 1),
    NATURAL_64_CODE: (0, 2**64 - 1),
}


def type_code(desc):
    """TUPLE's code of the type described by `desc` (a TypeDesc; its key may carry a universe
    suffix such as "@BASE"). Every non-basic type is a reference (0); user expanded types too,
    as in EiffelBase."""
    key = getattr(desc, "key", None)
    if not isinstance(key, str):
        return REFERENCE_CODE
    return CODES.get(key.split("@", 1)[0], REFERENCE_CODE)


def value_code(v):
    """TUPLE's code guessed from a value alone (no declared type known): what a manifest tuple
    would have given it (`bool` BOOLEAN, `int` INTEGER_32 or INTEGER_64 when out of its range,
    `float` REAL_64, a character CHARACTER_8 or CHARACTER_32 above 255, else a reference)."""
    if isinstance(v, bool):
        return BOOLEAN_CODE
    if isinstance(v, int):
        lo, hi = RANGES[INTEGER_32_CODE]
        return INTEGER_32_CODE if lo <= v <= hi else INTEGER_64_CODE
    if isinstance(v, float):
        return REAL_64_CODE
    if isinstance(v, str) and len(v) == 1:
        return CHARACTER_8_CODE if ord(v) < 256 else CHARACTER_32_CODE
    return REFERENCE_CODE


def is_attached_desc(desc):
    """Does `desc` describe an attached type? (TypeDesc's `attached`; unknown means detachable.)"""
    return bool(getattr(desc, "attached", False))


def value_fits(desc, v):
    """May `v` be a value of the type `desc` (checked loosely, see the module's doc)? `desc` None
    (type unknown) accepts everything."""
    if desc is None:
        return True
    code = type_code(desc)
    if code == REFERENCE_CODE:
        if v is None:
            return not is_attached_desc(desc)
        accepts = getattr(desc, "accepts", None)
        if accepts is None or not (isinstance(v, _BASIC) or hasattr(type(v), "_conforms_")):
            return True
        return accepts(v)
    if code == BOOLEAN_CODE:
        return isinstance(v, bool)
    if isinstance(v, bool) or v is None:
        return False
    if code in RANGES:
        lo, hi = RANGES[code]
        return isinstance(v, int) and lo <= v <= hi
    if code in (REAL_64_CODE, REAL_32_CODE):
        return isinstance(v, (int, float))
    if code == POINTER_CODE:
        return isinstance(v, int)
    if code == CHARACTER_8_CODE:
        return isinstance(v, str) and len(v) == 1 and ord(v) < 256
    return isinstance(v, str) and len(v) == 1  # CHARACTER_32


def _declared(current, index):
    """The TypeDesc of item `index` (1-based), or None when `_gen_` does not say."""
    gen = getattr(current, "_gen_", ())
    if 1 <= index <= len(gen):
        return gen[index - 1]
    return None


def _check_index(current, index, items):
    if not 1 <= index <= len(items):
        raise IndexError(f"TUPLE index {index} not in 1 .. {len(items)}")


# --- Access ---


def item(current, index):
    """Item at `index` (1-based)."""
    items = items_of(current)
    if index < 1:
        _check_index(current, index, items)
    return items[index - 1]


def item_code(current, index):
    """Code of the declared type of the item at `index` (TUPLE's `..._code` constants)."""
    desc = _declared(current, index)
    if desc is not None:
        return type_code(desc)
    items = items_of(current)
    _check_index(current, index, items)
    return value_code(items[index - 1])


# --- Measurement ---


def count(current):
    """Number of items."""
    return len(items_of(current))


# --- Comparison ---


def object_comparison(current):
    """Does `is_equal` compare reference items with `~`?"""
    return getattr(current, "_object_comparison", False)


def compare_objects(current):
    current._object_comparison = True


def compare_references(current):
    current._object_comparison = False


# --- Status report ---


def valid_type_for_index(current, v, index):
    """May `v` be put at `index`? As EiffelBase: Void only where the declared type is a detachable
    reference type; otherwise `v` must be a value of the declared type (checked loosely)."""
    desc = _declared(current, index)
    if desc is None:
        return True
    return value_fits(desc, v)


# --- Element change ---


def put(current, v, index):
    """Put `v` at `index` (1-based)."""
    items = items_of(current)
    if index < 1:
        _check_index(current, index, items)
    items[index - 1] = v
