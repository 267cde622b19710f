"""A node's parameters and the parameter services of ROS 2 (`ros2 param list/get/set/describe`):
`ParameterNode(bus, node)` answers `<node>/list_parameters`, `get_parameters`, `set_parameters`,
`set_parameters_atomically`, `describe_parameters` and `get_parameter_types`
(rcl_interfaces/srv, as rclpy's ParameterService offers them, rclpy/parameter_service.py) over a
DdsBus's services (scoopc.robots.services). Parameters hold booleans, integers, doubles and
strings (rcl_interfaces/msg/ParameterType 1 to 4); a parameter's type is fixed when it is
declared, as in rclpy without dynamic typing. `on_set(name, value)` callbacks run after a change.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np

from . import ros_messages, velocity
from .graph import node_namespace
from .services import ServiceServer, service_store

NOT_SET, BOOL, INTEGER, DOUBLE, STRING = 0, 1, 2, 3, 4  # rcl_interfaces/msg/ParameterType
_FIELDS = {BOOL: "bool_value", INTEGER: "integer_value", DOUBLE: "double_value", STRING: "string_value"}
_TYPE_NAMES = {BOOL: "a bool", INTEGER: "an integer", DOUBLE: "a double", STRING: "a string"}
SERVICES = {
    "list_parameters": "rcl_interfaces/srv/ListParameters",
    "get_parameters": "rcl_interfaces/srv/GetParameters",
    "set_parameters": "rcl_interfaces/srv/SetParameters",
    "set_parameters_atomically": "rcl_interfaces/srv/SetParametersAtomically",
    "describe_parameters": "rcl_interfaces/srv/DescribeParameters",
    "get_parameter_types": "rcl_interfaces/srv/GetParameterTypes",
}


def type_of(value) -> int:
    if isinstance(value, bool):
        return BOOL
    if isinstance(value, int):
        return INTEGER
    if isinstance(value, float):
        return DOUBLE
    if isinstance(value, str):
        return STRING
    raise TypeError(f"parameters hold booleans, integers, doubles and strings, not {type(value).__name__}")


@dataclass
class Parameter:
    name: str
    type: int
    value: object
    description: str = ""
    read_only: bool = False
    check: object = None  # value -> None, or why it cannot be taken (a range)


class ParameterNode:
    """The parameters of the node `node` ("/robot1/explorer") and their services on `bus`."""

    def __init__(self, bus, node: str):
        self.bus, self.node = bus, node.rstrip("/") or "/"
        self._lock = threading.Lock()
        self._params: dict[str, Parameter] = {}  # [_lock]
        self._callbacks = []  # on_set(name, value), called after a change, outside the lock
        self.store = service_store(bus.distro)  # before the servers: a request may come at once
        prefix = "" if self.node == "/" else self.node
        self.servers = [
            ServiceServer(bus, f"{prefix}/{service}", srvtype, getattr(self, f"_{service}"))
            for service, srvtype in SERVICES.items()
        ]

    # -- the program's side ----------------------------------------------------------------------
    def declare(self, name: str, value, description: str = "", read_only: bool = False, check=None) -> None:
        with self._lock:
            if name in self._params:
                raise ValueError(f"parameter {name} is already declared")
            self._params[name] = Parameter(name, type_of(value), value, description, read_only, check)

    def get(self, name: str):
        with self._lock:
            return self._params[name].value

    def set(self, name: str, value, notify: bool = True) -> str | None:
        """Set a declared parameter: None when done, else why not (the reason services report);
        `notify=False`: the `on_set` callbacks are not called (the program set it itself)."""
        return self._set_all([(name, value)], notify)

    def on_set(self, callback) -> None:
        self._callbacks.append(callback)

    def _check(self, name: str, value) -> str | None:  # [_lock]
        known = self._params.get(name)
        if known is None:
            return f"parameter {name} is not declared"
        if known.read_only:
            return f"parameter {name} is read-only"
        try:
            kind = type_of(value)
        except TypeError as e:
            return str(e)
        if kind != known.type:
            return f"parameter {name} is {_TYPE_NAMES[known.type]}, not {_TYPE_NAMES.get(kind, 'a value')}"
        return known.check(value) if known.check is not None else None

    def _set_all(self, changes, notify: bool = True) -> str | None:
        with self._lock:
            for name, value in changes:
                why = self._check(name, value)
                if why is not None:
                    return why
            for name, value in changes:
                self._params[name].value = value
        for name, value in changes if notify else ():
            for callback in list(self._callbacks):
                callback(name, value)
        return None

    # -- the services ----------------------------------------------------------------------------
    def _response(self, srvtype: str, **fields):
        return ros_messages.new(f"{srvtype}_Response", store=self.store, **fields)

    def _value_msg(self, store, param: Parameter | None):
        if param is None:
            return ros_messages.new("rcl_interfaces/msg/ParameterValue", store=store, type=NOT_SET)
        return ros_messages.new(
            "rcl_interfaces/msg/ParameterValue", store=store, type=param.type, **{_FIELDS[param.type]: param.value}
        )

    @staticmethod
    def _value_of(msg):
        """The Python value of a ParameterValue message, or the reason it cannot be used."""
        kind = int(msg.type)
        if kind not in _FIELDS:
            return None, f"parameter type {kind} is not supported (booleans, integers, doubles and strings are)"
        value = getattr(msg, _FIELDS[kind])
        return {BOOL: bool, INTEGER: int, DOUBLE: float, STRING: str}[kind](value), None

    def _result(self, store, why):
        return ros_messages.new(
            "rcl_interfaces/msg/SetParametersResult", store=store, successful=why is None, reason=why or ""
        )

    def _list_parameters(self, request):
        depth, prefixes = int(request.depth), list(request.prefixes)
        with self._lock:
            names = sorted(self._params)
        chosen = []
        for name in names:
            if prefixes:
                inside = [p for p in prefixes if name == p or name.startswith(p + ".")]
                if not inside or (depth and name[len(inside[0]) :].count(".") >= depth):
                    continue
            elif depth and name.count(".") >= depth:
                continue
            chosen.append(name)
        found_prefixes = sorted({n.rsplit(".", 1)[0] for n in chosen if "." in n})
        result = ros_messages.new(
            "rcl_interfaces/msg/ListParametersResult", store=self.store, names=chosen, prefixes=found_prefixes
        )
        return self._response(SERVICES["list_parameters"], result=result)

    def _get_parameters(self, request):
        with self._lock:
            found = [self._params.get(name) for name in request.names]
        return self._response(SERVICES["get_parameters"], values=[self._value_msg(self.store, p) for p in found])

    def _changes(self, parameters):
        changes, why = [], None
        for p in parameters:
            value, why = self._value_of(p.value)
            if why is not None:
                return None, why
            changes.append((p.name, value))
        return changes, None

    def _set_parameters(self, request):
        results = []
        for p in request.parameters:
            value, why = self._value_of(p.value)
            if why is None:
                why = self._set_all([(p.name, value)])
            results.append(self._result(self.store, why))
        return self._response(SERVICES["set_parameters"], results=results)

    def _set_parameters_atomically(self, request):
        changes, why = self._changes(request.parameters)
        if why is None:
            why = self._set_all(changes)
        return self._response(SERVICES["set_parameters_atomically"], result=self._result(self.store, why))

    def _describe_parameters(self, request):
        with self._lock:
            found = [(name, self._params.get(name)) for name in request.names]
        descriptors = [
            ros_messages.new(
                "rcl_interfaces/msg/ParameterDescriptor",
                store=self.store,
                name=name,
                type=p.type if p else NOT_SET,
                description=p.description if p else "",
                read_only=p.read_only if p else False,
            )
            for name, p in found
        ]
        return self._response(SERVICES["describe_parameters"], descriptors=descriptors)

    def _get_parameter_types(self, request):
        with self._lock:
            kinds = [self._params[n].type if n in self._params else NOT_SET for n in request.names]
        return self._response(SERVICES["get_parameter_types"], types=np.array(kinds, dtype=np.uint8))

    def close(self) -> None:
        for server in self.servers:
            server.close()


def node_parameters(bus, name: str, namespace: str | None, use_sim_time: bool) -> ParameterNode:
    """The parameters of a ROS 2 run's node `name` under `namespace`: `use_sim_time` (its start
    value given), which switches command stamps between the system clock and /clock
    (scoopc.robots.velocity). The services close with the bus."""
    node = ParameterNode(bus, node_namespace(namespace).rstrip("/") + "/" + name)
    node.declare("use_sim_time", bool(use_sim_time), "stamp commands with /clock instead of the system clock")
    clocks = []

    def switch(parameter, value):
        if parameter == "use_sim_time":
            if value and not clocks:
                clocks.append(velocity.sim_time(bus))
            velocity.use_clock(clocks[0] if value else None)

    node.on_set(switch)
    return node
