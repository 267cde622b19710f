"""How a message reaches a signaler: always as a call on the signaler's processor; on a bus whose
callbacks come on a thread of its own (DDS, rclpy), a leaf callback runs on that thread when the
processor is idle (no thread switch per message), and the program sees the same readings."""

import threading
from pathlib import Path

from scoopc import cli
from scoopc.kernel.ext import ros_subscriber
from scoopc.robots import ros_messages

PROGRAMS = Path(__file__).parent / "programs"


def odometry(x):
    msg = ros_messages.new("nav_msgs/msg/Odometry")
    msg.pose.pose.position.x = x
    return msg


def run_odometry_program(bus, capsys, monkeypatch):
    """Run tests/robots/programs/odometry on `bus`, fed by a thread of the test (not a processor):
    readings with x = 2 until one was delivered on that thread, then x = 1000. Returns (exit code,
    output, whether the feeder's thread ran a delivery, threads that ran deliveries)."""
    threads = []
    real_deliver = ros_subscriber.deliver

    def deliver(listener, link):
        threads.append(threading.get_ident())
        real_deliver(listener, link)

    monkeypatch.setattr(ros_subscriber, "deliver", deliver)
    fed_here = threading.Event()

    def feed():
        assert bus.wait_for_subscriber("/odom", 30)
        for _ in range(500):
            bus.publish("/odom", odometry(2.0))
            if threading.get_ident() in threads:
                fed_here.set()
                break
            threading.Event().wait(0.002)
        bus.publish("/odom", odometry(1000.0))

    feeder = threading.Thread(target=feed, daemon=True)
    feeder.start()
    code = cli.main(["run", str(PROGRAMS / "odometry"), "--robot", "none"])
    feeder.join(10)
    out, err = capsys.readouterr()
    return code, out + err, fed_here.is_set(), set(threads) - {feeder.ident}


def test_on_a_bus_with_its_own_thread_a_leaf_callback_runs_there(bus, capsys, monkeypatch):
    bus.own_thread_callbacks = True
    code, out, fed_here, _ = run_odometry_program(bus, capsys, monkeypatch)
    assert code == 0, out
    assert fed_here
    assert "past " in out and "last 1000 " in out  # past: 2 or already 1000


def test_on_the_in_process_bus_deliveries_go_to_the_processors_thread(bus, capsys, monkeypatch):
    code, out, fed_here, others = run_odometry_program(bus, capsys, monkeypatch)
    assert code == 0, out
    assert not fed_here and others  # a worker ran every delivery
    assert "past " in out and "last 1000 " in out  # past: 2 or already 1000
