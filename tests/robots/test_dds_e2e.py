"""End to end over loopback DDS between processes: the simulator node (`scoopc sim`, simnode.py) in a
subprocess, driven (1) by this test's own DdsBus and (2) by a compiled Eiffel program run with
`scoopc run --robot ros2` in another subprocess. Checks are on the robot's odometry (positions and
speeds), never on wall-clock timings; the time limits only bound a broken run. Last, the two robot
benchmarks (benchmarks/robots_latency.py, robots_rate.py: processes talking over loopback DDS) at
smoke sizes: their output's format only."""

import os
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import domains  # tests/robots/domains.py: a DDS domain per test, disjoint per worker
import pytest

pytest.importorskip("cyclonedds")

from foxglove_client import FoxgloveClient, free_port  # noqa: E402  (tests/foxglove_client.py)

import scoopc  # noqa: E402
from scoopc.robots import dds, record, ros_messages  # noqa: E402

pytestmark = pytest.mark.slow  # long: outside the quick selection (pytest -m "not slow")

ROOT = Path(__file__).resolve().parents[2]
WORLD = """name: e2e
size: [3.0, 2.0]
duration: 300
robots:
  - {name: thymio, namespace: robot1, kind: thymio, start: [0.5, 0.5, 0.0]}
"""
PROGRAM = Path(__file__).parent / "programs" / "dds_forward"
TIMEOUT = 30.0


@pytest.fixture(scope="module")
def env(tmp_path_factory):
    """Loopback DDS in a random test domain, for this process and the children."""
    folder = tmp_path_factory.mktemp("dds_e2e")
    (folder / "world.yaml").write_text(WORLD)
    settings = dds.loopback_environment(folder, domains.next_domain())
    saved = {name: os.environ.get(name) for name in settings}
    os.environ.update(settings)
    child = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    child["E2E_WORLD"] = str(folder / "world.yaml")  # a Thymio on /robot1 at (0.5, 0.5)
    yield child
    for name, value in saved.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value


class Odometry:
    """The latest odometry of /robot1 seen by this process."""

    def __init__(self, bus):
        self.cond = threading.Condition()
        self.count = 0
        self.x = self.v = None
        bus.subscribe("/robot1/odom", self)

    def __call__(self, msg):
        with self.cond:
            self.count += 1
            self.x, self.v = msg.pose.pose.position.x, msg.twist.twist.linear.x
            self.cond.notify_all()

    def wait(self, predicate, timeout=TIMEOUT):
        with self.cond:
            assert self.cond.wait_for(lambda: self.count and predicate(self), timeout), (
                f"odometry never satisfied the condition (last x={self.x}, v={self.v})"
            )
            return self.x, self.v

    def settled(self):
        """Wait until the robot reports zero speed and keeps its position over 20 more readings."""
        x, _ = self.wait(lambda o: o.v == 0.0)
        seen = self.count
        self.wait(lambda o: o.count >= seen + 20)
        with self.cond:
            assert self.v == 0.0 and abs(self.x - x) < 1e-9, (x, self.x, self.v)
            return self.x


class SimNode:
    """`scoopc sim WORLD` in a subprocess (stderr to a file); `stop()` sends SIGTERM, returns the status."""

    def __init__(self, env, folder, *options):
        self.stderr_path = folder / "sim.err"
        self.png, self.mcap = folder / "sim.png", folder / "sim.mcap"
        command = [
            sys.executable,
            "-m",
            "scoopc",
            "sim",
            env["E2E_WORLD"],
            "--duration",
            "0",
            "--progress",
            "0",
            "--png",
            str(self.png),
            "--record",
            str(self.mcap),
            *options,
        ]
        with open(self.stderr_path, "w") as err:
            self.proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err, env=env)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(TIMEOUT)
        finally:
            if self.proc.poll() is None:
                self.proc.kill()

    @property
    def stderr(self):
        return self.stderr_path.read_text()


@pytest.fixture
def node(env, tmp_path):
    made = []

    def start(*options):
        made.append(SimNode(env, tmp_path, *options))
        return made[-1]

    yield start
    for sim in made:
        sim.stop()


