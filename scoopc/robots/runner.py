"""Running a compiled program against a robot: the in-process simulator (the default for programs
that use Roboscoop) or a ROS 2 robot (`--robot ros2`).

On the simulator, the world steps on the runtime's clock: a dedicated processor (SIMULATOR) gets
a periodic timer of one world step. With the virtual clock (the default) simulated time jumps to
the next step only when every processor waits, so a program's reaction to the sensor messages of
one step is over before the next step; `realtime` paces the steps to the wall clock instead. The
run ends at the world's duration (the program is stopped) or as soon as the program is over:
every processor idle and no timer pending but the simulator's.

Safety: whatever ends the run (normal end, uncaught exception, deadlock, Ctrl-C, the duration),
every cmd_vel topic the program published on gets a zero velocity before the run returns.
"""

from __future__ import annotations

import math
import re
import signal
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import scoopc.runtime as srt
from scoopc.runtime.clock import Timer

from ..exits import UsageError
from ..project import beside_program
from ..results import RunResult
from ..runtime.stop_signals import STOP_SIGNALS, shielded, status_of
from . import transport, velocity
from .bus import Bus
from .silence import Watch, say

DEFAULT_WORLD = {
    "name": "arena",
    "size": [5.0, 5.0],
    "duration": 120,
    "goal": [4.3, 4.3],
    "charging_station": {"position": [0.5, 4.5], "radius": 0.25},
    "boxes": [{"center": [2.5, 2.5], "size": [0.6, 0.6]}],
    "robots": [{"name": "robot1", "kind": "thymio", "start": [0.6, 0.6, 0.0]}],
}

_SIGNAL_NAMES = {int(getattr(signal, name)): name for name in STOP_SIGNALS if hasattr(signal, name)}
_NODE_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")  # rcl's node names (rmw_validate_node_name)
_TWISTS = ("geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped")


class RobotError(UsageError):
    """A robot run that cannot start (bad world, unknown namespace, no ROS 2 transport): exit 2."""


@dataclass
class RobotOptions:
    """How a Roboscoop program runs (the robot options of `scoopc run`, docs/ROBOTS.md)."""

    robot: str | None = None  # "sim", "ros2" or "none"; None: "sim" for Roboscoop programs
    world: Any = None  # a world file's path, a dict or a World; None: world.yaml beside
    #                                     the program, else the built-in arena
    namespace: str | None = None  # which robot of the world, or a ROS 2 robot's topic prefix
    realtime: bool = False  # pace the simulator to the wall clock
    duration: float | None = None  # seconds to run (default: the world's duration; ROS 2: none)
    goal: tuple | None = None  # (x, y) told to the program (default: the world's)
    png: str | Path | bool | None = None  # the trajectory picture; True: <program>.png
    gif: str | Path | None = None
    record: str | Path | None = None  # an MCAP recording of every topic
    ros_distro: str | None = None  # humble, jazzy or lyrical; None: ROS_DISTRO, else jazzy
    use_sim_time: bool = False  # ROS 2: stamp commands with the latest /clock, not the system clock
    wait_robot: float = 3.0  # ROS 2: seconds before silent topics are reported
    require_robot: bool = False  # ROS 2: a topic still silent after `wait_robot` fails the run (exit 3)
    profile: str | Path | None = None  # a robot.yaml profile; None: robot.yaml beside the program, if any
    node_name: str | None = None  # ROS 2: the program's node name (default: the root class in lower case)

    def __post_init__(self):
        if self.robot not in (None, "sim", "ros2", "none"):
            raise UsageError(f"robot must be sim, ros2 or none, not {self.robot!r}")
        if self.ros_distro is not None:
            from .ros_messages import (
                DISTROS,  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
            )

            if self.ros_distro.lower() not in DISTROS:
                raise UsageError(f"ros_distro must be one of {', '.join(DISTROS)}, not {self.ros_distro!r}")
        if self.node_name is not None and not _NODE_NAME.match(self.node_name):
            raise UsageError(
                f"node_name {self.node_name!r} is not a valid ROS 2 node name "
                "(letters, digits and underscores, not starting with a digit)"
            )
        if not (self.wait_robot >= 0):
            raise UsageError(f"wait_robot must be 0 seconds or more, not {self.wait_robot!r}")


