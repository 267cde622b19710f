"""Smoke test of benchmarks/run.py: tiny sizes, output format and result checks (never timings),
for the hand-written variants and the dialect versions compiled by scoopc."""

import contextlib
import os
import re
import subprocess
import sys
import threading

import pytest

pytestmark = pytest.mark.slow  # long: outside the quick selection (pytest -m "not slow")

RUN = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "run.py")
NAMES = ["mutex", "condition", "prodcons", "threadring", "chameneos"]
NUMBER = r"\d+\.\d+"
BENCH_LINE = re.compile(
    rf"^(\w+) ((?:\w+=\d+ )+)scoop_s=({NUMBER}) compiled_s=({NUMBER}) "
    rf"baseline_s=({NUMBER}) ratio=({NUMBER}) compiled_ratio={NUMBER} "
    rf"compiled_vs_api=({NUMBER}) us_per_op={NUMBER}/{NUMBER}/{NUMBER} cpu_ratio={NUMBER}$"
)
API_LINE = re.compile(
    rf"^(\w+) ((?:\w+=\d+ )+)scoop_s=({NUMBER}) baseline_s=({NUMBER}) "
    rf"ratio=({NUMBER}) us_per_op={NUMBER}/{NUMBER} cpu_ratio={NUMBER}$"
)
COMPILED_LINE = re.compile(
    rf"^# compiled (\d+) dialect versions with scoopc in {NUMBER} s "
    rf"\(assertions=none; the standard library: {NUMBER} s, compiled once or cached\)$"
)
GEOMEAN_LINE = re.compile(rf"geomean_ratio={NUMBER} compiled_vs_api_geomean={NUMBER} compiled_vs_api_max={NUMBER}")
SUMMARY = (
    rf"compiled_geomean=({NUMBER}) compiled_worst=({NUMBER}) \((\w+)\)  "
    rf"target each <= 1\.5, geomean <= 1\.0: (met|MISSED)"
)
COMPILED_SUMMARY_LINE = re.compile(rf"^compiled against threads: {SUMMARY}$")
UNPINNED_LINE = re.compile(rf"^unpinned, (\d+) cpus: {SUMMARY}  \[((?:\w+={NUMBER} ?)+)\]$")
MICRO_LINE = re.compile(rf"^micro (\w+) scoop_us={NUMBER} baseline_us={NUMBER} ratio={NUMBER}  \(.+\)$")
MICRO_KEYS = [
    "async_command",
    "async_command_queued",
    "sync_query",
    "reserve_1_wait_condition",
    "reserve_1",
    "reserve_2",
    "reserve_4",
    "reserve_8",
]


def run(*options):
    command = [sys.executable, RUN, *options]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


@pytest.fixture(scope="module")
def smoke():
    done = run("--smoke")
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout.splitlines()


def test_header_states_parameters(smoke):
    assert smoke[0].startswith("# scoopc benchmarks:")
    assert "pinned to cpu" in smoke[0] and "size=smoke" in smoke[0]


def test_every_dialect_version_is_compiled_once(smoke):
    match = COMPILED_LINE.match(smoke[1])
    assert match and match.group(1) == "5", smoke


def test_one_line_per_benchmark_in_order(smoke):
    matches = [BENCH_LINE.match(line) for line in smoke[2:7]]
    assert all(matches), smoke
    assert [m.group(1) for m in matches] == NAMES


def test_geomean_line(smoke):
    assert GEOMEAN_LINE.fullmatch(smoke[7]), smoke


def test_compiled_against_threads_geomean_and_worst(smoke):
    match = COMPILED_SUMMARY_LINE.match(smoke[8])
    assert match, smoke
    compiled = {line.split()[0]: float(re.search(rf"compiled_ratio=({NUMBER})", line).group(1)) for line in smoke[2:7]}
    assert match.group(3) == max(compiled, key=compiled.get)
    assert float(match.group(2)) == compiled[match.group(3)]
    assert (match.group(4) == "met") == (float(match.group(1)) <= 1.0 and float(match.group(2)) <= 1.5)


def test_a_pinned_run_ends_with_the_unpinned_figure(smoke):
    if len(os.sched_getaffinity(0)) < 2:
        pytest.skip("one CPU: there is no unpinned figure")
    match = UNPINNED_LINE.match(smoke[9])
    assert match, smoke
    assert int(match.group(1)) == len(os.sched_getaffinity(0))
    assert [item.split("=")[0] for item in match.group(6).split()] == NAMES


def test_micro_lines(smoke):
    micro = [MICRO_LINE.match(line) for line in smoke[8:] if line.startswith("micro ")]
    assert all(micro), smoke
    assert [m.group(1) for m in micro] == MICRO_KEYS


