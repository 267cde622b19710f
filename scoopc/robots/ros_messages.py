"""The message model: ROS 2 message types come from rosbags' type store of one ROS 2 distribution.

The distribution (`DISTROS`: humble, jazzy, lyrical) is chosen once per process, before the first
message is made: `use_distro(name)` (scoopc run/sim/msg with `--ros-distro`, else `ROS_DISTRO`, else
jazzy: `resolve_distro`). `typestore()` is that distribution's store; message definitions, CDR
layouts and type hashes follow it (Jazzy's sensor_msgs/Range has `variance`, Humble's has not).

A message object IS an instance of the type store's dataclass. `new(typename, **fields)` builds one
with ROS 2 default values for every omitted field (0, 0.0, False, "", zero-filled fixed arrays,
empty sequences, default nested messages). Arrays and sequences of numbers (and bool) are numpy
arrays, as rosbags makes them; arrays and sequences of strings or messages are Python lists.

A field description is rosbags' `(Nodetype, detail)` pair: `(BASE, (name, bound))`, `(NAME, typename)`,
`(ARRAY, (element, length))` or `(SEQUENCE, (element, bound))` (bound 0: unbounded).
"""

from __future__ import annotations

import os
from functools import cache
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


#: the supported ROS 2 distributions and rosbags' type store of each
DISTROS = {"humble": Stores.ROS2_HUMBLE, "jazzy": Stores.ROS2_JAZZY, "lyrical": Stores.ROS2_LYRICAL}
DEFAULT_DISTRO = "jazzy"
_distro = [DEFAULT_DISTRO]  # the process's distribution (set by use_distro)


class DistroError(ValueError):
    """An unknown ROS 2 distribution name."""


def resolve_distro(option: str | None = None, environ=None) -> tuple[str, str]:
    """(distribution, where it came from): `option` (--ros-distro), else ROS_DISTRO, else jazzy."""
    environ = os.environ if environ is None else environ
    for value, source in ((option, "--ros-distro"), (environ.get("ROS_DISTRO"), "ROS_DISTRO")):
        if value:
            name = value.strip().lower()
            if name not in DISTROS:
                hint = " (or pass --ros-distro)" if source == "ROS_DISTRO" else ""
                raise DistroError(
                    f"{source}={value!r} is not a supported ROS 2 distribution: use one of {', '.join(DISTROS)}{hint}"
                )
            return name, source
    return DEFAULT_DISTRO, "the default"


def use_distro(name: str) -> None:
    """Make `name` the process's distribution (its type store becomes `typestore()`)."""
    name = name.lower()
    if name not in DISTROS:
        raise DistroError(f"{name!r} is not a supported ROS 2 distribution: use one of {', '.join(DISTROS)}")
    _distro[0] = name


def distro() -> str:
    """The process's ROS 2 distribution ("humble", "jazzy" or "lyrical")."""
    return _distro[0]


@cache
def store_of(name: str):
    """rosbags' type store of a distribution (one per process and distribution)."""
    return get_typestore(DISTROS[name])


def typestore():
    """The process's default type store: the chosen distribution's."""
    return store_of(_distro[0])


def union_fields(typename: str) -> list[tuple[str, tuple]]:
    """The fields of `typename` in every supported distribution: the newest layout's order, then
    fields only older ones have (what the library's Eiffel message classes carry)."""
    seen: dict = {}
    for name in reversed(list(DISTROS)):
        store = store_of(name)
        if typename in store.fielddefs:
            for field, desc in store.fielddefs[typename][1]:
                seen.setdefault(field, desc)
    return list(seen.items())


def store_with(definitions: dict[str, str], base=None):
    """A fresh type store (the process's distribution) in which the given `.msg` definitions
    ({typename: text}) are registered. The default store is never changed."""
    store = get_typestore(DISTROS[_distro[0]])
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


# ---- service types ---------------------------------------------------------------------------------

#: `.srv` definitions known to scoopc (comments left out), from ros2/rcl_interfaces (the parameter
#: services) and ros2/common_interfaces (std_srvs)
SRV_DEFINITIONS = {
    "rcl_interfaces/srv/GetParameters": "string[] names\n---\nParameterValue[] values\n",
    "rcl_interfaces/srv/SetParameters": "Parameter[] parameters\n---\nSetParametersResult[] results\n",
    "rcl_interfaces/srv/SetParametersAtomically": "Parameter[] parameters\n---\nSetParametersResult result\n",
    "rcl_interfaces/srv/ListParameters": (
        "uint64 DEPTH_RECURSIVE=0\nstring[] prefixes\nuint64 depth\n---\nListParametersResult result\n"
    ),
    "rcl_interfaces/srv/DescribeParameters": "string[] names\n---\nParameterDescriptor[] descriptors\n",
    "rcl_interfaces/srv/GetParameterTypes": "string[] names\n---\nuint8[] types\n",
    "std_srvs/srv/Trigger": "---\nbool success\nstring message\n",
    "std_srvs/srv/Empty": "---\n",
    "std_srvs/srv/SetBool": "bool data\n---\nbool success\nstring message\n",
}


def split_srv(text: str) -> tuple[str, ...]:
    """The parts of a `.srv` (request, response) or `.action` (goal, result, feedback) definition."""
    parts, current = [], []
    for line in text.splitlines():
        if line.strip() == "---":
            parts.append("\n".join(current) + "\n")
            current = []
        else:
            current.append(line)
    parts.append("\n".join(current) + "\n")
    return tuple(parts)


@cache
def service_store(distro: str, extra: tuple = ()):
    """A type store of `distro` with every service type of SRV_DEFINITIONS (and `extra`, pairs of
    (srv type, definition)) registered as `<pkg>/srv/<Name>_Request` and `_Response`."""
    store = get_typestore(DISTROS[distro])
    _register_services(store, extra)
    return store


