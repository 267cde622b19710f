"""The schema of simulator world files (docs/ROBOTS.md, "Simulator worlds") and the checks that
span several keys (a start inside the arena). Input: a world file's text; output: the plain values
`World.from_dict` builds from, or a WorldError naming file:line:col and the key's path."""

from __future__ import annotations

from ..yamlschema import Flag, Map, Number, OneOf, Reader, Seq, Text, keys_of, point

KIND_NAMES = ("thymio", "diff_drive", "turtlebot3")
MAX_BEAMS = 10_000  # a laser scan is computed every period: a larger count would stall the simulation
MAX_SIZE = 10_000.0  # metres

_POSITIVE = Number(above=0.0)
_FRACTION = Number(low=0.0, high=1.0)
_RATE = Number(low=0.0)

RECTANGLE_BY_CORNERS = Map({"min": point(), "max": point()}, required=("min", "max"))
RECTANGLE_BY_CENTRE = Map({"center": point(), "size": point(low=0.0)}, required=("center", "size"))
SEGMENT = Map({"from": point(), "to": point()}, required=("from", "to"))
POLYGON = Map({"polygon": Seq(point(), 3, 10_000)}, required=("polygon",))


def _by_keys(node, fitting):
    """Among mapping shapes, the one whose required keys the node uses."""
    keys = keys_of(node)
    for each in fitting:
        if set(each.required) & keys:
            return each
    return fitting[0]


def _shapes(*choices, says):
    return OneOf(choices, says=says, pick=_by_keys)


RECTANGLE = _shapes(RECTANGLE_BY_CORNERS, RECTANGLE_BY_CENTRE, says="a rectangle ({min, max} or {center, size})")

LASER = Map(
    {
        "range": _POSITIVE,
        "beams": Number(low=1, high=MAX_BEAMS, whole=True),
        "fov_deg": Number(above=0.0, high=360.0),
        "rate": Number(above=0.0, high=1000.0),
    }
)
BATTERY = Map(
    {
        "capacity": _POSITIVE,
        "initial": _FRACTION,
        "drain_idle": _RATE,
        "drain_motion": _RATE,
        "charge_rate": _RATE,
    }
)
ROBOT = Map(
    {
        "name": Text(),
        "namespace": Text(pattern=r"^/?[A-Za-z_][A-Za-z0-9_]*$", pattern_says="not a ROS 2 namespace"),
        "kind": Text(choices=KIND_NAMES),
        "start": Seq(Number(), 2, 3),
        "radius": _POSITIVE,
        "max_linear": _POSITIVE,
        "max_angular": _POSITIVE,
        "cmd_vel_stamped": Flag(),
        "laser": OneOf((Flag(), LASER), says="true, false or a mapping (range, beams, fov_deg, rate)"),
        "battery": BATTERY,
    }
)
WALL = _shapes(
    SEGMENT, RECTANGLE_BY_CORNERS, RECTANGLE_BY_CENTRE, says="a wall ({from, to}, {min, max} or {center, size})"
)
HOLE = _shapes(
    RECTANGLE_BY_CORNERS, RECTANGLE_BY_CENTRE, POLYGON, says="a hole ({min, max}, {center, size} or {polygon})"
)
WORLD = Map(
    {
        "name": Text(),
        "size": Seq(Number(above=0.0, high=MAX_SIZE), 2, 2),
        "border": Flag(),
        "step": Number(above=0.0, high=1.0),
        "duration": Number(low=0.0),
        "seed": Number(whole=True),
        "goal": point(),
        "charging_station": OneOf(
            (point(), Map({"position": point(), "radius": _POSITIVE}, required=("position",))),
            says="a point [x, y] or a mapping (position, radius)",
        ),
        "walls": Seq(WALL),
        "boxes": Seq(RECTANGLE),
        "holes": Seq(HOLE),
        "robots": Seq(ROBOT, 1, 64),
    },
    description="A scoopc simulator world (docs/ROBOTS.md, Simulator worlds)",
)


def check_places(data: dict, reader: Reader) -> None:
    """Checks across keys: each robot starts inside the arena."""
    width, height = data.get("size", [5.0, 5.0])
    for i, robot in enumerate(data.get("robots") or ()):
        start = robot.get("start")
        if start is not None and not (0 <= start[0] <= width and 0 <= start[1] <= height):
            reader.fail_at(
                f"robots[{i}].start",
                f"({start[0]}, {start[1]}) is outside the arena (0..{width} by 0..{height})",
            )
