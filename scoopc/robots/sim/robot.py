"""One simulated differential-drive robot: kinematics, cmd_vel watchdog, collisions, falls, battery."""

import math
import threading

import numpy as np

WATCHDOG = 0.5  # seconds without cmd_vel before the robot stops


class SimRobot:
    """State of one robot; `advance(dt, now, world, others)` integrates one fixed step."""

    def __init__(self, spec):
        self.spec = spec
        self.name = spec.name
        self.namespace = spec.namespace
        self.x, self.y, self.theta = spec.start
        self.v = 0.0  # actual velocities (after limits, watchdog, collisions)
        self.w = 0.0
        self.cmd = (0.0, 0.0)  # last commanded (linear.x, angular.z), clamped
        self.last_cmd_time = None  # simulated time of the last cmd_vel
        self.cmd_count = 0
        self.battery = spec.battery.initial
        self.charging = False
        self.fallen = False
        self.fell_at = None
        self.in_contact = False
        self.empty = False
        self.collisions = []  # (time, x, y)
        self.watchdog_stops = []  # times at which the watchdog zeroed the command
        self.distance = 0.0
        self.trajectory = [(0.0, self.x, self.y, self.theta)]
        self._lock = threading.Lock()

    # ---- commands (called from the bus, possibly on another thread) ---------------------------------

    def command(self, linear, angular, now):
        s = self.spec
        v = max(-s.max_linear, min(s.max_linear, float(linear)))
        w = max(-s.max_angular, min(s.max_angular, float(angular)))
        if not (math.isfinite(v) and math.isfinite(w)):
            v = w = 0.0
        with self._lock:
            self.cmd = (v, w)
            self.last_cmd_time = now
            self.cmd_count += 1

    # ---- one step ---------------------------------------------------------------------------------

    def advance(self, dt, now, world, others):
        with self._lock:
            if self.cmd != (0.0, 0.0) and (self.last_cmd_time is None or now - self.last_cmd_time >= WATCHDOG - 1e-9):
                self.cmd = (0.0, 0.0)
                self.watchdog_stops.append(now)
            v, w = self.cmd
        if self.fallen or self.empty:
            v = w = 0.0
        x, y, th = self.x, self.y, self.theta
        if abs(w) > 1e-9:
            nth = th + w * dt
            nx = x + v / w * (math.sin(nth) - math.sin(th))
            ny = y - v / w * (math.cos(nth) - math.cos(th))
        else:
            nth, nx, ny = th, x + v * math.cos(th) * dt, y + v * math.sin(th) * dt
        nth = math.atan2(math.sin(nth), math.cos(nth))
        moved = (nx != x) or (ny != y)
        blocked = False
        if moved:
            r = self.spec.radius
            pt = np.array([[nx, ny]])
            clear = world.clearance(pt)[0]
            if clear < r:
                blocked = True
            else:
                for o in others:
                    if math.hypot(nx - o.x, ny - o.y) < r + o.spec.radius:
                        blocked = True
                        break
        if blocked:
            if not self.in_contact:
                self.collisions.append((now, x, y))
            self.in_contact = True
            with self._lock:
                self.cmd = (0.0, 0.0)
            self.v, self.w = 0.0, w
            self.theta = nth
        else:
            if moved:
                self.in_contact = False
            self.distance += math.hypot(nx - x, ny - y)
            self.x, self.y, self.theta = nx, ny, nth
            self.v, self.w = v, w
        if not self.fallen and world.holes and world.in_hole([[self.x, self.y]])[0]:
            self.fallen = True
            self.fell_at = (now, self.x, self.y)
            self.v = self.w = 0.0
            with self._lock:
                self.cmd = (0.0, 0.0)
        self._battery(dt, world)
        self.trajectory.append((now, self.x, self.y, self.theta))

    def _battery(self, dt, world):
        b = self.spec.battery
        self.charging = world.at_station(self.x, self.y) and not self.fallen
        if self.charging:
            self.battery = min(1.0, self.battery + b.charge_rate * dt)
        else:
            effort = max(abs(self.v) / self.spec.max_linear, abs(self.w) / self.spec.max_angular)
            self.battery = max(0.0, self.battery - (b.drain_idle + b.drain_motion * effort) * dt)
        self.empty = self.battery <= 0.0

    # ---- geometry helpers -------------------------------------------------------------------------

    def to_world(self, px, py):
        c, s = math.cos(self.theta), math.sin(self.theta)
        return self.x + c * px - s * py, self.y + s * px + c * py

    def path_length(self):
        return self.distance
