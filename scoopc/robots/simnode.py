"""`scoopc sim WORLD`: the simulator as a ROS 2 node, paced to the wall clock.

The simulator (scoopc.robots.sim) steps on its own clock, at `--rate` simulated seconds per wall
second (1 by default, `--realtime`; 0: as fast as it can), and talks ROS 2 through
`backends.open_ros2_bus` (DdsBus over cyclonedds unless rclpy is there and SCOOPC_ROS2_BACKEND
says otherwise): it subscribes each robot's cmd_vel and publishes odom, the range sensors, the
laser scan, battery_state and /clock (see docs/ROBOTS.md). A ROS 2 controller, or a scoopc program
run with `scoopc run --robot ros2`, in another process drives it.

Commands arrive on the transport's thread; they are queued and applied between two steps on the
node's own thread, so a step sees a consistent state. A node that falls behind the wall clock
catches up by at most MAX_LAG seconds; beyond that simulated time runs slower (no burst of
steps). Progress lines go to stderr. It stops at the end of `--duration` (default: the world's
`duration`; `--duration 0`: until interrupted), or on Ctrl-C / SIGTERM (a clean stop, exit
status 0): every robot is stopped, `--png`, `--gif` and the `--record` MCAP file are written, the
transport is closed.

For scoopc's argument parser: `add_arguments(parser)` declares the options, `command(args)` runs
a parsed command, `main(argv)` does both (`python -m scoopc.robots.simnode WORLD ...`).
"""

from __future__ import annotations

import argparse
import collections
import math
import signal
import sys
import threading
import time

from ..exits import Exit
from .backends import describe, open_ros2_bus
from .bus import Tap

MAX_LAG = 0.25  # wall-clock seconds the node may fall behind before it drops the debt


NODE = ("scoopc_sim", None)  # the simulator's node in the ROS graph: /scoopc_sim


def add_arguments(parser: argparse.ArgumentParser) -> argparse.ArgumentParser:
    parser.add_argument("world", metavar="WORLD", help="the world file (YAML, see docs/ROBOTS.md)")
    pace = parser.add_mutually_exclusive_group()
    pace.add_argument(
        "--realtime", action="store_true", help="step at real-time speed, one simulated second per second (the default)"
    )
    pace.add_argument(
        "--rate",
        type=float,
        metavar="X",
        help="simulated seconds per wall-clock second (2: twice as fast; 0: as fast as possible)",
    )
    parser.add_argument(
        "--duration",
        type=float,
        metavar="S",
        help="simulated seconds to run (default: the world's duration; 0: until interrupted)",
    )
    parser.add_argument("--domain", type=int, metavar="N", help="the ROS 2 domain id (default: ROS_DOMAIN_ID, else 0)")
    parser.add_argument(
        "--ros-distro",
        type=str.lower,
        choices=("humble", "jazzy", "lyrical"),
        metavar="DISTRO",
        help="the ROS 2 distribution whose messages and type hashes are used: humble, jazzy or "
        "lyrical (default: ROS_DISTRO, else jazzy)",
    )
    parser.add_argument("--png", metavar="FILE", help="write the trajectories as a PNG at the end")
    parser.add_argument("--gif", metavar="FILE", help="write an animated GIF of the run at the end")
    parser.add_argument("--record", metavar="FILE", help="record every topic into an MCAP file (ROS 2 schemas, CDR)")
    parser.add_argument(
        "--progress",
        type=float,
        default=5.0,
        metavar="S",
        help="wall-clock seconds between progress lines on stderr (default 5; 0: none)",
    )
    return parser


def build_parser() -> argparse.ArgumentParser:
    return add_arguments(
        argparse.ArgumentParser(
            prog="scoopc sim",
            description="Run the simulator as a ROS 2 node (DDS): it subscribes each robot's "
            "cmd_vel and publishes its sensors and /clock, paced to the wall clock.",
        )
    )


class NodeBus:
    """The simulator's view of the ROS 2 bus: publishes go out at once; received commands wait in a
    queue until `drain()` (the node's thread, between steps). Taps see both, in that order."""

    def __init__(self, bus):
        self.bus = bus
        self._pending = collections.deque()  # (topic, callback, msg); deque appends are atomic
        self._taps = []

    def publish(self, topic, msg):
        for tap in self._taps:
            tap(topic, msg)
        self.bus.publish(topic, msg)

    def subscribe(self, topic, callback):
        return self.bus.subscribe(topic, lambda msg: self._pending.append((topic, callback, msg)))

    def drain(self) -> int:
        count = 0
        while self._pending:
            topic, callback, msg = self._pending.popleft()
            for tap in self._taps:
                tap(topic, msg)
            callback(msg)
            count += 1
        return count

    def tap(self, callback):
        tap = Tap(self, callback)
        self._taps = self._taps + [tap]
        return tap

    def _untap(self, tap):
        self._taps = [t for t in self._taps if t is not tap]


