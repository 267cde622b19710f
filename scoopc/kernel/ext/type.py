"""TYPE's `built_in` features: a TYPE object's `_gen_[0]` is the type it describes
(scoopc.kernel.types.TypeDesc)."""

from __future__ import annotations

from .. import types as T


def _desc(current):
    return current._gen_[0]


def name(current):
    from ..strings import new_immutable_8

    return new_immutable_8(current._region_, _desc(current).name)


def name_32(current):
    from ..strings import new_immutable_32

    return new_immutable_32(current._region_, _desc(current).name)


_IDS: dict = {}


def type_id(current):
    return _IDS.setdefault(_desc(current), len(_IDS) + 1)


def generic_parameter_type(current, i):
    from ..support import type_object

    return type_object(current._region_, _desc(current).generics[i - 1])


def generic_parameter_count(current):
    return len(_desc(current).generics)


def has_default(current):
    desc = _desc(current)
    return desc.is_expanded or not desc.attached


def is_deferred(current):
    cls = _desc(current).pyclass
    return bool(cls is not None and getattr(cls, "_deferred_", False))


def is_expanded(current):
    return _desc(current).is_expanded


def is_attached(current):
    return _desc(current).attached


def is_equal(current, other):
    return other is not None and _desc(current) is _desc(other)


def is_strictly_conforming_to(current, other):
    return _desc(current) is not _desc(other) and _desc(current).conforms_to(_desc(other))


def is_conforming_to(current, other):
    return _desc(current).conforms_to(_desc(other))


def default(current):
    return _desc(current).default(current._region_)


__all__ = ["T"]
