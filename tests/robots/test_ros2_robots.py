"""Issue 16, "topics a real robot hears": scoopc against a twin of a stock ROS 2 node on
rmw_cyclonedds_cpp (tests/robots/rmw_twin.py), between processes on loopback DDS.

One test per breakage: (1) a Jazzy TurtleBot3 takes TwistStamped, (2) with stamps of the system
clock, (3) ROS_LOCALHOST_ONLY / ROS_AUTOMATIC_DISCOVERY_RANGE / ROS_STATIC_PEERS, (4) a stock
(reliable) subscriber hears `scoopc sim`, (5) each distribution's message layouts, (6) the Thymio's
missing battery topic, (7) silent topics are reported. Waits are on conditions; time limits only
bound a broken run (the one negative discovery check, OFF, is bounded by a positive control)."""

import json
import os
import re
import subprocess
import sys
import threading
import time
from pathlib import Path

import domains  # tests/robots/domains.py: a DDS domain per test, disjoint per worker
import pytest

pytest.importorskip("cyclonedds")

from scoopc.robots import cdr, dds, eiffel_messages, ros_messages  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
import rmw_twin  # noqa: E402
import rmw_twin_actions  # noqa: E402
import rmw_twin_graph  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
PROGRAMS = Path(__file__).parent / "programs"
TIMEOUT = 60.0
WORLD = """name: ros2_robots
size: [4.0, 3.0]
duration: 300
robots:
  - {name: thymio, namespace: robot1, kind: thymio, start: [0.5, 0.5, 0.0]}
  - {name: tb3, namespace: tb3, kind: turtlebot3, start: [2.5, 1.5, 0.0]}
"""
INTERFACE_ONLY = """<?xml version="1.0" encoding="UTF-8"?>
<CycloneDDS xmlns="https://cdds.io/config"><Domain Id="any"><General>
  <Interfaces><NetworkInterface address="127.0.0.1"/></Interfaces></General></Domain></CycloneDDS>
"""


@pytest.fixture(scope="module")
def env(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ros2_robots")
    (folder / "world.yaml").write_text(WORLD)
    settings = dds.loopback_environment(folder, domains.next_domain())
    saved = {name: os.environ.get(name) for name in [*settings, "ROS_DISTRO"]}
    os.environ.update(settings)
    os.environ.pop("ROS_DISTRO", None)
    child = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""), PYTHONUNBUFFERED="1")
    child["WORLD"] = str(folder / "world.yaml")
    yield child
    for name, value in saved.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value


