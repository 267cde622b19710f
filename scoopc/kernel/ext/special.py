"""SPECIAL's `external "Python"` features (stdlib/base/structures/storage/special.e).

Representation (docs codegen_spec.md): `_items`, a Python list whose length is `count` (slots
beyond `count` do not exist in the host); `_cap`, the capacity; `_gen_[0]`, the TypeDesc of T
(`.default(region)` gives T's default value, a fresh object made in `region` for a user
expanded type). A SPECIAL of a basic numeric type once passed to an external keeps its items in
an `array.array` instead (scoopc.kernel.externals: the external's numpy array is a view of it),
which every function here accepts as well.

Preconditions (special.e's) are checked by the generated code when one of these functions
raises: so each refuses, with IndexError or ValueError, every input its precondition excludes
(a negative index would otherwise read from the end, a count grow past the capacity), and the
caller sees the precondition violation, never the host's exception.
"""

from array import array

_IMMUTABLE = (int, float, str, bool, type(None))


def _like(items, values: list):
    """`values` as a run that can replace a slice of `items` (an `array.array` takes only its own kind)."""
    return values if type(items) is list else array(items.typecode, values)


def _new_like(current, items, cap):
    """A new SPECIAL of the same dynamic type and actual generic as `current`, in its region."""
    pycls = type(current)
    result = pycls.__new__(pycls)
    result._region_ = current._region_
    result._gen_ = current._gen_
    result._items = items
    result._cap = cap
    return result


def _bad_index(current, i):
    raise IndexError(f"SPECIAL index {i} not in 0 .. {len(current._items) - 1}")


def _check_room(current, new_count):
    if new_count > current._cap:
        raise IndexError(f"SPECIAL of capacity {current._cap} cannot hold {new_count} items")


# --- Initialization ---


def make_empty(current, n):
    """Make room for `n` items; none is in use yet."""
    if n < 0:
        raise ValueError(f"SPECIAL.make_empty: negative capacity {n}")
    current._items = []
    current._cap = n


# --- Access ---


def item(current, i):
    """Item at index `i` (0-based)."""
    if i < 0:
        _bad_index(current, i)
    return current._items[i]


# --- Measurement ---


def count(current):
    return len(current._items)


def capacity(current):
    return current._cap


# --- Element change ---


def put(current, v, i):
    """Replace the item at index `i` (< count) by `v`."""
    if i < 0:
        _bad_index(current, i)
    current._items[i] = v


def extend(current, v):
    """Add `v` at index `count`."""
    items = current._items
    if len(items) >= current._cap:
        _check_room(current, len(items) + 1)
    items.append(v)


def fill_with(current, v, start_index, end_index):
    """Put `v` at every index from `start_index` to `end_index` (both included), using slots
    beyond `count` if needed (`start_index` <= `count`)."""
    items = current._items
    n = end_index + 1 - start_index
    if start_index < 0 or start_index > len(items) or n < 0:
        _bad_index(current, start_index)
    if n == 0:
        return
    _check_room(current, max(len(items), end_index + 1))
    items[start_index : end_index + 1] = _like(items, [v] * n)


def fill_with_default(current, start_index, end_index):
    """Put T's default value at every index from `start_index` to `end_index`, using slots beyond
    `count` if needed. The default is asked for once per slot unless it is an immutable host value
    (an expanded object must be a fresh object in every slot)."""
    items = current._items
    n = end_index + 1 - start_index
    if start_index < 0 or start_index > len(items) or n < 0:
        _bad_index(current, start_index)
    if n == 0:
        return
    _check_room(current, max(len(items), end_index + 1))
    desc = current._gen_[0]
    region = current._region_
    first = desc.default(region)
    if isinstance(first, _IMMUTABLE):
        values = [first] * n
    else:
        values = [first]
        values.extend(desc.default(region) for _ in range(n - 1))
    items[start_index : end_index + 1] = _like(items, values)


def copy_data(current, other, source_index, destination_index, n):
    """Copy the `n` items of `other` from `source_index` to this block from `destination_index` on
    (`destination_index` <= `count`; the count grows when the copy goes past it). `other` may be
    `current` (overlapping ranges are then handled like `move_data`)."""
    items = current._items
    if destination_index < 0 or destination_index > len(items):
        _bad_index(current, destination_index)
    if n < 0 or source_index < 0 or source_index + n > len(other._items):
        raise IndexError(
            f"SPECIAL.copy_data: {n} items from {source_index} not in a source of count {len(other._items)}"
        )
    _check_room(current, destination_index + n)
    run = other._items[source_index : source_index + n]
    items[destination_index : destination_index + n] = run if type(run) is type(items) else _like(items, list(run))


def move_data(current, source_index, destination_index, n):
    """Move `n` items from `source_index` to `destination_index` (the ranges may overlap; the
    count grows when the destination goes past it)."""
    copy_data(current, current, source_index, destination_index, n)


# --- Resizing ---


def keep_head(current, n):
    """Keep only the first `n` items (0 <= `n` <= `count`)."""
    if n < 0 or n > len(current._items):
        raise ValueError(f"SPECIAL.keep_head: count {n} not in 0 .. {len(current._items)}")
    del current._items[n:]


def keep_tail(current, n):
    """Keep only the last `n` items (0 <= `n` <= `count`), moved to the front."""
    if n < 0 or n > len(current._items):
        raise ValueError(f"SPECIAL.keep_tail: count {n} not in 0 .. {len(current._items)}")
    items = current._items
    if n < len(items):
        del items[: len(items) - n]


def resized_area(current, n):
    """A new block of capacity `n` with the first min (count, n) items of this one."""
    if n < 0:
        raise ValueError(f"SPECIAL.resized_area: negative capacity {n}")
    return _new_like(current, current._items[:n], n)


def aliased_resized_area(current, n):
    """This block, given capacity `n` and keeping its first min (count, n) items (the host list
    grows on demand, so resizing in place is always possible)."""
    if n < 0:
        raise ValueError(f"SPECIAL.aliased_resized_area: negative capacity {n}")
    del current._items[n:]
    current._cap = n
    return current


# --- Removal ---


def wipe_out(current):
    """Put no slot in use (capacity unchanged)."""
    del current._items[:]


# --- Duplication ---


def copy(current, other):
    """Take the capacity, items (shallow) and actual generic of `other`, in a list of its own."""
    if other is current:
        return
    current._items = list(other._items)
    current._cap = other._cap
    current._gen_ = other._gen_
