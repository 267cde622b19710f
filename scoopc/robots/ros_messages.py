"""The message model: ROS 2 message types come from rosbags' type store (ROS 2 Humble).

A message object IS an instance of the type store's dataclass. `new(typename, **fields)` builds one
with ROS 2 default values for every omitted field (0, 0.0, False, "", zero-filled fixed arrays,
empty sequences, default nested messages). Arrays and sequences of numbers (and bool) are numpy
arrays, as rosbags makes them; arrays and sequences of strings or messages are Python lists.

A field description is rosbags' `(Nodetype, detail)` pair: `(BASE, (name, bound))`, `(NAME, typename)`,
`(ARRAY, (element, length))` or `(SEQUENCE, (element, bound))` (bound 0: unbounded).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.base import Nodetype

BASE, NAME, ARRAY, SEQUENCE = Nodetype.BASE, Nodetype.NAME, Nodetype.ARRAY, Nodetype.SEQUENCE

#: numpy dtypes (little endian) of the numeric base types. As in rosbags, `byte` holds a signed
#: octet (-128..127) and `char` an unsigned one (0..255); on the wire both are one octet.
DTYPES = {
    "bool": np.dtype("bool"),
    "byte": np.dtype("int8"),
    "char": np.dtype("uint8"),
    "int8": np.dtype("int8"),
    "uint8": np.dtype("uint8"),
    "int16": np.dtype("<i2"),
    "uint16": np.dtype("<u2"),
    "int32": np.dtype("<i4"),
    "uint32": np.dtype("<u4"),
    "int64": np.dtype("<i8"),
    "uint64": np.dtype("<u8"),
    "float32": np.dtype("<f4"),
    "float64": np.dtype("<f8"),
}
STRING_TYPES = ("string", "wstring")


@lru_cache(maxsize=1)
def typestore():
    """The process-wide default type store (ROS 2 Humble)."""
    return get_typestore(Stores.ROS2_HUMBLE)


def store_with(definitions: dict[str, str], base=None):
    """A fresh type store (ROS 2 Humble, plus `base`'s extra types if given) in which the given
    `.msg` definitions ({typename: text}) are registered. The default store is never changed."""
    store = get_typestore(Stores.ROS2_HUMBLE)
    types: dict = {}
    for name, text in definitions.items():
        types.update(get_types_from_msg(text, name))
    store.register(types)
    return store


def _store(store):
    return typestore() if store is None else store


def has_type(typename: str, store=None) -> bool:
    return typename in _store(store).fielddefs


def fields(typename: str, store=None) -> list[tuple[str, tuple]]:
    """The fields of a message type, in order: [(name, field description)]."""
    try:
        return _store(store).fielddefs[typename][1]
    except KeyError:
        raise KeyError(f"unknown ROS 2 message type `{typename}`") from None


def constants(typename: str, store=None) -> list[tuple[str, str, Any]]:
    """The constants of a message type: [(name, base type, value)]."""
    return _store(store).fielddefs[typename][0]


def message_class(typename: str, store=None) -> type:
    return _store(store).types[typename]


def typename_of(msg: Any) -> str:
    """The ROS type name of a message object ("geometry_msgs/msg/Twist")."""
    return msg.__msgtype__


def is_numeric(element: tuple) -> bool:
    """Whether an array/sequence element description is a base type stored in a numpy array."""
    return element[0] == BASE and element[1][0] in DTYPES


def default_value(desc: tuple, store=None) -> Any:
    """The ROS 2 default value of one field description."""
    kind, detail = desc
    if kind == BASE:
        name = detail[0]
        if name in STRING_TYPES:
            return ""
        if name == "bool":
            return False
        return 0.0 if name.startswith("float") else 0
    if kind == NAME:
        return new(detail, store)
    element, size = detail
    if kind == ARRAY:
        if is_numeric(element):
            return np.zeros(size, dtype=DTYPES[element[1][0]])
        return [default_value(element, store) for _ in range(size)]
    if is_numeric(element):
        return np.zeros(0, dtype=DTYPES[element[1][0]])
    return []


def new(typename: str, store=None, **values: Any) -> Any:
    """A message of type `typename`: the given field values, defaults for the others."""
    described = fields(typename, store)
    unknown = set(values) - {name for name, _ in described}
    if unknown:
        raise TypeError(f"{typename} has no field {', '.join(sorted(unknown))}")
    arguments = {name: values[name] if name in values else default_value(desc, store) for name, desc in described}
    return message_class(typename, store)(**arguments)


def nested_types(typename: str, store=None, found: list[str] | None = None) -> list[str]:
    """`typename` and every message type its fields use, recursively (each once, `typename` first)."""
    found = [] if found is None else found
    if typename in found:
        return found
    found.append(typename)
    for _, desc in fields(typename, store):
        element = desc if desc[0] in (BASE, NAME) else desc[1][0]
        if element[0] == NAME:
            nested_types(element[1], store, found)
    return found
