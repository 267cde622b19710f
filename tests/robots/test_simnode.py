"""The simulator node (scoopc.robots.simnode) in-process on the in-process Bus: commands applied
between steps, pacing to a (fake) wall clock, the end of a run (duration, stop), its PNG, GIF and
MCAP outputs, and the command line. The node over DDS between processes: test_dds_e2e.py."""

import io
import math
import threading

import pytest
from PIL import Image

from scoopc.robots import record, ros_messages, simnode
from scoopc.robots.bus import Bus

WORLD = {
    "name": "strip",
    "size": [3.0, 1.0],
    "duration": 60,
    "robots": [{"name": "thymio", "namespace": "robot1", "kind": "thymio", "start": [0.5, 0.5, 0.0]}],
}


def twist(v):
    return ros_messages.new("geometry_msgs/msg/Twist", linear=ros_messages.new("geometry_msgs/msg/Vector3", x=v))


class GoTo:
    """A controller on the bus: 0.1 m/s forward until odometry says x >= target, then zero."""

    def __init__(self, bus, target, stop_after=None):
        self.bus, self.target, self.stop_after = bus, target, stop_after
        self.seen = 0
        self.done = threading.Event()
        bus.subscribe("/robot1/odom", self.on_odom)

    def on_odom(self, msg):
        self.seen += 1
        self.bus.publish("/robot1/cmd_vel", twist(0.1 if msg.pose.pose.position.x < self.target else 0.0))
        if self.stop_after is not None and self.seen >= self.stop_after:
            self.done.set()


def load_world():
    from scoopc.robots.sim import World

    return World.from_dict(WORLD)


def test_node_bus_applies_commands_between_steps_and_taps_both_ways():
    inner = Bus()
    node = simnode.NodeBus(inner)
    got, tapped = [], []
    node.subscribe("/robot1/cmd_vel", got.append)
    tap = node.tap(lambda topic, msg: tapped.append(topic))
    inner.publish("/robot1/cmd_vel", twist(0.1))  # arrives from the transport: queued
    assert got == [] and tapped == []
    node.publish("/robot1/odom", ros_messages.new("nav_msgs/msg/Odometry"))
    assert node.drain() == 1 and [m.linear.x for m in got] == [0.1]
    assert tapped == ["/robot1/odom", "/robot1/cmd_vel"] and node.drain() == 0
    tap.close()
    node.publish("/clock", ros_messages.new("rosgraph_msgs/msg/Clock"))
    assert tapped == ["/robot1/odom", "/robot1/cmd_vel"]


def test_run_drives_the_robot_and_writes_png_gif_and_mcap(tmp_path):
    bus = Bus()
    GoTo(bus, 1.0)
    err = io.StringIO()
    paths = {kind: tmp_path / f"run.{kind}" for kind in ("png", "gif", "mcap")}
    status = simnode.run(
        load_world(),
        rate=0,
        duration=12.0,
        bus=bus,
        stderr=err,
        progress=0,
        png=paths["png"],
        gif=paths["gif"],
        record=paths["mcap"],
    )
    text = err.getvalue()
    assert status == 0, text
    assert "world 'strip' (thymio on /robot1)" in text and "as fast as possible, for 12 s" in text
    assert "duration reached at t=12.00 s" in text
    recorded = record.read(paths["mcap"])
    odometry = [(t, msg.pose.pose.position.x) for topic, t, msg in recorded if topic == "/robot1/odom"]
    assert odometry[0] == (0, 0.5) and odometry[-1][0] == 12_000_000_000
    assert odometry[-1][1] == pytest.approx(1.0, abs=0.005)  # drove 0.5 m, stopped at x = 1
    commands = [msg.linear.x for topic, _, msg in recorded if topic == "/robot1/cmd_vel"]
    assert commands[0] == 0.1 and commands[-1] == 0.0 and len(commands) == len(odometry)  # one per odometry
    with Image.open(paths["png"]) as png:
        assert png.size[0] > png.size[1] > 0  # a 3 x 1 m world
    with Image.open(paths["gif"]) as gif:
        assert gif.n_frames > 10 and gif.info["loop"] == 0
    assert f"recorded {len(recorded)} messages" in text


