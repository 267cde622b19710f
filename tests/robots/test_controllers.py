"""Roboscoop controllers (stdlib/roboscoop/controller/): CANCELLABLE_CONTROL_LOOP and
SIMPLE_CONTROLLER, run in-process with `scoopc run --virtual-clock` against the bus."""

import threading
from pathlib import Path

from scoopc import cli
from scoopc.robots import ros_messages

PROGRAMS = Path(__file__).parent / "programs"


def run(capsys, name):
    code = cli.main(["run", str(PROGRAMS / name), "--virtual-clock", "--robot", "none"])
    out, err = capsys.readouterr()
    return code, out, err


def range_msg(value, max_range=0.14):
    return ros_messages.new("sensor_msgs/msg/Range", range=value, min_range=0.0, max_range=max_range)


def test_cancellable_loop_runs_at_its_period_and_never_after_the_stop(capsys):
    code, out, err = run(capsys, "cancellable")
    assert (code, err) == (0, "")
    iterations, after_stop, elapsed = out.splitlines()
    words = iterations.split()
    assert words[0] == "iterations"
    at_stop, final, steps = map(int, words[1:])
    assert 9 <= at_stop <= 12, out  # 100 ms period, stopped after 1 s of virtual time
    assert at_stop == final == steps, out  # nothing ran during the second after the stop
    assert after_stop == "after_stop False"
    assert abs(float(elapsed.split()[1]) - 1.0) < 0.15


def test_simple_controller_goes_straight_turns_and_stops(bus, capsys):
    commands, lock = [], threading.Lock()
    phase = {"n": 0}
    wake = threading.Event()

    def on_cmd(msg):
        with lock:
            commands.append((msg.linear.x, msg.angular.z, phase["n"]))
        wake.set()

    def seen(pred):
        with lock:
            return any(pred(v, w, n) for v, w, n in commands)

    def wait_for(pred, timeout=8):
        while not seen(pred):
            if not wake.wait(timeout):
                return False
            wake.clear()
        return True

    bus.subscribe("/cmd_vel", on_cmd)
    results = {}

    def drive_the_sensors():
        assert bus.wait_for_subscriber("/ground/right", 30)
        results["straight"] = wait_for(lambda v, w, n: n == 0 and v > 0 and w == 0)
        phase["n"] = 1
        bus.publish("/proximity/left", range_msg(0.03))  # obstacle on the left
        results["right_turn"] = wait_for(lambda v, w, n: n == 1 and v == 0 and w < 0)
        phase["n"] = 2
        bus.publish("/proximity/left", range_msg(float("inf")))  # left clear, right blocked
        bus.publish("/proximity/right", range_msg(0.02))
        results["left_turn"] = wait_for(lambda v, w, n: n == 2 and v == 0 and w > 0)
        phase["n"] = 3
        bus.publish("/proximity/right", range_msg(0.5))  # out of range: clear
        results["straight_again"] = wait_for(lambda v, w, n: n == 3 and v > 0 and w == 0)
        phase["n"] = 4
        bus.publish("/ground/right", range_msg(0.2, max_range=0.1))  # a hole: the program stops
        results["done"] = True

    thread = threading.Thread(target=drive_the_sensors, daemon=True)
    thread.start()
    code, out, err = run(capsys, "simple_controller")
    thread.join(10)
    assert (code, out, err) == (0, "finished\n", "")
    assert results == {"straight": True, "right_turn": True, "left_turn": True, "straight_again": True, "done": True}
    assert commands[0][:2] == (0.1, 0.0)
    assert all(w in (0.0, 0.5, -0.5) and v in (0.0, 0.1) for v, w, _ in commands)
    assert commands[-1][:2] == (0.0, 0.0)  # zero after the stop
    zeros = [i for i, (v, w, _) in enumerate(commands) if v == 0 and w == 0]
    assert zeros == [len(commands) - 1]  # and nothing after it
    assert bus.subscriber_count("/proximity/left") == 0
