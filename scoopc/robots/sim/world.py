"""Simulator worlds: YAML world files, geometry (segments, boxes, holes) and vectorised queries.

Coordinates are metres, x right, y up, origin at the world's lower-left corner; angles in radians,
counter-clockwise, 0 along +x. The format is documented in docs/ROBOTS.md, section "Simulator worlds".
"""

import math
from dataclasses import dataclass, field

import numpy as np

from ..yamlschema import Reader, SchemaError, check_data, load, read_text
from . import world_schema

KINDS = {
    # kind: radius (m), max linear (m/s), max angular (rad/s), laser by default
    "thymio": dict(radius=0.055, max_linear=0.14, max_angular=3.0, laser=False),
    "diff_drive": dict(radius=0.15, max_linear=0.5, max_angular=2.0, laser=True),
    # TurtleBot3 burger: cmd_vel is TwistStamped from Jazzy on (the distribution's bringup)
    "turtlebot3": dict(radius=0.105, max_linear=0.22, max_angular=2.84, laser=True),
}


class WorldError(SchemaError):
    """A malformed world description: `file:line:col: key.path: what is wrong`."""


@dataclass
class LaserSpec:
    range: float = 2.0
    beams: int = 360
    fov: float = 2 * math.pi  # centred on the robot's heading
    rate: float = 10.0


@dataclass
class BatterySpec:
    capacity: float = 1.0  # Ah, reported in BatteryState.capacity
    initial: float = 1.0  # fraction 0..1
    drain_idle: float = 0.0005  # fraction per second, always
    drain_motion: float = 0.002  # fraction per second at full linear (or angular) speed
    charge_rate: float = 0.02  # fraction per second at the charging station


@dataclass
class RobotSpec:
    name: str
    namespace: str
    kind: str
    start: tuple  # (x, y, theta)
    radius: float
    max_linear: float
    max_angular: float
    laser: object  # LaserSpec or None
    battery: BatterySpec
    cmd_vel_stamped: bool = False