@dataclass
class RobotSettings:
    """What ROBOT_ENVIRONMENT tells the program (stdlib/roboscoop/util/robot_environment.e)."""

    mode: str = "none"  # "none", "sim" or "ros2"
    namespaces: list = field(default_factory=list)  # topic prefixes: "/robot1" or ""
    limits: list = field(default_factory=list)  # (max_linear, max_angular) per robot
    main: int = 0  # index of "the" robot (`namespace`)
    goal: tuple | None = None
    station: tuple | None = None  # (x, y, radius)
    duration: float = -1.0
    distro: str = "jazzy"  # the ROS 2 distribution (ROBOT_ENVIRONMENT.ros_distro)
    stamped: list = field(default_factory=list)  # per robot: does its cmd_vel take TwistStamped?
    profile: Any = None  # the robot profile (scoopc.robots.profile.Profile) of a ROS 2 run


ROS2_LIMITS = (0.2, 1.0)  # speed limits reported for a ROS 2 robot (m/s, rad/s)
SERVICE = "robot"  # the RobotSettings' key in the runtime's services
PARAMETERS = "parameters"  # the ParameterNode's key (ROS_PARAMETER; None without one)
SIMULATOR_SERVICE = "simulator"  # the Simulator's key, in a simulated run (the live view draws its world)


def settings_of(rt) -> RobotSettings:
    """The robot settings of the run on runtime `rt` (a run without a robot: the defaults)."""
    return rt.services.get(SERVICE) or RobotSettings()


class SafetyBus:
    """The program's view of a bus: remembers the topics velocity commands went to, so that the
    robot can be stopped whatever ends the run. Everything else goes to the bus it wraps."""

    def __init__(self, bus):
        self.bus = bus
        self.command_topics = {}  # topic -> stamped?
        self._lock = threading.Lock()

    def publish(self, topic, msg):
        typename = getattr(type(msg), "__msgtype__", "")
        if typename in _TWISTS:
            with self._lock:
                self.command_topics[topic] = typename == _TWISTS[1]
        return self.bus.publish(topic, msg)

    def __getattr__(self, name):
        return getattr(self.bus, name)

    def stop_robots(self):
        """A zero velocity on every cmd_vel topic used (Twist or TwistStamped as the program sent)."""
        from .velocity import twist, twist_stamped  # deferred: loads rosbags (start-up)

        with self._lock:
            topics = dict(self.command_topics)
        for topic, stamped in topics.items():
            try:
                self.bus.publish(topic, twist_stamped(0.0, 0.0) if stamped else twist(0.0, 0.0))
            except Exception as e:  # noqa: BLE001 - keep stopping the others
                print(f"scoopc: could not stop the robot on {topic}: {e}", file=sys.stderr)
        return sorted(topics)


# ---- the simulator on the runtime's clock ------------------------------------------------------


class _Driver:
    """Lives on the SIMULATOR processor; its periodic timer steps the world."""


