"""ROS 2 backend selection (scoopc.robots.backends): SCOOPC_ROS2_BACKEND, rclpy forced but missing,
the fallback to DdsBus. rclpy cannot be installed here: its presence is simulated with a stand-in
module, and RclpyBus runs only against a stand-in of the rclpy calls it makes (its CDR conversion,
subscriptions, taps and shutdown), never against rclpy itself (see rclpy_bus.py's note)."""

import io
import os
import sys
import time
import types

import domains  # tests/robots/domains.py: a DDS domain per test, disjoint per worker
import pytest

from scoopc.robots import backends, rclpy_bus

pytest.importorskip("cyclonedds")


@pytest.fixture(autouse=True)
def environment(monkeypatch, tmp_path):
    """Loopback DDS in a test domain; no backend chosen by the caller's environment."""
    from scoopc.robots import dds

    for name, value in dds.loopback_environment(tmp_path, domains.next_domain()).items():
        monkeypatch.setenv(name, value)
    monkeypatch.delenv(backends.ENV, raising=False)


@pytest.fixture
def no_rclpy(monkeypatch):
    monkeypatch.setitem(sys.modules, "rclpy", None)  # `import rclpy` raises ImportError


@pytest.fixture
def fake_rclpy(monkeypatch):
    """An importable `rclpy`, and a stand-in RclpyBus that records how it was opened."""
    monkeypatch.setitem(sys.modules, "rclpy", types.ModuleType("rclpy"))

    class StandIn:
        def __init__(self, domain=None, types=None, writer_qos=None, report=None, node_name=None, namespace=None):
            self.domain, self.types = domain, types

    monkeypatch.setattr(rclpy_bus, "RclpyBus", StandIn)
    return StandIn


def test_requested_reads_the_variable_and_checks_it(monkeypatch):
    assert backends.requested() == "auto"
    for value, expected in (("dds", "dds"), ("RCLPY", "rclpy"), (" auto ", "auto"), ("", "auto")):
        monkeypatch.setenv(backends.ENV, value)
        assert backends.requested() == expected
    assert backends.requested("dds") == "dds"  # an explicit choice wins over the variable
    monkeypatch.setenv(backends.ENV, "fastdds")
    with pytest.raises(backends.BackendError, match="SCOOPC_ROS2_BACKEND='fastdds' is not a ROS 2 backend"):
        backends.requested()
    with pytest.raises(backends.BackendError, match="auto, rclpy, dds"):
        backends.open_ros2_bus()


def test_rclpy_forced_but_missing_is_a_clear_error(monkeypatch, no_rclpy):
    assert "Error" in backends.rclpy_problem()
    monkeypatch.setenv(backends.ENV, "rclpy")
    with pytest.raises(backends.BackendError) as caught:
        backends.open_ros2_bus()
    text = str(caught.value)
    assert "SCOOPC_ROS2_BACKEND=rclpy but rclpy cannot be imported" in text
    assert "source" in text and "SCOOPC_ROS2_BACKEND=dds" in text
    with pytest.raises(backends.BackendError):
        backends.resolve("rclpy")


def test_auto_falls_back_to_dds_when_rclpy_is_missing(no_rclpy):
    from scoopc.robots.dds import DdsBus

    assert backends.resolve() == "dds"
    bus = backends.open_ros2_bus(domain=int(os.environ["ROS_DOMAIN_ID"]), types={"/chatter": "std_msgs/msg/String"})
    try:
        assert isinstance(bus, DdsBus) and backends.describe(bus) == "dds"
        assert bus.domain == int(os.environ["ROS_DOMAIN_ID"]) and bus.types == {"/chatter": "std_msgs/msg/String"}
    finally:
        bus.close()


def test_auto_prefers_rclpy_when_importable(fake_rclpy):
    assert backends.rclpy_problem() is None
    assert backends.resolve() == "rclpy" == backends.resolve("rclpy")
    bus = backends.open_ros2_bus(domain=7)
    assert isinstance(bus, fake_rclpy) and bus.domain == 7
    assert backends.describe(bus) == "StandIn"


def test_dds_forced_even_when_rclpy_is_there(monkeypatch, fake_rclpy):
    from scoopc.robots.dds import DdsBus

    monkeypatch.setenv(backends.ENV, "dds")
    assert backends.resolve() == "dds"
    bus = backends.open_ros2_bus()
    try:
        assert isinstance(bus, DdsBus) and bus.domain == int(os.environ["ROS_DOMAIN_ID"])
    finally:
        bus.close()


def test_rclpy_bus_without_rclpy_says_so():
    if rclpy_bus.rclpy is not None:  # a ROS 2 environment: nothing to check here
        pytest.skip("rclpy is importable")
    with pytest.raises(ImportError, match="source a ROS 2 installation"):
        rclpy_bus.RclpyBus()


