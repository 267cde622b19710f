"""ARRAY's `external "Python"` features (stdlib/base/structures/storage/array.e): `item` (and
its synonym `at`) and `put`, the accessors under every array a program indexes.

Each does what the Eiffel body it stands for does (`area.item (i - lower)`,
`area.put (v, i - lower)`) and refuses, with IndexError, every index that `valid_index`
rejects; the generated code then evaluates the precondition `valid_key`, so the caller sees
the precondition violation (codegen REFUSING_HOSTS). For an ARRAY, `valid_index` is
`lower <= i <= upper`, checked here without a call; a descendant may redefine it, so for
one the redefined query is asked and SPECIAL's own routines do the rest, as in Eiffel.
"""


def _refuse(current, i):
    raise IndexError(f"ARRAY index {i} not in {current.lower} .. {current.upper}")


def item(current, i):
    """Item at index `i`."""
    if type(current)._key_ == "ARRAY":
        j = i - current.lower
        if j < 0 or i > current.upper:
            _refuse(current, i)
        return current.area._items[j]
    if not current.valid_index(i):
        _refuse(current, i)
    return current.area.item(i - current.lower)


at = item


def put(current, v, i):
    """Replace the item at index `i` by `v`."""
    if type(current)._key_ == "ARRAY":
        j = i - current.lower
        if j < 0 or i > current.upper:
            _refuse(current, i)
        current.area._items[j] = v
        return
    if not current.valid_index(i):
        _refuse(current, i)
    current.area.put(v, i - current.lower)