class SimDriver:
    def __init__(self, sim, duration, progress=None):
        self.sim = sim
        self.end_ns = int(round(duration * 1e9)) if duration is not None and duration >= 0 else None
        self.progress = progress
        self.stopped_by = None  # "duration" or "program", once the simulation is over
        self.timer = None
        self.rt = None
        self._next_report = 0.0
        self._wall0 = time.monotonic()

    def attach(self, rt):
        """Called on the root's thread once the runtime exists, before the root is created."""
        self.rt = rt
        proc = srt.Processor(rt, False, "SIMULATOR")
        self.holder = proc.new(_Driver)
        self.holder.driver = self
        dt = self.sim.dt_ns
        self.timer = srt.call_later(dt, self.holder, _tick, period_ns=dt, phase=0)

    def tick(self):
        if self.stopped_by is not None:
            return
        if self.end_ns is not None and self.sim.time_ns >= self.end_ns:
            self._finish("duration")
        elif self._program_over():
            self._finish("program")
        else:
            self.sim.step()
            if self.progress is not None:
                self._report()

    def _program_over(self):
        """Is every processor but SIMULATOR idle, with no timer pending but ours?"""
        rt = self.rt
        with rt.glock:
            if rt.n_running != 1 or rt.runnable or rt.clock.due:
                return False
            return not any(
                isinstance(e[-1], Timer) and e[-1] is not self.timer and not e[-1].cancelled for e in rt.clock.heap
            )

    def _finish(self, reason):
        self.stopped_by = reason
        self.timer.cancel()
        if reason == "duration":
            self.rt.stop()

    def _report(self):
        wall = time.monotonic() - self._wall0
        if wall < self._next_report:
            return
        self._next_report = wall + 1.0
        end = f" of {self.end_ns / 1e9:.0f}" if self.end_ns is not None else ""
        self.progress(f"simulated {self.sim.time:.1f} s{end} ({wall:.0f} s)")


def _tick(holder):
    holder.driver.tick()


# ---- choosing the world and the settings -------------------------------------------------------


def find_world(program_paths, world=None):
    """The world to simulate: `world` (path, dict or World), else world.yaml beside the program,
    else the built-in arena. Returns (World, where it came from)."""
    from .sim.world import (  # deferred: start-up (scoopc.robots.sim.world loads only when this is used)
        World,
        WorldError,
    )

    if isinstance(world, World):
        return world, world.name
    if isinstance(world, dict):
        return _load(lambda: World.from_dict(world), "the given world"), "the given world"
    if world is None:
        world = beside_program(program_paths, "world.yaml")
    if world is None:
        return World.from_dict(DEFAULT_WORLD), "the built-in arena"
    path = Path(world)
    if not path.is_file():
        raise RobotError(f"no world file {path}")
    try:
        return _load(lambda: World.load(str(path)), str(path)), str(path)
    except WorldError:
        raise
    except (OSError, ValueError, TypeError, KeyError) as e:
        raise RobotError(f"{path}: not a valid world: {e}") from None


def _load(make, where):
    from .sim.world import WorldError  # deferred: start-up (scoopc.robots.sim.world loads only when this is used)

    try:
        return make()
    except WorldError as e:
        text = str(e)
        raise RobotError(text if text.startswith(where) else f"{where}: {text}") from None


def _prefix(namespace):
    namespace = (namespace or "").strip("/")
    return f"/{namespace}" if namespace else ""


def sim_settings(world, namespace=None, goal=None, duration=None):
    namespaces = [_prefix(r.namespace) for r in world.robots]
    main = 0
    if namespace is not None:
        wanted = _prefix(namespace)
        if wanted not in namespaces:
            raise RobotError(
                f"the world has no robot with namespace {wanted or '/'!r} (it has {', '.join(namespaces)})"
            )
        main = namespaces.index(wanted)
    station = (*world.station, world.station_radius) if world.station is not None else None
    return RobotSettings(
        mode="sim",
        namespaces=namespaces,
        main=main,
        limits=[(r.max_linear, r.max_angular) for r in world.robots],
        stamped=[r.cmd_vel_stamped for r in world.robots],
        goal=tuple(goal) if goal is not None else world.goal,
        station=station,
        duration=world.duration if duration is None else duration,
    )


def ros2_settings(namespace=None, goal=None, duration=None):
    return RobotSettings(
        mode="ros2",
        namespaces=[_prefix(namespace)],
        limits=[ROS2_LIMITS],
        goal=tuple(goal) if goal is not None else None,
        duration=-1.0 if duration is None else duration,
    )


# ---- runs --------------------------------------------------------------------------------------