# -- RclpyBus against a stand-in of the rclpy API it calls (not rclpy itself: see the module's note) --
class FakeRclpy:
    """The few rclpy calls RclpyBus makes; a publication is delivered at once, as bytes, to every
    raw subscription of the same topic (like a ROS graph with one process)."""

    def __init__(self):
        self.subscriptions, self.published, self.inits, self.qos, self.events = [], [], [], {}, {}
        self.graph = []  # [(topic, type, "publisher" or "subscription")] of other nodes
        fake = self

        class Context:
            def __init__(self):
                self.shut = False

            def ok(self):
                return not self.shut

            def try_shutdown(self):
                self.shut = True

        class Publisher:
            def __init__(self, topic):
                self.topic = topic

            def publish(self, data):
                assert isinstance(data, bytes)
                fake.published.append((self.topic, data))
                for topic, callback, raw in list(fake.subscriptions):
                    if topic == self.topic and raw:
                        callback(data)

            def get_subscription_count(self):
                return sum(topic == self.topic for topic, _, _ in fake.subscriptions)

        class Node:
            def create_publisher(self, msgclass, topic, qos, event_callbacks=None):
                fake.qos[topic] = qos
                fake.events[("publisher", topic)] = event_callbacks
                return Publisher(topic)

            def create_subscription(self, msgclass, topic, callback, qos, event_callbacks=None, raw=False):
                entry = (topic, callback, raw)
                fake.subscriptions.append(entry)
                fake.events[("subscription", topic)] = event_callbacks
                fake.qos[("subscription", topic)] = qos
                return entry

            def get_topic_names_and_types(self):
                return [(topic, [typename]) for topic, typename, _ in fake.graph]

            def _infos(self, topic, kind):
                return [
                    types.SimpleNamespace(topic_type=typename)
                    for t, typename, k in fake.graph
                    if t == topic and k == kind
                ]

            def get_publishers_info_by_topic(self, topic):
                return self._infos(topic, "publisher")

            def get_subscriptions_info_by_topic(self, topic):
                return self._infos(topic, "subscription")

            def destroy_subscription(self, entry):
                fake.subscriptions.remove(entry)

            def count_publishers(self, topic):
                return sum(t == topic for t, _ in fake.published) + len(self._infos(topic, "publisher"))

            def destroy_node(self):
                fake.destroyed = True

        class Executor:
            def __init__(self, context):
                self.context = context

            def add_node(self, node):
                pass

            def spin_once(self, timeout_sec):
                time.sleep(timeout_sec / 10)

            def shutdown(self):
                pass

        rclpy = types.ModuleType("rclpy")
        rclpy.Context = Context
        rclpy.init = lambda context, domain_id=None: fake.inits.append(domain_id)
        rclpy.create_node = lambda name, context, namespace=None: Node()
        executors = types.ModuleType("rclpy.executors")
        executors.SingleThreadedExecutor = Executor
        qos = types.ModuleType("rclpy.qos")
        qos.HistoryPolicy = types.SimpleNamespace(KEEP_LAST="keep_last")
        qos.ReliabilityPolicy = types.SimpleNamespace(BEST_EFFORT="best_effort", RELIABLE="reliable")
        qos.QoSProfile = lambda **kw: ("profile", tuple(sorted(kw.items())))
        qos.qos_profile_sensor_data = "sensor_data"
        events = types.ModuleType("rclpy.event_handler")

        class Callbacks:
            def __init__(self, incompatible_qos=None):
                self.incompatible_qos = incompatible_qos

        events.PublisherEventCallbacks = events.SubscriptionEventCallbacks = Callbacks
        utilities = types.ModuleType("rosidl_runtime_py.utilities")
        utilities.get_message = lambda typename: typename
        self.modules = {
            "rclpy": rclpy,
            "rclpy.executors": executors,
            "rclpy.qos": qos,
            "rclpy.event_handler": events,
            "rosidl_runtime_py": types.ModuleType("rosidl_runtime_py"),
            "rosidl_runtime_py.utilities": utilities,
        }


@pytest.fixture
def fake_ros():
    import importlib

    fake = FakeRclpy()
    saved = {name: sys.modules.get(name) for name in fake.modules}
    sys.modules.update(fake.modules)
    module = importlib.reload(rclpy_bus)
    yield fake, module
    for name, value in saved.items():
        if value is None:
            sys.modules.pop(name, None)
        else:
            sys.modules[name] = value
    importlib.reload(rclpy_bus)


