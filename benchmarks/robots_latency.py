"""Sensor-to-command latency over DDS (loopback only): a compiled Roboscoop controller against a
hand-written cyclonedds echo, measured in the same run.

The measuring process (this one, on scoopc's DdsBus) writes nav_msgs/Odometry on /latency/odom with
pose.position.x = a sequence number and waits for the geometry_msgs/Twist on /latency/cmd_vel whose
linear.x echoes it; one message in flight at a time. Two responders, each a separate process:

* `baseline`: the echo anyone would write with cyclonedds' Python API (hand-written IDL structs
  named as ROS 2 names them, a WaitSet, take, write);
* `compiled`: benchmarks/programs/robots_latency (ROS_SUBSCRIBER -> ODOMETRY_SIGNALER -> a
  LATENCY_CONTROLLER on its own processor, waiting on a wait condition -> ROS_PUBLISHER), run with
  `scoopc run --robot ros2` (DDS through cyclonedds unless rclpy is installed).

Both responders run at once, the baseline on topics of its own (/latency_base/...), and the timed
round trips alternate between them in blocks of BLOCK, so that a change in the machine's load during
the run weighs on both alike (measured one after the other, the ratio of two runs of --quick could
differ by half). Each gets warm-up messages (its start, the compilation, DDS discovery) first. It
prints, per responder, the median, p99 and mean round trip (us) and the messages lost (no answer
within 1 s, odometry is best effort), then the ratio compiled/baseline. DDS stays on 127.0.0.1 (a generated
Cyclone DDS configuration, a random domain in 100..200). `python benchmarks/robots_latency.py --help`.
"""

import argparse
import os
import platform
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PROGRAM = os.path.join(HERE, "programs", "robots_latency")
SIZES = {"full": (10_000, 200), "quick": (1_000, 100), "smoke": (100, 20)}  # timed, warm-up
TOPICS = {
    "compiled": ("/latency/odom", "/latency/cmd_vel"),  # (odometry, command)
    "baseline": ("/latency_base/odom", "/latency_base/cmd_vel"),
}
BLOCK = 50  # consecutive timed round trips to one responder
LOST_AFTER = 1.0  # seconds without an answer: the message counts as lost


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Round-trip latency odometry -> cmd_vel over loopback DDS: a compiled Roboscoop "
        "controller (scoopc run --robot ros2) against a hand-written cyclonedds Python echo."
    )
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--quick", action="store_true", help="1,000 timed messages per responder")
    size.add_argument("--smoke", action="store_true", help="100 timed messages: for tests")
    parser.add_argument("-n", type=int, metavar="N", help="timed messages per responder (default 10,000)")
    parser.add_argument(
        "--domain", type=int, metavar="ID", help="the loopback DDS domain id (default: random in 100..200)"
    )
    parser.add_argument("--only", choices=("baseline", "compiled"), help="measure one responder")
    parser.add_argument("--echo", action="store_true", help=argparse.SUPPRESS)
    return parser.parse_args(argv)


# --- the baseline responder: cyclonedds' Python API, written by hand -----------------------------


def echo_main():
    """Answer each Odometry on rt/latency_base/odom with a Twist on rt/latency_base/cmd_vel
    (linear.x = x)."""
    from dataclasses import dataclass, field

    from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState, WaitSet
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.idl import IdlStruct
    from cyclonedds.idl.types import array, float64, int32, uint32
    from cyclonedds.pub import DataWriter
    from cyclonedds.qos import Policy, Qos
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic
    from cyclonedds.util import duration

    @dataclass
    class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
        sec: int32 = 0
        nanosec: uint32 = 0

    @dataclass
    class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
        stamp: Time = field(default_factory=Time)
        frame_id: str = ""

    @dataclass
    class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
        x: float64 = 0.0
        y: float64 = 0.0
        z: float64 = 0.0

    @dataclass
    class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
        x: float64 = 0.0
        y: float64 = 0.0
        z: float64 = 0.0
        w: float64 = 1.0

    @dataclass
    class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
        position: Point = field(default_factory=Point)
        orientation: Quaternion = field(default_factory=Quaternion)

    @dataclass
    class PoseWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovariance_"):
        pose: Pose = field(default_factory=Pose)
        covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)

    @dataclass
    class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
        x: float64 = 0.0
        y: float64 = 0.0
        z: float64 = 0.0

    @dataclass
    class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
        linear: Vector3 = field(default_factory=Vector3)
        angular: Vector3 = field(default_factory=Vector3)

    @dataclass
    class TwistWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::TwistWithCovariance_"):
        twist: Twist = field(default_factory=Twist)
        covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)

    @dataclass
    class Odometry(IdlStruct, typename="nav_msgs::msg::dds_::Odometry_"):
        header: Header = field(default_factory=Header)
        child_frame_id: str = ""
        pose: PoseWithCovariance = field(default_factory=PoseWithCovariance)
        twist: TwistWithCovariance = field(default_factory=TwistWithCovariance)

    participant = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))
    plain_cdr = Policy.DataRepresentation(use_cdrv0_representation=True)  # XCDR1, as ROS 2 sends
    sensor = Qos(Policy.Reliability.BestEffort, Policy.Durability.Volatile, Policy.History.KeepLast(5), plain_cdr)
    command = Qos(
        Policy.Reliability.Reliable(duration(milliseconds=100)),
        Policy.Durability.Volatile,
        Policy.History.KeepLast(10),
        plain_cdr,
    )
    odom, cmd = TOPICS["baseline"]
    reader = DataReader(participant, Topic(participant, "rt" + odom, Odometry), qos=sensor)
    writer = DataWriter(participant, Topic(participant, "rt" + cmd, Twist), qos=command)
    waitset = WaitSet(participant)
    waitset.attach(ReadCondition(reader, SampleState.Any | ViewState.Any | InstanceState.Any))
    print("ready", flush=True)
    while True:
        waitset.wait(duration(seconds=10))
        for sample in reader.take(16):
            x = sample.pose.pose.position.x
            writer.write(Twist(linear=Vector3(x=x)))
            if x < 0:
                time.sleep(0.2)  # let the last answer go out
                return 0