@dataclass
class World:
    name: str
    width: float
    height: float
    segments: np.ndarray  # (M, 4): x1 y1 x2 y2, every wall and box edge
    boxes: np.ndarray  # (B, 4): xmin ymin xmax ymax (solid)
    holes: list  # list of (K, 2) polygons
    goal: object  # (x, y) or None
    station: object  # (x, y) or None
    station_radius: float
    duration: float
    seed: int
    robots: list = field(default_factory=list)
    step: float = 0.01

    # ---- loading ---------------------------------------------------------------------------------

    @classmethod
    def load(cls, path):
        """The world in file `path`, checked against its schema (a WorldError names the place)."""
        reader = Reader(str(path), WorldError)
        data = load(read_text(path, reader, "world file"), world_schema.WORLD, reader)
        world_schema.check_places(data, reader)
        return cls._build(data, default_name=str(path).rsplit("/", 1)[-1].rsplit(".", 1)[0])

    @classmethod
    def from_dict(cls, data, default_name="world"):
        """The world described by plain data (as a world file's), checked against the same schema."""
        reader = Reader("the given world", WorldError, positions=False)
        checked = check_data(data, world_schema.WORLD, reader)
        world_schema.check_places(checked, reader)
        return cls._build(checked, default_name)

    @classmethod
    def _build(cls, data, default_name):
        size = data.get("size", [5.0, 5.0])
        width, height = float(size[0]), float(size[1])
        segs, boxes, holes = [], [], []
        if data.get("border", True):
            segs += [(0, 0, width, 0), (width, 0, width, height), (width, height, 0, height), (0, height, 0, 0)]
        for w in data.get("walls", []) or []:
            if "from" in w:
                (x1, y1), (x2, y2) = w["from"], w["to"]
                segs.append((x1, y1, x2, y2))
            else:
                boxes.append(_rect(w))
        for b in data.get("boxes", []) or []:
            boxes.append(_rect(b))
        for x0, y0, x1, y1 in boxes:
            segs += [(x0, y0, x1, y0), (x1, y0, x1, y1), (x1, y1, x0, y1), (x0, y1, x0, y0)]
        for h in data.get("holes", []) or []:
            if "polygon" in h:
                holes.append(np.asarray(h["polygon"], dtype=float))
            else:
                x0, y0, x1, y1 = _rect(h)
                holes.append(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=float))
        station = data.get("charging_station")
        st_pos, st_r = None, 0.0
        if station is not None:
            if isinstance(station, dict):
                st_pos, st_r = tuple(map(float, station["position"])), float(station.get("radius", 0.2))
            else:
                st_pos, st_r = tuple(map(float, station)), 0.2
        goal = data.get("goal")
        world = cls(
            name=str(data.get("name", default_name)),
            width=width,
            height=height,
            segments=np.asarray(segs, dtype=float).reshape(-1, 4),
            boxes=np.asarray(boxes, dtype=float).reshape(-1, 4),
            holes=holes,
            goal=tuple(map(float, goal)) if goal is not None else None,
            station=st_pos,
            station_radius=st_r,
            duration=float(data.get("duration", 60.0)),
            seed=int(data.get("seed", 0)),
            step=float(data.get("step", 0.01)),
        )
        robots = data.get("robots") or [{"name": "robot1"}]
        for i, r in enumerate(robots):
            world.robots.append(_robot_spec(r, i))
        names = [r.namespace for r in world.robots]
        if len(set(names)) != len(names):
            raise WorldError("two robots share a namespace")
        return world

    # ---- queries ---------------------------------------------------------------------------------

    def in_hole(self, points):
        """Boolean array: which of the (N, 2) points lie over a hole."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        inside = np.zeros(len(pts), dtype=bool)
        for poly in self.holes:
            inside |= points_in_polygon(pts, poly)
        return inside

    def in_box(self, points):
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        if not len(self.boxes):
            return np.zeros(len(pts), dtype=bool)
        b = self.boxes
        x, y = pts[:, :1], pts[:, 1:2]
        return ((x > b[:, 0]) & (x < b[:, 2]) & (y > b[:, 1]) & (y < b[:, 3])).any(axis=1)

    def clearance(self, points):
        """Distance from each point to the nearest wall or box edge (0 inside a box)."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        if not len(self.segments):
            return np.full(len(pts), np.inf)
        d = segment_distances(pts, self.segments).min(axis=1)
        return np.where(self.in_box(pts), 0.0, d)

    def at_station(self, x, y):
        return self.station is not None and math.hypot(x - self.station[0], y - self.station[1]) <= self.station_radius


def _rect(d):
    if "min" in d:
        (x0, y0), (x1, y1) = d["min"], d["max"]
    elif "center" in d:
        (cx, cy), (sx, sy) = d["center"], d["size"]
        x0, y0, x1, y1 = cx - sx / 2, cy - sy / 2, cx + sx / 2, cy + sy / 2
    else:
        raise WorldError(f"a rectangle needs min/max or center/size: {d!r}")
    return (float(min(x0, x1)), float(min(y0, y1)), float(max(x0, x1)), float(max(y0, y1)))