def run_with_robot(
    launch,
    settings,
    bus,
    *,
    sim=None,
    duration=None,
    recorder=None,
    png=None,
    gif=None,
    progress=None,
    stderr=None,
    extra_start=None,
    program="",
):
    """Run `launch(on_start)` (which runs the program and returns its exit status) with `bus` as the
    transport and, when `sim` is given, the simulator stepped on the runtime's clock. The program
    reads `settings` through ROBOT_ENVIRONMENT (the runtime's `services`); `program` names it in
    the pictures' titles."""
    stderr = stderr or sys.stderr
    safety = SafetyBus(bus)
    previous_bus = transport.use(safety)
    driver = (
        SimDriver(sim, duration if duration is not None else settings.duration, progress) if sim is not None else None
    )
    result = RunResult(status=0, sim=sim)

    def on_start(rt):
        rt.services[SERVICE] = settings
        if sim is not None:
            rt.services[SIMULATOR_SERVICE] = sim
        if driver is not None:
            driver.attach(rt)
        if extra_start is not None:
            extra_start(rt)

    try:
        result.status = launch(on_start)
    except KeyboardInterrupt as interrupt:  # a signal after the runtime had handled the first
        result.status = status_of(interrupt)
        stderr.write(f"scoopc: stopped by {getattr(interrupt, 'signal_name', 'SIGINT')}\n")
    finally:
        with shielded():  # a second signal must not cut the robot's stop short
            result.stopped_topics = safety.stop_robots()
            if recorder is not None:
                result.record = str(recorder.close())
        transport.use(previous_bus)
    if result.status > 128 and result.status - 128 in _SIGNAL_NAMES:
        result.stopped_by = _SIGNAL_NAMES[result.status - 128]
    elif driver is not None:
        result.stopped_by = driver.stopped_by or "program"
    if driver is not None:
        result.png = _render(sim, png, "render_png", stderr, program)
        result.gif = _render(sim, gif, "render_gif", stderr, program)
    return result


def _recorder(bus, path, clock=None):
    """A recorder of every message on `bus` (made before the simulator, so that its first
    messages are in it; `clock`: the simulated time for messages without a stamp)."""
    if not path:
        return None
    from .record import Recorder  # deferred: start-up (scoopc.robots.record loads only when this is used)

    try:
        return Recorder(bus, str(path), clock=clock)
    except OSError as e:
        raise RobotError(f"cannot record to {path}: {e.strerror or e}") from None


def _render(sim, path, how, stderr, program=""):
    if not path:
        return None
    try:
        if how == "render_png":
            sim.render_png(str(path), program=program)
        else:
            from .sim.render import (
                render_gif,  # deferred: start-up (scoopc.robots.sim.render loads only when this is used)
            )

            render_gif(sim, str(path), program=program)
    except Exception as e:  # noqa: BLE001 - the run itself succeeded
        stderr.write(f"scoopc: could not write {path}: {e}\n")
        return None
    return str(path)


def describe_end(result, wall, asked: bool = False) -> str:
    """One line for stderr after a simulated run (`asked`: the duration was given, not the world's)."""
    sim = result.sim
    why = {
        "duration": "the duration asked for" if asked else "the world's duration",
        "program": "the program ended",
    }.get(result.stopped_by, f"stopped by {result.stopped_by}")
    parts = []
    for robot in sim.robots:
        text = f"{robot.name} moved {robot.distance:.2f} m"
        if robot.collisions:
            text += f", {len(robot.collisions)} collision{'s' if len(robot.collisions) != 1 else ''}"
        if robot.fallen:
            text += ", fell into a hole"
        if not math.isclose(robot.battery, robot.spec.battery.initial):
            text += f", battery {robot.battery:.0%}"
        parts.append(text)
    line = f"scoopc: simulated {sim.time:.1f} s in {wall:.1f} s ({why}): " + "; ".join(parts)
    if result.png:
        line += f"\nscoopc: trajectory written to {result.png}"
    if result.gif:
        line += f"\nscoopc: animation written to {result.gif}"
    if result.record:
        line += f"\nscoopc: recording written to {result.record}"
    return line


def open_ros2_bus(report=None, node=None):
    """The ROS 2 transport: rclpy or DDS (see scoopc.robots.backends), as the node `node`
    ((name, namespace)) of the ROS graph."""
    from .backends import (
        open_ros2_bus as choose,  # deferred: start-up (scoopc.robots.backends loads only when this is used)
    )

    return choose(report=report, node=node)