@pytest.fixture
def bus(env):
    made = dds.DdsBus()
    yield made
    made.close()


def twist(v):
    return ros_messages.new("geometry_msgs/msg/Twist", linear=ros_messages.new("geometry_msgs/msg/Vector3", x=v))


def test_sim_node_driven_over_dds(node, bus):
    sim = node()
    odom = Odometry(bus)
    start_x, _ = odom.wait(lambda o: True)
    assert start_x == pytest.approx(0.5) and bus.wait_for_subscriber("/robot1/cmd_vel", TIMEOUT)
    deadline = time.monotonic() + TIMEOUT
    with odom.cond:  # drive at 0.1 m/s until the robot has moved 5 cm
        while not (odom.x > start_x + 0.05 and odom.v == pytest.approx(0.1)):
            assert time.monotonic() < deadline, "the robot did not move"
            bus.publish("/robot1/cmd_vel", twist(0.1))
            odom.cond.wait(0.05)
    bus.publish("/robot1/cmd_vel", twist(0.0))
    stopped_at = odom.settled()
    assert stopped_at > start_x + 0.05
    assert sim.stop() == 0, sim.stderr
    assert "stopped by SIGTERM" in sim.stderr and f"trajectories in {sim.png}" in sim.stderr
    assert sim.png.stat().st_size > 0
    recorded = record.read(sim.mcap)
    commands = [msg.linear.x for topic, _, msg in recorded if topic == "/robot1/cmd_vel"]
    assert commands and set(commands) == {0.1, 0.0} and commands[-1] == 0.0
    odometry = [msg.pose.pose.position.x for topic, _, msg in recorded if topic == "/robot1/odom"]
    assert odometry[0] == pytest.approx(0.5) and odometry[-1] == pytest.approx(stopped_at)
    clocks = [t for topic, t, _ in recorded if topic == "/clock"]
    assert clocks == sorted(clocks) and len(clocks) > 10


@pytest.mark.parametrize("how", ["scoopc run", "compile -o"])
def test_compiled_program_drives_the_sim_node_with_robot_ros2(env, node, bus, tmp_path, how):
    """`scoopc run --robot ros2`, and the output of `scoopc compile -o` run with `--robot ros2`."""
    if how == "scoopc run":
        command = ["scoopc", "run", str(PROGRAM), "--robot", "ros2"]
    else:
        assert scoopc.compile([PROGRAM], tmp_path / "out").status == 0
        command, tmp_path = ["dds_forward", "--robot", "ros2"], tmp_path / "out"
    sim = node()
    odom = Odometry(bus)
    odom.wait(lambda o: True)
    run = subprocess.run(
        [sys.executable, "-m", *command],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    start, end = [line.split() for line in run.stdout.splitlines()]
    assert start[0] == "start" and end[0] == "end"
    assert float(start[1]) == pytest.approx(0.5) and float(end[2]) == pytest.approx(0.5)
    moved = float(end[1]) - float(start[1])
    assert 0.1 < moved < 0.3, run.stdout  # 2 s at 0.1 m/s, then stopped
    assert "sent a zero velocity on /robot1/cmd_vel" in run.stderr
    final = odom.settled()  # the robot stays stopped
    assert final == pytest.approx(float(end[1]), abs=1e-6)
    assert sim.stop() == 0, sim.stderr
    commands = [msg.linear.x for topic, _, msg in record.read(sim.mcap) if topic == "/robot1/cmd_vel"]
    # 40 at 0.1 m/s, the program's zero, the runner's zero (the first may go out before DDS matched)
    assert 30 <= len(commands) <= 42 and commands[-2:] == [0.0, 0.0] and set(commands[:-2]) == {0.1}


@pytest.mark.parametrize("name", ["SIGINT", "SIGTERM", "SIGHUP"])
def test_a_stop_signal_on_a_ros2_run_stops_the_robot(env, node, bus, tmp_path, name):
    """`scoopc run --robot ros2` ended by a signal: the program stops, the robot gets a zero velocity
    (the last command the simulator node recorded) and stays stopped."""
    sim = node()
    odom = Odometry(bus)
    odom.wait(lambda o: True)
    number = getattr(signal, name)
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "scoopc",
            "run",
            str(PROGRAM.parent / "drive_until_stopped"),
            "--robot",
            "ros2",
            "--namespace",
            "robot1",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(env, PYTHONUNBUFFERED="1"),
        cwd=tmp_path,
    )
    try:
        assert proc.stdout.readline() == "moving\n"  # the robot has moved under the program
        proc.send_signal(number)
        _, err = proc.communicate(timeout=TIMEOUT)
    finally:
        proc.kill()
    assert proc.returncode == 128 + number, err
    assert f"scoopc: stopped by {name}" in err and "sent a zero velocity on /robot1/cmd_vel" in err, err
    assert "Traceback" not in err
    odom.settled()
    assert sim.stop() == 0, sim.stderr
    commands = [msg.linear.x for topic, _, msg in record.read(sim.mcap) if topic == "/robot1/cmd_vel"]
    assert 0.1 in commands and commands[-1] == 0.0