class _Stop:
    """Set by SIGTERM (and SIGINT) handlers: the loop ends at the next step."""

    def __init__(self):
        self.requested = None

    def __call__(self, signum, frame):
        self.requested = signal.Signals(signum).name


def _say(stderr, text):
    print(f"scoopc sim: {text}", file=stderr, flush=True)


def _progress(sim, wall, commands):
    poses = ", ".join(f"{r.name} ({r.x:.2f}, {r.y:.2f}, {r.theta:+.2f})" for r in sim.robots)
    return f"t={sim.time:.1f} s (wall {wall:.1f} s), {commands} commands; {poses}"


def driver_qos(spec) -> dict:
    """{topic: (reliability, depth)} of the publishers of the driver a simulated robot stands for:
    the Thymio driver (jeguzzi/ros-thymio, thymio_driver/thymio_driver/base.py and
    thymio_driver_node.py: create_publisher(..., 1), rclpy's default reliable QoS) and the TurtleBot3
    bringup (ROBOTIS-GIT/turtlebot3, turtlebot3_node/src/odometry.cpp and sensors/sensors.hpp:
    rclcpp::QoS(rclcpp::KeepLast(10)), reliable) publish reliably; laser scans go out best effort
    as laser drivers publish them (sensor-data QoS)."""
    from .sim import sensors  # deferred: start-up (scoopc.robots.sim.sensors loads only when this is used)

    prefix = f"/{spec.namespace}" if spec.namespace else ""
    depth = 1 if spec.kind == "thymio" else 10
    qos = {
        f"{prefix}/odom": ("reliable", depth),
        f"{prefix}/battery_state": ("reliable", depth),
        f"{prefix}/scan": ("best_effort", 10),
    }
    if spec.kind == "thymio":
        for name in sensors.PROXIMITY:
            qos[f"{prefix}/proximity/{name}"] = ("reliable", 1)
        for name in sensors.GROUND:
            qos[f"{prefix}/ground/{name}"] = ("reliable", 1)
    return qos


