"""DdsBus: ROS 2 conventions over cyclonedds, on loopback only (CYCLONEDDS_URI set before any participant)."""

import math
import os
import subprocess
import sys
import textwrap
import threading
import time

import domains  # tests/robots/domains.py: a DDS domain per test, disjoint per worker
import numpy as np
import pytest

pytest.importorskip("cyclonedds")

from scoopc.robots import cdr, dds, ros_messages  # noqa: E402

TIMEOUT = 10.0


@pytest.fixture(scope="module", autouse=True)
def loopback(tmp_path_factory):
    """Loopback-only DDS in a domain unlikely to clash; restores the environment afterwards."""
    path = tmp_path_factory.mktemp("dds") / "cyclonedds.xml"
    path.write_text(dds.LOOPBACK_CONFIG)
    saved = {name: os.environ.get(name) for name in ("CYCLONEDDS_URI", "ROS_DOMAIN_ID")}
    os.environ["CYCLONEDDS_URI"] = path.as_uri()
    os.environ["ROS_DOMAIN_ID"] = str(domains.next_domain())
    yield
    for name, value in saved.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value


@pytest.fixture
def buses():
    made = []

    def make(**kwargs):
        bus = dds.DdsBus(**kwargs)
        made.append(bus)
        return bus

    yield make
    for bus in made:
        bus.close()


class Inbox:
    """Collects messages from a reader thread; `get()` waits for the next one (event, timeout)."""

    def __init__(self):
        self.items = []
        self.cond = threading.Condition()

    def __call__(self, msg):
        with self.cond:
            self.items.append(msg)
            self.cond.notify_all()

    def get(self, index=0, timeout=TIMEOUT):
        with self.cond:
            assert self.cond.wait_for(lambda: len(self.items) > index, timeout), "no message delivered"
            return self.items[index]


def twist(lx=0.25, az=-1.5):
    msg = ros_messages.new("geometry_msgs/msg/Twist")
    msg.linear.x, msg.angular.z = lx, az
    return msg


def odometry():
    msg = ros_messages.new("nav_msgs/msg/Odometry", child_frame_id="robot1/base_link")
    msg.header.frame_id = "odom"
    msg.header.stamp.sec, msg.header.stamp.nanosec = 12, 345_000_000
    msg.pose.pose.position.x, msg.pose.pose.position.y = 1.5, -0.75
    msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(0.3), math.cos(0.3)
    msg.pose.covariance = np.arange(36, dtype=np.float64) / 10
    msg.twist.twist.linear.x, msg.twist.twist.angular.z = 0.1, 0.2
    return msg


def assert_same(a, b):
    assert cdr.serialize(a) == cdr.serialize(b)
    assert a.__msgtype__ == b.__msgtype__


# -- conventions ---------------------------------------------------------------------------------
def test_names_types_and_qos_families():
    assert dds.dds_topic_name("/cmd_vel") == "rt/cmd_vel"
    assert dds.dds_topic_name("/robot1/cmd_vel") == "rt/robot1/cmd_vel"
    assert dds.dds_type_name("geometry_msgs/msg/Twist") == "geometry_msgs::msg::dds_::Twist_"
    assert dds.dds_type_name("nav_msgs/msg/Odometry") == "nav_msgs::msg::dds_::Odometry_"
    with pytest.raises(ValueError):
        dds.dds_topic_name("cmd_vel")
    kinds = {
        "/cmd_vel": "command",
        "/robot1/cmd_vel": "command",
        "/robot1/odom": "sensor",
        "/scan": "sensor",
        "/robot1/proximity/center_left": "sensor",
        "/robot1/ground/left": "sensor",
        "/robot1/battery_state": "sensor",
        "/clock": "clock",
        "/chatter": "command",
    }
    assert {topic: dds.topic_kind(topic) for topic in kinds} == kinds
    assert dds.default_type("/robot1/proximity/left") == "sensor_msgs/msg/Range"
    assert dds.default_type("/robot2/odom") == "nav_msgs/msg/Odometry"
    assert dds.default_type("/chatter") is None
    # the ROS 2 (Jazzy) type hash of geometry_msgs/msg/Twist, as `ros2 topic info -v` shows it
    assert (
        dds.type_hash("geometry_msgs/msg/Twist")
        == "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a"
    )