# --- the measuring side -------------------------------------------------------------------------


class Pinger:
    """Sends numbered odometry to one responder and waits for the matching command (on our DdsBus)."""

    def __init__(self, bus, variant):
        from scoopc.robots import ros_messages

        self.bus = bus
        self.variant = variant
        self.odom_topic, cmd_topic = TOPICS[variant]
        self.odom = ros_messages.new("nav_msgs/msg/Odometry", child_frame_id="base_link")
        self.odom.header.frame_id = "odom"
        self.cond = threading.Condition()
        self.answer = None
        self.arrived = 0
        self.number = 0
        self.samples, self.lost = [], 0
        bus.subscribe(cmd_topic, self.on_command)

    def on_command(self, msg):
        arrived = time.perf_counter_ns()
        with self.cond:
            self.answer, self.arrived = msg.linear.x, arrived
            self.cond.notify_all()

    def ping(self, timeout=LOST_AFTER, number=None):
        """Round trip of the next message (or of `number`) in ns (None: no answer within `timeout`)."""
        if number is None:
            self.number += 1
            number = self.number
        self.odom.pose.pose.position.x = float(number)
        with self.cond:
            self.answer = None
        start = time.perf_counter_ns()
        self.bus.publish(self.odom_topic, self.odom)
        with self.cond:
            if not self.cond.wait_for(lambda: self.answer == number, timeout):
                return None
            return self.arrived - start

    def timed(self, count):
        for _ in range(count):
            rtt = self.ping()
            if rtt is None:
                self.lost += 1
            else:
                self.samples.append(rtt / 1000)

    def figures(self):
        """{median_us, p99_us, mean_us, lost, n} of the timed round trips."""
        samples = sorted(self.samples)
        return {
            "median_us": statistics.median(samples),
            "p99_us": samples[min(len(samples) - 1, int(0.99 * len(samples)))],
            "mean_us": statistics.fmean(samples),
            "lost": self.lost,
            "n": len(samples),
        }


def responder(variant, env):
    if variant == "baseline":
        command = [sys.executable, os.path.abspath(__file__), "--echo"]
    else:
        command = [sys.executable, "-m", "scoopc", "run", PROGRAM, "--robot", "ros2"]
    return subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def await_answer(pinger, proc):
    """Ping until the responder (starting, compiling, discovering) answers."""
    deadline = time.monotonic() + 120
    while pinger.ping(0.2) is None:
        if proc.poll() is not None or time.monotonic() > deadline:
            raise RuntimeError(f"{pinger.variant} responder never answered: {proc.stderr.read()[-500:]}")


def finish(pinger, proc):
    """Ask the responder to stop (a negative x, best effort) and check that it exits cleanly."""
    for _ in range(50):
        if pinger.ping(0.2, number=-1.0) is not None or proc.poll() is not None:
            break
    status = proc.wait(30)
    if status != 0:
        raise RuntimeError(f"{pinger.variant} responder exited {status}: {proc.stderr.read()[-500:]}")


def measure(variants, bus, env, timed, warmup):
    """{variant: figures} of `timed` round trips to each responder, in alternating blocks."""
    pingers = [Pinger(bus, variant) for variant in variants]
    procs = [responder(variant, env) for variant in variants]
    try:
        for pinger, proc in zip(pingers, procs):
            await_answer(pinger, proc)
        for pinger in pingers:
            pinger.timed(warmup)
            pinger.samples, pinger.lost = [], 0
        done = 0
        while done < timed:
            block = min(BLOCK, timed - done)
            for pinger in pingers:
                pinger.timed(block)
            done += block
        for pinger, proc in zip(pingers, procs):
            finish(pinger, proc)
    finally:
        for proc in procs:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    return {pinger.variant: pinger.figures() for pinger in pingers}


def main(argv=None):
    args = parse_args(argv)
    if args.echo:
        return echo_main()
    size = "smoke" if args.smoke else "quick" if args.quick else "full"
    timed, warmup = SIZES[size]
    timed = args.n or timed
    sys.path.insert(0, ROOT)
    from scoopc.robots import dds

    folder = tempfile.mkdtemp(prefix="scoopc-latency-")
    settings = dds.loopback_environment(folder, args.domain if args.domain is not None else random.randint(100, 200))
    os.environ.update(settings)
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    print(
        f"# robots_latency: python {platform.python_version()}, {os.cpu_count()} cpus, load "
        f"{os.getloadavg()[0]:.1f}, loopback DDS domain {settings['ROS_DOMAIN_ID']}, size={size}: "
        f"{timed} timed round trips each after {warmup} warm-up, one in flight, alternating blocks of {BLOCK}",
        flush=True,
    )
    variants = [args.only] if args.only else ["baseline", "compiled"]
    bus = dds.DdsBus()
    try:
        results = measure(variants, bus, env, timed, warmup)
    finally:
        bus.close()
    for variant in variants:
        found = results[variant]
        print(
            f"latency {variant} n={found['n']} median_us={found['median_us']:.0f} "
            f"p99_us={found['p99_us']:.0f} mean_us={found['mean_us']:.0f} lost={found['lost']}",
            flush=True,
        )
    if len(results) == 2:
        base, ours = results["baseline"], results["compiled"]
        print(
            f"ratio compiled/baseline median={ours['median_us'] / base['median_us']:.2f} "
            f"p99={ours['p99_us'] / base['p99_us']:.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
