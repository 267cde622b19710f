"""ROUTINE's `external "Python"` features (stdlib/base/agents/routine.e), and the call machinery
PROCEDURE.call and FUNCTION.item/flexible_item share (`run`).

Representation of an agent (docs codegen_spec.md): `_fn`, a Python callable taking every operand of
the routine in order (target first); `_slots`, a list with one entry per operand, the closed ones
filled; `_open`, the increasing tuple of the indices in `_slots` of the open operands; `_gen_[0]`,
the TypeDesc of OPEN_ARGS (its `generics`, when present, are the types of the open operands).
`_operands` (absent means Void) is the attribute `operands` of EiffelBase, set by `set_operands`.

EiffelBase facts followed (library/base/elks/kernel/routine.e, function.e):
* `operands` is a plain attribute, Void until `set_operands (args)` stores `args` itself (not a
  copy); `apply` calls with it. It is not a view of the open slots.
* `target`: the closed target, else item 1 of `operands` when that is a non-empty tuple, else Void.
* `valid_operands (args)`: Void only when there is no open operand; otherwise at least `open_count`
  items, item k fitting the type of open operand k, and, when the target is open, item 1 not Void.
* `hash_code` depends on the routine only (EiffelBase: `rout_disp.hash_code.bit_xor (routine_id)`),
  so agents equal by `is_equal` have equal hash codes whatever their closed operands.
* `is_equal`: same routine, same open positions, closed operands and `operands` equal as tuples
  (`~`: items compared with `=`: by value for basic values, by identity for objects).
* `copy`: `standard_copy`, then `operands := operands.twin`.
* `flexible_call (a)` calls the dynamic `call` (so FUNCTION's `call` sets `last_result`);
  FUNCTION.`flexible_item (a)` is `item` on the items of `a`. Items beyond `open_count` are ignored.

A call never writes into `_slots` (it fills a fresh list): an agent may be called again from inside
its own call, or by several processors.
"""

import os
import zlib

from ..tuples import items_of, twin
from .tuple import value_fits

_BASIC = (bool, int, float, str)


# --- Calling ---


def operand_list(current, args):
    """Every operand of a call of `current` with the tuple-like `args` as open operands."""
    open_ = current._open
    slots = current._slots
    if not open_:
        return slots
    items = items_of(args)
    if len(items) < len(open_):
        raise TypeError(f"agent call with {len(items)} operands; {len(open_)} are open")
    ops = list(slots)
    for k, i in enumerate(open_):
        ops[i] = items[k]
    return ops


def run(current, args):
    """Call the routine of `current` with the items of `args` as open operands; its result."""
    return current._fn(*operand_list(current, args))


# --- Access ---


def operands(current):
    """Open operands set by `set_operands` (Void until then)."""
    return getattr(current, "_operands", None)


def target(current):
    """The closed target; else item 1 of `operands` if there is one; else Void."""
    if 0 not in current._open:
        return current._slots[0]
    items = items_of(operands(current))
    return items[0] if len(items) > 0 else None


def hash_code(current):
    """Hash code of the routine (not of the operands, as EiffelBase), >= 0 and the same in every
    run (no `id`, no salted `str` hash)."""
    return zlib.crc32(_routine_name(current._fn).encode("utf-8")) & 0x7FFFFFFF


# --- Measurement ---


def open_count(current):
    return len(current._open)


# --- Status report ---


def is_target_closed(current):
    return 0 not in current._open


def valid_operands(current, args):
    """Are `args` suitable open operands? Void only without open operands; else a tuple-like with
    at least `open_count` items, each fitting (tuple.value_fits, loosely by Python type) the type
    of its open operand when OPEN_ARGS's TypeDesc gives it, and item 1 not Void when the target
    is open."""
    open_ = current._open
    n = len(open_)
    if args is None:
        return n == 0
    items = items_of(args)
    if len(items) < n:
        return False
    types = _open_types(current)
    for k in range(min(n, len(types))):
        if not value_fits(types[k], items[k]):
            return False
    if 0 in open_:
        return items[0] is not None
    return True


# --- Comparison ---


def is_equal(current, other):
    """Same routine, same open positions, equal closed operands and equal `operands`."""
    if other is current:
        return True
    if other is None:
        return False
    if tuple(current._open) != tuple(other._open) or len(current._slots) != len(other._slots):
        return False
    if not _same_routine(current._fn, other._fn):
        return False
    open_ = set(current._open)
    for i, (a, b) in enumerate(zip(current._slots, other._slots)):
        if i not in open_ and not _same(a, b):
            return False
    return _tuples_equal(operands(current), operands(other))


