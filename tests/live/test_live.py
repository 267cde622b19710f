"""`scoopc run --live PORT`: a client of the Foxglove WebSocket protocol (foxglove_client.py)
subscribes to the run's channels and decodes what arrives: the runtime's processors, waits and
events, the simulator's scene and robots, and the ROS topics with their ROS 2 schemas."""

import socket
import sys
from pathlib import Path

import pytest
from foxglove_client import FoxgloveClient, free_port

from scoopc import cli
from scoopc.driver import live
from scoopc.exits import Exit

HERE = Path(__file__).parent
WAITS = HERE / "waits"
EXPLORATION = HERE.parents[1] / "samples" / "exploration"


@pytest.mark.slow
def test_exploration_live_sends_processors_waits_scene_robots_and_topics(capsys):
    port = free_port()
    client = FoxgloveClient(port)
    code = cli.main(["run", str(EXPLORATION), "--live", str(port), "--duration", "2", "--no-png"])
    client.close()
    assert code == Exit.OK, capsys.readouterr().err
    processors = client.on("/scoop/processors")
    assert processors and all(m["processors"] for m in processors)
    classes = {p["class"] for m in processors for p in m["processors"]}
    assert {"EXPLORATION", "SIMULATOR", "SIMPLE_CONTROLLER"} <= classes
    states = {p["state"] for m in processors for p in m["processors"]}
    assert states <= set(live.snapshot.STATES) and "idle" in states
    assert client.on("/scoop/waits") and all("waits" in m for m in client.on("/scoop/waits"))
    scene = client.on("/sim/scene")[-1]
    ids = {e["id"] for e in scene["entities"]}
    assert {"walls", "holes", "robot/robot1"} <= ids
    robot = next(e for e in scene["entities"] if e["id"] == "robot/robot1")
    assert robot["cylinders"] and robot["arrows"] and len(robot["lines"][0]["points"]) > 2  # body, heading, trail
    assert len(robot["lines"][-1]["points"]) == 2 * 7  # the Thymio's seven proximity beams
    poses = client.on("/sim/robots")
    assert poses[-1]["robots"][0]["name"] == "robot1" and 0 < poses[-1]["robots"][0]["battery"] <= 1
    topics = {c["topic"]: c for c in client.channels.values()}
    odom = topics["/robot1/odom"]
    assert (odom["encoding"], odom["schemaName"], odom["schemaEncoding"]) == ("cdr", "nav_msgs/msg/Odometry", "ros2msg")
    assert "geometry_msgs/PoseWithCovariance pose" in odom["schema"]
    assert client.on("/robot1/odom") and client.on("/robot1/cmd_vel")
    assert topics["/scoop/events"]["schemaName"] == "foxglove.Log"


@pytest.mark.slow
def test_a_deadlocks_cycle_arrives_on_the_events_channel(capsys):
    port = free_port()
    client = FoxgloveClient(port, {"/scoop/events", "/scoop/waits"})
    code = cli.main(["run", str(WAITS), "--live", str(port), "--", "0"])
    client.close()
    assert code == Exit.RUNTIME
    (event,) = client.on("/scoop/events")
    assert event["kind"] == "deadlock" and event["level"] == 5
    assert event["message"].startswith("deadlock: every processor is idle or blocked")
    consume = {"routine": "CONSUMER.consume", "file": "consumer.e", "line": 22}
    assert event["sources"] == [consume] and (event["file"], event["line"]) == (consume["file"], 22)
    waits = [w for m in client.on("/scoop/waits") for w in m["waits"]]
    assert waits and waits[0]["clause"] == "has_value: c.value > 0" and waits[0]["over"] == ["P2"]


def test_live_runs_without_a_client_after_the_wait(monkeypatch, capsys):
    monkeypatch.setattr(live, "FIRST_CLIENT", 0.05)
    assert cli.main(["run", str(WAITS), "--live", str(free_port()), "--", "10"]) == Exit.OK
    err = capsys.readouterr().err
    assert "scoopc: no Foxglove client after 0.05 s: running without one" in err


def test_live_without_the_sdk_says_how_to_install_it(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "foxglove", None)
    assert cli.main(["run", str(WAITS), "--live", str(free_port()), "--", "10"]) == Exit.USAGE
    assert 'needs the foxglove-sdk package: pip install "scoopc[live]"' in capsys.readouterr().err


def test_live_on_a_port_in_use_is_a_usage_error(capsys):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        assert cli.main(["run", str(WAITS), "--live", str(port), "--", "10"]) == Exit.USAGE
    assert f"--live: cannot serve on port {port}" in capsys.readouterr().err