def run(
    world,
    *,
    rate=1.0,
    duration=None,
    domain=None,
    png=None,
    gif=None,
    record=None,
    progress=5.0,
    bus=None,
    stderr=None,
    stop=None,
    ros_distro=None,
) -> int:
    """Run the node; returns the exit status. `bus`: a bus to use instead of opening one (closed by the
    caller); `stop`: a threading.Event that ends the run (tests); `ros_distro`: humble, jazzy or
    lyrical (None: ROS_DISTRO, else jazzy)."""
    import yaml  # deferred: start-up (yaml loads only when this is used)

    from . import ros_messages  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
    from .sim import Simulator, World, WorldError  # deferred: start-up (scoopc.robots.sim loads only when this is used)

    stderr = sys.stderr if stderr is None else stderr
    try:
        distro, source = ros_messages.resolve_distro(ros_distro)
    except ros_messages.DistroError as e:
        _say(stderr, f"error: {e}")
        return Exit.USAGE
    ros_messages.use_distro(distro)
    try:
        loaded = world if isinstance(world, World) else World.load(world)
    except (OSError, WorldError, ValueError, TypeError, LookupError, yaml.YAMLError) as e:
        _say(stderr, f"error: cannot load the world {world}: {e}")
        return Exit.USAGE
    end = loaded.duration if duration is None else duration
    end = math.inf if not end or end <= 0 else end
    own_bus = bus is None
    if own_bus:
        stamped = {
            f"/{spec.namespace}/cmd_vel" if spec.namespace else "/cmd_vel": "geometry_msgs/msg/TwistStamped"
            for spec in loaded.robots
            if spec.cmd_vel_stamped
        }
        qos = {}
        for spec in loaded.robots:
            qos.update(driver_qos(spec))
        try:
            bus = open_ros2_bus(
                domain, types=stamped, writer_qos=qos, report=lambda text: _say(stderr, text), node=NODE
            )
        except Exception as e:  # noqa: BLE001 - no backend, DDS cannot start, ...
            _say(stderr, f"error: cannot open the ROS 2 transport: {e}")
            return Exit.USAGE
    backend = describe(bus)
    node = NodeBus(bus)
    recorder = sim = None
    flag = _Stop()
    handlers = {}
    if threading.current_thread() is threading.main_thread():
        for signum in (signal.SIGINT, signal.SIGTERM):
            handlers[signum] = signal.signal(signum, flag)
    try:
        if record:
            from .record import Recorder  # deferred: start-up (scoopc.robots.record loads only when this is used)

            clock = {"sim": None}
            recorder = Recorder(node, record, clock=lambda: clock["sim"].time_ns if clock["sim"] else 0)
        sim = Simulator(loaded, node)
        if recorder is not None:
            clock["sim"] = sim
        robots = ", ".join(f"{r.name} on /{r.namespace}" if r.namespace else r.name for r in sim.robots)
        pace = f"{rate:g}x real time" if rate > 0 else "as fast as possible"
        length = "until interrupted" if end == math.inf else f"for {end:g} s"
        domain_text = getattr(bus, "domain", domain)
        discovery = getattr(bus, "discovery", None)
        _say(
            stderr,
            f"world {loaded.name!r} ({robots}), ROS 2 {distro} ({source}), domain {domain_text} ({backend}"
            + (f", {discovery}" if discovery else "")
            + f"), {pace}, {length}",
        )
        for warning in getattr(bus, "discovery_warnings", ()):
            _say(stderr, warning)
        commands, start, last_report, lag = 0, time.monotonic(), time.monotonic(), 0.0
        last_qos = start
        end_ns = None if end == math.inf else int(round(end * 1e9))
        while end_ns is None or sim.time_ns < end_ns:
            if flag.requested or (stop is not None and stop.is_set()):
                break
            commands += node.drain()
            sim.step()
            now = time.monotonic()
            if rate > 0:
                ahead = start + sim.time / rate - now
                if ahead > 0:
                    time.sleep(ahead)
                else:
                    lag = max(lag, -ahead)
                    if -ahead > MAX_LAG:  # too far behind: slow the simulated time, no burst
                        start -= ahead
            if now - last_qos >= 1.0 and hasattr(bus, "check_qos"):
                last_qos = now  # a stock reader asking reliable on the laser, ...
                bus.check_qos()
            if progress and now - last_report >= progress:
                last_report = now
                _say(stderr, _progress(sim, now - start, commands))
        commands += node.drain()
        if hasattr(bus, "check_qos"):
            bus.check_qos()
        why = (
            f"stopped by {flag.requested}"
            if flag.requested
            else "stopped"
            if stop is not None and stop.is_set()
            else "duration reached"
        )
        sim.stop_all()
        _say(
            stderr,
            f"{why} at t={sim.time:.2f} s; {_progress(sim, time.monotonic() - start, commands)}"
            + (f"; fell behind the wall clock by up to {lag * 1000:.0f} ms" if lag > 0.05 else ""),
        )
        for robot in sim.robots:
            if robot.collisions or robot.fallen:
                fell = ", fell into a hole" if robot.fallen else ""
                _say(stderr, f"{robot.name}: {len(robot.collisions)} collisions{fell}")
    finally:
        for signum, handler in handlers.items():
            signal.signal(signum, handler)
        if recorder is not None:
            recorder.close()
        if sim is not None:
            sim.close()
        if own_bus:
            bus.close()
    if recorder is not None:
        _say(stderr, f"recorded {recorder.count} messages on {len(recorder.counts)} topics in {record}")
    status = 0
    for path, what, render in ((png, "trajectories", sim.render_png), (gif, "animation", _gif(sim))):
        if path:
            try:
                _say(stderr, f"{what} in {render(path)}")
            except (OSError, ValueError) as e:
                _say(stderr, f"error: cannot write {path}: {e}")
                status = 1
    return status


def _gif(sim):
    def render(path):
        from .sim.render import render_gif  # deferred: start-up (scoopc.robots.sim.render loads only when this is used)

        return render_gif(sim, path)

    return render


def command(args: argparse.Namespace) -> int:
    """Run a parsed `scoopc sim` command (the handler scoopc's CLI registers)."""
    rate = 1.0 if args.rate is None else args.rate
    if rate < 0:
        print("scoopc sim: error: --rate must be 0 or more", file=sys.stderr)
        return Exit.USAGE
    return run(
        args.world,
        rate=rate,
        duration=args.duration,
        domain=args.domain,
        png=args.png,
        gif=args.gif,
        record=args.record,
        progress=args.progress,
        ros_distro=args.ros_distro,
    )


def main(argv=None) -> int:
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as e:  # argparse: --help (0) or a usage error (2)
        return int(e.code or 0)
    return command(args)


if __name__ == "__main__":
    sys.exit(main())
