"""The simulator: fixed-step, deterministic; publishes and subscribes the robots' topics on a Bus.

Per robot, under its namespace NS: subscribes /NS/cmd_vel (geometry_msgs/msg/Twist, or TwistStamped when
the robot says `cmd_vel_stamped: true`); publishes /NS/odom (50 Hz), /NS/proximity/<name> and
/NS/ground/<left,right> (Thymio, 20 Hz), /NS/scan (10 Hz, when the robot has a laser), /NS/battery_state
(1 Hz); and /clock (every step). Time is simulated: integer nanoseconds, one step = world.step seconds.
"""

import math

import numpy as np

from . import sensors
from .robot import SimRobot
from .world import World


def _period(rate, dt_ns):
    return max(1, int(round(1e9 / rate / dt_ns)))


class Simulator:
    """`step()` advances one fixed step; `run_until(t)` steps up to simulated time t (seconds)."""

    def __init__(
        self,
        world,
        bus=None,
        *,
        odom_rate=50.0,
        proximity_rate=20.0,
        ground_rate=20.0,
        battery_rate=1.0,
        clock_rate=None,
    ):
        if not isinstance(world, World):
            world = World.load(world) if isinstance(world, str) else World.from_dict(world)
        if bus is None:
            from scoopc.robots.bus import Bus

            bus = Bus()
        self.world = world
        self.bus = bus
        self.dt_ns = int(round(world.step * 1e9))
        self.steps = 0
        self.robots = [SimRobot(spec) for spec in world.robots]
        self.rng = np.random.default_rng(world.seed)
        self._periods = {
            "odom": _period(odom_rate, self.dt_ns),
            "proximity": _period(proximity_rate, self.dt_ns),
            "ground": _period(ground_rate, self.dt_ns),
            "battery": _period(battery_rate, self.dt_ns),
            "clock": 1 if clock_rate is None else _period(clock_rate, self.dt_ns),
        }
        self._subs = []
        self._names = {}  # robot name -> {short topic name: full name}
        for robot in self.robots:
            topic = self.topic(robot, "cmd_vel")
            self._subs.append(bus.subscribe(topic, self._cmd_callback(robot)))
        self._publish_sensors(initial=True)

    # ---- naming -----------------------------------------------------------------------------------

    @staticmethod
    def topic(robot, name):
        return f"/{robot.namespace}/{name}" if robot.namespace else f"/{name}"

    def robot(self, name=None):
        if name is None:
            return self.robots[0]
        for r in self.robots:
            if name in (r.name, r.namespace):
                return r
        raise KeyError(name)

    @property
    def time_ns(self):
        return self.steps * self.dt_ns

    @property
    def time(self):
        """Simulated time in seconds."""
        return self.time_ns / 1e9

    # ---- commands ---------------------------------------------------------------------------------

    def _cmd_callback(self, robot):
        def on_cmd(msg):
            twist = getattr(msg, "twist", msg)  # TwistStamped or Twist
            robot.command(twist.linear.x, twist.angular.z, self.time)

        return on_cmd

    # ---- stepping ---------------------------------------------------------------------------------

    def step(self):
        self.steps += 1
        now = self.time
        dt = self.dt_ns / 1e9
        for robot in self.robots:
            robot.advance(dt, now, self.world, [o for o in self.robots if o is not robot])
        if self.steps % self._periods["clock"] == 0 and self._wants("/clock"):
            self.bus.publish("/clock", sensors.clock_msg(self.time_ns))
        self._publish_sensors()

    def run_until(self, t, stop=None):
        """Steps until simulated time >= t seconds (or until `stop()` is true, checked each step)."""
        end = int(round(t * 1e9))
        while self.time_ns < end:
            self.step()
            if stop is not None and stop():
                break

    def run(self, stop=None):
        """The world's whole duration."""
        self.run_until(self.world.duration, stop)

    def close(self):
        for s in self._subs:
            s.close()
        self._subs = []

    def _due(self, what, period=None):
        return self.steps % (period or self._periods[what]) == 0

    def _wants(self, topic):
        """Does anyone listen to `topic`? (A bus that cannot tell, such as DDS: assume so.)
        Messages nobody would receive are neither computed nor built."""
        wants = getattr(self.bus, "wants", None)
        return True if wants is None else wants(topic)

    def _publish_sensors(self, initial=False):
        t_ns, pub, wants = self.time_ns, self.bus.publish, self._wants
        for robot in self.robots:
            topic = self._topic_names(robot)
            if (initial or self._due("odom")) and wants(topic["odom"]):
                pub(topic["odom"], sensors.odom_msg(robot, t_ns))
            if robot.spec.kind == "thymio" and (initial or self._due("proximity")):
                heard = [name for name in sensors.PROXIMITY if wants(topic[f"proximity/{name}"])]
                if heard:
                    values = sensors.proximity_ranges(robot, self.world, self.robots)
                    for name in heard:
                        pub(topic[f"proximity/{name}"], sensors.proximity_msg(robot, name, values[name], t_ns))
            if robot.spec.kind == "thymio" and (initial or self._due("ground")):
                heard = [name for name in sensors.GROUND if wants(topic[f"ground/{name}"])]
                if heard:
                    values = sensors.ground_ranges(robot, self.world)
                    for name in heard:
                        pub(topic[f"ground/{name}"], sensors.ground_msg(robot, name, values[name], t_ns))
            laser = robot.spec.laser
            if (
                laser is not None
                and (initial or self._due("scan", _period(laser.rate, self.dt_ns)))
                and wants(topic["scan"])
            ):
                ranges = sensors.laser_ranges(robot, self.world, self.robots)
                pub(topic["scan"], sensors.scan_msg(robot, ranges, t_ns))
            if (initial or self._due("battery")) and wants(topic["battery_state"]):
                pub(topic["battery_state"], sensors.battery_msg(robot, t_ns))

    def _topic_names(self, robot):
        names = self._names.get(robot.name)
        if names is None:
            short = ["odom", "scan", "battery_state", "cmd_vel"]
            short += [f"proximity/{n}" for n in sensors.PROXIMITY] + [f"ground/{n}" for n in sensors.GROUND]
            names = self._names[robot.name] = {n: self.topic(robot, n) for n in short}
        return names

    # ---- results ----------------------------------------------------------------------------------

    def stop_all(self):
        """Zero velocity to every robot (the safety path on program exit)."""
        for robot in self.robots:
            robot.command(0.0, 0.0, self.time)

    def trajectory(self, name=None):
        """(N, 4) array: t, x, y, theta per step."""
        return np.array(self.robot(name).trajectory)

    def reachable_grid(self, name=None, resolution=0.05):
        """Boolean grid [iy, ix] of cells whose centre a robot centre can reach from its start pose
        (inside the world, clear of walls and boxes by the robot radius, not over a hole)."""
        robot = self.robot(name)
        w = self.world
        nx, ny = int(math.ceil(w.width / resolution)), int(math.ceil(w.height / resolution))
        xs = (np.arange(nx) + 0.5) * resolution
        ys = (np.arange(ny) + 0.5) * resolution
        gx, gy = np.meshgrid(xs, ys)
        pts = np.stack([gx.ravel(), gy.ravel()], axis=1)
        free = w.clearance(pts) >= robot.spec.radius
        if w.holes:
            free &= ~w.in_hole(pts)
        free = free.reshape(ny, nx)
        sx, sy = robot.spec.start[:2]
        start = (min(ny - 1, int(sy / resolution)), min(nx - 1, int(sx / resolution)))
        reach = np.zeros_like(free)
        if not free[start]:
            return reach
        reach[start] = True
        while True:  # flood fill, 4-connected, vectorised
            grown = reach.copy()
            grown[1:, :] |= reach[:-1, :]
            grown[:-1, :] |= reach[1:, :]
            grown[:, 1:] |= reach[:, :-1]
            grown[:, :-1] |= reach[:, 1:]
            grown &= free
            if (grown == reach).all():
                return reach
            reach = grown

    def coverage(self, name=None, resolution=0.05, radius=None):
        """Fraction of the reachable floor (reachable_grid) whose cells lie within `radius` (default: the
        robot radius) of the robot's trajectory."""
        robot = self.robot(name)
        reach = self.reachable_grid(name, resolution)
        total = reach.sum()
        if total == 0:
            return 0.0
        radius = robot.spec.radius if radius is None else radius
        traj = self.trajectory(name)[:, 1:3]
        cells = np.unique(np.floor(traj / resolution).astype(int), axis=0)
        k = int(math.ceil(radius / resolution))
        offs = np.array(
            [
                (dx, dy)
                for dx in range(-k, k + 1)
                for dy in range(-k, k + 1)
                if math.hypot(dx, dy) * resolution <= radius
            ]
        )
        stamped = (cells[:, None, :] + offs[None, :, :]).reshape(-1, 2)
        ny, nx = reach.shape
        ok = (stamped[:, 0] >= 0) & (stamped[:, 0] < nx) & (stamped[:, 1] >= 0) & (stamped[:, 1] < ny)
        seen = np.zeros_like(reach)
        seen[stamped[ok, 1], stamped[ok, 0]] = True
        return float((seen & reach).sum() / total)

    def summary(self):
        return {
            r.name: {
                "x": r.x,
                "y": r.y,
                "theta": r.theta,
                "distance": r.distance,
                "battery": r.battery,
                "collisions": len(r.collisions),
                "fallen": r.fallen,
                "cmd_vel": r.cmd_count,
            }
            for r in self.robots
        }

    def render_png(self, path, **kw):
        from .render import render_png

        return render_png(self, path, **kw)
