"""Issue 17, "a real node": a scoopc program's DdsBus is a node of the ROS graph. A graph reader built
on rmw_dds_common's definitions (tests/robots/rmw_twin_graph.py GraphReader, as graph_cache.cpp reads the
graph) sees the node, names its endpoints, and decodes ros_discovery_info with the distribution's
Gid (24 bytes in Humble, 16 from Jazzy on). The processes `scoopc run` and `scoopc sim` are checked
in tests/robots/test_ros2_robots.py (slow)."""

import sys
import threading
import time
from pathlib import Path

import domains  # tests/robots/domains.py: a DDS domain per test
import numpy as np
import pytest

pytest.importorskip("cyclonedds")

from scoopc.exits import UsageError  # noqa: E402
from scoopc.robots import backends, dds, graph, ros_messages, runner  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
import rmw_twin  # noqa: E402
import rmw_twin_actions  # noqa: E402
import rmw_twin_graph  # noqa: E402

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
    monkeypatch.setenv("ROS_DOMAIN_ID", str(domains.next_domain()))
    monkeypatch.setenv(backends.ENV, "dds")
    previous = ros_messages.distro()
    ros_messages.use_distro(distro)
    bus = backends.open_ros2_bus(node=("explorer", "robot1"))
    twin = rmw_twin.Node(distro)
    reader = rmw_twin_graph.GraphReader(twin)
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
    monkeypatch.setenv("ROS_DOMAIN_ID", str(domains.next_domain()))
    bus = dds.DdsBus()
    twin = rmw_twin.Node("jazzy")
    reader = rmw_twin_graph.GraphReader(twin)
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


# -- services, both ways, in rmw_cyclonedds_cpp's format ----------------------------------------------------


@pytest.fixture
def bus_and_twin(monkeypatch):
    monkeypatch.setenv("ROS_DOMAIN_ID", str(domains.next_domain()))
    bus = dds.DdsBus()
    twin = rmw_twin.Node(bus.distro)
    yield bus, twin
    twin.close()
    bus.close()


def test_a_service_both_ways_with_a_stock_node(bus_and_twin):
    from scoopc.robots import services

    bus, twin = bus_and_twin
    asked = []

    def answer(request):
        asked.append(request.__msgtype__)
        return server.new_response(success=True, message=f"call {len(asked)}")

    server = services.ServiceServer(bus, "/robot1/reset", "std_srvs/srv/Trigger", answer)
    client = twin.create_client("std_srvs/srv/Trigger", "/robot1/reset")
    assert [client.call(client.new_request(), TIMEOUT).message for _ in range(2)] == ["call 1", "call 2"]
    assert asked == ["std_srvs/srv/Trigger_Request"] * 2

    stock = twin.create_service(
        "std_srvs/srv/Trigger", "/twin/go", lambda request: stock.new_response(success=True, message="stock")
    )
    ours = services.ServiceClient(bus, "/twin/go", "std_srvs/srv/Trigger")
    assert ours.wait_for_service(TIMEOUT)
    reply = ours.call(ours.new_request(), TIMEOUT)
    assert (reply.success, reply.message) == (True, "stock")
    silent = services.ServiceClient(bus, "/nobody/there", "std_srvs/srv/Trigger")
    with pytest.raises(services.ServiceTimeout, match="no reply from /nobody/there within 0.2 s"):
        silent.call(silent.new_request(), 0.2)


def test_a_server_closed_while_answering_still_sends_that_reply(bus_and_twin):
    """close() during a handler (the program's `close' right after its answer counted): the reply of
    the request in progress goes out before the endpoints are deleted; it was dropped."""
    import threading

    from scoopc.robots import services

    bus, twin = bus_and_twin
    closer = []

    def answer(request):
        closer.append(threading.Thread(target=server.close))
        closer[0].start()
        assert _until(lambda: server._closed)  # close has begun: it waits for this reply
        return server.new_response(success=True, message="last")

    server = services.ServiceServer(bus, "/robot1/last", "std_srvs/srv/Trigger", answer)
    client = twin.create_client("std_srvs/srv/Trigger", "/robot1/last")
    assert client.call(client.new_request(), TIMEOUT).message == "last"
    closer[0].join(TIMEOUT)
    assert not closer[0].is_alive() and server._deleted


def test_the_wire_format_is_the_request_header_then_the_message():
    from scoopc.robots import cdr, services

    store = services.service_store("jazzy")
    request = ros_messages.new("std_srvs/srv/SetBool_Request", store=store, data=True)
    body = cdr.serialize(request, "std_srvs/srv/SetBool_Request", store)
    wire = services.request_bytes(7, 3, body)
    assert wire[:4] == b"\x00\x01\x00\x03" and wire[4:20] == (7).to_bytes(8, "little") + (3).to_bytes(8, "little")
    assert wire[20] == 1 and len(wire) % 4 == 0
    assert services.parse_request(wire)[:2] == (7, 3)


# -- parameters: each operation from a stock node ------------------------------------------------------------


