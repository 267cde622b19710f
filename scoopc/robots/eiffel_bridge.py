"""The one generic bridge between Eiffel objects of `scoopc msg` classes and type-store ros_messages.

`to_message(obj)` reads the Eiffel object's attributes by field name (the naming scheme of
`eiffel_messages`) and builds the rosbags message; `from_message(msg, region)` makes the Eiffel object
(its class must be part of the compiled program: registered in `scoopc.kernel.CLASSES`) in `region`.
Values follow the codegen object model (/work/plan/codegen_spec.md): basic types are Python ints,
floats and bools, STRING is a kernel string (`_s`), ARRAY [T] has `area` (a SPECIAL with `_items`),
`lower` and `upper`.
"""

from __future__ import annotations

import keyword
from typing import Any

import numpy as np

from .. import kernel
from ..kernel import types
from . import ros_messages
from .eiffel_messages import attribute_name, class_name, eiffel_type
from .ros_messages import BASE, DTYPES, NAME


def python_name(field: str) -> str:
    """The Python attribute of a message field in generated code (a `_` after Python keywords)."""
    name = attribute_name(field)
    return name + "_" if keyword.iskeyword(name) else name


def typename_of_class(name: str, store=None) -> str:
    """The ROS type name of a generated class (GEOMETRY_MSGS_TWIST -> geometry_msgs/msg/Twist)."""
    store = ros_messages.typestore() if store is None else store
    for typename in store.fielddefs:
        if class_name(typename) == name.split("@")[0]:
            return typename
    raise KeyError(f"{name} is not the class of a known ROS 2 message type")


def _host(desc: tuple, value: Any, store) -> Any:
    kind, detail = desc
    if kind == BASE:
        if detail[0] in ros_messages.STRING_TYPES:
            from ..kernel import strings  # deferred: start-up (loaded on first use only)

            return strings.shown(value)  # the bytes of a STRING_8, a ROS string's UTF-8
        return value
    if kind == NAME:
        return to_message(value, detail, store)
    element = detail[0]
    items = list(value.area._items[: value.upper - value.lower + 1]) if value is not None else []
    converted = [_host(element, item, store) for item in items]
    if ros_messages.is_numeric(element):
        return np.array(converted, dtype=DTYPES[element[1][0]])
    return converted


def to_message(obj: Any, typename: str | None = None, store=None) -> Any:
    """The type-store message with the field values of an Eiffel object of a generated class."""
    typename = typename or typename_of_class(type(obj).__name__, store)
    # exactly the chosen distribution's layout: a field the class lacks (a class generated for
    # another distribution) keeps its default, one the distribution lacks is left out
    values = {
        field: _host(desc, getattr(obj, python_name(field)), store)
        for field, desc in ros_messages.fields(typename, store)
        if hasattr(obj, python_name(field))
    }
    return ros_messages.new(typename, store, **values)


def _type_desc(type_name: str):
    return types.t("STRING_8" if type_name == "STRING" else type_name)


def _eiffel(desc: tuple, value: Any, region, store) -> Any:
    kind, detail = desc
    if kind == BASE:
        if detail[0] in ros_messages.STRING_TYPES:
            from ..kernel import strings  # deferred: start-up (loaded on first use only)

            return strings.new_string_8_of(region, value)  # its UTF-8 bytes, one character each
        if detail[0] == "bool":
            return bool(value)
        return float(value) if detail[0].startswith("float") else int(value)
    if kind == NAME:
        return from_message(value, region, store)
    element = detail[0]
    items = [_eiffel(element, item, region, store) for item in value]
    generic = (_type_desc(eiffel_type(element)),)
    special = region.new(kernel.cls("SPECIAL"))
    special._gen_, special._items, special._cap = generic, items, len(items)
    array = region.new(kernel.cls("ARRAY"))
    array._gen_, array.area, array.lower, array.upper = generic, special, 1, len(items)
    return array


def from_message(msg: Any, region, store=None) -> Any:
    """A new Eiffel object (in `region`) of the generated class of `msg`'s type, with its values."""
    typename = ros_messages.typename_of(msg)
    obj = region.new(kernel.cls(class_name(typename)))
    described = ros_messages.fields(typename, store)
    for field, desc in described:
        setattr(obj, python_name(field), _eiffel(desc, getattr(msg, field), region, store))
    if store is None:  # fields of other distributions the class carries: defaults
        present = {field for field, _ in described}
        for field, desc in ros_messages.union_fields(typename):
            if field not in present and desc[0] == BASE:
                setattr(obj, python_name(field), _eiffel(desc, ros_messages.default_value(desc), region, store))
    return obj