def run(options: RobotOptions, launch, program_paths, program_name: str, stderr=None) -> RunResult:
    """A run with a robot (`options.robot` is "sim" or "ros2"): set up the transport (and the
    simulator), run `launch(on_start, virtual_clock)`, stop the robot, report on `stderr`. Raises
    RobotError, before the program starts, when the run cannot be set up."""
    stderr = stderr or sys.stderr
    progress = _progress_line(stderr)
    wall = time.monotonic()
    distro = choose_distro(options.ros_distro)
    if options.robot != "sim":
        stderr.write(f"scoopc: ROS 2 {distro[0]} ({distro[1]})\n")
    try:
        if options.robot == "sim":
            result = _run_simulated(options, launch, program_paths, program_name, stderr, progress)
        else:
            result = _run_ros2(options, launch, program_paths, program_name, stderr)
    finally:
        velocity.use_clock(None)
    if progress is not None:
        progress("", final=True)
    if result.sim is not None:
        stderr.write(describe_end(result, time.monotonic() - wall, options.duration is not None) + "\n")
    elif result.stopped_topics:
        stderr.write(f"scoopc: sent a zero velocity on {', '.join(result.stopped_topics)}\n")
    return result


def choose_distro(option=None) -> tuple[str, str]:
    """Resolve and install the run's ROS 2 distribution: (name, where the choice came from)."""
    from . import ros_messages  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)

    try:
        name, source = ros_messages.resolve_distro(option)
    except ros_messages.DistroError as e:
        raise RobotError(str(e)) from None
    ros_messages.use_distro(name)
    return name, source


def _run_simulated(options, launch, program_paths, program_name, stderr, progress) -> RunResult:
    from . import ros_messages, velocity  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
    from .sim.simulator import (
        Simulator,  # deferred: start-up (scoopc.robots.sim.simulator loads only when this is used)
    )

    world, source = find_world(program_paths, options.world)
    load_profile(program_paths, options.profile)  # checked here too: a mistake shows before the robot is real
    settings = sim_settings(world, options.namespace, options.goal, options.duration)
    settings.distro = ros_messages.distro()
    bus = Bus()
    clock = _Later()
    for named in (options.png, options.gif, options.record):
        if isinstance(named, (str, Path)) and Path(named).exists():
            say(stderr, f"replacing the existing file {named}")
    recorder = _recorder(bus, options.record, clock)
    sim = Simulator(world, bus)
    clock.read = lambda: sim.time_ns
    velocity.use_clock(clock)  # stamps in simulated time, as /clock tells it
    if progress is not None:
        progress(f"simulating {world.name} ({source}), {settings.duration:g} s", final=True)
    png = unnamed_output(program_name, "png") if options.png is True else (options.png or None)
    return run_with_robot(
        lambda on_start: launch(on_start, not options.realtime),
        settings,
        bus,
        sim=sim,
        recorder=recorder,
        png=png,
        gif=options.gif,
        progress=progress,
        stderr=stderr,
        program=program_name,
    )


def unnamed_output(program_name: str, suffix: str, root: Path = Path("runs")) -> Path:
    """Where a picture nobody named goes: runs/<program>/<n>/<program>.<suffix>, n one more than
    the highest run number there, so that no run replaces another's files."""
    folder = root / program_name.lower()
    numbers = [int(p.name) for p in folder.iterdir() if p.name.isdigit()] if folder.is_dir() else []
    run_folder = folder / str(max(numbers, default=0) + 1)
    run_folder.mkdir(parents=True, exist_ok=True)
    return run_folder / f"{program_name.lower()}.{suffix}"


def load_profile(program_paths, given=None):
    """The run's robot profile (scoopc.robots.profile): `given`, else robot.yaml beside the
    program, else None; RobotError (exit 2) naming the file, line, column and key when invalid."""
    from . import profile  # deferred: start-up (scoopc.robots.profile loads only when this is used)

    path = profile.find(program_paths, given)
    if path is None:
        return None
    try:
        return profile.load(path)
    except profile.ProfileError as e:
        raise RobotError(str(e)) from None