def test_framing_pads_to_four_and_records_the_padding():
    data = cdr.serialize(ros_messages.new("std_msgs/msg/String", data="ab"))  # 4 + 4 + 3 bytes
    framed = dds.frame(data)
    assert len(framed) % 4 == 0 and framed[:3] == data[:3] and framed[3] == 1
    assert framed[4 : len(data)] == data[4:] and framed[len(data) :] == b"\x00"
    assert dds.frame(framed) == framed
    assert_same(cdr.deserialize(framed, "std_msgs/msg/String"), ros_messages.new("std_msgs/msg/String", data="ab"))


# -- two participants in this process -------------------------------------------------------------
def test_two_buses_exchange_twist_and_odometry(buses):
    a, b = buses(), buses()
    cmd, odom = Inbox(), Inbox()
    b.subscribe("/cmd_vel", cmd)
    b.subscribe("/robot1/odom", odom)
    assert a.wait_for_subscriber("/cmd_vel", TIMEOUT)
    assert a.wait_for_subscriber("/robot1/odom", TIMEOUT)
    sent_twist, sent_odom = twist(), odometry()
    a.publish("/cmd_vel", sent_twist)
    a.publish("/robot1/odom", sent_odom)
    got = cmd.get()
    assert got.linear.x == 0.25 and got.angular.z == -1.5
    assert_same(got, sent_twist)
    got = odom.get()
    assert got.child_frame_id == "robot1/base_link" and got.header.stamp.nanosec == 345_000_000
    assert np.array_equal(got.pose.covariance, sent_odom.pose.covariance)
    assert_same(got, sent_odom)
    assert a.errors == [] and b.errors == []


def test_discovery_sees_ros_names_qos_and_type_hash(buses):
    a, b = buses(), buses()
    b.subscribe("/robot1/cmd_vel", Inbox())
    b.subscribe("/robot1/odom", Inbox())
    for topic, typename in (("/robot1/cmd_vel", "geometry_msgs/msg/Twist"), ("/robot1/odom", "nav_msgs/msg/Odometry")):
        assert a.wait_for_subscriber(topic, TIMEOUT)
        writer = a.writer(topic, typename)
        remote = [writer.get_matched_subscription_data(h) for h in writer.get_matched_subscriptions()]
        assert len(remote) == 1
        endpoint = remote[0]
        assert endpoint.topic_name == "rt" + topic
        assert endpoint.type_name == dds.dds_type_name(typename)
        qos = endpoint.qos
        userdata = qos[dds.Policy.Userdata].data
        assert userdata == f"typehash={ros_messages.typestore().hash_rihs01(typename)};".encode()
        assert qos[dds.Policy.Durability] == dds.Policy.Durability.Volatile
        if topic.endswith("cmd_vel"):
            assert isinstance(qos[dds.Policy.Reliability], dds.Policy.Reliability.Reliable)
            assert qos[dds.Policy.History] == dds.Policy.History.KeepLast(10)
        else:
            assert qos[dds.Policy.Reliability] == dds.Policy.Reliability.BestEffort
            assert qos[dds.Policy.History] == dds.Policy.History.KeepLast(5)


def test_best_effort_reader_does_not_match_a_reliable_expectation(buses):
    """Sensor topics are best effort: a reliable reader (ROS default QoS) must not match our odom writer."""
    from cyclonedds.qos import Qos
    from cyclonedds.sub import DataReader

    a, b = buses(), buses()
    sensor = Inbox()
    b.subscribe("/robot1/odom", sensor)  # best effort: matches
    topic = b._topic("/robot1/odom", "nav_msgs/msg/Odometry")
    reliable = DataReader(b.participant, topic, qos=Qos(*dds.qos_policies("/cmd_vel")))
    assert a.wait_for_subscriber("/robot1/odom", TIMEOUT)
    a.publish("/robot1/odom", odometry())
    sensor.get()
    assert reliable.get_subscription_matched_status().current_count == 0
    reliable.__del__()


