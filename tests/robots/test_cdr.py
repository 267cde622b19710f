"""CDR golden tests: our encoder equals rosbags' `serialize_cdr` byte for byte for every message type of
the ROS 2 Humble type store (non-default values from a seeded generator), and our decoder round-trips."""

import random
import struct

import numpy as np
import pytest

from scoopc.robots import cdr, ros_messages
from scoopc.robots.ros_messages import ARRAY, BASE, DTYPES, NAME

STORE = ros_messages.typestore()
CORE = ("std_msgs", "geometry_msgs", "nav_msgs", "sensor_msgs", "builtin_interfaces", "rosgraph_msgs")
ALL_TYPES = sorted(STORE.fielddefs)
TEXTS = ["", "a", "ab", "abc", "héllo", "ロボット", "x" * 9, "tab\tand\nnewline"]

EXTRA = {
    "test_msgs/msg/Kinds": """
bool flag
byte b
char c
int8 i8
uint8 u8
int16 i16
uint16 u16
int32 i32
uint32 u32
int64 i64
uint64 u64
float32 f32
float64 f64
string s
string<=5 bounded_s
bool[3] flags
char[2] chars
int16[<=4] bounded_ints
string[] names
string<=3[2] short_names
geometry_msgs/Point[2] points
geometry_msgs/Point[<=3] some_points
test_msgs/Inner[] inners
uint8 after
""",
    "test_msgs/msg/Inner": """
uint8 tag
float64[] values
string label
""",
}


def generate(desc, rng, store=STORE):
    """A random value of a field description, inside its type's range and bounds."""
    kind, detail = desc
    if kind == BASE:
        name, bound = detail
        if name in ("string", "wstring"):
            text = rng.choice(TEXTS)
            return text[:bound] if bound else text
        if name == "bool":
            return rng.random() < 0.5
        if name.startswith("float"):
            value = rng.choice([0.0, -1.5, 1e-3, 3.25e10, rng.uniform(-1e6, 1e6), float("inf")])
            return float(np.float32(value)) if name == "float32" else value
        info = np.iinfo(DTYPES[name])
        return rng.choice([int(info.min), int(info.max), 0, 1, rng.randint(int(info.min), int(info.max))])
    if kind == NAME:
        return generate_message(detail, rng, store)
    element, size = detail
    count = size if kind == ARRAY else rng.randint(0, min(size, 4) if size else 4)
    items = [generate(element, rng, store) for _ in range(count)]
    if ros_messages.is_numeric(element):
        return np.array(items, dtype=DTYPES[element[1][0]])
    return items


def generate_message(typename, rng, store=STORE):
    return ros_messages.new(
        typename, store, **{name: generate(desc, rng, store) for name, desc in ros_messages.fields(typename, store)}
    )


def same(a, b):
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.dtype == b.dtype and np.array_equal(a, b)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if hasattr(a, "__msgtype__"):
        return a.__msgtype__ == b.__msgtype__ and all(
            same(getattr(a, n), getattr(b, n)) for n in a.__dataclass_fields__ if n != "__msgtype__"
        )
    return type(a) is type(b) and a == b


def check(msg, typename, store=STORE):
    ours = cdr.serialize(msg, typename, store)
    theirs = bytes(store.serialize_cdr(msg, typename))
    assert ours == theirs, typename
    back = cdr.deserialize(ours, typename, store)
    assert same(back, msg), typename
    assert same(back, store.deserialize_cdr(theirs, typename)), typename


def test_the_store_covers_the_core_packages():
    packages = {name.split("/")[0] for name in ALL_TYPES}
    assert set(CORE) <= packages
    assert len(ALL_TYPES) >= 100


@pytest.mark.parametrize("typename", ALL_TYPES)
def test_every_type_equals_rosbags(typename):
    check(ros_messages.new(typename), typename)  # defaults
    rng = random.Random(typename)
    for _ in range(20):
        check(generate_message(typename, rng), typename)


def test_every_field_kind_from_a_msg_definition():
    store = ros_messages.store_with(EXTRA)
    rng = random.Random(7)
    for _ in range(40):
        check(generate_message("test_msgs/msg/Kinds", rng, store), "test_msgs/msg/Kinds", store)


def test_alignment_is_relative_to_the_end_of_the_header():
    stamp = ros_messages.new("builtin_interfaces/msg/Time", sec=1, nanosec=2)
    msg = ros_messages.new("std_msgs/msg/Header", stamp=stamp, frame_id="ab")
    data = cdr.serialize(msg)
    assert data[:4] == b"\x00\x01\x00\x00"
    assert data[4:] == struct.pack("<iII", 1, 2, 3) + b"ab\x00"
    odd = ros_messages.new("std_msgs/msg/String", data="")
    assert cdr.serialize(odd) == b"\x00\x01\x00\x00" + struct.pack("<I", 1) + b"\x00"
    twist = cdr.serialize(ros_messages.new("sensor_msgs/msg/Range", radiation_type=1, range=2.0))
    assert twist == bytes(
        STORE.serialize_cdr(
            ros_messages.new("sensor_msgs/msg/Range", radiation_type=1, range=2.0), "sensor_msgs/msg/Range"
        )
    )


def test_big_endian_input_is_decoded():
    data = b"\x00\x00\x00\x00" + struct.pack(">iI", -3, 7)
    time = cdr.deserialize(data, "builtin_interfaces/msg/Time")
    assert (time.sec, time.nanosec) == (-3, 7)
    header = cdr.deserialize(b"\x00\x00\x00\x00" + struct.pack(">iII", 1, 2, 3) + b"ab\x00", "std_msgs/msg/Header")
    assert (header.stamp.sec, header.stamp.nanosec, header.frame_id) == (1, 2, "ab")


def test_bounds_and_lengths_are_checked():
    store = ros_messages.store_with(EXTRA)
    msg = generate_message("test_msgs/msg/Kinds", random.Random(1), store)
    msg.bounded_ints = np.zeros(5, dtype=np.int16)
    with pytest.raises(ValueError):
        cdr.serialize(msg, "test_msgs/msg/Kinds", store)
    with pytest.raises(ValueError):
        cdr.deserialize(b"\x00\x01\x00\x00\x01", "builtin_interfaces/msg/Time")
    whole = cdr.serialize(ros_messages.new("nav_msgs/msg/Odometry", child_frame_id="base_link"))
    for end in (8, 14, 20, 30, 100, len(whole) - 1):  # cut in a string, in a run, in an array
        with pytest.raises(ValueError):
            cdr.deserialize(whole[:end], "nav_msgs/msg/Odometry")


def test_new_fills_defaults_and_rejects_unknown_fields():
    odom = ros_messages.new("nav_msgs/msg/Odometry", child_frame_id="base")
    assert odom.child_frame_id == "base" and odom.pose.pose.orientation.w == 0.0
    assert odom.pose.covariance.shape == (36,) and odom.pose.covariance.dtype == np.float64
    assert ros_messages.new("sensor_msgs/msg/LaserScan").ranges.dtype == np.float32
    with pytest.raises(TypeError):
        ros_messages.new("geometry_msgs/msg/Twist", speed=1)
    with pytest.raises(KeyError):
        ros_messages.fields("nope_msgs/msg/Nothing")
    nested = ros_messages.nested_types("geometry_msgs/msg/Twist")
    assert nested == ["geometry_msgs/msg/Twist", "geometry_msgs/msg/Vector3"]
