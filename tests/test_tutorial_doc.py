"""docs/tutorial.md is true: every command it shows (after a `$`) that needs no real robot and no
ROS 2 installation runs, and prints what the tutorial shows; `...` stands for what varies (within
a line: any text; alone on a line: any number of lines). Each "things to try" is made and its
stated effect checked; the ROS 2 step runs against `scoopc sim` in a second process.

Lines starting with `scoopc:` are compared with stderr, the others with stdout. The runs are
long (simulated minutes), so most tests are marked slow."""

import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "robots"))
import domains  # noqa: E402 - tests/robots/domains.py: a DDS domain per test, disjoint per worker

from scoopc import cli  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TUTORIAL = ROOT / "docs" / "tutorial.md"
FIRST = ROOT / "samples" / "first_controller"


def shown_commands() -> list[tuple[str, list[str]]]:
    """(command, the output lines shown after it) for every `$` line of the tutorial, in order."""
    found: list[tuple[str, list[str]]] = []
    open_block = False
    for line in TUTORIAL.read_text(encoding="utf-8").splitlines():
        if not line.startswith("    "):
            open_block = False
            continue
        text = line[4:]
        if text.startswith("$ "):
            found.append((text[2:].split("  #")[0].strip(), []))
            open_block = True
        elif open_block:
            found[-1][1].append(text)
    return found


def matches(shown: list[str], actual: list[str]) -> bool:
    """Whether `actual` lines are `shown`, with `...` for any text (a line of its own: any lines)."""
    pattern = "".join(
        r"(?:[^\n]*\n)*?" if line == "..." else ".*?".join(map(re.escape, line.split("..."))) + r"\n" for line in shown
    )
    return re.fullmatch(pattern, "".join(f"{a}\n" for a in actual), re.DOTALL) is not None


def compare(shown: list[str], out: str, err: str) -> None:
    """Shown lines against the outputs: all against stderr when the command printed nothing on
    stdout (`scoopc check`), else `scoopc:` lines against stderr and the others against stdout."""
    if not out:
        assert matches(shown, err.splitlines()), f"stderr:\n{err}\nshown:\n" + "\n".join(shown)
        return
    streams: dict[bool, list[str]] = {True: [], False: []}
    for line in shown:
        if line == "...":
            streams[True].append(line)
            streams[False].append(line)
        else:
            streams[line.startswith("scoopc:")].append(line)
    assert matches(streams[False], out.splitlines()), f"stdout:\n{out}\nshown:\n" + "\n".join(streams[False])
    assert matches(streams[True], err.splitlines()), f"stderr:\n{err}\nshown:\n" + "\n".join(streams[True])


def run_shown(command: str, capsys, monkeypatch, tmp_path, terminal=False, root=ROOT) -> tuple[int, str, str]:
    """Run a tutorial command in this process, in `tmp_path`, with its paths in the repository."""
    argv = shlex.split(command)
    assert argv[0] == "scoopc"
    argv = [str(root / a) if a.startswith("samples/") else a for a in argv[1:]]
    monkeypatch.chdir(tmp_path)
    if terminal:  # what a terminal shows: scoopc check ends with its summary line
        monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    try:
        status = cli.main(argv)
    except SystemExit as done:  # --version
        status = done.code
    out, err = capsys.readouterr()
    err = re.sub(r"\x1b\[[0-9;]*m", "", err)  # a terminal's colours
    # The progress bar of building the standard library: the first command of a checkout's
    # compiler only, as the tutorial says (one line redrawn, then ended).
    return status, out, re.sub(r"(?:\r\x1b\[K(?:scoopc: [^\r\n]*)?)+\n", "", err)


SHOWN = shown_commands()
COMMANDS = {command: output for command, output in reversed(SHOWN)}  # the first showing of each
CHECKS = [output for command, output in SHOWN if command == "scoopc check samples/first_controller"]


def test_the_tutorial_shows_its_commands():
    assert {
        "scoopc --version",
        "scoopc run samples/exploration",
        "scoopc run samples/first_controller",
        "scoopc check samples/first_controller",
        "scoopc run samples/exploration --duration 60 --record exploration.mcap --gif exploration.gif",
        "scoopc sim samples/first_controller/world.yaml",
        "scoopc run samples/first_controller --robot ros2 --namespace robot1",
    } <= set(COMMANDS)


def test_the_matcher():
    assert matches(["a ... c"], ["a b c"]) and not matches(["a ... c"], ["a b d"])
    assert matches(["x", "...", "y"], ["x", "1", "2", "y"]) and matches(["x", "...", "y"], ["x", "y"])
    assert not matches(["x"], ["x", "extra"])


def test_version(capsys, monkeypatch, tmp_path):
    status, out, err = run_shown("scoopc --version", capsys, monkeypatch, tmp_path)
    assert status == 0
    compare(COMMANDS["scoopc --version"], out, err)