def scoopc(env, *args, **kw):
    return subprocess.Popen(
        [sys.executable, "-m", "scoopc", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        **kw,
    )


def finish(proc, timeout=TIMEOUT):
    try:
        out, err = proc.communicate(timeout=timeout)
    finally:
        if proc.poll() is None:
            proc.kill()
    return proc.returncode, out, err


# -- (5) message layouts of each distribution, both ways, every type the library uses ------------------


@pytest.mark.parametrize("distro", list(ros_messages.DISTROS))
def test_each_distribution_decodes_what_a_run_of_it_encodes_and_the_reverse(distro):
    previous = ros_messages.distro()
    ros_messages.use_distro(distro)
    try:
        rosbags = ros_messages.store_of(distro)
        for typename in eiffel_messages.library_types():
            ours = cdr.serialize(ros_messages.new(typename), typename)
            decoded = rosbags.deserialize_cdr(ours, typename)  # what a node of `distro` reads
            assert bytes(rosbags.serialize_cdr(decoded, typename)) == ours, typename
            theirs = bytes(rosbags.serialize_cdr(rmw_twin.new_message(rosbags, typename), typename))
            assert cdr.serialize(cdr.deserialize(theirs, typename), typename) == theirs, typename
        has_variance = "variance" in dict(ros_messages.fields("sensor_msgs/msg/Range"))
        assert has_variance == (distro != "humble")
        qos = dds.qos_for("/a/range", "sensor_msgs/msg/Range")
        userdata = [p for p in qos if type(p).__name__ == "Userdata"]
        if distro == "humble":
            assert not userdata  # Humble's rmw sets no endpoint user data
        else:
            assert userdata[0].data == f"typehash={rosbags.hash_rihs01('sensor_msgs/msg/Range')};".encode()
    finally:
        ros_messages.use_distro(previous)


def test_a_jazzy_node_decodes_the_range_a_jazzy_run_publishes_over_dds(env):
    """Breakage 5: Humble's Range (no `variance`) was sent whatever the distribution."""
    ros_messages.use_distro("jazzy")
    bus = dds.DdsBus(writer_qos={"/r16/proximity/center": ("reliable", 1)})  # as `scoopc sim` publishes it
    twin = rmw_twin.Node("jazzy")
    try:
        heard = twin.create_subscription("sensor_msgs/msg/Range", "/r16/proximity/center", depth=10)
        assert bus.wait_for_subscriber("/r16/proximity/center", TIMEOUT, msgtype="sensor_msgs/msg/Range")
        sent = ros_messages.new("sensor_msgs/msg/Range", range=0.05, variance=0.25)
        bus.publish("/r16/proximity/center", sent)
        assert heard.wait_for(lambda s: s.messages, TIMEOUT)
        assert heard.messages[0].variance == 0.25 and heard.messages[0].range == pytest.approx(0.05)
        assert heard.raw[0] == dds.frame(cdr.serialize(sent))
    finally:
        twin.close()
        bus.close()


# -- (4) a stock subscriber hears `scoopc sim`; QoS incompatibilities are reported --------------------------


@pytest.mark.slow
def test_a_stock_node_hears_the_sim_node_and_a_reliable_laser_reader_is_reported(env, tmp_path):
    sim = scoopc(env, "sim", env["WORLD"], "--duration", "0", "--progress", "0", "--ros-distro", "jazzy")
    twin = rmw_twin.Node("jazzy")
    try:
        odom = twin.create_subscription("nav_msgs/msg/Odometry", "/robot1/odom")  # depth 10, reliable
        center = twin.create_subscription("sensor_msgs/msg/Range", "/robot1/proximity/center")
        ground = twin.create_subscription("sensor_msgs/msg/Range", "/robot1/ground/left")
        tb3 = twin.create_subscription("nav_msgs/msg/Odometry", "/tb3/odom")
        scan = twin.create_subscription("sensor_msgs/msg/LaserScan", "/tb3/scan")  # reliable: no match
        for sub in (odom, center, ground, tb3):
            assert sub.wait_for(lambda s: len(s.messages) >= 3, TIMEOUT), sub.topic
        assert center.messages[-1].range == -1.0  # the Thymio driver's "nothing seen"
        assert ground.messages[-1].range == 0.0  # floor
        assert scan.wait_for(lambda s: s.incompatible() > 0, TIMEOUT)
        # issue 17: the simulator is the node /scoopc_sim of the ROS graph
        graph = rmw_twin_graph.GraphReader(twin)
        assert graph.wait_for(lambda g: "/scoopc_sim" in g.nodes(), TIMEOUT)
        assert ("writer", "nav_msgs/msg/Odometry", "/scoopc_sim") in graph.endpoints("/robot1/odom")
        assert ("reader", "geometry_msgs/msg/TwistStamped", "/scoopc_sim") in graph.endpoints("/tb3/cmd_vel")
        graph.close()
        sim.send_signal(2)
        status, _, err = finish(sim)
        assert status == 0, err
        assert "ROS 2 jazzy (--ros-distro)" in err
        assert err.count("/tb3/scan: a subscriber asks reliable, this publisher is best effort") == 1, err
    finally:
        if sim.poll() is None:
            sim.kill()
        twin.close()


# -- (1), (2), (6), (7): programs against twins of the robots' drivers ----------------------------------------


@pytest.mark.slow
def test_a_humble_thymio_gets_twist_and_its_missing_battery_is_reported(env, tmp_path):
    twin = rmw_twin.Node("humble")
    graph = rmw_twin_graph.GraphReader(twin)
    try:
        # History depth plays no part in QoS matching; a keep-last depth of 1 (the driver's own) let a
        # loaded test process, taking samples late, lose commands it counts below (a CI rehearsal saw it)
        driver = twin.create_subscription("geometry_msgs/msg/Twist", "/robot1/cmd_vel", depth=32)
        run = scoopc(
            env,
            "run",
            str(PROGRAMS / "thymio_ros2"),
            "--robot",
            "ros2",
            "--ros-distro",
            "humble",
            "--duration",
            "6",
            "--wait-robot",
            "1",
            "--node-name",
            "thymio_brain",
            cwd=tmp_path,
        )
        assert driver.wait_for(lambda s: len(s.messages) >= 1, TIMEOUT)
        # issue 17: the program is a node (--node-name; no --namespace: "/"), with Humble's 24-byte gids
        assert graph.wait_for(lambda g: g.nodes() == ["/thymio_brain"], TIMEOUT), graph.nodes()
        assert graph.endpoints("/robot1/cmd_vel") == [
            ("reader", "geometry_msgs/msg/Twist", "_NODE_NAME_UNKNOWN_"),
            ("writer", "geometry_msgs/msg/Twist", "/thymio_brain"),
        ]
        assert set(graph.gid_sizes) == {24}
        status, out, err = finish(run, 180)
        assert status == 0, err
        assert out.startswith("battery 1\n") and "sent" in out
        assert "scoopc: ROS 2 humble (--ros-distro)" in err
        assert "no battery topic: the ROS 2 Thymio driver publishes none" in err
        # (7): silent topics said once, then the line of what was heard at the end of --duration
        assert err.count("nothing heard on /robot1/ground/left (no publisher)") == 1, err
        assert "nothing on /robot1/ground/left" in err and "stopped the program after 6 s" in err
        assert driver.wait_for(lambda s: len(s.messages) >= 15, TIMEOUT)
        assert {m.linear.x for m in driver.messages} >= {0.05}
        assert all(m.__msgtype__ == "geometry_msgs/msg/Twist" for m in driver.messages)
    finally:
        graph.close()
        twin.close()


@pytest.mark.slow
def test_a_jazzy_turtlebot3_gets_twist_stamped_stamped_with_the_system_clock(env, tmp_path):
    twin = rmw_twin.Node("jazzy")
    try:
        driver = twin.create_subscription("geometry_msgs/msg/TwistStamped", "/tb3/cmd_vel")
        run = scoopc(
            env, "run", str(PROGRAMS / "turtlebot3_ros2"), "--robot", "ros2", "--ros-distro", "jazzy", cwd=tmp_path
        )
        status, out, err = finish(run, 180)
        assert status == 0, err
        assert "stamped True" in out
        assert driver.wait_for(lambda s: len(s.messages) >= 15, TIMEOUT)
        for msg, at in zip(driver.messages, driver.received_at):
            stamp = msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9
            # ROS time is the system clock: stamped before it was received, and not long before
            # (a monotonic stamp, time since boot, would be hours off; the delivery's own delay
            # on a loaded machine is a fraction of a second, so the bound is loose on purpose)
            assert at - 5.0 < stamp <= at + 0.01, (stamp, at)
        assert {m.twist.linear.x for m in driver.messages} >= {0.1}
    finally:
        twin.close()


@pytest.mark.slow
def test_a_twist_program_against_a_twist_stamped_robot_is_told_why_it_does_not_move(env, tmp_path):
    """Breakage 1's other face, and (7) with --require-robot: exit 3 after --wait-robot seconds,
    naming the silent topics and the namespace the graph has."""
    twin = rmw_twin.Node("jazzy")
    try:
        twin.create_subscription("geometry_msgs/msg/TwistStamped", "/robot1/cmd_vel")
        pub = twin.create_publisher("sensor_msgs/msg/Range", "/proximity/center")
        pub.publish(pub.new(range=-1.0))
        run = scoopc(
            env,
            "run",
            str(PROGRAMS / "thymio_ros2"),
            "--robot",
            "ros2",
            "--require-robot",
            "--wait-robot",
            "2",
            cwd=tmp_path,
        )
        status, out, err = finish(run, 180)
        assert status == 3, err
        assert (
            "/robot1/cmd_vel: the robot reads geometry_msgs/msg/TwistStamped, this program sends "
            "geometry_msgs/msg/Twist" in err
        )
        assert "the ROS graph has /proximity/center (this program asked /robot1/proximity/center)" in err
        assert "exiting (--require-robot)" in err and "Traceback" not in err
    finally:
        twin.close()


def test_nothing_heard_names_the_namespace_mistake():
    from scoopc.robots.silence import nearby

    graph = {"/odom": "", "/scan": "", "/proximity/left": "", "/robot2/odom": ""}
    assert nearby("/robot1/odom", graph) == ["/odom", "/robot2/odom"]
    assert nearby("/robot1/proximity/left", graph) == ["/proximity/left"]
    assert nearby("/robot1/battery_state", graph) == []


# -- (3) discovery as rmw_cyclonedds_cpp configures it -----------------------------------------------------------


def test_discovery_configuration_of_each_range():
    uri = {"CYCLONEDDS_URI": "file:///x.xml"}
    config, text, _ = dds.discovery_config("jazzy", {})  # SUBNET: multicast, participant indices
    assert config == (
        "<CycloneDDS><Domain><Discovery><ParticipantIndex>auto</ParticipantIndex>"
        "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex></Discovery></Domain></CycloneDDS>,"
    )
    assert text == "discovery SUBNET"
    config, _, _ = dds.discovery_config("jazzy", {"ROS_STATIC_PEERS": "10.0.0.2;robot.local", **uri})
    assert config == (
        "<CycloneDDS><Domain><Discovery><ParticipantIndex>auto</ParticipantIndex>"
        '<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex><Peers><Peer address="10.0.0.2"/>'
        '<Peer address="robot.local"/></Peers></Discovery></Domain></CycloneDDS>,file:///x.xml'
    )
    config, _, warnings = dds.discovery_config(
        "jazzy", {"ROS_AUTOMATIC_DISCOVERY_RANGE": "SYSTEM_DEFAULT", "ROS_STATIC_PEERS": "10.0.0.2", **uri}
    )
    assert config == "file:///x.xml" and "ignored" in warnings[0]
    config, _, _ = dds.discovery_config("jazzy", {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"})
    assert "<AllowMulticast>false</AllowMulticast>" in config and '<Peer address="localhost"/>' in config
    config, _, _ = dds.discovery_config(
        "jazzy", {"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF", "ROS_STATIC_PEERS": "10.0.0.2"}, pid=42
    )
    assert "<Tag>ros_discovery_off_42</Tag>" in config and "Peer" not in config
    config, _, warnings = dds.discovery_config(
        "jazzy", {"ROS_LOCALHOST_ONLY": "1", "ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"}
    )
    assert '<Peer address="localhost"/>' in config and "deprecated" in warnings[0]
    config, _, _ = dds.discovery_config("humble", {"ROS_LOCALHOST_ONLY": "1", **uri})
    assert config.startswith('<CycloneDDS><Domain><General><Interfaces><NetworkInterface address="127.0.0.1"/>')
    assert config.endswith(",file:///x.xml")
    assert dds.discovery_config("humble", {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"})[0] == ""


LISTEN = """
import sys, threading
from scoopc.robots import dds
bus = dds.DdsBus()
got = threading.Event()
bus.subscribe("/disc/odom", lambda msg: got.set())
print("ready", bus.discovery, flush=True)
print("heard" if got.wait(float(sys.argv[1])) else "silent", flush=True)
bus.close()
"""
TALK = """
import time
from scoopc.robots import dds, ros_messages
bus = dds.DdsBus()
print("ready", bus.discovery, flush=True)
while True:
    bus.publish("/disc/odom", ros_messages.new("nav_msgs/msg/Odometry"))
    time.sleep(0.05)
"""


def _discovery(env, tmp_path, variables, wait):
    """A DdsBus listener and a talker in two processes with `variables`; the listener's last line."""
    uri = tmp_path / "interface_only.xml"
    uri.write_text(INTERFACE_ONLY)  # loopback only, no peers: discovery is up to the variables
    child = dict(
        env,
        CYCLONEDDS_URI=uri.resolve().as_uri(),
        ROS_DOMAIN_ID=str(domains.next_domain()),
        ROS_DISTRO="jazzy",
        **variables,
    )
    talker = subprocess.Popen(
        [sys.executable, "-c", TALK], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=child
    )
    try:
        assert talker.stdout.readline().startswith("ready"), talker.stderr.read()
        done = subprocess.run(
            [sys.executable, "-c", LISTEN, str(wait)], capture_output=True, text=True, env=child, timeout=TIMEOUT + 30
        )
        assert done.returncode == 0, done.stderr
        return done.stdout.splitlines()
    finally:
        talker.kill()
        talker.wait()


@pytest.mark.slow
@pytest.mark.parametrize(
    "variables",
    [{"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}, {"ROS_STATIC_PEERS": "127.0.0.1"}, {"ROS_LOCALHOST_ONLY": "1"}],
    ids=["LOCALHOST", "static peers", "ROS_LOCALHOST_ONLY"],
)
def test_two_processes_discover_each_other_as_the_variables_say(env, tmp_path, variables):
    lines = _discovery(env, tmp_path, variables, TIMEOUT)
    assert lines[-1] == "heard", lines


@pytest.mark.slow
def test_discovery_off_keeps_two_processes_apart(env, tmp_path):
    start = time.monotonic()
    control = _discovery(env, tmp_path, {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}, TIMEOUT)
    needed = time.monotonic() - start  # what discovery takes here, with margin below
    assert control[-1] == "heard"
    lines = _discovery(env, tmp_path, {"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF"}, max(3.0, 3 * needed))
    assert lines[0].startswith("ready discovery OFF") and lines[-1] == "silent", lines


# -- a robot.yaml profile, and the line of what was heard on Ctrl-C ----------------------------------------------


def _reader_qos(participant, topic):
    """The QoS of the DDS readers of `topic` (any participant), as discovery tells them."""
    from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsSubscription

    reader = BuiltinDataReader(participant, BuiltinTopicDcpsSubscription)
    try:
        return [s.qos for s in reader.read(N=256) or () if s.topic_name == "rt" + topic]
    finally:
        reader.__del__()


@pytest.mark.slow
def test_a_robot_profile_names_the_topics_the_type_the_qos_and_ctrl_c_says_what_was_heard(env, tmp_path):
    """DIFF_DRIVE_ROBOT.make_from_profile with tests/robots/programs/profile_ros2/robot.yaml: TwistStamped
    on /wheels/cmd, odometry on /wheels/odom read reliably with depth 3; Ctrl-C ends the run (130) with
    one line of what was heard."""
    from cyclonedds.qos import Policy

    twin = rmw_twin.Node("jazzy")
    stop = threading.Event()
    odom = twin.create_publisher("nav_msgs/msg/Odometry", "/wheels/odom")

    def publish():
        while not stop.wait(0.05):
            odom.publish(odom.new())

    talker = threading.Thread(target=publish)
    talker.start()
    run = None
    try:
        driver = twin.create_subscription("geometry_msgs/msg/TwistStamped", "/wheels/cmd")
        run = scoopc(env, "run", str(PROGRAMS / "profile_ros2"), "--robot", "ros2", cwd=tmp_path)
        # issue 17: the program waits on its ROS_PARAMETER `speed' until a stock node sets it
        setting = twin.create_client("rcl_interfaces/srv/SetParameters", "/profile_ros2/set_parameters")

        def parameter(name, **value):
            value = rmw_twin.new_message(twin.store, "rcl_interfaces/msg/ParameterValue", **value)
            return rmw_twin.new_message(twin.store, "rcl_interfaces/msg/Parameter", name=name, value=value)

        speeds = [
            parameter("speed", type=2, integer_value=1),
            parameter("speed", type=3, double_value=0.1),
            parameter("mode", type=4, string_value="bold"),  # ROS_PARAMETER [STRING]
        ]
        deadline = time.monotonic() + 120
        while True:  # until the program, started, has declared it
            results = setting.call(setting.new_request(parameters=speeds), 120).results
            if results[1].reason != "parameter speed is not declared" or time.monotonic() > deadline:
                break
            assert not driver.messages  # still waiting for its speed
            time.sleep(0.1)
        assert [(r.successful, r.reason) for r in results] == [
            (False, "parameter speed is a double, not an integer"),
            (True, ""),
            (True, ""),
        ]
        assert driver.wait_for(lambda s: len(s.messages) >= 5, TIMEOUT)
        qos = None
        deadline = time.monotonic() + TIMEOUT
        while not qos and time.monotonic() < deadline:
            qos = _reader_qos(twin.participant, "/wheels/odom")
            time.sleep(0.05)
        assert qos and Policy.History.KeepLast(3) in qos[0]
        assert isinstance(qos[0][Policy.Reliability], Policy.Reliability.Reliable)
        graph = rmw_twin_graph.GraphReader(twin)  # issue 17: the node is named after the root class
        assert graph.wait_for(lambda g: g.nodes() == ["/profile_ros2"], TIMEOUT), graph.nodes()
        assert ("writer", "geometry_msgs/msg/TwistStamped", "/profile_ros2") in graph.endpoints("/wheels/cmd")
        graph.close()
        # issue 17: `ros2 param set /profile_ros2 use_sim_time true` switches the stamps to /clock
        assert abs(driver.messages[-1].header.stamp.sec - time.time()) < 5
        clock = twin.create_publisher("rosgraph_msgs/msg/Clock", "/clock")
        at_1000 = clock.new(clock=rmw_twin.new_message(twin.store, "builtin_interfaces/msg/Time", sec=1000))
        clock.publish(at_1000)
        request = setting.new_request(parameters=[parameter("use_sim_time", type=1, bool_value=True)])
        assert setting.call(request, TIMEOUT).results[0].successful
        for _ in range(3):  # /clock is best effort for the program's reader: say it again while it subscribes
            clock.publish(at_1000)
            time.sleep(0.2)
        assert driver.wait_for(lambda s: s.messages[-1].header.stamp.sec == 1000, TIMEOUT)
        time.sleep(0.3)  # some odometry heard
        run.send_signal(2)
        status, out, err = finish(run)
        assert status == 130, err
        said = "profile True stamped True max 0.29999999999999999 1.2 cmd /wheels/cmd odom /wheels/odom\n"
        assert out == said + "speed 0.10000000000000001 after 1 change, mode bold\n", out
        assert "robot profile" in err and "robot.yaml" in err
        heard = [line for line in err.splitlines() if line.startswith("scoopc: heard ")]
        assert len(heard) == 1 and "nothing on /scan" in heard[0], err  # the laser of the profile: none here
        assert int(heard[0].split("/wheels/odom (")[1].split(")")[0]) > 0, err
        assert {m.twist.linear.x for m in driver.messages} >= {0.1}
    finally:
        stop.set()
        talker.join()
        if run is not None and run.poll() is None:
            run.kill()
        twin.close()


# -- issue 17: ROS_SERVICE_CLIENT and ROS_SERVICE_SERVER in a program, against a stock node ----------------


@pytest.mark.slow
def test_a_program_calls_a_stock_service_and_serves_one(env, tmp_path):
    twin = rmw_twin.Node("jazzy")
    run = None
    try:
        made = threading.Event()  # a request may come before create_service has returned

        def reply(request):
            made.wait()
            return trigger.new_response(success=True, message="hi")

        trigger = twin.create_service("std_srvs/srv/Trigger", "/twin/trigger", reply)
        made.set()
        run = scoopc(env, "run", str(PROGRAMS / "service_ros2"), "--robot", "ros2", cwd=tmp_path)
        enable = twin.create_client("std_srvs/srv/SetBool", "/svc/enable")
        reply = enable.call(enable.new_request(data=True), 120)
        assert (reply.success, reply.message) == (True, "enabled True")
        status, out, err = finish(run, 120)
        assert status == 0, err
        assert out == "trigger: hi\nserved data=True\n", err
    finally:
        if run is not None and run.poll() is None:
            run.kill()
        twin.close()


# -- issue 17: the NavigateToPose sample against a stand-in Nav2 server in another process ---------------------


def _navigate_server(env, steps, period):
    server = subprocess.Popen(
        [
            sys.executable,
            str(Path(__file__).parent / "rmw_twin.py"),
            "navigate",
            "--steps",
            str(steps),
            "--period",
            str(period),
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    assert server.stdout.readline().strip() == '{"ready": true}', server.stderr.read()
    return server


def _events(server):
    server.kill()
    out, _ = server.communicate()
    return [json.loads(line) for line in out.splitlines()]


@pytest.mark.slow
def test_the_navigate_to_pose_sample_reaches_its_goal(env, tmp_path):
    server = _navigate_server(env, steps=5, period=0.1)
    try:
        run = scoopc(
            env, "run", str(ROOT / "samples" / "navigate_to_pose"), "--robot", "ros2", "--", "3", "4", cwd=tmp_path
        )
        status, out, err = finish(run, 180)
        assert status == 0, err
        assert out.splitlines()[0] == "goal sent: 3 4"
        reached = re.fullmatch(r"goal reached after (\d+) feedback messages, (\S+) m remaining", out.splitlines()[1])
        assert reached and 1 <= int(reached[1]) <= 5 and float(reached[2]) in (4.0, 3.0, 2.0, 1.0, 0.0), out
    finally:
        events = _events(server)
    assert events == [{"goal": [3.0, 4.0], "frame": "map"}, {"succeeded": 5}]


@pytest.mark.slow
def test_the_navigate_to_pose_sample_cancels_its_goal_when_the_stop_signaler_fires(env, tmp_path):
    server = _navigate_server(env, steps=1000, period=0.05)
    try:
        run = scoopc(
            env,
            "run",
            str(ROOT / "samples" / "navigate_to_pose"),
            "--robot",
            "ros2",
            "--",
            "1",
            "0",
            "1.5",
            cwd=tmp_path,
        )
        status, out, err = finish(run, 180)
        assert status == 0, err
        lines = out.splitlines()
        assert lines[:2] == ["goal sent: 1 0", "stop requested: cancelling the goal"], out
        assert lines[2].startswith("goal canceled after "), out
    finally:
        events = _events(server)
    assert events[0] == {"goal": [1.0, 0.0], "frame": "map"} and "canceled" in events[1], events
    assert 0 < events[1]["canceled"] < 1000


@pytest.mark.slow
def test_a_program_serves_an_action_to_a_stock_client(env, tmp_path):
    """ROS_ACTION_SERVER in tests/robots/programs/action_server_ros2, against the twin's action client:
    feedback and result of one goal, the cancel of another."""
    twin = rmw_twin.Node("jazzy")
    run = None
    try:
        run = scoopc(env, "run", str(PROGRAMS / "action_server_ros2"), "--robot", "ros2", cwd=tmp_path)
        client = rmw_twin_actions.TwinActionClient(twin, "example_interfaces/action/Fibonacci", "/fib")
        first = client.send_goal(timeout=120, order=5)
        done = client.result(first, TIMEOUT)
        assert (done.status, list(done.result.sequence)) == (4, [0, 1, 1, 2, 3, 5])
        assert [list(f.sequence) for f in client.feedback_of(first, 6)] == [[0, 1, 1, 2, 3, 5][:n] for n in range(1, 7)]
        second = client.send_goal(order=3)
        cancel = client.cancel(second)
        assert cancel.return_code == 0 and bytes(cancel.goals_canceling[0].goal_id.uuid) == second
        assert client.result(second, TIMEOUT).status == 5
        status, out, err = finish(run, 120)
        assert status == 0, err
        assert out == "goal 1: order 5, 6 feedback\ngoal 2: cancelled\n", err
    finally:
        if run is not None and run.poll() is None:
            run.kill()
        twin.close()