def test_close_releases_everything(buses):
    bus = dds.DdsBus()
    inbox = Inbox()
    sub = bus.subscribe("/cmd_vel", inbox)
    bus.publish("/cmd_vel", twist())  # our own participant's reader gets it too (ROS does)
    inbox.get()
    thread = bus._thread
    bus.close()
    assert not thread.is_alive() and sub.closed
    bus.close()  # idempotent
    with pytest.raises(RuntimeError):
        bus.publish("/cmd_vel", twist())


def test_subscription_close_and_callback_errors(buses):
    a, b = buses(), buses()
    first, second = Inbox(), Inbox()

    def broken(msg):
        raise ValueError("boom")

    b.subscribe("/cmd_vel", broken)
    sub1 = b.subscribe("/cmd_vel", first)
    b.subscribe("/cmd_vel", second)
    assert b.subscriber_count("/cmd_vel") == 3 and b.topics() == ["/cmd_vel"]
    assert a.wait_for_subscriber("/cmd_vel", TIMEOUT)
    a.publish("/cmd_vel", twist(1.0))
    assert first.get().linear.x == 1.0 and second.get().linear.x == 1.0
    assert [type(e) for e in b.errors] == [ValueError]
    sub1.close()
    a.publish("/cmd_vel", twist(2.0))
    assert second.get(1).linear.x == 2.0
    assert len(first.items) == 1


# -- a separate process over loopback UDP -----------------------------------------------------------
ECHO = textwrap.dedent("""
    import sys
    from scoopc.robots import dds, ros_messages
    bus = dds.DdsBus()
    bus.writer("/cmd_vel_echo", "geometry_msgs/msg/Twist")
    def on_cmd(raw):
        bus.publish_raw("/cmd_vel_echo", "geometry_msgs/msg/Twist", raw)
    def on_twist(msg):
        odom = ros_messages.new("nav_msgs/msg/Odometry", child_frame_id="robot1/base_link")
        odom.twist.twist = msg
        bus.publish("/robot1/odom", odom)
    bus.subscribe("/cmd_vel", on_cmd, raw=True)
    bus.subscribe("/cmd_vel", on_twist)
    assert bus.wait_for_subscriber("/cmd_vel_echo", 10) and bus.wait_for_subscriber("/robot1/odom", 10)
    print("ready", flush=True)
    sys.stdin.read()
    bus.close()
    print("bye", flush=True)
""")


def test_separate_process_over_loopback(buses):
    bus = buses()
    echoed, odom = Inbox(), Inbox()
    bus.subscribe("/cmd_vel_echo", echoed, msgtype="geometry_msgs/msg/Twist", raw=True)
    bus.subscribe("/robot1/odom", odom)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    env = dict(os.environ, PYTHONPATH=root + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.Popen(
        [sys.executable, "-c", ECHO], stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env, text=True
    )
    try:
        assert proc.stdout.readline().strip() == "ready"
        assert bus.wait_for_subscriber("/cmd_vel", TIMEOUT)
        reader = bus._readers["/robot1/odom"].reader
        assert bus.wait_for_publisher("/robot1/odom", TIMEOUT)
        remote = reader.get_matched_publication_data(reader.get_matched_publications()[0])
        assert (remote.topic_name, remote.type_name) == ("rt/robot1/odom", "nav_msgs::msg::dds_::Odometry_")
        sent = twist(0.125, 0.5)
        deadline = time.monotonic() + TIMEOUT
        while not odom.items:  # odom is best effort: resend until one arrives
            assert time.monotonic() < deadline, "no odometry from the other process"
            bus.publish("/cmd_vel", sent)
            with odom.cond:
                odom.cond.wait_for(lambda: odom.items, 0.5)
        got = odom.get()
        assert got.child_frame_id == "robot1/base_link"
        assert_same(got.twist.twist, sent)
        raw = echoed.get()  # the bytes as they crossed the wire, twice
        expected = ros_messages.typestore().serialize_cdr(sent, "geometry_msgs/msg/Twist")
        assert bytes(raw) == bytes(expected)  # 52 bytes: no padding needed
    finally:
        proc.stdin.close()
        assert proc.wait(TIMEOUT) == 0
    assert proc.stdout.read().strip() == "bye"
