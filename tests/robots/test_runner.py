"""`scoopc run` with a robot: the in-process simulator stepped on the runtime's clock, the run's
end (the program's end or the world's duration), the safety stop, ROBOT_ENVIRONMENT, and the
command line's robot options."""

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from scoopc import cli

from harness import run_on_simulator

PROGRAMS = Path(__file__).parent / "programs"


def test_a_program_that_ends_ends_the_simulation(capsys):
    result = run_on_simulator(PROGRAMS / "run_forward")
    out, err = capsys.readouterr()
    assert result.status == 0, err
    assert result.stopped_by == "program"
    robot = result.sim.robot()
    lines = out.splitlines()
    assert lines[0] == "robot /robot1 of 1 simulated True goal 4.2999999999999998,4.2999999999999998"
    stopped_at = float(lines[1].split()[-1])
    assert 2.0 <= stopped_at < 2.05  # 0.1 m/s, checked every 100 ms of simulated time
    assert abs(robot.x - stopped_at) < 0.02 and robot.cmd == (0.0, 0.0)
    # from 0.6 m to 2.0 m at 0.1 m/s: 14 s; the run ends within a few steps of the program
    assert 14.0 <= result.sim.time <= 14.5
    assert "scoopc: simulated 14." in err and "(the program ended)" in err


def test_the_duration_asked_for_stops_a_program_that_runs_on(capsys):
    result = run_on_simulator(PROGRAMS / "run_forever", duration=12)
    out, err = capsys.readouterr()
    assert result.status == 0, err
    assert result.stopped_by == "duration"
    assert result.sim.time == pytest.approx(12.0)
    assert result.sim.robot().x == pytest.approx(0.6 + 0.1 * 12, abs=0.03)
    assert "(the duration asked for)" in err


def test_runs_on_the_virtual_clock_are_repeatable(capsys):
    first = run_on_simulator(PROGRAMS / "run_forever", duration=5).sim.trajectory()
    second = run_on_simulator(PROGRAMS / "run_forever", duration=5).sim.trajectory()
    capsys.readouterr()
    assert (first == second).all()


def test_a_failing_program_leaves_the_robot_stopped(capsys):
    result = run_on_simulator(PROGRAMS / "run_crash")
    out, err = capsys.readouterr()
    assert result.status == 3
    assert "check violated: `never_here`" in err and "CRASH.make" in err
    assert result.stopped_topics == ["/robot1/cmd_vel"]
    robot = result.sim.robot()
    assert robot.cmd == (0.0, 0.0)  # the zero velocity came over the bus
    assert robot.cmd_count == 2 and robot.x > 0.62  # it had moved (until the 0.5 s watchdog), then the stop


def test_robot_environment_reads_the_world_beside_the_program(capsys):
    result = run_on_simulator(PROGRAMS / "run_world")
    out, err = capsys.readouterr()
    assert result.status == 0, err
    assert out.splitlines() == [
        "robot /alpha (1 of 2)",
        "/alpha 0.14000000000000001 3",
        "/beta 0.5 2",
        "simulated True ros2 False",
        "goal True 2.5 1.5",
        "station True 0.29999999999999999 1.7 0.20000000000000001",
        "duration 20",
    ]


def test_namespace_goal_and_duration_options(capsys):
    result = run_on_simulator(PROGRAMS / "run_world", namespace="beta", goal=(1.0, -2.0), duration=3)
    out, _ = capsys.readouterr()
    lines = out.splitlines()
    assert result.status == 0 and result.stopped_by == "program"
    assert lines[0] == "robot /beta (2 of 2)"
    assert lines[4] == "goal True 1 -2"
    assert lines[6] == "duration 3"


def test_cli_writes_the_trajectory_png(tmp_path, capsys, monkeypatch):
    """An unnamed picture goes to runs/<program>/<n>/, one folder per run (none replaces another's);
    a named one is written where named, and replacing an existing file says so."""
    monkeypatch.chdir(tmp_path)
    for n in (1, 2):
        assert cli.main(["run", str(PROGRAMS / "run_forward")]) == 0
        err = capsys.readouterr().err
        picture = tmp_path / "runs" / "forward" / str(n) / "forward.png"
        assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert err.splitlines()[-1] == f"scoopc: trajectory written to runs/forward/{n}/forward.png"
    named = tmp_path / "x.png"
    assert cli.main(["run", str(PROGRAMS / "run_forward"), "--png", str(named)]) == 0
    assert named.exists() and "replacing" not in capsys.readouterr().err
    assert cli.main(["run", str(PROGRAMS / "run_forward"), "--png", str(named)]) == 0
    assert f"scoopc: replacing the existing file {named}" in capsys.readouterr().err.splitlines()


