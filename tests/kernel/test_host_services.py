"""Host-service externals: DOUBLE_MATH, SINGLE_MATH, PLATFORM, MEMORY, ISE_SCOOP_RUNTIME,
ARGUMENTS, ARGUMENTS_32, EXECUTION_ENVIRONMENT, OPERATING_ENVIRONMENT, C_DATE, TIME."""

import calendar
import gc
import math
import os
import struct
import sys
import time as pytime

import pytest

from scoopc import kernel
from scoopc.kernel import strings as K
from scoopc.kernel.ext import (
    arguments,
    arguments_32,
    c_date,
    double_math as D,
    execution_environment as E,
    ise_scoop_runtime,
    memory,
    operating_environment,
    platform,
    single_math as S,
    time as T,
)
from scoopc.runtime.main import finish, start


class Region:
    def __init__(self, pid=1):
        self.id = pid
        self.slept = []

    def sleep(self, ns, where=None):
        self.slept.append(ns)


class Str:
    pass


class Obj:
    def __init__(self, region):
        self._region_ = region


@pytest.fixture
def cur():
    saved = dict(kernel.CLASSES)
    for key in ("STRING_8", "STRING_32", "IMMUTABLE_STRING_8", "IMMUTABLE_STRING_32"):
        kernel.CLASSES[key] = type(key, (Str,), {})
    yield Obj(Region())
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)


def single(x):
    return struct.unpack("f", struct.pack("f", x))[0]


# --- math ----------------------------------------------------------------------------------


def test_double_math_is_libm(cur):
    assert D.cosine(cur, 0.5) == math.cos(0.5) and D.sine(cur, 1.0) == math.sin(1.0)
    assert D.tangent(cur, 0.3) == math.tan(0.3) and D.arc_tangent(cur, 2.0) == math.atan(2.0)
    assert D.arc_cosine(cur, 0.2) == math.acos(0.2) and D.arc_sine(cur, -0.2) == math.asin(-0.2)
    assert D.sqrt(cur, 2.0) == math.sqrt(2.0) and D.exp(cur, 1.0) == math.e
    assert D.log(cur, math.e) == 1.0 and D.log_2(cur, 8.0) == 3.0 and D.log10(cur, 1000.0) == 3.0
    assert D.floor(cur, -2.5) == -3.0 and D.ceiling(cur, 2.1) == 3.0
    assert isinstance(D.floor(cur, 2.7), float)


def test_double_math_gives_c_special_values_instead_of_python_errors(cur):
    assert math.isnan(D.sqrt(cur, -1.0)) and math.isnan(D.arc_cosine(cur, 2.0))
    assert D.log(cur, 0.0) == -math.inf and math.isnan(D.log10(cur, -1.0))
    assert D.exp(cur, 1000.0) == math.inf and math.isnan(D.cosine(cur, math.inf))
    assert D.floor(cur, math.inf) == math.inf and math.isnan(D.ceiling(cur, math.nan))
    assert math.copysign(1.0, D.ceiling(cur, -0.5)) == -1.0  # C's ceil (-0.5) is -0.0


def test_single_math_computes_in_double_and_rounds(cur):
    x = single(0.7)
    assert S.cosine(cur, x) == single(math.cos(x)) and S.sqrt(cur, 2.0) == single(math.sqrt(2.0))
    assert S.log_2(cur, 1024.0) == 10.0 and S.floor(cur, single(-1.5)) == -2.0
    assert S.exp(cur, 100.0) == math.inf and math.isnan(S.arc_sine(cur, 3.0))
    for fn in (S.sine, S.tangent, S.arc_cosine, S.arc_tangent, S.log, S.log10, S.ceiling):
        assert fn(cur, 0.5) == single(fn(cur, 0.5))


# --- platform, memory, runtime -----------------------------------------------------------------


def test_platform(cur):
    assert platform.is_windows(cur) == (os.name == "nt")
    assert platform.is_unix(cur) != platform.is_windows(cur)
    assert platform.is_mac(cur) == (sys.platform == "darwin")
    assert platform.is_little_endian(cur) == (sys.byteorder == "little")
    assert platform.is_64_bits(cur) == (sys.maxsize > 2**32)
    assert operating_environment.directory_separator(cur) == os.sep
    assert operating_environment.case_sensitive_path_names(cur) == (os.name != "nt")


def test_memory(cur, monkeypatch):
    was = gc.isenabled()
    # which collections are asked for; a real full collection of a test worker's heap takes seconds
    asked = []
    monkeypatch.setattr(gc, "collect", lambda generation=2: asked.append(generation) or 0)
    try:
        memory.collection_off(cur)
        assert not memory.collecting(cur)
        memory.collection_on(cur)
        assert memory.collecting(cur)
        memory.collect(cur)
        memory.full_collect(cur)
        memory.full_coalesce(cur)
    finally:
        (gc.enable if was else gc.disable)()
    assert asked == [0, 2, 2]


def test_region_id(cur):
    other = Obj(Region(5))
    assert ise_scoop_runtime.region_id(cur, cur) == 0  # the root region is 0
    assert ise_scoop_runtime.region_id(cur, other) == 4
    assert ise_scoop_runtime.region_id(cur, 3) == 0  # a value: the caller's region
    assert ise_scoop_runtime.region_id(cur, Obj(Region(0x10000))) == 0  # wraps short of 0xFFFF


