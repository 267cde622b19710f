"""TUPLE objects made or read from Python (codegen_spec.md: a TUPLE has `_items`, a Python list of
its items, and `_gen_`, the TypeDescs of its item types).

`new_tuple` builds a TUPLE in a region; `items_of` reads the items of anything tuple-like that the
externals accept (a TUPLE object, a Python tuple or list, Void).
"""

from . import cls


def new_tuple(region, items, gen=()):
    """A new TUPLE object in `region` holding `items` (copied into a list of its own), with item
    types `gen` (a tuple of TypeDescs; may be empty for an untyped tuple)."""
    pycls = cls("TUPLE")
    obj = pycls.__new__(pycls)
    obj._region_ = region
    obj._items = list(items)
    obj._gen_ = tuple(gen)
    return obj


def items_of(t):
    """The items of the tuple-like `t` (a sequence; do not mutate it unless `t` is a TUPLE you own).

    Void gives `()`; a Python tuple or list is its own item sequence (docs/RUNTIME.md: a Python
    tuple counts as a TUPLE made by the client). A TUPLE object made by `create` (ANY's
    `default_create`, no host storage yet) gets `_items` from the defaults of its `_gen_` here."""
    if t is None:
        return ()
    if isinstance(t, (tuple, list)):
        return t
    try:
        return t._items
    except AttributeError:
        region = getattr(t, "_region_", None)
        items = [g.default(region) for g in getattr(t, "_gen_", ())]
        t._items = items
        return items


def twin(region, t):
    """A TUPLE with the items (shallow), item types and comparison criterion of `t`, storage of its
    own, in `region`; Void for Void; a Python tuple is immutable and returned as it is."""
    if t is None or isinstance(t, tuple):
        return t
    if isinstance(t, list):
        return list(t)
    pycls = type(t)
    result = pycls.__new__(pycls)
    result._region_ = region
    result._items = list(items_of(t))
    result._gen_ = getattr(t, "_gen_", ())
    if getattr(t, "_object_comparison", False):
        result._object_comparison = True
    return result