def test_run_ends_on_a_stop_request():
    bus = Bus()
    controller = GoTo(bus, 9.0, stop_after=25)
    err = io.StringIO()
    assert simnode.run(load_world(), rate=0, duration=0, bus=bus, stderr=err, progress=0, stop=controller.done) == 0
    # the 25th odometry (50 Hz, the first at t=0) sets the stop: the run ends before the next step
    assert "until interrupted" in err.getvalue() and "stopped at t=0.48 s" in err.getvalue()


def test_pacing_follows_the_wall_clock(monkeypatch):
    """At --rate 2, 3 simulated seconds take 1.5 s of (fake) wall time; at rate 0 none."""
    now = [100.0]
    monkeypatch.setattr(simnode.time, "monotonic", lambda: now[0])
    monkeypatch.setattr(simnode.time, "sleep", lambda s: now.__setitem__(0, now[0] + s))
    for rate, wall in ((2.0, 1.5), (0.5, 6.0), (0, 0.0)):
        start = now[0]
        err = io.StringIO()
        assert simnode.run(load_world(), rate=rate, duration=3.0, bus=Bus(), stderr=err, progress=1.0) == 0
        assert now[0] - start == pytest.approx(wall)
        progress_lines = [line for line in err.getvalue().splitlines() if "(wall" in line]
        assert len(progress_lines) == max(1, math.ceil(wall))  # one a second, and the last


def test_a_slow_node_lets_simulated_time_run_slower(monkeypatch):
    """Each step costing 30 ms of (fake) wall time at rate 1: the node lags, but never more than
    MAX_LAG plus a step: it drops the debt instead of bursting to catch up."""
    now = [0.0]

    def monotonic():
        now[0] += 0.015  # two readings per step: 30 ms a step
        return now[0]

    monkeypatch.setattr(simnode.time, "monotonic", monotonic)
    monkeypatch.setattr(simnode.time, "sleep", lambda s: now.__setitem__(0, now[0] + s))
    err = io.StringIO()
    assert simnode.run(load_world(), rate=1.0, duration=1.0, bus=Bus(), stderr=err, progress=0) == 0
    lag = int(err.getvalue().split("fell behind the wall clock by up to ")[1].split(" ms")[0])
    assert 200 <= lag <= (simnode.MAX_LAG + 0.05) * 1000


def test_an_unwritable_picture_is_reported(tmp_path):
    err = io.StringIO()
    status = simnode.run(
        load_world(), rate=0, duration=0.1, bus=Bus(), stderr=err, progress=0, png=tmp_path / "missing" / "run.png"
    )
    assert status == 1 and "error: cannot write" in err.getvalue()


def test_command_line(tmp_path, capsys):
    assert simnode.main(["--help"]) == 0
    assert "WORLD" in capsys.readouterr().out
    assert simnode.main([]) == 2
    assert simnode.main([str(tmp_path / "missing.yaml")]) == 2
    assert "cannot load the world" in capsys.readouterr().err
    bad = tmp_path / "bad.yaml"
    bad.write_text("size: [1.0]\n")
    assert simnode.main([str(bad), "--rate", "0"]) == 2
    assert simnode.main([str(bad), "--rate", "-1"]) == 2
    assert "--rate must be 0 or more" in capsys.readouterr().err
    parser = simnode.add_arguments(__import__("argparse").ArgumentParser())
    args = parser.parse_args(["w.yaml", "--rate", "4", "--domain", "7", "--duration", "5"])
    assert (args.world, args.rate, args.domain, args.duration, args.realtime) == ("w.yaml", 4.0, 7, 5.0, False)
