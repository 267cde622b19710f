"""ANY's `built_in` features for objects of generated classes (values of basic types are served
by scoopc.kernel.basic): reflection, copying and comparison, `tagged_out`."""

from __future__ import annotations

from array import array

from .. import types as T
from ..strings import new_string_8
from ..support import type_object


def _string(region, text):
    return new_string_8(region, text)


def generator(current):
    return _string(current._region_, type(current)._key_.split("@")[0])


def generating_type(current):
    return type_object(current._region_, T.of(current))


def conforms_to(current, other):
    return T.of(current).conforms_to(T.of(other))


def same_type(current, other):
    return other is not None and T.of(current) is T.of(other)


# A SPECIAL's items: a list, or an array.array for numbers passed to an external (ext/special.py).
_SEQUENCES = (list, array)


def _fields(obj) -> dict:
    return {k: v for k, v in obj.__dict__.items() if k != "_region_"}


def standard_is_equal(current, other):
    if type(current) is not type(other):
        return False
    mine, theirs = _fields(current), _fields(other)
    names = set(mine) | set(theirs)
    cls = type(current)
    return all(_same_value(mine.get(n, getattr(cls, n, None)), theirs.get(n, getattr(cls, n, None))) for n in names)


def _same_value(a, b) -> bool:
    if a is b:
        return True
    if isinstance(a, _SEQUENCES) and isinstance(b, _SEQUENCES):
        return len(a) == len(b) and all(_same_value(x, y) for x, y in zip(a, b))
    if hasattr(a, "_region_") or hasattr(b, "_region_"):
        return False
    return type(a) is type(b) and a == b


def _blank(current):
    cls = type(current)
    obj = cls.__new__(cls)
    obj._region_ = current._region_
    return obj


def standard_copy(current, other):
    region = current._region_
    theirs = _fields(other)
    for name in _fields(current):  # a field `other` never set holds its class default
        if name not in theirs and not name.startswith("_"):
            theirs[name] = getattr(type(other), name, None)
    current.__dict__.update({k: (v[:] if isinstance(v, _SEQUENCES) else v) for k, v in theirs.items()})
    current._region_ = region


def copy(current, other):
    standard_copy(current, other)


def standard_twin(current):
    obj = _blank(current)
    standard_copy(obj, current)
    return obj


def twin(current):
    """A copy made by the object's own (possibly redefined) `copy`."""
    obj = _blank(current)
    if hasattr(current, "_gen_"):
        obj._gen_ = current._gen_
    obj.copy(current)
    return obj


def deep_twin(current):
    return _deep(current, {})


def _deep(value, memo):
    if isinstance(value, list):
        return [_deep(v, memo) for v in value]
    if isinstance(value, array):
        return value[:]  # numbers only
    if not hasattr(value, "_region_") or not hasattr(type(value), "_key_"):
        return value
    found = memo.get(id(value))
    if found is not None:
        return found
    obj = _blank(value)
    memo[id(value)] = obj
    for name, item in _fields(value).items():
        obj.__dict__[name] = _deep(item, memo)
    return obj


def is_deep_equal(current, other):
    return _deep_equal(current, other, set())


def _deep_equal(a, b, seen) -> bool:
    if a is b:
        return True
    if isinstance(a, _SEQUENCES) and isinstance(b, _SEQUENCES):
        return len(a) == len(b) and all(_deep_equal(x, y, seen) for x, y in zip(a, b))
    if hasattr(type(a), "_key_") and hasattr(type(b), "_key_"):
        if type(a) is not type(b):
            return False
        if (id(a), id(b)) in seen:
            return True
        seen.add((id(a), id(b)))
        fa, fb = _fields(a), _fields(b)
        return set(fa) == set(fb) and all(_deep_equal(fa[n], fb[n], seen) for n in fa)
    return type(a) is type(b) and a == b


def tagged_out(current):
    """EiffelStudio's layout: the class name and address, then one line per attribute."""
    lines = [f"{T.of(current).name} [0x{id(current):016X}]"]
    for name, value in sorted(_fields(current).items()):
        if name.startswith("_"):
            continue
        shown = f"{T.of(value).name} [0x{id(value):016X}]" if hasattr(type(value), "_key_") else _basic_out(value)
        lines.append(f"  {name}: {shown}")
    return _string(current._region_, "\n".join(lines) + "\n")


def _basic_out(value) -> str:
    if value is None:
        return "Void"
    if isinstance(value, bool):
        return "True" if value else "False"
    return str(value)