def test_rclpy_bus_converts_through_cdr_on_the_rclpy_api(fake_ros):
    from scoopc.robots import cdr, ros_messages

    fake, module = fake_ros
    bus = module.RclpyBus(domain=5)
    got, raw, tapped = [], [], []
    bus.tap(lambda topic, msg: tapped.append((topic, msg.__msgtype__)))
    bus.subscribe("/robot1/cmd_vel", got.append)
    bus.subscribe("/robot1/cmd_vel", raw.append, raw=True)
    assert bus.wait_for_subscriber("/robot1/cmd_vel", 1) and bus.subscriber_count("/robot1/cmd_vel") == 2
    sent = ros_messages.new("geometry_msgs/msg/Twist", linear=ros_messages.new("geometry_msgs/msg/Vector3", x=0.3))
    bus.publish("/robot1/cmd_vel", sent)
    assert fake.inits == [5] and fake.published == [("/robot1/cmd_vel", cdr.serialize(sent))]
    assert [m.linear.x for m in got] == [0.3] and raw == [cdr.serialize(sent)]
    bus.publish("/robot1/odom", ros_messages.new("nav_msgs/msg/Odometry"))  # not subscribed: tapped here
    assert (
        tapped
        == [
            ("/robot1/cmd_vel", "geometry_msgs/msg/Twist"),  # each once
            ("/robot1/odom", "nav_msgs/msg/Odometry"),
        ]
        and bus.errors == []
    )
    assert fake.qos["/robot1/odom"] == "sensor_data" and fake.qos["/robot1/cmd_vel"][0] == "profile"
    assert bus.wait_for_publisher("/robot1/odom", 1) and bus.topics() == ["/robot1/cmd_vel"]
    with pytest.raises(TypeError):
        bus.publish("/robot1/cmd_vel", ros_messages.new("std_msgs/msg/String"))
    bus.close()
    assert fake.destroyed and not bus._thread.is_alive()
    with pytest.raises(RuntimeError):
        bus.publish("/robot1/cmd_vel", sent)


def test_rclpy_bus_reports_what_rclpy_tells(fake_ros):
    """The reports of a ROS 2 run on RclpyBus: QoS incompatibilities from rclpy's incompatible_qos
    events (each topic once, worded as DdsBus), silent topics with the graph's nearby names, and a
    velocity topic read with another type, through silence.Watch as `scoopc run` uses it."""
    from scoopc.robots import ros_messages, silence

    fake, module = fake_ros
    told = []
    bus = module.RclpyBus(reader_qos={"/robot1/odom": ("reliable", 1)}, report=told.append)
    bus.subscribe("/robot1/odom", lambda msg: None)
    bus.subscribe("/robot1/scan", lambda msg: None)
    bus.publish("/robot1/cmd_vel", ros_messages.new("geometry_msgs/msg/Twist"))
    profile = ("profile", (("depth", 1), ("history", "keep_last"), ("reliability", "reliable")))
    assert fake.qos[("subscription", "/robot1/odom")] == profile
    reliability = types.SimpleNamespace(last_policy_kind=1 << 4, total_count=1)
    for _ in range(2):  # told twice by rclpy, reported once
        fake.events[("subscription", "/robot1/odom")].incompatible_qos(reliability)
    fake.events[("publisher", "/robot1/cmd_vel")].incompatible_qos(types.SimpleNamespace(last_policy_kind=1 << 1))
    assert bus.check_qos() == [
        "/robot1/odom: the publisher is best effort, this reader asks reliable",
        "/robot1/cmd_vel: a subscriber's QoS is incompatible with this publisher's (durability)",
    ]
    assert bus.check_qos() == [] and len(told) == 2
    fake.graph = [
        ("/odom", "nav_msgs/msg/Odometry", "publisher"),
        ("/robot1/cmd_vel", "geometry_msgs/msg/TwistStamped", "subscription"),
    ]
    fake.subscriptions[:] = [s for s in fake.subscriptions if s[0] != "/robot1/cmd_vel"]
    bus.publish("/robot1/scan", ros_messages.new("sensor_msgs/msg/LaserScan"))  # heard once
    assert bus.heard() == {"/robot1/odom": (0, 0), "/robot1/scan": (1, 1)}
    out = io.StringIO()
    watch = silence.Watch(bus, 3, False, out)
    assert watch.report_silence()
    text = out.getvalue()
    assert "nothing heard on /robot1/odom (no publisher)" in text
    assert "/odom (this program asked /robot1/odom): is the namespace right?" in text
    assert "/robot1/cmd_vel: the robot reads geometry_msgs/msg/TwistStamped, this program sends" in text
    out.truncate(0)
    watch.summary()
    assert "heard /robot1/scan (1); nothing on /robot1/odom" in out.getvalue()
    bus.close()