@pytest.mark.parametrize(
    "options, message",
    [
        (["--world", "/nonexistent/world.yaml"], "no world file /nonexistent/world.yaml"),
        (["--namespace", "gamma"], "the world has no robot with namespace '/gamma' (it has /alpha, /beta)"),
    ],
)
def test_robot_usage_errors(options, message, capsys):
    assert cli.main(["run", str(PROGRAMS / "run_world"), "--no-png", *options]) == 2
    assert f"scoopc: error: {message}" in capsys.readouterr().err


def test_a_malformed_world_is_reported(tmp_path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text("robots:\n  - {kind: tank}\n")
    assert cli.main(["run", str(PROGRAMS / "run_world"), "--no-png", "--world", str(bad)]) == 2
    assert f"scoopc: error: {bad}:2:12: robots[0].kind: must be one of thymio" in capsys.readouterr().err


def test_programs_without_roboscoop_get_no_robot(capsys):
    program = Path(__file__).parents[1] / "golden" / "boolean_ops"
    assert cli.main(["run", str(program)]) == 0
    assert "scoopc: simulated" not in capsys.readouterr().err


@pytest.mark.parametrize("name", ["SIGINT", "SIGTERM", "SIGHUP"])
def test_a_stop_signal_stops_the_robot_and_finishes_the_run(tmp_path, name):
    """Whatever signal ends a run, the robot's last command is a zero velocity, the recording and the
    picture are written, and the exit status is 128 + the signal's number."""
    from scoopc.robots import record

    number = getattr(signal, name)
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "scoopc",
            "run",
            str(PROGRAMS / "drive_until_stopped"),
            "--realtime",
            "--record",
            "run.mcap",
            "--png",
            "run.png",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        cwd=tmp_path,
    )
    try:
        assert proc.stdout.readline() == "moving\n"  # velocity commands have reached the robot
        proc.send_signal(number)
        out, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 128 + number, err
    assert f"scoopc: stopped by {name}" in err and f"(stopped by {name})" in err and "Traceback" not in err
    commands = [msg.linear.x for topic, _, msg in record.read(tmp_path / "run.mcap") if topic == "/robot1/cmd_vel"]
    assert 0.1 in commands and commands[-1] == 0.0
    assert (tmp_path / "run.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_record_and_gif_of_a_simulated_run(tmp_path, capsys):
    from scoopc.robots import record

    mcap, gif = tmp_path / "run.mcap", tmp_path / "run.gif"
    result = run_on_simulator(PROGRAMS / "run_forward", record=mcap, gif=gif)
    err = capsys.readouterr().err
    assert result.status == 0, err
    assert f"recording written to {mcap}" in err and f"animation written to {gif}" in err
    assert gif.read_bytes()[:6] == b"GIF89a"
    messages = record.read(mcap)
    topics = {topic for topic, _, _ in messages}
    assert {"/robot1/cmd_vel", "/robot1/odom", "/clock"} <= topics
    commands = [(t, m) for topic, t, m in messages if topic == "/robot1/cmd_vel"]
    # cmd_vel has no stamp: it is logged at the simulated time it was sent, the last one the stop
    assert commands[0][0] <= 200_000_000 and commands[-1][1].linear.x == 0.0
    assert 14.0e9 <= commands[-1][0] <= 14.5e9
    times = [t for _, t, _ in messages]
    assert times == sorted(times)


def test_a_recording_that_cannot_be_written_is_a_usage_error(capsys):
    assert cli.main(["run", str(PROGRAMS / "run_forward"), "--no-png", "--record", "/nonexistent/x.mcap"]) == 2
    assert "scoopc: error: cannot record to /nonexistent/x.mcap" in capsys.readouterr().err