# --- Element change ---


def set_operands(current, args):
    """Make `args` (kept, not copied) the operands of the next `apply`."""
    current._operands = args


# --- Basic operations ---


def flexible_call(current, a):
    """Call the routine with the items of the tuple-like `a` as open operands, through the
    dynamic `call` (FUNCTION's keeps the result in `last_result`)."""
    current.call(a)


# --- Duplication ---


def copy(current, other):
    """Stand for the same routine and operands as `other`: every field of `other` (EiffelBase's
    `standard_copy`; `_region_` stays), `_slots` in a list of its own, `operands` twinned."""
    if other is current:
        return
    mine = getattr(current, "__dict__", None)
    theirs = getattr(other, "__dict__", None)
    if mine is not None and theirs is not None:
        for key in [k for k in mine if k not in theirs and k != "_region_"]:
            del mine[key]
        for key, value in theirs.items():
            if key != "_region_":
                mine[key] = value
    current._fn = other._fn
    current._open = other._open
    current._slots = list(other._slots)
    ops = operands(other)
    if ops is not None:
        current._operands = twin(current._region_, ops)
    elif mine is not None:
        mine.pop("_operands", None)


# --- Helpers ---


def _open_types(current):
    """TypeDescs of the open operands (OPEN_ARGS's generics), or () when not known."""
    gen = getattr(current, "_gen_", ())
    if not gen:
        return ()
    return tuple(getattr(gen[0], "generics", None) or ())


def _same(a, b):
    """Eiffel `=` on two values: basic values by type and value, objects by identity."""
    if a is b:
        return True
    if isinstance(a, _BASIC) and isinstance(b, _BASIC):
        return type(a) is type(b) and a == b
    return False


def _same_object(a, b):
    """Eiffel `~`: `=`, or the same dynamic type and `is_equal`."""
    if _same(a, b):
        return True
    if a is None or b is None or type(a) is not type(b) or isinstance(a, _BASIC):
        return False
    equal = getattr(a, "is_equal", None)
    return bool(equal(b)) if equal is not None else False


def _tuples_equal(a, b):
    """`a ~ b` for two tuple-likes or Void: the same type, count and comparison criterion, items
    compared with `=` (`~` when `object_comparison`), as TUPLE.is_equal."""
    if a is b:
        return True
    if a is None or b is None or type(a) is not type(b):
        return False
    by_object = getattr(a, "_object_comparison", False)
    if by_object != getattr(b, "_object_comparison", False):
        return False
    xs, ys = items_of(a), items_of(b)
    if len(xs) != len(ys):
        return False
    test = _same_object if by_object else _same
    return all(test(x, y) for x, y in zip(xs, ys))


def _unbound(fn):
    """The function under a bound method (its `__self__` is then part of the routine)."""
    return getattr(fn, "__func__", fn)


def _same_routine(f, g):
    """Do `f` and `g` stand for the same routine? The same callable (or equal bound methods), or two
    closures of one code object (an agent expression evaluated twice) over identical cells, defaults
    and bound target."""
    if f is g or f == g:
        return True
    if getattr(f, "__self__", None) is not getattr(g, "__self__", None):
        return False
    f0, g0 = _unbound(f), _unbound(g)
    code = getattr(f0, "__code__", None)
    if code is None or code is not getattr(g0, "__code__", None):
        return False
    if getattr(f0, "__defaults__", None) != getattr(g0, "__defaults__", None):
        return False
    fc = getattr(f0, "__closure__", None) or ()  # one code object: as many cells
    gc = getattr(g0, "__closure__", None) or ()
    try:
        return all(_same(x.cell_contents, y.cell_contents) for x, y in zip(fc, gc))
    except ValueError:  # an empty cell
        return False


def _routine_name(fn):
    """A name of the routine stable across runs (and across output directories) and equal for
    `_same_routine` callables: the code object's file name, line and qualified name, else the
    callable's module and qualified name."""
    f0 = _unbound(fn)
    code = getattr(f0, "__code__", None)
    if code is not None:
        qualname = getattr(code, "co_qualname", code.co_name)
        return f"{os.path.basename(code.co_filename)}:{code.co_firstlineno}:{qualname}"
    kind = f0 if isinstance(f0, type) else type(f0)
    name = getattr(f0, "__qualname__", None) or kind.__qualname__
    return f"{getattr(f0, '__module__', None) or kind.__module__}.{name}"
