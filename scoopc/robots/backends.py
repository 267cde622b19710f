"""Which ROS 2 transport a program talks through: rclpy when it is importable, else our DdsBus.

`open_ros2_bus(domain=None)` gives a bus with the interface of `bus.Bus` (publish, subscribe,
subscriber_count, topics, wait_for_subscriber, close) on ROS 2:

* `rclpy`: `rclpy_bus.RclpyBus`, a node of a sourced ROS 2 installation (any RMW it is set up with);
* `dds`: `dds.DdsBus`, ROS 2's conventions spoken over cyclonedds directly (no ROS installation).

The environment variable SCOOPC_ROS2_BACKEND chooses: `auto` (the default: rclpy when importable,
else dds), `rclpy` (an error when rclpy cannot be imported) or `dds`. An explicit `backend=`
argument wins over the variable.
"""

from __future__ import annotations

import importlib
import os

ENV = "SCOOPC_ROS2_BACKEND"
CHOICES = ("auto", "rclpy", "dds")


class BackendError(RuntimeError):
    """The requested ROS 2 backend is unknown or cannot be used here."""


def requested(backend: str | None = None) -> str:
    """The backend asked for: `backend`, else SCOOPC_ROS2_BACKEND, else "auto" (checked)."""
    choice = backend if backend is not None else os.environ.get(ENV, "")
    choice = (choice or "auto").strip().lower()
    if choice not in CHOICES:
        source = "backend" if backend is not None else ENV
        raise BackendError(f"{source}={choice!r} is not a ROS 2 backend: use one of {', '.join(CHOICES)}")
    return choice


def rclpy_problem() -> str | None:
    """Why rclpy cannot be used (None when `import rclpy` works)."""
    try:
        importlib.import_module("rclpy")
    except ImportError as e:
        return f"{type(e).__name__}: {e}"
    except Exception as e:  # a broken ROS 2 environment fails in other ways too
        return f"{type(e).__name__}: {e}"
    return None


def resolve(backend: str | None = None) -> str:
    """ "rclpy" or "dds": the backend `open_ros2_bus` would use now."""
    choice = requested(backend)
    if choice == "dds":
        return "dds"
    problem = rclpy_problem()
    if choice == "rclpy" and problem is not None:
        raise BackendError(
            f"{ENV}=rclpy but rclpy cannot be imported ({problem}). Source a ROS 2 installation "
            f"(e.g. `source /opt/ros/jazzy/setup.bash`) in this shell, or set {ENV}=dds (or auto) "
            f"to speak ROS 2 over cyclonedds without rclpy."
        )
    return "rclpy" if problem is None else "dds"


def open_ros2_bus(
    domain: int | None = None,
    *,
    backend: str | None = None,
    types: dict | None = None,
    writer_qos: dict | None = None,
    report=None,
    node: tuple | None = None,
):
    """A ROS 2 bus on `domain` (None: ROS_DOMAIN_ID, default 0), through the chosen backend;
    `writer_qos` ({topic: (reliability, depth)}) and `report` (QoS incompatibilities) as DdsBus takes them;
    `node` (name, namespace): the bus is that node of the ROS graph (DdsBus: scoopc.robots.graph)."""
    if resolve(backend) == "rclpy":
        from .rclpy_bus import RclpyBus  # deferred: start-up (scoopc.robots.rclpy_bus loads only when this is used)

        name, namespace = node or ("scoopc", None)
        return RclpyBus(
            domain=domain, types=types, writer_qos=writer_qos, report=report, node_name=name, namespace=namespace
        )
    from .dds import DdsBus  # deferred: start-up (scoopc.robots.dds loads only when this is used)

    bus = DdsBus(domain=domain, types=types, writer_qos=writer_qos, report=report)
    if node is not None:
        from .graph import GraphNode  # deferred: start-up (scoopc.robots.graph loads only when this is used)

        try:
            GraphNode(bus, *node)
        except Exception:
            bus.close()
            raise
    return bus


def describe(bus) -> str:
    """A short name of a bus's backend for messages ("rclpy", "dds", "in-process")."""
    name = type(bus).__name__
    return {"RclpyBus": "rclpy", "DdsBus": "dds"}.get(name, "in-process" if name == "Bus" else name)
