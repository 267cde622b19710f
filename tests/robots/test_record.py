"""Recording (scoopc.robots.record): a simulated run taped off the bus into one MCAP file, read back
by three independent readers (the mcap library with mcap-ros2-support's decoder, rosbags' rosbag2
reader, ours); the schemas, channels and log times; Bus.tap and DdsBus.tap; the GIF animation."""

import os
import threading

import domains  # tests/robots/domains.py: a DDS domain per test, disjoint per worker
import numpy as np
import pytest
from mcap.reader import make_reader

from scoopc.robots import cdr, record, ros_messages
from scoopc.robots.bus import Bus
from scoopc.robots.sim import Simulator

WORLD = {
    "name": "rec",
    "size": [3.0, 3.0],
    "duration": 10,
    "robots": [
        {
            "name": "thymio",
            "namespace": "robot1",
            "kind": "thymio",
            "start": [0.5, 0.5, 0.0],
            "laser": {"range": 2.0, "beams": 90},
        }
    ],
}


def twist(v, w=0.0):
    return ros_messages.new(
        "geometry_msgs/msg/Twist",
        linear=ros_messages.new("geometry_msgs/msg/Vector3", x=v),
        angular=ros_messages.new("geometry_msgs/msg/Vector3", z=w),
    )


@pytest.fixture
def recorded_run(tmp_path):
    """Two simulated seconds of a Thymio driving a curve, recorded; every published message kept too."""
    bus = Bus()
    published = []
    bus.tap(lambda topic, msg: published.append((topic, cdr.serialize(msg))))
    sim = Simulator(WORLD, bus)  # its first sensor round is published before the recorder
    path = tmp_path / "run.mcap"
    published.clear()
    with record.Recorder(bus, path, clock=lambda: sim.time_ns) as recorder:
        for step in range(200):
            if step % 10 == 5:
                bus.publish("/robot1/cmd_vel", twist(0.1, 0.5))
            sim.step()
    bus.publish("/robot1/cmd_vel", twist(0.0))  # after close: not recorded
    return path, published[:-1], recorder


def test_mcap_file_has_ros2_schemas_channels_and_every_message(recorded_run):
    path, published, recorder = recorded_run
    with open(path, "rb") as f:
        reader = make_reader(f)
        header, summary = reader.get_header(), reader.get_summary()
        assert header.profile == "ros2" and header.library == "scoopc"
        schemas = {s.name: s for s in summary.schemas.values()}
        assert set(schemas) == {
            "geometry_msgs/msg/Twist",
            "rosgraph_msgs/msg/Clock",
            "nav_msgs/msg/Odometry",
            "sensor_msgs/msg/Range",
            "sensor_msgs/msg/LaserScan",
            "sensor_msgs/msg/BatteryState",
        }
        for name, schema in schemas.items():
            assert schema.encoding == "ros2msg"
            assert schema.data.decode() == ros_messages.typestore().generate_msgdef(name, ros_version=2)[0]
        assert "MSG: std_msgs/Header" in schemas["nav_msgs/msg/Odometry"].data.decode()
        channels = {c.topic: c for c in summary.channels.values()}
        assert all(c.message_encoding == "cdr" for c in channels.values())
        assert schemas["sensor_msgs/msg/Range"].id == channels["/robot1/proximity/left"].schema_id
        assert summary.statistics.message_count == len(published) == recorder.count
        f.seek(0)
        stored = [(channel.topic, message.data) for _, channel, message in make_reader(f).iter_messages()]
    assert sorted(stored) == sorted(published)  # the same bytes, our CDR with its header
    assert recorder.counts["/robot1/cmd_vel"] == 20 and recorder.counts["/clock"] == 200


def test_log_times_are_stamps_or_the_simulated_clock(recorded_run):
    path, _, _ = recorded_run
    rows = record.read(path)
    assert [t for _, t, _ in rows] == sorted(t for _, t, _ in rows)
    for topic, log_time, msg in rows:
        if topic == "/clock":
            assert log_time == msg.clock.sec * 10**9 + msg.clock.nanosec
        elif topic == "/robot1/cmd_vel":  # no stamp: the simulator's time
            assert log_time % 100_000_000 == 50_000_000
        else:
            assert log_time == msg.header.stamp.sec * 10**9 + msg.header.stamp.nanosec
    assert rows[-1][1] == 2_000_000_000


def test_mcap_ros2_support_decodes_it(recorded_run):
    from mcap_ros2.decoder import DecoderFactory

    path, _, _ = recorded_run
    ours = record.read(path)
    with open(path, "rb") as f:
        theirs = [
            (channel.topic, message.log_time, decoded)
            for _, channel, message, decoded in make_reader(
                f, decoder_factories=[DecoderFactory()]
            ).iter_decoded_messages(log_time_order=True)
        ]
    assert len(theirs) == len(ours)
    for (topic, t, mine), (their_topic, their_t, decoded) in zip(ours, theirs):
        assert (topic, t) == (their_topic, their_t)
        if topic.endswith("odom"):
            assert decoded.pose.pose.position.x == mine.pose.pose.position.x
            assert list(decoded.pose.covariance) == list(mine.pose.covariance)
            assert decoded.child_frame_id == mine.child_frame_id
        elif topic.endswith("scan"):
            assert np.array_equal(np.asarray(decoded.ranges, dtype=np.float32), mine.ranges)
            assert decoded.header.frame_id == mine.header.frame_id
        elif topic.endswith("cmd_vel"):
            assert (decoded.linear.x, decoded.angular.z) == (0.1, 0.5)
        elif "proximity" in topic or "ground" in topic:
            assert decoded.range == pytest.approx(mine.range) and decoded.radiation_type == mine.radiation_type