def test_check_ends_with_its_summary(capsys, monkeypatch, tmp_path):
    command = "scoopc check samples/first_controller"
    status, out, err = run_shown(command, capsys, monkeypatch, tmp_path, terminal=True)
    assert status == 0
    compare(CHECKS[0], out, err)


def copy_of_first_controller(tmp_path: Path, *edits: tuple[str, str]) -> Path:
    """samples/first_controller copied into tmp_path/samples/, with `edits` made in its class."""
    folder = tmp_path / "samples" / "first_controller"
    shutil.copytree(FIRST, folder, ignore=shutil.ignore_patterns("__pycache__"))
    source = folder / "first_controller.e"
    text = source.read_text()
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new)
    source.write_text(text)
    return tmp_path


def test_try_a_call_on_a_separate_target_outside_a_reservation(capsys, monkeypatch, tmp_path):
    """`robot.drive.send (0.1, 0.0)` in `make`: refused with VUTA(3), explained by --explain VUTA3."""
    root = copy_of_first_controller(
        tmp_path, ("\t\t\tcreate timer.make\n", "\t\t\tcreate timer.make\n\t\t\trobot.drive.send (0.1, 0.0)\n")
    )
    status, out, err = run_shown("scoopc check samples/first_controller", capsys, monkeypatch, tmp_path, True, root)
    assert status == 1 and "Python" not in err
    compare(CHECKS[1], out, err)
    assert err.rstrip().endswith("1 class checked, 1 error")
    status, out, _ = run_shown("scoopc check --explain VUTA3", capsys, monkeypatch, tmp_path)
    assert status == 0 and out.startswith("VUTA(3): ")


def test_try_a_misspelt_feature_and_a_missing_end(capsys, monkeypatch, tmp_path):
    """The novice's first mistakes: the checker names the feature meant and the routine whose
    `end` is missing, and no message names Python."""
    root = copy_of_first_controller(tmp_path, ("Result := not range.has_obstacle", "Result := not range.has_obstacl"))
    status, _, err = run_shown("scoopc check samples/first_controller", capsys, monkeypatch, tmp_path, True, root)
    assert status == 1 and "did you mean `has_obstacle`?" in err and "Python" not in err
    source = root / "samples" / "first_controller" / "first_controller.e"
    text = source.read_text()
    last = '\t\t\tprint ("Done after " + timer.elapsed.rounded.out + " s%N")\n'
    assert last + "\t\tend\n" in text
    source.write_text(text.replace(last + "\t\tend\n", last, 1))
    status, _, err = run_shown("scoopc check samples/first_controller", capsys, monkeypatch, tmp_path, True, root)
    assert status == 1 and "Python" not in err and "python" not in err
    assert "error SYNTAX-END: missing `end` of the `do` of `make`" in err
    assert "the `end` was due before line" in err


@pytest.mark.slow
@pytest.mark.parametrize("program", ["exploration", "first_controller"])
def test_run_a_sample_as_shown(capsys, monkeypatch, tmp_path, program):
    command = f"scoopc run samples/{program}"
    status, out, err = run_shown(command, capsys, monkeypatch, tmp_path)
    assert status == 0
    compare(COMMANDS[command], out, err)
    assert len(list((tmp_path / "runs" / program).glob(f"*/{program}.png"))) == 1


@pytest.mark.slow
def test_record_a_run_and_read_it_with_rosbags(capsys, monkeypatch, tmp_path):
    from rosbags.highlevel import AnyReader  # deferred: optional (a large import only this test needs)

    command = "scoopc run samples/exploration --duration 60 --record exploration.mcap --gif exploration.gif"
    status, out, err = run_shown(command, capsys, monkeypatch, tmp_path)
    assert status == 0
    compare(COMMANDS[command], out, err)
    assert (tmp_path / "exploration.gif").read_bytes()[:6] == b"GIF89a"
    with AnyReader([tmp_path / "exploration.mcap"]) as reader:
        topics = {c.topic for c in reader.connections}
        assert {"/robot1/cmd_vel", "/robot1/odom", "/robot1/proximity/left", "/clock"} <= topics
        odom = [c for c in reader.connections if c.topic == "/robot1/odom"]
        _, _, raw = next(reader.messages(connections=odom))
        message = reader.deserialize(raw, odom[0].msgtype)
        assert message.header.frame_id  # a decoded nav_msgs/Odometry


def stops(out: str) -> list[str]:
    return [line for line in out.splitlines() if line.startswith("Stop ")]