def test_each_parameter_operation_from_a_stock_node(bus_and_twin):
    from scoopc.robots import parameters

    bus, twin = bus_and_twin
    node = parameters.ParameterNode(bus, "/robot1/explorer")
    node.declare("use_sim_time", False, "stamp commands with /clock")
    node.declare("nav.speed", 0.2)
    node.declare("nav.mode", "careful", read_only=True)
    changed = []
    node.on_set(lambda name, value: changed.append((name, value)))
    store = twin.store

    def client(name, srvtype):
        return twin.create_client(srvtype, f"/robot1/explorer/{name}")

    def value(kind, **field):
        return rmw_twin.new_message(store, "rcl_interfaces/msg/ParameterValue", type=kind, **field)

    def param(name, v):
        return rmw_twin.new_message(store, "rcl_interfaces/msg/Parameter", name=name, value=v)

    listing = client("list_parameters", "rcl_interfaces/srv/ListParameters")
    result = listing.call(listing.new_request(), TIMEOUT).result
    assert list(result.names) == ["nav.mode", "nav.speed", "use_sim_time"] and list(result.prefixes) == ["nav"]
    result = listing.call(listing.new_request(prefixes=["nav"]), TIMEOUT).result
    assert list(result.names) == ["nav.mode", "nav.speed"]

    getting = client("get_parameters", "rcl_interfaces/srv/GetParameters")
    values = getting.call(getting.new_request(names=["use_sim_time", "nav.speed", "nope"]), TIMEOUT).values
    assert [(v.type, v.bool_value, v.double_value) for v in values] == [
        (1, False, 0.0),
        (3, False, 0.2),
        (0, False, 0.0),
    ]

    setting = client("set_parameters", "rcl_interfaces/srv/SetParameters")
    results = setting.call(
        setting.new_request(
            parameters=[
                param("use_sim_time", value(1, bool_value=True)),
                param("nav.speed", value(4, string_value="fast")),
                param("nav.mode", value(4, string_value="bold")),
                param("nope", value(2, integer_value=1)),
            ]
        ),
        TIMEOUT,
    ).results
    assert [(r.successful, r.reason) for r in results] == [
        (True, ""),
        (False, "parameter nav.speed is a double, not a string"),
        (False, "parameter nav.mode is read-only"),
        (False, "parameter nope is not declared"),
    ]
    assert changed == [("use_sim_time", True)] and node.get("use_sim_time") is True

    atomic = client("set_parameters_atomically", "rcl_interfaces/srv/SetParametersAtomically")
    result = atomic.call(
        atomic.new_request(
            parameters=[param("nav.speed", value(3, double_value=0.5)), param("nope", value(1, bool_value=True))]
        ),
        TIMEOUT,
    ).result
    assert not result.successful and node.get("nav.speed") == 0.2  # all or nothing
    result = atomic.call(atomic.new_request(parameters=[param("nav.speed", value(3, double_value=0.5))]), TIMEOUT)
    assert result.result.successful and node.get("nav.speed") == 0.5

    describing = client("describe_parameters", "rcl_interfaces/srv/DescribeParameters")
    descriptors = describing.call(describing.new_request(names=["use_sim_time", "nav.mode"]), TIMEOUT).descriptors
    assert [(d.name, d.type, d.description, d.read_only) for d in descriptors] == [
        ("use_sim_time", 1, "stamp commands with /clock", False),
        ("nav.mode", 4, "", True),
    ]
    typing = client("get_parameter_types", "rcl_interfaces/srv/GetParameterTypes")
    assert list(typing.call(typing.new_request(names=["nav.mode", "x"]), TIMEOUT).types) == [4, 0]


# -- actions, both ways: feedback, cancel and result ---------------------------------------------------------


def _fibonacci(order):
    sequence = [0, 1]
    while len(sequence) < order + 1:
        sequence.append(sequence[-1] + sequence[-2])
    return sequence[: order + 1]


