"""Fuzzing what users and the network hand scoopc besides Eiffel: world files, .msg definitions and
CDR payloads. Each input either works or is refused with the input's own error (WorldError, a usage
error, ValueError for CDR), never another exception. SCOOPC_HYPOTHESIS_PROFILE=thorough runs longer."""

import string

import pytest
import yaml
from hypothesis import HealthCheck, given, settings, strategies as st

from scoopc import cli
from scoopc.robots import cdr, ros_messages
from scoopc.robots.sim.world import World, WorldError

KEYS = ["name", "size", "step", "duration", "seed", "goal", "charging_station", "walls", "boxes", "holes", "robots"]
KEYS += ["kind", "start", "laser", "beams", "battery", "capacity", "min", "max", "center", "from", "to", "polygon"]
SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**12), 10**12),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(string.printable, max_size=6),
)
VALUES = st.recursive(
    SCALARS,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.sampled_from(KEYS), inner, max_size=4),
    max_leaves=12,
)
WORLDS = st.dictionaries(st.sampled_from(KEYS), VALUES, max_size=6)


@pytest.mark.slow  # 200 worlds built: about 20 s on an idle 2-core machine
@settings(suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture], deadline=None)
@given(data=WORLDS)
def test_a_world_either_loads_or_is_refused_with_a_place(tmp_path, data):
    path = tmp_path / "world.yaml"
    path.write_text(yaml.safe_dump(data))
    try:
        world = World.load(str(path))
    except WorldError as e:
        assert str(e).startswith(str(path))
        return
    assert world.step > 0 and all(r.laser is None or r.laser.beams >= 1 for r in world.robots)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None)
@given(text=st.text(string.printable + "é∀\x00", max_size=200))
def test_any_text_as_a_world_file_is_loaded_or_refused(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("w") / "world.yaml"
    path.write_text(text, encoding="utf-8")
    try:
        World.load(str(path))
    except WorldError:
        pass


FIELD_TYPES = ["int8", "uint8", "int32", "uint64", "float64", "string", "bool", "geometry_msgs/Point", "nope/Thing"]
MSG_LINES = st.one_of(
    st.builds(
        lambda t, arr, name: f"{t}{arr} {name}",
        st.sampled_from(FIELD_TYPES),
        st.sampled_from(["", "[]", "[3]", "[-1]", "[<=2]", "[0]"]),
        st.from_regex(r"[a-z][a-z0-9_]{0,6}", fullmatch=True),
    ),
    st.builds(
        lambda t, name, value: f"{t} {name}={value}",
        st.sampled_from(["int8", "uint8", "int64", "uint64", "float32"]),
        st.from_regex(r"[A-Z][A-Z0-9_]{0,6}", fullmatch=True),
        st.integers(-(2**70), 2**70),
    ),
    st.text(string.printable, max_size=30),
)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None, max_examples=60)
@given(lines=st.lists(MSG_LINES, min_size=1, max_size=5))
def test_a_msg_file_gives_classes_or_exit_2(tmp_path_factory, lines):
    folder = tmp_path_factory.mktemp("m")
    (folder / "Thing.msg").write_text("\n".join(lines) + "\n")
    status = cli.main(["msg", "--file", str(folder / "Thing.msg"), "--type", "fz_msgs/msg/Thing", "-o", str(folder)])
    assert status in (0, 2)


@settings(suppress_health_check=[HealthCheck.too_slow], deadline=None)
@given(
    payload=st.binary(max_size=120),
    typename=st.sampled_from(
        ["std_msgs/msg/String", "geometry_msgs/msg/Twist", "sensor_msgs/msg/LaserScan", "nav_msgs/msg/Odometry"]
    ),
    header=st.sampled_from([b"\x00\x01\x00\x00", b"\x00\x00\x00\x00", b""]),
)
def test_the_cdr_decoder_decodes_or_raises_value_error(payload, typename, header):
    try:
        msg = cdr.deserialize(header + payload, typename)
    except ValueError:
        return
    assert ros_messages.typename_of(msg) == typename
