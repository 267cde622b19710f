"""ROS_PARAMETER's `external "Python"` features (stdlib/roboscoop/communication/ros_parameter.e).

The parameter is declared in the node's ParameterNode (scoopc.robots.parameters; the runtime
service `runner.PARAMETERS` of a ROS 2 run over DDS). A change from outside, on the service's
thread, becomes an ASYNCHRONOUS call of `on_change' on the parameter object's processor, logged by
an outside client of the runtime, as subscriptions deliver messages: no Eiffel field is written
from the transport's thread."""

import scoopc.runtime as rt
from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.robots import runner

_INT32 = (-(2**31), 2**31 - 1)


def _node():
    return rt.current().services.get(runner.PARAMETERS)


def _checker(value):
    if isinstance(value, int) and not isinstance(value, bool):

        def in_range(v):
            return None if _INT32[0] <= v <= _INT32[1] else f"{v} is out of INTEGER's range"

        return in_range
    return None


def _is_string(value) -> bool:
    return hasattr(value, "_s")  # a STRING object of the kernel


def _host(value):
    """The parameter's value as the node keeps it: a STRING's text (its bytes read as UTF-8),
    else the basic value."""
    return strings.shown(value) if _is_string(value) else value


def declare_parameter(current):
    node = _node()
    value = current.item
    name = strings.text(current.name)
    if not (isinstance(value, (bool, int, float)) or (_is_string(value) and strings.is8(value))):
        raise failure(
            current._region_,
            "DEVELOPER_EXCEPTION",
            f"ROS_PARAMETER {name}: a parameter is a BOOLEAN, an INTEGER, a REAL_64 or a STRING",
        )
    value = _host(value)
    if node is None:
        return  # no ROS 2 node: the parameter keeps its value
    try:
        node.declare(name, value, strings.shown(current.description), check=_checker(value))
    except ValueError as e:
        raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_PARAMETER: {e}") from None
    source = rt.outside_client(f"parameter {name}")
    rt.add_shutdown_hook(source.close)

    def changed(parameter, new):
        if parameter == name:
            try:
                source.call(current, _on_change, (new,))
            except Exception:  # noqa: BLE001 - the runtime is shutting down: drop it
                pass

    node.on_set(changed)


def _on_change(current, value):
    if isinstance(value, str):  # a STRING parameter: a new STRING in the parameter's region
        value = strings.new_string_8_of(current._region_, value)
    current.on_change(value)


def publish_item(current):
    node = _node()
    if node is not None:
        node.set(strings.text(current.name), _host(current.item), notify=False)