def test_an_action_of_a_stock_server_with_feedback_cancel_and_result(monkeypatch):
    """Our ActionClient against the twin's action server (rcl_action's names, types and QoS)."""
    from scoopc.robots import actions

    monkeypatch.setenv("ROS_DOMAIN_ID", str(domains.next_domain()))
    bus = dds.DdsBus()
    twin = rmw_twin.Node(bus.distro)
    release = {}

    def execute(goal):  # Fibonacci, one number per feedback; waits for the test before the last
        for n in range(1, int(goal.goal.order) + 1):
            if goal.cancel_requested:
                goal.finish(5, sequence=np.array(_fibonacci(n - 1), dtype=np.int32))
                return
            goal.publish_feedback(sequence=np.array(_fibonacci(n), dtype=np.int32))
            if n == 2:
                release.setdefault(goal.id, threading.Event()).wait(TIMEOUT)
        goal.finish(4, sequence=np.array(_fibonacci(int(goal.goal.order)), dtype=np.int32))

    try:
        server = rmw_twin_actions.TwinActionServer(twin, "example_interfaces/action/Fibonacci", "/fib", execute)
        client = actions.ActionClient(bus, "/fib", "example_interfaces/action/Fibonacci")
        assert client.wait_for_server(TIMEOUT)
        statuses, feedback = [], []
        goal = client.send_goal(
            client.new_goal(order=4),
            TIMEOUT,
            on_feedback=lambda f: feedback.append(list(f.sequence)),
            on_status=statuses.append,
        )
        assert goal.accepted and server.events == [("goal", goal.id)]
        assert _until(lambda: len(feedback) == 2)
        release.setdefault(goal.id, threading.Event()).set()
        assert goal.done.wait(TIMEOUT)
        assert goal.status == actions.SUCCEEDED and list(goal.result.sequence) == [0, 1, 1, 2, 3]
        assert feedback == [[0, 1], [0, 1, 1], [0, 1, 1, 2], [0, 1, 1, 2, 3]]
        assert statuses[0] == actions.ACCEPTED and statuses[-1] == actions.SUCCEEDED
        # a goal cancelled while it runs ends CANCELED, its result what the server made of it
        second = client.send_goal(client.new_goal(order=5), TIMEOUT)
        assert _until(lambda: second.feedback is not None and len(second.feedback.sequence) == 3)
        replies = []
        second.cancel(replies.append)
        assert _until(lambda: replies) == [actions.CANCEL_NONE]
        release.setdefault(second.id, threading.Event()).set()
        assert second.done.wait(TIMEOUT)
        assert second.status == actions.CANCELED and list(second.result.sequence) == [0, 1, 1]
        assert ("cancel", second.id) in server.events
    finally:
        for event in release.values():
            event.set()
        twin.close()
        bus.close()


def test_our_action_server_to_a_stock_client(monkeypatch):
    """The twin's action client against our ActionServer: status on the transient-local status
    topic, feedback by goal id, a cancel request, results, an unknown goal's result."""
    from scoopc.robots import actions

    monkeypatch.setenv("ROS_DOMAIN_ID", str(domains.next_domain()))
    bus = dds.DdsBus()
    twin = rmw_twin.Node(bus.distro)
    go = threading.Event()

    def run(goal):
        goal.execute()
        for n in range(1, int(goal.goal.order) + 1):
            if goal.status == actions.CANCELING:
                goal.canceled(server.new_result(sequence=np.array(_fibonacci(n - 1), dtype=np.int32)))
                return
            goal.publish_feedback(server.new_feedback(sequence=np.array(_fibonacci(n), dtype=np.int32)))
            go.wait(TIMEOUT)
        goal.succeed(server.new_result(sequence=np.array(_fibonacci(int(goal.goal.order)), dtype=np.int32)))

    workers = []

    def accepted(goal):  # each goal on a thread of the test's own, joined at the end
        workers.append(threading.Thread(target=run, args=(goal,)))
        workers[-1].start()

    server = actions.ActionServer(bus, "/fib", "example_interfaces/action/Fibonacci", on_accepted=accepted)
    try:
        client = rmw_twin_actions.TwinActionClient(twin, "example_interfaces/action/Fibonacci", "/fib")
        first = client.send_goal(order=3)
        go.set()
        done = client.result(first)
        assert (done.status, list(done.result.sequence)) == (actions.SUCCEEDED, [0, 1, 1, 2])
        assert [list(f.sequence) for f in client.feedback_of(first, 3)] == [[0, 1], [0, 1, 1], [0, 1, 1, 2]]
        assert _until(lambda: client.statuses_of(first)[-1:] == [actions.SUCCEEDED])
        go.clear()
        second = client.send_goal(order=4)
        assert _until(lambda: client.feedback_of(second))
        cancel = client.cancel(second)
        assert cancel.return_code == actions.CANCEL_NONE and bytes(cancel.goals_canceling[0].goal_id.uuid) == second
        go.set()
        done = client.result(second)
        assert done.status == actions.CANCELED
        assert client.cancel(second).return_code == actions.CANCEL_TERMINATED
        assert client.result(bytes(16)).status == actions.UNKNOWN
        assert actions.CANCELING in client.statuses_of(second)
    finally:
        go.set()
        for worker in workers:
            worker.join()
        twin.close()
        server.close()
        bus.close()


@pytest.mark.slow  # compiles a program
def test_an_action_client_off_dds_says_why_it_cannot_send():
    """On a transport without a DDS participant (here `--robot none`) `is_available` is False and
    `send_goal` raises an Eiffel exception that names what is needed."""
    import io

    import scoopc

    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([Path(__file__).parent / "programs" / "action_off_dds"], robot="none", stdout=out, stderr=err)
    assert result.status == 3 and out.getvalue() == "available False\n", err.getvalue()
    assert (
        "ROS_ACTION_CLIENT /fib: ROS 2 actions need a ROS 2 robot over DDS (scoopc run --robot ros2)" in err.getvalue()
    )
    assert "Traceback" not in err.getvalue()