def test_rosbags_reads_the_single_file(recorded_run):
    from rosbags.rosbag2 import Reader

    path, published, _ = recorded_run
    store = ros_messages.typestore()
    with Reader(path) as reader:
        assert reader.message_count == len(published)
        types = {c.topic: c.msgtype for c in reader.connections}
        assert types["/robot1/odom"] == "nav_msgs/msg/Odometry" and types["/clock"] == "rosgraph_msgs/msg/Clock"
        last = {}
        for connection, timestamp, raw in reader.messages():
            last[connection.topic] = (timestamp, store.deserialize_cdr(raw, connection.msgtype))
    t, odom = last["/robot1/odom"]
    assert t == 2_000_000_000 and odom.pose.pose.position.x > 0.55 and odom.pose.pose.orientation.z > 0.1


def test_log_time_rules_without_a_clock(tmp_path):
    bus = Bus()
    path = tmp_path / "plain.mcap"
    recorder = record.Recorder(bus, path, compression="none")
    odom = ros_messages.new("nav_msgs/msg/Odometry")
    odom.header.stamp.sec, odom.header.stamp.nanosec = 3, 250
    bus.publish("/robot1/odom", odom)
    bus.publish("/robot1/cmd_vel", twist(0.2))  # the latest stamp seen
    recorder.write("/note", ros_messages.new("std_msgs/msg/String", data="hello"), log_time=7)
    with pytest.raises(TypeError):
        bus.publish("/robot1/odom", twist(0.1))  # one type per topic
    assert recorder.close() == str(path) and recorder.close() == str(path)
    bus.publish("/robot1/cmd_vel", twist(0.3))  # closed: nothing more
    rows = record.read(path)
    assert [(topic, t) for topic, t, _ in rows] == [
        ("/note", 7),
        ("/robot1/odom", 3_000_000_250),
        ("/robot1/cmd_vel", 3_000_000_250),
    ]
    assert rows[0][2].data == "hello" and record.stamp_ns(twist(0.0)) is None


def test_bus_tap_sees_every_topic_and_closes():
    bus = Bus()
    seen, delivered = [], []
    tap = bus.tap(lambda topic, msg: seen.append(topic))
    bus.subscribe("/a", delivered.append)
    bus.publish("/a", 1)
    bus.publish("/b", 2)  # no subscriber: still tapped
    assert seen == ["/a", "/b"] and delivered == [1] and bus.subscriber_count("/b") == 0

    def broken(topic, msg):
        raise ValueError("tap")

    bus.tap(broken)
    with pytest.raises(ValueError):
        bus.publish("/a", 3)
    assert delivered == [1, 3] and seen[-1] == "/a"  # the subscribers still got it
    tap.close()
    tap.close()
    with pytest.raises(ValueError):
        bus.publish("/a", 4)
    assert seen == ["/a", "/b", "/a"]


def test_dds_bus_tap_records_what_it_publishes_and_receives(tmp_path, monkeypatch):
    pytest.importorskip("cyclonedds")
    from scoopc.robots import dds

    for name, value in dds.loopback_environment(tmp_path, domains.next_domain()).items():
        monkeypatch.setenv(name, value)
    sender, receiver = dds.DdsBus(), dds.DdsBus()
    try:
        got = threading.Event()
        receiver.subscribe("/robot1/cmd_vel", lambda msg: got.set())
        own = threading.Event()
        receiver.subscribe("/robot1/status", lambda msg: own.set(), msgtype="std_msgs/msg/String")
        path = tmp_path / "dds.mcap"
        recorder = record.Recorder(receiver, path, clock=lambda: 42)
        assert sender.wait_for_subscriber("/robot1/cmd_vel", 10)
        sender.publish("/robot1/cmd_vel", twist(0.25))
        assert got.wait(10)
        receiver.publish("/robot1/status", ros_messages.new("std_msgs/msg/String", data="ok"))
        assert own.wait(10)  # its own reader got it too
        recorder.close()
    finally:
        sender.close()
        receiver.close()
    rows = record.read(path)
    # the received Twist once; its own String once (not again when its own reader gets it)
    assert sorted((topic, t) for topic, t, _ in rows) == [("/robot1/cmd_vel", 42), ("/robot1/status", 42)]
    assert os.path.getsize(path) > 0


def test_render_gif_frames_timing_and_content(tmp_path):
    from PIL import Image

    from scoopc.robots.sim.render import COLORS, render_gif

    bus = Bus()
    sim = Simulator(WORLD, bus)
    for step in range(1000):  # 10 s: a curve, then a collision-free stop
        if step % 10 == 0:
            bus.publish("/robot1/cmd_vel", twist(0.1 if step < 600 else 0.0, 0.4))
        sim.step()
    path = tmp_path / "run.gif"
    assert render_gif(sim, path, fps=5, speed=2.0) == path  # a frame every 0.4 simulated seconds
    with Image.open(path) as gif:
        assert gif.n_frames == 26 and gif.info["loop"] == 0
        durations = []
        for index in range(gif.n_frames):
            gif.seek(index)
            durations.append(gif.info["duration"])
            if index in (1, gif.n_frames - 1):
                colors = {color for _, color in gif.convert("RGB").getcolors(1 << 16)}
                assert COLORS[0] in colors  # the robot (and its trail)
        assert durations[:-1] == [200] * 25 and durations[-1] >= 1000
    capped = tmp_path / "capped.gif"
    render_gif(sim, capped, max_frames=12)  # default speed: the run fits in 12 frames
    with Image.open(capped) as gif:
        assert gif.n_frames <= 13
    with pytest.raises(ValueError):
        render_gif(sim, tmp_path / "bad.gif", fps=0)