# --- arguments ---------------------------------------------------------------------------------


def test_arguments(cur):
    saved = list(arguments.PROGRAM)
    try:
        check_arguments(cur)
    finally:
        arguments.PROGRAM[:] = saved


def check_arguments(cur):
    arguments.set_arguments(["prog", "-v", "f\u00e9e"])
    assert arguments.argument_count(cur) == 2 and arguments_32.argument_count(cur) == 2
    a0 = arguments.i_th_argument(cur, 0)
    assert type(a0).__name__ == "STRING_8" and K.text(a0) == "prog" and a0._region_ is cur._region_
    b2 = arguments_32.i_th_argument(cur, 2)
    assert type(b2).__name__ == "IMMUTABLE_STRING_32" and K.text(b2) == "f\u00e9e"
    with pytest.raises(IndexError):
        arguments.i_th_argument(cur, 3)
    with pytest.raises(IndexError):
        arguments.i_th_argument(cur, -1)
    with pytest.raises(ValueError):
        arguments.set_arguments([])


# --- execution environment --------------------------------------------------------------------


def test_environment_variables(cur, monkeypatch):
    monkeypatch.delenv("SCOOPC_TEST_VAR", raising=False)
    key = K.new_string_8(cur._region_, "SCOOPC_TEST_VAR")
    assert E.item(cur, key) is None
    E.put(cur, K.new_string_32(cur._region_, "v\u00e9"), key)
    value = E.item(cur, key)
    assert type(value).__name__ == "STRING_32" and K.text(value) == "v\u00e9"
    assert os.environ["SCOOPC_TEST_VAR"] == "v\u00e9"


def test_directories(cur, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert K.text(E.current_working_directory(cur)) == str(tmp_path)
    sub = tmp_path / "sub"
    sub.mkdir()
    E.change_working_directory(cur, K.new_string_8(cur._region_, str(sub)))
    assert os.getcwd() == str(sub) and E.return_code(cur) == 0
    E.change_working_directory(cur, K.new_string_8(cur._region_, str(tmp_path / "none")))
    assert os.getcwd() == str(sub) and E.return_code(cur) == -1
    monkeypatch.setenv("HOME", str(tmp_path))
    assert K.text(E.home_directory_name(cur)) == str(tmp_path)
    monkeypatch.setenv("SHELL", "/bin/zsh")
    if os.name != "nt":
        assert K.text(E.root_directory_name(cur)) == "/"
        assert K.text(E.default_shell(cur)) == "/bin/zsh"
    assert E.available_cpu_count(cur) >= 1


def test_sleep_uses_the_runtime_clock(cur):
    E.sleep(cur, 1500)
    assert cur._region_.slept == [1500]


@pytest.mark.skipif(os.name == "nt", reason="POSIX shell commands")
def test_system_and_launch(cur, tmp_path):
    E.system(cur, K.new_string_8(cur._region_, "exit 3"))
    assert E.return_code(cur) == 3
    E.system(cur, K.new_string_8(cur._region_, f"echo hi > {tmp_path / 'o.txt'}"))
    assert E.return_code(cur) == 0 and (tmp_path / "o.txt").read_text() == "hi\n"
    E.launch(cur, K.new_string_8(cur._region_, f"echo bg > {tmp_path / 'bg.txt'}"))
    deadline = pytime.time() + 10
    while not (tmp_path / "bg.txt").exists() or not (tmp_path / "bg.txt").read_text():
        assert pytime.time() < deadline
        pytime.sleep(0.01)


# --- C_DATE and TIME ---------------------------------------------------------------------------


def test_c_date_fields(cur):
    ts = calendar.timegm((2024, 1, 5, 15, 7, 9)) + 0.123456
    assert [c_date.field(cur, ts, True, i) for i in range(1, 8)] == [2024, 1, 5, 15, 7, 9, 123]
    local = pytime.localtime(int(ts))
    assert c_date.field(cur, ts, False, 4) == local.tm_hour
    assert c_date.field(cur, ts, False, 3) == local.tm_mday
    with pytest.raises(ValueError):
        c_date.field(cur, ts, True, 8)


def test_c_date_and_time_read_the_wall_clock(cur):
    before = pytime.time()
    now = c_date.current_timestamp(cur)
    assert before <= now <= pytime.time()
    secs = T.fine_seconds_now(cur, True)
    t = pytime.time()
    expected = t % 86400
    assert 0 <= secs < 86400 and (abs(secs - expected) < 2 or abs(secs - expected) > 86398)
    assert round(secs * 1000) == pytest.approx(secs * 1000, abs=1e-6)  # milliseconds


def test_virtual_clock_moves_c_date_and_time():
    rt, root = start(virtual_clock=True, deadlock_tick=0.05, stdout=None)
    try:
        probe = Obj(root)
        t0 = c_date.current_timestamp(probe)
        s0 = T.fine_seconds_now(probe, True)
        root.sleep(3_600 * 10**9)  # one virtual hour, at once
        t1 = c_date.current_timestamp(probe)
        s1 = T.fine_seconds_now(probe, True)
    finally:
        assert finish(rt, root) == 0
    assert t1 - t0 == pytest.approx(3600, abs=1e-3)
    assert (s1 - s0) % 86400 == pytest.approx(3600, abs=0.002)
