"""Every program in samples/ compiles and runs (virtual clock, assertions on, --trace-processors);
its output equals tests/golden/samples_expected/<sample>.out per processor (each processor's lines
in order) and satisfies the invariants the sample is about, read from the output. The samples'
own contracts (a buffer never exceeds its capacity, a fork is never picked up while held, ...)
are checked at run time: a violation would fail the run (exit 3, stderr). Neither stream may name
a Python exception; robot samples run 5 simulated seconds for that check alone."""

from __future__ import annotations

import re
import sys
import zlib
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from golden_support import REPO, Config, assert_no_host_exception, assert_output, compile_program, run_program  # noqa: E402

# Robot samples (a world.yaml beside the program) run on the simulator: tests/robots checks what
# they do; here only that a short run shows no Python exception.
SAMPLES = sorted(
    p for p in (REPO / "samples").iterdir() if p.is_dir() and any(p.glob("*.e")) and not (p / "world.yaml").exists()
)
ROBOT_SAMPLES = sorted(
    p for p in (REPO / "samples").iterdir() if p.is_dir() and any(p.glob("*.e")) and (p / "world.yaml").exists()
)
ROBOT_SECONDS = 5  # simulated: start-up, the first sensor readings and commands
EXPECTED = Path(__file__).parent / "samples_expected"


def lines(out: str) -> list[str]:
    """All lines without their processor tags, in the order written."""
    return [re.sub(r"^\[P\d+\] ?", "", line) for line in out.splitlines()]


def matching(out: str, pattern: str) -> list[tuple]:
    return [m.groups() for m in (re.match(pattern, line) for line in lines(out)) if m]


# --- what each sample must show, read from its output ------------------------------------------
def check_producer_consumer(out: str) -> None:
    puts = matching(out, r"producer (\d+) put (\d+)$")
    for p in (1, 2, 3):
        mine = [int(v) for q, v in puts if int(q) == p]
        assert mine == [p * 100 + i for i in range(1, 6)], f"producer {p} put {mine}"
    took = sum(int(n) for (n,) in matching(out, r"consumer \d+ took (\d+) items$"))
    assert took == len(puts) == 15
    ((total,),) = matching(out, r"consumers took items adding up to (\d+)$")
    assert int(total) == sum(int(v) for _, v in puts)


def check_dining_philosophers(out: str) -> None:
    meals = matching(out, r"Philosopher (\d+) eats with forks (\d+) and (\d+) \(round (\d+)\)$")
    for n in range(1, 6):
        mine = [(int(l_), int(r), int(k)) for p, l_, r, k in meals if int(p) == n]
        assert mine == [(n, n % 5 + 1, k) for k in (1, 2, 3)], f"philosopher {n}: {mine}"
    done = matching(out, r"Philosopher (\d+) is done after (\d+) meals$")
    assert sorted(int(p) for p, _ in done) == [1, 2, 3, 4, 5] and all(m == "3" for _, m in done)


def check_readers_writers(out: str) -> None:
    edits = matching(out, r"Writer (\d+): edit (\d+) of (\d+) written$")
    ((revision, _),) = matching(out, r"Document: revision (\d+), (\d+) lines$")
    assert int(revision) == len(edits) == 6
    readers = matching(out, r"Reader \d+: read up to revision (\d+), every revision read was whole$")
    assert [r for (r,) in readers] == [revision] * 3


def check_parallel_sum(out: str) -> None:
    parts = matching(out, r"Worker \d+: squares of (\d+)\.\.(\d+) add up to (\d+)$")
    ((total,),) = matching(out, r"Sum of the squares of 1\.\.10000: (\d+)$")
    assert sum(int(s) for _, _, s in parts) == int(total) == 10000 * 10001 * 20001 // 6
    for low, high, s in parts:
        assert int(s) == sum(i * i for i in range(int(low), int(high) + 1))


def check_sleeping_barber(out: str) -> None:
    cuts = matching(out, r"Barber: cuts the hair of customer (\d+)$")
    seated = matching(out, r"Customer (\d+): sits down in the waiting room$")
    left = matching(out, r"Customer (\d+): no free chair, leaves$")
    assert sorted(cuts) == sorted(seated) and len(cuts) + len(left) == 10
    ((customers, away),) = matching(out, r"Shop: closes after (\d+) customers, (\d+) turned away$")
    assert int(customers) == 10 and int(away) == len(left)
    ((given,),) = matching(out, r"Barber: shop closed, (\d+) haircuts given$")
    assert int(given) == len(cuts)


