"""Programs run from `scoopc compile -o` output (`python -m PACKAGE`) as `scoopc run` runs them: a
Roboscoop program on the built-in simulator, in the world.yaml compiled beside it, with `scoopc run`'s
robot options (the same output for the same options), a wrong option or a Python without scoopc
told in one line with exit code 2; a program with a C library of its own (checksums). Over ROS 2:
tests/robots/test_dds_e2e.py runs compiled output with `--robot ros2`."""

from __future__ import annotations

import io
import subprocess
import sys
from pathlib import Path

import pytest

import scoopc
from scoopc.exits import Exit

pytestmark = pytest.mark.slow  # compiles, then runs child Pythons

SAMPLES = Path(__file__).resolve().parents[1] / "samples"


def python_m(out: Path, *argv: str, flags: tuple[str, ...] = ()) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, *flags, "-m", *argv], cwd=out, capture_output=True, text=True, timeout=120)


def run_here(paths, **options) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run(paths, stdout=out, stderr=err, **options)
    return result.status, out.getvalue(), err.getvalue()


@pytest.fixture(scope="module")
def scan_filter(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("compiled") / "out"
    assert scoopc.compile([SAMPLES / "scan_filter"], out).status == Exit.OK
    return out


def test_a_robot_program_runs_on_the_simulator_as_scoopc_run_runs_it(scan_filter):
    assert (scan_filter / "scan_filter" / "world.yaml").read_text() == (
        SAMPLES / "scan_filter" / "world.yaml"
    ).read_text()
    done = python_m(scan_filter, "scan_filter", "--duration", "3", "--no-png")
    status, out, err = run_here([SAMPLES / "scan_filter"], duration=3)
    assert (done.returncode, status) == (Exit.OK, Exit.OK), done.stderr + err
    assert done.stdout == out and out.count("scans filtered") == 3
    assert "scoopc: simulated 3.0 s in" in done.stderr and "robot1 moved 0.00 m" in done.stderr


def test_the_robot_options_are_scoopc_runs(scan_filter, tmp_path):
    world = (SAMPLES / "scan_filter" / "world.yaml").read_text()
    (tmp_path / "no_box.yaml").write_text(
        world.replace("duration: 30", "duration: 3").replace("boxes:\n  - {center", "# ")
    )
    png = tmp_path / "run.png"
    done = python_m(scan_filter, "scan_filter", "--world", str(tmp_path / "no_box.yaml"), "--png", str(png))
    status, out, _ = run_here([SAMPLES / "scan_filter"], world=str(tmp_path / "no_box.yaml"))
    assert (done.returncode, status) == (Exit.OK, Exit.OK), done.stderr
    assert done.stdout == out and out.count("scans filtered") == 3 and "front 0.95 m" not in out
    assert png.stat().st_size > 0


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (("--dration", "3"), "scoopc: error: unrecognized arguments: --dration 3"),
        (("--world", "no_such_world.yaml"), "scoopc: error: no world file no_such_world.yaml"),
        (("--robot", "mars"), "argument --robot: invalid choice: 'mars'"),
        (("stray",), "scoopc: error: unrecognized arguments: stray"),
    ],
)
def test_a_wrong_option_is_a_usage_error(scan_filter, argv, message):
    done = python_m(scan_filter, "scan_filter", *argv)
    assert done.returncode == Exit.USAGE and message in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and done.stdout == ""


def test_a_python_without_scoopc_is_told_so(scan_filter):
    done = python_m(scan_filter, "scan_filter", flags=("-S", "-E"))  # no site-packages: no scoopc
    assert done.returncode == Exit.USAGE and "Traceback" not in done.stderr, done.stderr
    assert done.stderr.startswith("scan_filter: error: this program was compiled by scoopc ")
    assert "cannot import (No module named 'scoopc'); install scoopc" in done.stderr


def test_a_program_with_its_own_c_library(tmp_path):
    ecf = SAMPLES / "checksums" / "checksums.ecf"
    assert scoopc.compile([ecf], tmp_path / "out").status == Exit.OK
    done = python_m(tmp_path / "out", "checksums")
    status, out, err = run_here([ecf])
    assert (done.returncode, status) == (Exit.OK, Exit.OK), done.stderr + err
    assert done.stdout == out and "Checksummed 4 blocks of 50000 bytes" in out