def _node_parameters(bus, name, namespace, use_sim_time):
    """The program's node's parameter services (DdsBus; an rclpy node has rclpy's own)."""
    if not hasattr(bus, "owned"):
        return None
    from .parameters import node_parameters  # deferred: start-up (cyclonedds loads only when this is used)

    return node_parameters(bus, name, namespace, use_sim_time)


def _run_ros2(options, launch, program_paths, program_name, stderr) -> RunResult:
    from . import ros_messages, velocity  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)

    settings = ros2_settings(options.namespace, options.goal, options.duration)
    settings.distro = ros_messages.distro()
    settings.profile = profile = load_profile(program_paths, options.profile)
    node_name = options.node_name or program_name.lower()
    if profile is not None:
        settings.limits = [(profile.max_linear or ROS2_LIMITS[0], profile.max_angular or ROS2_LIMITS[1])]
        say(stderr, f"robot profile {profile.path}")
    try:
        bus = open_ros2_bus(report=lambda text: say(stderr, text), node=(node_name, options.namespace))
    except Exception as e:  # noqa: BLE001 - no backend, DDS cannot start, ...
        raise RobotError(f"cannot open the ROS 2 transport: {e}") from None
    if profile is not None:
        writers, readers = profile.qos(settings.namespaces[0])
        bus.writer_qos.update(writers)
        bus.reader_qos.update(readers)
    for warning in getattr(bus, "discovery_warnings", ()):
        say(stderr, warning)
    if getattr(bus, "discovery", None):
        say(stderr, f"domain {bus.domain}, {bus.discovery}")
    try:
        recorder = _recorder(bus, options.record)
        if options.use_sim_time:
            velocity.use_clock(velocity.sim_time(bus))
        parameters = _node_parameters(bus, node_name, options.namespace, options.use_sim_time)
    except RobotError:
        _close_ros2(bus)
        raise
    expired = threading.Event()
    watch = Watch(bus, options.wait_robot, options.require_robot, stderr)
    try:
        result = run_with_robot(
            lambda on_start: launch(on_start, None),
            settings,
            bus,
            recorder=recorder,
            stderr=stderr,
            extra_start=_starts(
                _deadline(settings.duration, expired),
                watch.start,
                lambda rt: rt.services.update({PARAMETERS: parameters}),
            ),
        )
        watch.finish()
        if watch.failed:
            result.status = 3
            result.stopped_by = "require_robot"
        elif expired.is_set() or result.status > 128:
            watch.summary()
    finally:
        watch.finish()
        _close_ros2(bus)
    if expired.is_set() and not watch.failed:
        result.stopped_by = "duration"
        stderr.write(f"scoopc: stopped the program after {settings.duration:g} s (--duration)\n")
    return result


def _starts(*hooks):
    hooks = [hook for hook in hooks if hook is not None]

    def on_start(rt):
        for hook in hooks:
            hook(rt)

    return on_start if hooks else None


def _deadline(duration, expired):
    """On a ROS 2 robot: stop the program after `duration` seconds of wall time (None: never)."""
    if duration is None or duration < 0:
        return None

    def stop(rt):
        expired.set()
        rt.stop()

    def on_start(rt):
        timer = threading.Timer(duration, stop, (rt,))
        timer.daemon = True
        timer.start()
        rt.shutdown_hooks.append(timer.cancel)

    return on_start


def _close_ros2(bus):
    with shielded():
        time.sleep(0.2)  # let the zero velocity reach the robot
        close = getattr(bus, "close", None)
        if close is not None:
            close()


class _Later:
    """A clock whose reading is set once the simulator exists."""

    def __init__(self):
        self.read = lambda: 0

    def __call__(self):
        return self.read()


def _progress_line(stderr):
    """Progress on stderr, rewriting one line, on a terminal only."""
    if not getattr(stderr, "isatty", lambda: False)():
        return None

    def show(message, final=False):
        stderr.write("\r\033[K" + (f"scoopc: {message}" if message else ""))
        if final and message:
            stderr.write("\n")
        stderr.flush()

    return show
