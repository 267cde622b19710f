"""Driver, the live view's robot channels: the simulator's world and robots as JSON messages of
Foxglove's schemas (`foxglove.SceneUpdate` for /sim/scene, read by Foxglove's 3D panel), and the
robots' poses, speeds and batteries for /sim/robots (plots). Pure functions of the simulator's
state, read without its lock: a picture, not logic."""

from __future__ import annotations

import math
from typing import Any

from ..robots.sim.sensors import PROXIMITY, PROXIMITY_RANGE

FRAME = "world"
TRAIL_POINTS = 400  # the trail so far, thinned to at most this many points
LINE_STRIP, LINE_LOOP, LINE_LIST = 0, 1, 2  # foxglove.LinePrimitive's types

Json = dict[str, Any]


def stamp(ns: int) -> Json:
    return {"sec": ns // 1_000_000_000, "nsec": ns % 1_000_000_000}


def _pose(x: float = 0.0, y: float = 0.0, z: float = 0.0, yaw: float = 0.0) -> Json:
    return {
        "position": {"x": x, "y": y, "z": z},
        "orientation": {"x": 0.0, "y": 0.0, "z": math.sin(yaw / 2), "w": math.cos(yaw / 2)},
    }


def _color(r: float, g: float, b: float, a: float = 1.0) -> Json:
    return {"r": r, "g": g, "b": b, "a": a}


def _point(x: float, y: float, z: float = 0.0) -> Json:
    return {"x": float(x), "y": float(y), "z": z}


def _line(kind: int, points: list[Json], color: Json, thickness: float = 0.02) -> Json:
    return {
        "type": kind,
        "pose": _pose(),
        "thickness": thickness,
        "scale_invariant": False,
        "points": points,
        "color": color,
        "colors": [],
        "indices": [],
    }


def _cylinder(x: float, y: float, radius: float, height: float, color: Json) -> Json:
    return {
        "pose": _pose(x, y, height / 2),
        "size": {"x": 2 * radius, "y": 2 * radius, "z": height},
        "bottom_scale": 1.0,
        "top_scale": 1.0,
        "color": color,
    }


def _entity(ns: int, ident: str, **primitives: list[Json]) -> Json:
    entity: Json = {
        "timestamp": stamp(ns),
        "frame_id": FRAME,
        "id": ident,
        "lifetime": {"sec": 0, "nsec": 0},
        "frame_locked": False,
        "metadata": [],
    }
    for kind in ("arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models"):
        entity[kind] = primitives.get(kind, [])
    return entity


def world_entities(world: Any, ns: int) -> list[Json]:
    """The walls, boxes, holes, charging station and goal."""
    walls = [_point(x, y, 0.05) for x1, y1, x2, y2 in world.segments for x, y in ((x1, y1), (x2, y2))]
    boxes = [
        {
            "pose": _pose((x0 + x1) / 2, (y0 + y1) / 2, 0.05),
            "size": {"x": float(x1 - x0), "y": float(y1 - y0), "z": 0.1},
            "color": _color(0.55, 0.4, 0.25),
        }
        for x0, y0, x1, y1 in world.boxes
    ]
    holes = [_line(LINE_LOOP, [_point(x, y, 0.001) for x, y in poly], _color(0.1, 0.1, 0.1)) for poly in world.holes]
    found = [_entity(ns, "walls", lines=[_line(LINE_LIST, walls, _color(0.3, 0.3, 0.35))], cubes=boxes)]
    found.append(_entity(ns, "holes", lines=holes))
    if world.station is not None:
        sx, sy = world.station
        cylinder = _cylinder(sx, sy, world.station_radius, 0.01, _color(0.2, 0.7, 0.3, 0.6))
        found.append(_entity(ns, "charging_station", cylinders=[cylinder]))
    if world.goal is not None:
        gx, gy = world.goal
        found.append(_entity(ns, "goal", cylinders=[_cylinder(gx, gy, 0.05, 0.3, _color(0.9, 0.2, 0.2))]))
    return found


def robot_entity(robot: Any, ns: int, scan: Any | None, proximity: dict[str, float] | None = None) -> Json:
    """A robot: its body, an arrow for its heading, its trail so far, its last laser rays and the
    beams of its proximity sensors (a Thymio's), each as long as its last reading."""
    x, y, theta, r = robot.x, robot.y, robot.theta, robot.spec.radius
    body = _cylinder(x, y, r, 0.05, _color(0.2, 0.4, 0.9) if not robot.fallen else _color(0.5, 0.5, 0.5))
    arrow = {
        "pose": _pose(x, y, 0.06, theta),
        "shaft_length": 1.5 * r,
        "shaft_diameter": 0.02,
        "head_length": 0.05,
        "head_diameter": 0.05,
        "color": _color(1.0, 0.8, 0.1),
    }
    trail = list(robot.trajectory)
    step = max(1, len(trail) // TRAIL_POINTS)
    points = [_point(px, py, 0.005) for _, px, py, _ in trail[::step]] + [_point(x, y, 0.005)]
    lines = [_line(LINE_STRIP, points, _color(0.2, 0.4, 0.9, 0.7), 0.01)]
    if scan is not None:
        lines.append(_line(LINE_LIST, _rays(x, y, theta, scan), _color(1.0, 0.2, 0.2, 0.5), 0.004))
    if proximity:
        lines.append(_line(LINE_LIST, _beams(x, y, theta, r, proximity), _color(1.0, 0.5, 0.0, 0.8), 0.006))
    return _entity(ns, f"robot/{robot.name}", cylinders=[body], arrows=[arrow], lines=lines)


def _rays(x: float, y: float, theta: float, scan: Any) -> list[Json]:
    points: list[Json] = []
    beams = list(scan.ranges)
    stride = max(1, len(beams) // 90)  # every ray of a sparse scan; about 90 of a dense one
    for i in range(0, len(beams), stride):
        d = float(beams[i])
        if not math.isfinite(d) or d <= 0:
            d = float(scan.range_max)
        a = theta + float(scan.angle_min) + i * float(scan.angle_increment)
        points += [_point(x, y, 0.04), _point(x + d * math.cos(a), y + d * math.sin(a), 0.04)]
    return points


def _beams(x: float, y: float, theta: float, radius: float, readings: dict[str, float]) -> list[Json]:
    points: list[Json] = []
    for name, value in readings.items():
        if name not in PROXIMITY:
            continue
        mount, beam = PROXIMITY[name]
        ox, oy = x + radius * math.cos(theta + mount), y + radius * math.sin(theta + mount)
        d = value if 0 <= value <= PROXIMITY_RANGE else PROXIMITY_RANGE  # -1: nothing in range
        a = theta + beam
        points += [_point(ox, oy, 0.04), _point(ox + d * math.cos(a), oy + d * math.sin(a), 0.04)]
    return points


def scene(sim: Any, ns: int, scans: dict[str, Any], proximity: dict[str, dict[str, float]] | None = None) -> Json:
    """The whole scene (a SceneUpdate replaces entities by id): the world and every robot."""
    near = proximity or {}
    robots = [robot_entity(robot, ns, scans.get(robot.name), near.get(robot.name)) for robot in sim.robots]
    return {"deletions": [], "entities": world_entities(sim.world, ns) + robots}


def robots(sim: Any, ns: int) -> Json:
    """The robots' poses, speeds and batteries (/sim/robots)."""
    return {
        "timestamp": stamp(ns),
        "robots": [
            {
                "name": robot.name,
                "x": robot.x,
                "y": robot.y,
                "heading": robot.theta,
                "linear": robot.v,
                "angular": robot.w,
                "battery": robot.battery,
                "charging": robot.charging,
                "fallen": robot.fallen,
            }
            for robot in sim.robots
        ],
    }
