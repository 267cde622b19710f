"""ARRAY's `external "Python"` features (stdlib/base/structures/storage/array.e): `item` (and
its synonym `at`) and `put`, the accessors under every array a program indexes.

Each does what the Eiffel body it stands for does (`area.item (i - lower)`,
`area.put (v, i - lower)`) and is bound as the routine itself (codegen STANDING_FOR_EIFFEL): no
Python call stands around it. For an index that `valid_index` rejects it calls the generated
`_item_refused_` (`_at_refused_`, `_put_refused_`), which evaluates the precondition `valid_key`
and reports its violation as for an Eiffel routine. For an ARRAY, `valid_index` is
`lower <= i <= upper`, checked here without a call; a descendant may redefine it, so for one
the redefined query is asked and SPECIAL's own routines do the rest, as in Eiffel.
"""


def _refuse(report, i, *before):
    report(*before, i)  # raises the precondition violation
    raise IndexError(f"ARRAY index {i} refused, but valid_index accepts it")


# The class ARRAY itself, once met (a program has one; a process that loads several programs'
# libraries keeps the last): `type(current) is _array` is a global load and an identity test,
# where `type(current)._key_` is an attribute lookup on a class, which CPython 3.11 does not
# specialize (docs/RUNTIME.md section 10).
_array: type | None = None


def _is_array(current) -> bool:
    """Is `current` a plain ARRAY (not a descendant, which may redefine `valid_index`)?"""
    global _array
    if type(current)._key_ != "ARRAY":
        return False
    _array = type(current)
    return True


def _reader(refused: str):
    """`item` and its synonym `at`, which differ in the name of the routine that reports."""

    def read(current, i):
        if type(current) is _array or _is_array(current):
            j = i - current.lower
            if j < 0 or i > current.upper:
                _refuse(getattr(current, refused), i)
            return current.area._items[j]
        if not current.valid_index(i):
            _refuse(getattr(current, refused), i)
        return current.area.item(i - current.lower)

    read.__doc__ = "Item at index `i`."
    return read


item = _reader("_item_refused_")
at = _reader("_at_refused_")


def put(current, v, i):
    """Replace the item at index `i` by `v`."""
    if type(current) is _array or _is_array(current):
        j = i - current.lower
        if j < 0 or i > current.upper:
            _refuse(current._put_refused_, i, v)
        current.area._items[j] = v
        return
    if not current.valid_index(i):
        _refuse(current._put_refused_, i, v)
    current.area.put(v, i - current.lower)
