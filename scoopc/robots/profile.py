"""Robot profiles: a `robot.yaml` file describing a differential-drive robot for
DIFF_DRIVE_ROBOT.`make_from_profile` (topic names, the velocity command's type, QoS, speed limits),
read and checked before the program starts. Input: a path; output: a `Profile`, or a
`ProfileError` naming the file, line, column and the key's path (`topics.cmd_vel.qos.depth`).

The schema is our own, a few lines per key, over PyYAML's node tree (which keeps each value's
position); docs/ROBOTS.md shows the format."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

#: the topics a profile may name, with the message types each may carry (the first is the default)
TOPIC_TYPES = {
    "cmd_vel": ("geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"),
    "odom": ("nav_msgs/msg/Odometry",),
    "battery_state": ("sensor_msgs/msg/BatteryState",),
    "scan": ("sensor_msgs/msg/LaserScan",),
}
RELIABILITIES = ("reliable", "best_effort")
_NAME = re.compile(r"^/?[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$")  # ROS 2 topic name rules


class ProfileError(ValueError):
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


class _Checker:
    def __init__(self, path: str):
        self.path = path

    def fail(self, node, where: str, text: str):
        mark = node.start_mark
        raise ProfileError(f"{self.path}:{mark.line + 1}:{mark.column + 1}: {where}: {text}")

    def mapping(self, node, where: str, allowed) -> dict:
        """{key: (key node, value node)} of a mapping whose keys are among `allowed`."""
        if not isinstance(node, yaml.MappingNode):
            self.fail(node, where, "must be a mapping (key: value lines)")
        found = {}
        for key, value in node.value:
            name = key.value if isinstance(key, yaml.ScalarNode) else None
            here = f"{where}.{name}" if where else str(name)
            if name not in allowed:
                self.fail(key, here, f"unknown key (expected one of: {', '.join(allowed)})")
            if name in found:
                self.fail(key, here, "given twice")
            found[name] = (key, value)
        return found

    def scalar(self, node, where: str):
        if not isinstance(node, yaml.ScalarNode):
            self.fail(node, where, "must be a single value")
        return yaml.safe_load(yaml.serialize(node))

    def positive_number(self, node, where: str) -> float:
        value = self.scalar(node, where)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
            self.fail(node, where, f"must be a number greater than 0, not {node.value!r}")
        return float(value)

    def text(self, node, where: str, choices=None) -> str:
        value = self.scalar(node, where)
        if not isinstance(value, str) or not value:
            self.fail(node, where, f"must be a text, not {node.value!r}")
        if choices is not None and value not in choices:
            self.fail(node, where, f"must be one of {', '.join(choices)}, not {value!r}")
        return value


def _topic(check: _Checker, key: str, node, where: str) -> TopicSpec:
    types = TOPIC_TYPES[key]
    allowed = ("name", "type", "qos") if len(types) > 1 else ("name", "qos")
    entries = check.mapping(node, where, allowed)
    spec = TopicSpec(key, types[0])
    if "name" in entries:
        spec.name = check.text(entries["name"][1], f"{where}.name")
        if not _NAME.match(spec.name):
            check.fail(entries["name"][1], f"{where}.name", f"not a ROS 2 topic name: {spec.name!r}")
    if "type" in entries:
        spec.type = check.text(entries["type"][1], f"{where}.type", types)
    if "qos" in entries:
        qos = check.mapping(entries["qos"][1], f"{where}.qos", ("reliability", "depth"))
        if "reliability" in qos:
            spec.reliability = check.text(qos["reliability"][1], f"{where}.qos.reliability", RELIABILITIES)
        if "depth" in qos:
            value_node = qos["depth"][1]
            depth = check.scalar(value_node, f"{where}.qos.depth")
            if isinstance(depth, bool) or not isinstance(depth, int) or not 1 <= depth <= 10000:
                check.fail(value_node, f"{where}.qos.depth", f"must be a whole number from 1 to 10000, not {depth!r}")
            spec.depth = depth
    return spec


def parse(text: str, path: str) -> Profile:
    """The profile in `text` (read from `path`, which error messages name)."""
    check = _Checker(path)
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark else path
        raise ProfileError(f"{where}: not valid YAML: {e.problem or e.context}") from None
    profile = Profile(path)
    profile.topics = {key: TopicSpec(key, types[0]) for key, types in TOPIC_TYPES.items()}
    if root is None:
        return profile
    entries = check.mapping(root, "", ("name", "limits", "topics"))
    if "name" in entries:
        profile.name = check.text(entries["name"][1], "name")
    if "limits" in entries:
        limits = check.mapping(entries["limits"][1], "limits", ("max_linear", "max_angular"))
        if "max_linear" in limits:
            profile.max_linear = check.positive_number(limits["max_linear"][1], "limits.max_linear")
        if "max_angular" in limits:
            profile.max_angular = check.positive_number(limits["max_angular"][1], "limits.max_angular")
    if "topics" in entries:
        for key, (_, node) in check.mapping(entries["topics"][1], "topics", tuple(TOPIC_TYPES)).items():
            profile.topics[key] = _topic(check, key, node, f"topics.{key}")
    return profile


def load(path) -> Profile:
    """The profile in file `path` (ProfileError when it cannot be read or is not valid)."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise ProfileError(f"{path}: cannot read the robot profile: {e.strerror or e}") from None
    return parse(text, str(path))


def find(program_paths, given=None) -> str | None:
    """The profile's path: `given`, else robot.yaml beside the program, else None."""
    if given is not None:
        return str(given)
    for p in program_paths or ():
        folder = Path(p) if Path(p).is_dir() else Path(p).parent
        if (folder / "robot.yaml").is_file():
            return str(folder / "robot.yaml")
    return None
