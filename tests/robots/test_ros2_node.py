"""Issue 17, "a real node": a scoopc program's DdsBus is a node of the ROS graph. A graph reader built
on rmw_dds_common's definitions (tests/robots/rmw_twin.py GraphReader, as graph_cache.cpp reads the
graph) sees the node, names its endpoints, and decodes ros_discovery_info with the distribution's
Gid (24 bytes in Humble, 16 from Jazzy on). The processes `scoopc run` and `scoopc sim` are checked
in tests/robots/test_ros2_robots.py (slow)."""

import random
import sys
import time
from pathlib import Path

import pytest

pytest.importorskip("cyclonedds")

from scoopc.exits import UsageError  # noqa: E402
from scoopc.robots import backends, dds, graph, ros_messages, runner  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
import rmw_twin  # noqa: E402

TIMEOUT = 30.0


def _until(predicate, timeout=TIMEOUT):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        found = predicate()
        if found:
            return found
        time.sleep(0.02)
    return predicate()


@pytest.mark.parametrize("distro, size", [("humble", 24), ("jazzy", 16)])
def test_a_graph_reader_sees_the_node_and_names_its_endpoints(distro, size, monkeypatch):
    monkeypatch.setenv("ROS_DOMAIN_ID", str(random.randint(100, 200)))
    monkeypatch.setenv(backends.ENV, "dds")
    previous = ros_messages.distro()
    ros_messages.use_distro(distro)
    bus = backends.open_ros2_bus(node=("explorer", "robot1"))
    twin = rmw_twin.Node(distro)
    reader = rmw_twin.GraphReader(twin)
    try:
        bus.subscribe("/robot1/odom", lambda msg: None)
        bus.publish("/robot1/cmd_vel", ros_messages.new("geometry_msgs/msg/Twist"))
        stock = twin.create_publisher("nav_msgs/msg/Odometry", "/robot1/odom")
        assert _until(lambda: reader.nodes()) == ["/robot1/explorer"]
        assert _until(lambda: len(reader.endpoints("/robot1/odom")) == 2)
        assert reader.endpoints("/robot1/odom") == [
            ("reader", "nav_msgs/msg/Odometry", "/robot1/explorer"),
            ("writer", "nav_msgs/msg/Odometry", "_NODE_NAME_UNKNOWN_"),  # the twin publishes no graph info
        ]
        assert _until(lambda: reader.endpoints("/robot1/cmd_vel")) == [
            ("writer", "geometry_msgs/msg/Twist", "/robot1/explorer")
        ]
        assert set(reader.gid_sizes) == {size}
        stock.close()
        # a reader closed later leaves the node's list (the graph is republished on every change)
        bus.subscribe("/robot1/scan", lambda msg: None).close()
        assert _until(lambda: not reader.endpoints("/robot1/scan"))
    finally:
        reader.close()
        twin.close()
        bus.close()
        ros_messages.use_distro(previous)


def test_a_bare_dds_participant_is_not_a_node(monkeypatch):
    """Without the graph node (DdsBus alone) the endpoints belong to no node, as before issue 17."""
    monkeypatch.setenv("ROS_DOMAIN_ID", str(random.randint(100, 200)))
    bus = dds.DdsBus()
    twin = rmw_twin.Node("jazzy")
    reader = rmw_twin.GraphReader(twin)
    try:
        bus.publish("/bare/cmd_vel", ros_messages.new("geometry_msgs/msg/Twist"))
        assert _until(lambda: reader.endpoints("/bare/cmd_vel")) == [
            ("writer", "geometry_msgs/msg/Twist", "_NODE_NAME_UNKNOWN_")
        ]
        assert reader.nodes() == []
    finally:
        reader.close()
        twin.close()
        bus.close()


def test_node_names_and_namespaces():
    assert graph.node_namespace(None) == "/" and graph.node_namespace("robot1/") == "/robot1"
    assert graph.gid_bytes(bytes(range(16)), "humble") == bytes(range(16)) + bytes(8)
    assert graph.gid_bytes(bytes(range(16)), "jazzy") == bytes(range(16))
    assert runner.RobotOptions(node_name="my_node").node_name == "my_node"
    with pytest.raises(UsageError, match="not a valid ROS 2 node name"):
        runner.RobotOptions(node_name="2fast")