def test_only_and_unpinned_select():
    done = run("--smoke", "--unpinned", "--only", "mutex")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert "unpinned" in lines[0]
    assert COMPILED_LINE.match(lines[1]).group(1) == "1"
    assert BENCH_LINE.match(lines[2]).group(1) == "mutex"
    assert GEOMEAN_LINE.fullmatch(lines[3]) and COMPILED_SUMMARY_LINE.match(lines[4]) and len(lines) == 5


def test_no_compiled_keeps_the_hand_written_variants_only():
    done = run("--smoke", "--no-compiled", "--only", "threadring")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert API_LINE.match(lines[1]).group(1) == "threadring"
    assert re.fullmatch(rf"geomean_ratio={NUMBER}", lines[2]) and len(lines) == 3


def test_unknown_benchmark_is_a_usage_error():
    assert run("--only", "nosuch").returncode == 2


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("variant", ["baseline", "scoop"])
def test_each_variant_checks_its_result(name, variant, monkeypatch):
    """A wrong count must raise, so a broken run can never print a fast time."""
    monkeypatch.syspath_prepend(os.path.dirname(RUN))
    monkeypatch.syspath_prepend(os.path.join(os.path.dirname(RUN), ".."))
    module = __import__("bench_" + name)
    from common import CheckFailed

    def wrong(label, got, expected):
        raise CheckFailed(label)

    monkeypatch.setattr(module, "check", wrong)
    if hasattr(module, "check_counts"):
        monkeypatch.setattr(module, "check_counts", lambda *a: wrong("counts", 0, 1))
    raised = run_with_timeout(lambda: getattr(module, variant)(**module.SIZES["smoke"]))
    assert isinstance(raised, CheckFailed), raised


@pytest.fixture(scope="module")
def builds(tmp_path_factory):
    """Every dialect version, compiled once with scoopc's API (as run.py does)."""
    folder = tmp_path_factory.mktemp("compiled")
    sys.path.insert(0, os.path.dirname(RUN))
    from common import compile_benchmark

    for name in NAMES:
        compile_benchmark(name, str(folder))
    return str(folder)


@pytest.mark.parametrize("name", NAMES)
def test_each_compiled_version_runs_and_checks_its_output(name, builds, monkeypatch):
    """The compiled program prints the expected line at a tiny size; a wrong expected output
    raises, so a broken compiled run can never print a fast time."""
    monkeypatch.syspath_prepend(os.path.dirname(RUN))
    module = __import__("bench_" + name)
    from common import CheckFailed, run_compiled

    params = module.SIZES["smoke"]
    with compiled_registry():
        result = run_with_timeout(lambda: run_compiled(builds, name, module, params))
        assert result is None
        monkeypatch.setattr(module, "program_output", lambda **p: "something else\n")
        raised = run_with_timeout(lambda: run_compiled(builds, name, module, params))
    assert isinstance(raised, CheckFailed), raised


_REGISTRY: dict = {}  # the class registry as the compiled programs left it


@contextlib.contextmanager
def compiled_registry():
    """The kernel's class registry as the compiled programs of this module need it: each test
    gets the registry back as it found it (tests/conftest.py), and modules imported by an
    earlier test do not register their classes again."""
    from scoopc import kernel

    kernel.CLASSES.update(_REGISTRY)
    try:
        yield
    finally:
        _REGISTRY.update(kernel.CLASSES)


def run_with_timeout(fn, seconds=20):
    """Run `fn` in a daemon thread so that a hung runtime fails the test instead of pytest.
    Returns what it raised (None if nothing)."""
    outcome = []

    def target():
        try:
            fn()
            outcome.append(None)
        except BaseException as e:
            outcome.append(e)

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(seconds)
    assert outcome, f"no result after {seconds} s: the run hangs"
    return outcome[0]


def test_a_failing_run_is_reported_and_fails_the_command(monkeypatch, capsys):
    monkeypatch.syspath_prepend(os.path.dirname(RUN))
    import run as harness

    with pytest.raises(harness.RunFailed):
        harness.run_child("nosuch", "scoop", "smoke")  # a crashing child: non-zero exit

    def broken(name, variant, size, build=None):
        raise harness.RunFailed(f"{name} {variant}: exit 1: CheckFailed: count")

    monkeypatch.setattr(harness, "run_child", broken)
    assert harness.main(["--smoke", "--unpinned", "--only", "mutex"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[2].startswith("mutex workers=") and "FAILED" in out[2]
    assert out[3] == "geomean_ratio=nan failed=mutex"


def test_exit_time_benchmark_smoke():
    """benchmarks/exit_time.py at smoke size: its output's format, and that a run with busy
    processors ends after Ctrl-C at all (the time limit only guards against a hang)."""
    exit_time = os.path.join(os.path.dirname(RUN), "exit_time.py")
    done = subprocess.run([sys.executable, exit_time, "--smoke"], capture_output=True, text=True, timeout=180)
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("# exit_time:") and "3 busy processors" in lines[0]
    assert re.fullmatch(rf"exit compiled_s={NUMBER} baseline_s={NUMBER} ratio={NUMBER}", lines[1]), lines[1]