def _robot_spec(r, i):
    kind = r.get("kind", "thymio")
    if kind not in KINDS:
        raise WorldError(f"unknown robot kind {kind!r} (thymio, diff_drive or turtlebot3)")
    k = KINDS[kind]
    name = str(r.get("name", f"robot{i + 1}"))
    ns = str(r.get("namespace", name)).strip("/")
    start = list(r.get("start", [0.5, 0.5, 0.0])) + [0.0]
    laser = r.get("laser", k["laser"])
    if laser is True:
        laser = LaserSpec()
    elif isinstance(laser, dict):
        laser = LaserSpec(
            range=float(laser.get("range", 2.0)),
            beams=int(laser.get("beams", 360)),
            fov=math.radians(float(laser.get("fov_deg", 360.0))),
            rate=float(laser.get("rate", 10.0)),
        )
    else:
        laser = None
    bat = r.get("battery", {}) or {}
    battery = BatterySpec(**{key: float(v) for key, v in bat.items() if key in BatterySpec.__dataclass_fields__})
    return RobotSpec(
        name=name,
        namespace=ns,
        kind=kind,
        start=(float(start[0]), float(start[1]), float(start[2])),
        radius=float(r.get("radius", k["radius"])),
        max_linear=float(r.get("max_linear", k["max_linear"])),
        max_angular=float(r.get("max_angular", k["max_angular"])),
        laser=laser,
        battery=battery,
        cmd_vel_stamped=bool(r.get("cmd_vel_stamped", _stamped_default(kind))),
    )


def _stamped_default(kind):
    """A TurtleBot3 takes TwistStamped from Jazzy on (ROBOTIS-GIT/turtlebot3, jazzy branch,
    turtlebot3_node/src/turtlebot3.cpp cmd_vel_callback); the others Twist."""
    if kind != "turtlebot3":
        return False
    from scoopc.robots.ros_messages import (
        distro,  # deferred: start-up (scoopc.robots.ros_messages loads only when this is used)
    )

    return distro() != "humble"


# ---- vectorised geometry ---------------------------------------------------------------------------


def segment_distances(points, segs):
    """(N, M) distances from N points to M segments."""
    p = points[:, None, :]
    a, b = segs[None, :, :2], segs[None, :, 2:]
    ab = b - a
    denom = (ab * ab).sum(-1)
    t = np.clip(((p - a) * ab).sum(-1) / np.where(denom == 0, 1, denom), 0.0, 1.0)
    closest = a + t[..., None] * ab
    return np.sqrt(((p - closest) ** 2).sum(-1))


def ray_cast(origins, dirs, segs, max_range, circles=None):
    """Distance along each ray (N origins, N unit directions) to the first segment or circle; inf if none
    within max_range. circles: (C, 3) x, y, r."""
    n = len(origins)
    best = np.full(n, np.inf)
    if len(segs):
        o, d = origins[:, None, :], dirs[:, None, :]
        a, s = segs[None, :, :2], segs[None, :, 2:] - segs[None, :, :2]
        denom = d[..., 0] * s[..., 1] - d[..., 1] * s[..., 0]
        ao = a - o
        safe = np.where(np.abs(denom) < 1e-12, 1.0, denom)
        t = (ao[..., 0] * s[..., 1] - ao[..., 1] * s[..., 0]) / safe
        u = (ao[..., 0] * d[..., 1] - ao[..., 1] * d[..., 0]) / safe
        ok = (np.abs(denom) >= 1e-12) & (t >= 0) & (u >= 0) & (u <= 1)
        best = np.where(ok, t, np.inf).min(axis=1)
    if circles is not None and len(circles):
        c = circles[None, :, :2]
        oc = origins[:, None, :] - c
        bq = (oc * dirs[:, None, :]).sum(-1)
        cq = (oc * oc).sum(-1) - circles[None, :, 2] ** 2
        disc = bq * bq - cq
        t = -bq - np.sqrt(np.maximum(disc, 0))
        ok = (disc >= 0) & (t >= 0)
        best = np.minimum(best, np.where(ok, t, np.inf).min(axis=1))
    return np.where(best <= max_range, best, np.inf)


def points_in_polygon(pts, poly):
    """Even-odd rule, vectorised over points."""
    x, y = pts[:, 0:1], pts[:, 1:2]
    x1, y1 = poly[:, 0], poly[:, 1]
    x2, y2 = np.roll(x1, -1), np.roll(y1, -1)
    cond = (y1 > y) != (y2 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xint = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
    return ((cond & (x < xint)).sum(axis=1) % 2) == 1