def _register_services(store, extra: tuple = ()) -> None:
    found: dict = {}
    for srvtype, text in (*SRV_DEFINITIONS.items(), *extra):
        package, _, name = srvtype.split("/")
        for half, part in zip(("Request", "Response"), split_srv(text)):
            parsed = get_types_from_msg(part, f"{package}/msg/{name}_{half}")
            found.update(
                {
                    key.replace("/msg/", "/srv/", 1) if key.endswith(f"{name}_{half}") else key: v
                    for key, v in parsed.items()
                }
            )
    store.register(found)


# ---- action types ----------------------------------------------------------------------------------

_NAV2_GOAL = "geometry_msgs/PoseStamped pose\nstring behavior_tree\n"
_NAV2_FEEDBACK = (
    "geometry_msgs/PoseStamped current_pose\nbuiltin_interfaces/Duration navigation_time\n"
    "builtin_interfaces/Duration estimated_time_remaining\nint16 number_of_recoveries\nfloat32 distance_remaining\n"
)
_NAV2_CODES = "uint16 NONE=0\n"
#: `.action` definitions known to scoopc, per distribution (comments left out): nav2_msgs'
#: NavigateToPose (ros-navigation/navigation2, branches humble and jazzy; Lyrical: main as of
#: Lyrical's release, 2026-05-22, nav2 having no lyrical branch) and example_interfaces' Fibonacci
ACTION_DEFINITIONS = {
    "nav2_msgs/action/NavigateToPose": {
        "humble": _NAV2_GOAL + "---\nstd_msgs/Empty result\n---\n" + _NAV2_FEEDBACK,
        "jazzy": _NAV2_GOAL + "---\n" + _NAV2_CODES + "uint16 error_code\nstring error_msg\n---\n" + _NAV2_FEEDBACK,
        "lyrical": _NAV2_GOAL
        + "---\n"
        + _NAV2_CODES
        + "uint16 UNKNOWN=9000\nuint16 FAILED_TO_LOAD_BEHAVIOR_TREE=9001\nuint16 TF_ERROR=9002\nuint16 TIMEOUT=9003\n"
        + "uint16 error_code\nstring error_msg\n---\n"
        + _NAV2_FEEDBACK
        + "float32 position_tracking_error\nfloat32 heading_tracking_error\n",
    },
    "example_interfaces/action/Fibonacci": dict.fromkeys(
        DISTROS, "int32 order\n---\nint32[] sequence\n---\nint32[] sequence\n"
    ),
}
#: the service action_msgs/srv/CancelGoal of every action (ros2/rcl_interfaces, action_msgs)
CANCEL_GOAL = "action_msgs/srv/CancelGoal"
SRV_DEFINITIONS[CANCEL_GOAL] = (
    "GoalInfo goal_info\n---\nint8 ERROR_NONE=0\nint8 ERROR_REJECTED=1\nint8 ERROR_UNKNOWN_GOAL_ID=2\n"
    "int8 ERROR_GOAL_TERMINATED=3\nint8 return_code\nGoalInfo[] goals_canceling\n"
)


def action_definition(actiontype: str, distro: str) -> str:
    """The `.action` text of a known action type in `distro` (KeyError if unknown)."""
    return ACTION_DEFINITIONS[actiontype][distro]


def action_types(actiontype: str) -> dict[str, str]:
    """The message types of an action and their roles, as rosidl derives them
    (rosidl_parser/definition.py, class Action): goal, result, feedback, the send_goal and
    get_result services' requests and responses, and the feedback message."""
    return {
        role: f"{actiontype}_{suffix}"
        for role, suffix in (
            ("goal", "Goal"),
            ("result", "Result"),
            ("feedback", "Feedback"),
            ("send_goal_request", "SendGoal_Request"),
            ("send_goal_response", "SendGoal_Response"),
            ("get_result_request", "GetResult_Request"),
            ("get_result_response", "GetResult_Response"),
            ("feedback_message", "FeedbackMessage"),
        )
    }


@cache
def action_store(distro: str, extra: tuple = ()):
    """A type store of `distro` with every service of SRV_DEFINITIONS and every action of
    ACTION_DEFINITIONS (and `extra`, pairs of (action type, definition)): each action's goal,
    result and feedback from its definition, and the types rosidl derives from them."""
    store = get_typestore(DISTROS[distro])
    _register_services(store)
    uuid, time = (NAME, "unique_identifier_msgs/msg/UUID"), (NAME, "builtin_interfaces/msg/Time")
    known = tuple((name, texts[distro]) for name, texts in ACTION_DEFINITIONS.items() if distro in texts)
    found: dict = {}
    for actiontype, text in (*known, *extra):
        package, _, name = actiontype.split("/")
        names = action_types(actiontype)
        for role, part in zip(("goal", "result", "feedback"), split_srv(text)):
            parsed = get_types_from_msg(part, f"{package}/msg/{name}_{role.capitalize()}")
            found.update(
                {
                    key.replace("/msg/", "/action/", 1) if key.endswith(f"{name}_{role.capitalize()}") else key: v
                    for key, v in parsed.items()
                }
            )
        found[names["send_goal_request"]] = ([], [("goal_id", uuid), ("goal", (NAME, names["goal"]))])
        found[names["send_goal_response"]] = ([], [("accepted", (BASE, ("bool", 0))), ("stamp", time)])
        found[names["get_result_request"]] = ([], [("goal_id", uuid)])
        found[names["get_result_response"]] = (
            [],
            [("status", (BASE, ("int8", 0))), ("result", (NAME, names["result"]))],
        )
        found[names["feedback_message"]] = ([], [("goal_id", uuid), ("feedback", (NAME, names["feedback"]))])
    store.register(found)
    return store