@pytest.mark.slow
def test_try_a_speed_above_the_limit(capsys, monkeypatch, tmp_path):
    """`Speed` 1.0: no faster than 0.14 m/s, and the same run as with 0.14."""
    import scoopc

    outs = []
    for speed in ("1.0", "0.14"):
        root = copy_of_first_controller(tmp_path / speed, ("Speed: REAL_64 = 0.1", f"Speed: REAL_64 = {speed}"))
        result = scoopc.run([str(root / "samples" / "first_controller")], [], robot="sim", png=False)
        out, _ = capsys.readouterr()
        outs.append(out)
        trajectory = result.sim.robot().trajectory
        fastest = max(
            ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5 / (t1 - t0)
            for (t0, x0, y0, _), (t1, x1, y1, _) in zip(trajectory, trajectory[1:])
            if t1 > t0
        )
        assert fastest <= 0.14 + 1e-6
    assert outs[0] == outs[1] and len(stops(outs[0])) == 3


@pytest.mark.slow
def test_try_without_await_sensors(capsys, monkeypatch, tmp_path):
    """Without `await_sensors`: a first stop at (0, 0) before the robot moved; the rest as before."""
    call = "\t\t\tawait_sensors (robot.range_signaler, robot.odometry)\n"
    root = copy_of_first_controller(tmp_path, (call, ""))
    status, out, _ = run_shown("scoopc run samples/first_controller", capsys, monkeypatch, tmp_path, root=root)
    assert status == 0
    assert "Remove the call of `await_sensors`: the program now reports `Stop 1 at x = 0 cm, y = 0 cm`" in (
        " ".join(TUTORIAL.read_text().split())
    )
    shown = [line for line in COMMANDS["scoopc run samples/first_controller"] if line.startswith("Stop ")]
    assert stops(out) == ["Stop 1 at x = 0 cm, y = 0 cm"] + shown[1:]


@pytest.mark.slow
def test_try_a_duration(capsys, monkeypatch, tmp_path):
    assert "Add `--duration 5`: the run stops after 5 simulated seconds, before the first stop" in (
        " ".join(TUTORIAL.read_text().split())
    )
    status, out, err = run_shown("scoopc run samples/first_controller --duration 5", capsys, monkeypatch, tmp_path)
    assert status == 0 and stops(out) == []
    assert "scoopc: simulated 5.0 s in " in err and "(the duration asked for)" in err


@pytest.mark.slow
def test_the_ros2_step_against_scoopc_sim_in_a_second_process(tmp_path):
    """Terminal 1: `scoopc sim`; terminal 2: the program over DDS (loopback only)."""
    env = dict(os.environ, ROS_DOMAIN_ID=str(domains.next_domain()), SCOOPC_ROS2_BACKEND="dds")
    env["CYCLONEDDS_URI"] = (
        "<CycloneDDS><Domain><General><Interfaces><NetworkInterface address='127.0.0.1'/></Interfaces>"
        "<AllowMulticast>false</AllowMulticast></General><Discovery><Peers><Peer address='127.0.0.1'/>"
        "</Peers><ParticipantIndex>auto</ParticipantIndex></Discovery></Domain></CycloneDDS>"
    )
    scoopc = [sys.executable, "-m", "scoopc"]
    sim_command, run_command = (
        "scoopc sim samples/first_controller/world.yaml",
        "scoopc run samples/first_controller --robot ros2 --namespace robot1",
    )
    assert sim_command in COMMANDS and run_command in COMMANDS
    with open(tmp_path / "sim.err", "w") as sim_err:
        sim = subprocess.Popen(scoopc + shlex.split(sim_command)[1:], cwd=ROOT, env=env, stderr=sim_err)
        try:
            time.sleep(2.0)
            done = subprocess.run(
                scoopc + shlex.split(run_command)[1:] + ["--duration", "20"],
                cwd=ROOT,
                env=env,
                capture_output=True,
                text=True,
                timeout=120,
            )
        finally:
            sim.terminate()
            sim.wait(timeout=30)
    shown_stop = next(line for line in COMMANDS[run_command] if line.startswith("Stop 1"))
    first = stops(done.stdout)[:1]
    assert first, done.stdout + done.stderr
    got = [int(v) for v in re.findall(r"-?\d+", first[0])[1:]]
    want = [int(v) for v in re.findall(r"-?\d+", shown_stop)[1:]]
    assert all(abs(a - b) <= 3 for a, b in zip(got, want)), (first, shown_stop)
    assert done.stderr.startswith("scoopc: ROS 2 ") and "Traceback" not in done.stderr


def test_the_eiffel_the_tutorial_quotes_is_the_real_code():
    """Every line of an ```eiffel block (but those with `...`) is a line of the library's
    SIMPLE_CONTROLLER or of samples/first_controller, as written there (the guard of `cruise` once
    was quoted inverted)."""
    sources = [ROOT / "stdlib" / "roboscoop" / "controller" / "simple_controller.e", FIRST / "first_controller.e"]
    real = {" ".join(line.split()) for path in sources for line in path.read_text().splitlines()}
    quoted = re.findall(r"```eiffel\n(.*?)```", TUTORIAL.read_text(), re.DOTALL)
    assert len(quoted) >= 4
    for block in quoted:
        for line in block.splitlines():
            line = " ".join(line.split())
            if line and "..." not in line:
                assert line in real, line
