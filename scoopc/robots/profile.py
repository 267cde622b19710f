"""Robot profiles: a `robot.yaml` file describing a differential-drive robot for
DIFF_DRIVE_ROBOT.`make_from_profile` (topic names, the velocity command's type, QoS, speed limits),
read and checked before the program starts. Input: a path; output: a `Profile`, or a
`ProfileError` naming the file, line, column and the key's path (`topics.cmd_vel.qos.depth`).

The schema is written in scoopc/robots/yamlschema.py's small language (shared with world files), over
PyYAML's node tree (which keeps each value's position); docs/ROBOTS.md shows the format."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..project import beside_program
from . import yamlschema
from .yamlschema import Map, Number, SchemaError, Text

#: the topics a profile may name, with the message types each may carry (the first is the default)
TOPIC_TYPES = {
    "cmd_vel": ("geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"),
    "odom": ("nav_msgs/msg/Odometry",),
    "battery_state": ("sensor_msgs/msg/BatteryState",),
    "scan": ("sensor_msgs/msg/LaserScan",),
}
RELIABILITIES = ("reliable", "best_effort")
_NAME = re.compile(r"^/?[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$")  # ROS 2 topic name rules


class ProfileError(SchemaError):
    """A profile that cannot be used: `str()` is `file:line:col: key.path: what is wrong`."""


@dataclass
class TopicSpec:
    name: str  # relative to the robot's namespace, or absolute ("/odom")
    type: str
    reliability: str | None = None  # None: the topic family's QoS (docs/ROBOTS.md)
    depth: int | None = None


@dataclass
class Profile:
    path: str
    name: str = ""
    max_linear: float | None = None
    max_angular: float | None = None
    topics: dict = field(default_factory=dict)  # key of TOPIC_TYPES -> TopicSpec (every key present)

    def topic(self, key: str, namespace: str) -> str:
        """The absolute ROS name of topic `key` for a robot under `namespace` ("" or "/robot1")."""
        name = self.topics[key].name
        return name if name.startswith("/") else f"{namespace}/{name}"

    @property
    def stamped(self) -> bool:
        return self.topics["cmd_vel"].type.endswith("TwistStamped")

    def qos(self, namespace: str) -> tuple[dict, dict]:
        """({topic: (reliability, depth)} of the writers, the same of the readers) it sets."""
        writers, readers = {}, {}
        for key, spec in self.topics.items():
            if spec.reliability or spec.depth:
                side = writers if key == "cmd_vel" else readers
                side[self.topic(key, namespace)] = (spec.reliability, spec.depth)
        return writers, readers


def _topic_schema(types: tuple) -> Map:
    keys = {
        "name": Text(pattern=_NAME.pattern, pattern_says="not a ROS 2 topic name"),
        "type": Text(choices=types),
        "qos": Map({"reliability": Text(choices=RELIABILITIES), "depth": Number(low=1, high=10000, whole=True)}),
    }
    if len(types) == 1:
        del keys["type"]
    return Map(keys)


SCHEMA = Map(
    {
        "name": Text(),
        "limits": Map({"max_linear": Number(above=0.0), "max_angular": Number(above=0.0)}),
        "topics": Map({key: _topic_schema(types) for key, types in TOPIC_TYPES.items()}),
    },
    description="A scoopc robot profile, robot.yaml (docs/ROBOTS.md)",
)


def parse(text: str, path: str) -> Profile:
    """The profile in `text` (read from `path`, which error messages name)."""
    data = yamlschema.load(text, SCHEMA, yamlschema.Reader(path, ProfileError))
    profile = Profile(path, name=data.get("name", ""))
    limits = data.get("limits", {})
    profile.max_linear, profile.max_angular = limits.get("max_linear"), limits.get("max_angular")
    profile.topics = {key: TopicSpec(key, types[0]) for key, types in TOPIC_TYPES.items()}
    for key, given in data.get("topics", {}).items():
        qos = given.get("qos", {})
        spec = TopicSpec(given.get("name", key), given.get("type", TOPIC_TYPES[key][0]))
        spec.reliability, spec.depth = qos.get("reliability"), qos.get("depth")
        profile.topics[key] = spec
    return profile


def load(path) -> Profile:
    """The profile in file `path` (ProfileError when it cannot be read or is not valid)."""
    reader = yamlschema.Reader(str(path), ProfileError)
    return parse(yamlschema.read_text(path, reader, "robot profile"), str(path))


def find(program_paths, given=None) -> str | None:
    """The profile's path: `given`, else robot.yaml beside the program, else None."""
    if given is not None:
        return str(given)
    found = beside_program(program_paths, "robot.yaml")
    return None if found is None else str(found)