def check_eyes_follow_ball(out: str) -> None:
    turns = matching(out, r"Eyes: ball at (-?\d+) degrees, head turns to (-?\d+)$")
    throws = matching(out, r"Thrower: ball thrown to (-?\d+) degrees$")
    assert [b for b, _ in turns] == [b for (b,) in throws]
    assert all(int(h) == max(-45, min(45, int(b))) for b, h in turns), "the head never turns beyond 45 degrees"
    ((count, last),) = matching(out, r"Head turned (\d+) times and looks at (-?\d+) degrees$")
    assert int(count) == len(turns) and last == turns[-1][1]


def check_move_limbs(out: str) -> None:
    steps = matching(out, r"Walker: step (\d+), leg to (-?\d+), arm to (-?\d+)$")
    assert steps and all(int(leg) == -int(arm) for _, leg, arm in steps), "the arm moves opposite the leg"
    ((taken,),) = matching(out, r"Walker: (\d+) steps taken$")
    assert int(taken) == len(steps)


def check_checksums(out: str) -> None:
    blocks = matching(out, r"Block (\d+) \(seed (\d+)\): crc32 (\d+)$")
    assert [int(b) for b, _, _ in blocks] == [1, 2, 3, 4]
    for _, seed, crc in blocks:  # the same generator in Python, checked against zlib's CRC-32
        state, data = int(seed), bytearray()
        for _ in range(50_000):
            state = (state * 1103515245 + 12345) & 0xFFFFFFFF
            data.append((state >> 16) & 0xFF)
        assert int(crc) == zlib.crc32(bytes(data))
    assert matching(out, r"Checksummed (\d+) blocks of (\d+) bytes$") == [("4", "50000")]


def check_navigate_to_pose(out: str) -> None:
    # without a ROS 2 robot there is no Nav2 server: the goal is refused at once, and said so
    # (the run against a stand-in server is tests/robots/test_ros2_robots.py's)
    assert [line.split("] ", 1)[-1] for line in out.splitlines()] == ["no action server /navigate_to_pose"]


CHECKS = {name[len("check_") :]: fn for name, fn in globals().items() if name.startswith("check_")}


def test_every_sample_has_a_check():
    assert sorted(s.name for s in SAMPLES if s.name not in CHECKS) == []


@pytest.mark.parametrize("sample", SAMPLES, ids=[s.name for s in SAMPLES])
def test_sample(sample: Path, tmp_path: Path, request):
    config = Config(compare="per_processor", virtual_clock=True)
    compiled, _ = compile_program(sample, tmp_path)
    outcome = run_program(compiled, config)
    assert_no_host_exception(outcome.out, outcome.err, sample.name)
    assert outcome.status == 0, f"{sample.name}: exit status {outcome.status}\n{outcome.err}"
    assert outcome.err == "", f"{sample.name}: unexpected stderr:\n{outcome.err}"
    expected = EXPECTED / f"{sample.name}.out"
    if request.config.getoption("--update-golden"):
        EXPECTED.mkdir(exist_ok=True)
        expected.write_text(outcome.out)
    assert expected.exists(), f"{expected} is missing: check the output, then run pytest --update-golden"
    assert_output(config, expected.read_text(), outcome.out, sample.name)
    check = CHECKS.get(sample.name)
    if check is not None:
        check(outcome.out)


@pytest.mark.parametrize("sample", ROBOT_SAMPLES, ids=[s.name for s in ROBOT_SAMPLES])
def test_robot_sample_shows_no_host_exception(sample: Path):
    """A robot sample, run briefly on the simulator: what the user sees names no Python exception."""
    import io

    from harness import run_on_simulator

    out, err = io.StringIO(), io.StringIO()
    result = run_on_simulator(sample, duration=ROBOT_SECONDS, stdout=out, stderr=err)
    assert_no_host_exception(out.getvalue(), err.getvalue(), sample.name)
    assert result.status == 0, f"{sample.name}: exit status {result.status}\n{err.getvalue()}"


def test_host_exception_check_catches_what_it_must():
    from golden_support import host_exceptions

    assert host_exceptions("scoopc: run-time failure: IndexError: list index out of range") != []
    assert host_exceptions("'TUPLE' object has no attribute '_items' (AttributeError)") != []
    assert host_exceptions("Traceback (most recent call last):") != []
    assert host_exceptions("precondition violated: `valid_key` (in ARRAY.item, array.e:115)") == []
    assert host_exceptions("KeyErrors and MyValueError are words of the program") == []