# -- the robot benchmarks over loopback DDS, smoke sizes: output format only, never timings ---------------
BENCHMARKS = ROOT / "benchmarks"
NUMBER = r"\d+"


def test_latency_benchmark_smoke(env):
    done = subprocess.run(
        [sys.executable, str(BENCHMARKS / "robots_latency.py"), "--smoke", "--domain", str(domains.next_domain())],
        capture_output=True,
        text=True,
        env=env,
        timeout=180,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("# robots_latency:") and "size=smoke" in lines[0] and "loopback DDS" in lines[0]
    for variant, line in zip(("baseline", "compiled"), lines[1:3]):
        assert re.fullmatch(
            rf"latency {variant} n=({NUMBER}) median_us={NUMBER} p99_us={NUMBER} "
            rf"mean_us={NUMBER} lost=({NUMBER})",
            line,
        ), line
    assert re.fullmatch(r"ratio compiled/baseline median=\d+\.\d\d p99=\d+\.\d\d", lines[3]), lines[3]


def test_rate_benchmark_smoke(env):
    done = subprocess.run(
        [
            sys.executable,
            str(BENCHMARKS / "robots_rate.py"),
            *("--smoke", "--transport", "dds", "--layout", "shared"),
            *("--domain", str(domains.next_domain())),
        ],
        capture_output=True,
        text=True,
        env=env,
        timeout=180,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("# robots_rate:") and "10 controllers x 0.2 s" in lines[0]
    assert len(lines) == 2 and re.fullmatch(
        rf"rate dds shared compiled_min_hz={NUMBER} compiled_median_hz={NUMBER} compiled_total_hz={NUMBER} "
        rf"baseline_median_hz={NUMBER} baseline_total_hz={NUMBER} ratio=\d+\.\d\d target_100hz=(met|MISSED)",
        lines[1],
    ), lines[1]


def test_live_view_of_a_program_on_a_ros2_robot(env, node, bus, tmp_path):
    """`--live` with `--robot ros2`: the /scoop channels and the run's ROS topics, with their
    ROS 2 schemas, reach a Foxglove-protocol client."""
    sim = node()
    Odometry(bus).wait(lambda o: True)
    port = free_port()
    client = FoxgloveClient(port, {"/scoop/processors", "/robot1/cmd_vel", "/robot1/odom"})
    run = subprocess.run(
        [sys.executable, "-m", "scoopc", "run", str(PROGRAM), "--robot", "ros2", "--live", str(port)],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        timeout=120,
    )
    client.close()
    assert run.returncode == 0, run.stderr
    assert sim.stop() == 0, sim.stderr
    assert any(p["class"] == "DDS_FORWARD" for m in client.on("/scoop/processors") for p in m["processors"])
    topics = {c["topic"]: c for c in client.channels.values()}
    assert (topics["/robot1/cmd_vel"]["encoding"], topics["/robot1/cmd_vel"]["schemaName"]) == (
        "cdr",
        "geometry_msgs/msg/Twist",
    )
    assert client.on("/robot1/cmd_vel") and client.on("/robot1/odom")
