"""The simulator core: kinematics, collisions, holes, watchdog, sensors, battery, determinism, rendering."""

import glob
import math
import os

import numpy as np
import pytest

from scoopc.robots.bus import Bus
from scoopc.robots.sim import Simulator, World
from scoopc.robots.sim.sensors import new

WORLDS = os.path.join(os.path.dirname(__file__), "..", "..", "samples", "worlds")


def twist(v, w):
    return new(
        "geometry_msgs/msg/Twist",
        linear=new("geometry_msgs/msg/Vector3", x=float(v)),
        angular=new("geometry_msgs/msg/Vector3", z=float(w)),
    )


def make(kind="thymio", start=(0.5, 0.5, 0.0), **world):
    robot = {"name": "r", "namespace": "robot1", "kind": kind, "start": list(start)}
    robot.update(world.pop("robot", {}))
    data = {"size": [4.0, 4.0], "duration": 30, "seed": 0, "robots": [robot]}
    data.update(world)
    bus = Bus()
    return Simulator(World.from_dict(data), bus), bus


def drive(sim, bus, v, w, seconds, ns="robot1"):
    """Send cmd_vel every 0.1 s (faster than the watchdog) for `seconds` of simulated time."""
    end = sim.time + seconds
    while sim.time < end - 1e-9:
        bus.publish(f"/{ns}/cmd_vel", twist(v, w))
        sim.run_until(min(end, sim.time + 0.1))


def latest(bus, topic):
    box = []
    bus.subscribe(topic, box.append)
    return box


def test_straight_line():
    sim, bus = make(start=(0.5, 1.0, 0.0))
    drive(sim, bus, 0.1, 0.0, 2.0)
    r = sim.robot()
    assert r.x == pytest.approx(0.7, abs=1e-6) and r.y == pytest.approx(1.0, abs=1e-9)
    assert sim.time == pytest.approx(2.0)


def test_turn_in_place_and_limits():
    sim, bus = make(start=(2.0, 2.0, 0.0))
    drive(sim, bus, 0.0, 1.0, math.pi / 2)
    r = sim.robot()
    assert (r.x, r.y) == (2.0, 2.0)
    assert r.theta == pytest.approx(math.pi / 2, abs=0.011)
    drive(sim, bus, 5.0, 0.0, 1.0)  # clamped to the Thymio's 0.14 m/s
    assert r.y == pytest.approx(2.0 + 0.14, abs=1e-3)


def test_collision_stops_and_is_recorded():
    sim, bus = make(start=(0.5, 1.0, 0.0), boxes=[{"min": [1.0, 0.5], "max": [1.5, 1.5]}])
    drive(sim, bus, 0.14, 0.0, 6.0)
    r = sim.robot()
    assert len(r.collisions) >= 1
    assert r.x <= 1.0 - r.spec.radius + 1e-9 and r.x > 1.0 - r.spec.radius - 0.01
    assert not r.fallen
    drive(sim, bus, -0.1, 0.0, 1.0)  # backing away is allowed
    assert r.x == pytest.approx(1.0 - r.spec.radius - 0.1, abs=0.01)


def test_fall_into_hole():
    sim, bus = make(start=(0.5, 1.0, 0.0), holes=[{"min": [1.0, 0.0], "max": [1.5, 2.0]}])
    drive(sim, bus, 0.14, 0.0, 6.0)
    r = sim.robot()
    assert r.fallen and r.fell_at[1] == pytest.approx(1.0, abs=0.01)
    x = r.x
    drive(sim, bus, 0.14, 0.0, 1.0)
    assert r.x == x


def test_watchdog_stops_after_half_a_second():
    sim, bus = make(start=(0.5, 1.0, 0.0))
    bus.publish("/robot1/cmd_vel", twist(0.1, 0.0))
    sim.run_until(0.45)
    assert sim.robot().v == pytest.approx(0.1)
    sim.run_until(2.0)
    r = sim.robot()
    assert r.v == 0.0 and r.watchdog_stops == [pytest.approx(0.5)]
    assert r.x == pytest.approx(0.5 + 0.1 * 0.49, abs=2e-3)


def test_proximity_sees_wall_at_right_distance():
    # the robot faces a wall at x = 1.0; its front surface is at 0.9 + radius
    sim, bus = make(start=(0.9, 1.0, 0.0), walls=[{"from": [1.0, 0.0], "to": [1.0, 4.0]}])
    center, rear = latest(bus, "/robot1/proximity/center"), latest(bus, "/robot1/proximity/rear_left")
    left = latest(bus, "/robot1/proximity/left")
    sim.run_until(0.1)
    r = sim.robot()
    assert center[-1].__msgtype__ == "sensor_msgs/msg/Range" and center[-1].max_range == pytest.approx(0.12)
    assert center[-1].range == pytest.approx(0.1 - r.spec.radius, abs=1e-5)
    expected_left = (0.1 - r.spec.radius * math.cos(math.radians(40))) / math.cos(math.radians(40))
    assert left[-1].range == pytest.approx(expected_left, abs=1e-5)
    assert rear[-1].range == -1.0  # the Thymio driver's "nothing seen"
    assert len(center) == 2  # at t = 0.05, 0.1 (20 Hz; t = 0 went out before subscribing)


def test_ground_sensors_see_a_hole():
    sim, bus = make(start=(0.9, 1.0, 0.0), holes=[{"min": [1.0, 0.0], "max": [2.0, 2.0]}])
    gl, gr = latest(bus, "/robot1/ground/left"), latest(bus, "/robot1/ground/right")
    sim.run_until(0.05)
    assert gl[-1].range == 0.0 and gr[-1].range == 0.0  # the Thymio driver: 0 over the floor
    drive(sim, bus, 0.1, 0.0, 0.8)  # ground sensors 5 cm ahead of the centre cross x = 1.0
    assert gl[-1].range == 1.0 and gr[-1].range == 1.0  # 1 (beyond max_range) over a hole
    assert not sim.robot().fallen


def test_laser_ranges_in_a_box_world():
    sim, bus = make(
        kind="diff_drive", start=(1.0, 2.0, 0.0), robot={"laser": {"range": 2.0, "beams": 360}}, size=[3.0, 4.0]
    )
    scans = latest(bus, "/robot1/scan")
    sim.run_until(0.1)
    s = scans[-1]
    assert s.__msgtype__ == "sensor_msgs/msg/LaserScan" and len(s.ranges) == 360 and s.range_max == 2.0
    angles = s.angle_min + s.angle_increment * np.arange(360)

    def at(a):
        return s.ranges[int(np.argmin(np.abs(np.angle(np.exp(1j * (angles - a))))))]

    assert at(0.0) == pytest.approx(2.0, abs=1e-4) or math.isinf(at(0.0))  # east wall at exactly 2 m
    assert at(math.pi) == pytest.approx(1.0, abs=1e-4)  # west wall
    assert at(math.pi / 2) == pytest.approx(2.0, abs=1e-4)  # north wall at y = 4
    assert at(-math.pi / 4) == pytest.approx(math.sqrt(2) * 1.0 + 0.0, abs=1e-3) or math.isinf(at(-math.pi / 4))
    assert at(-math.pi / 2) == pytest.approx(2.0, abs=1e-4)  # south wall at y = 0
    assert math.isinf(at(math.radians(30)))  # beyond the 2 m range


def test_odometry_and_clock_messages():
    sim, bus = make(start=(0.5, 1.0, 0.0))
    odom, clock = latest(bus, "/robot1/odom"), latest(bus, "/clock")
    drive(sim, bus, 0.1, 0.0, 1.0)
    o = odom[-1]
    assert o.__msgtype__ == "nav_msgs/msg/Odometry"
    assert o.pose.pose.position.x == pytest.approx(0.6, abs=1e-6) and o.twist.twist.linear.x == pytest.approx(0.1)
    assert (o.header.stamp.sec, o.header.stamp.nanosec) == (1, 0)
    assert len(odom) == 50 and len(clock) == 100  # 50 Hz and every 10 ms step
    assert clock[-1].clock.sec == 1


def test_battery_drains_and_recharges():
    sim, bus = make(
        start=(0.5, 1.0, 0.0),
        charging_station={"position": [2.5, 1.0], "radius": 0.2},
        robot={"battery": {"initial": 0.5, "drain_idle": 0.001, "drain_motion": 0.01, "charge_rate": 0.05}},
    )
    states = latest(bus, "/robot1/battery_state")
    drive(sim, bus, 0.14, 0.0, 10.0)
    r = sim.robot()
    assert r.battery < 0.5 - 0.09
    assert states[-1].__msgtype__ == "sensor_msgs/msg/BatteryState" and states[-1].percentage < 0.42
    drive(sim, bus, 0.14, 0.0, 4.0)  # reaches the station around x = 2.3 .. 2.7
    drive(sim, bus, 0.0, 0.0, 5.0)
    assert r.charging and r.battery > states[0].percentage
    sim.run_until(sim.time + 1.0)
    assert states[-1].power_supply_status == 1  # CHARGING


def test_empty_battery_stops_the_robot():
    sim, bus = make(start=(0.5, 1.0, 0.0), robot={"battery": {"initial": 0.01, "drain_motion": 0.01}})
    drive(sim, bus, 0.1, 0.0, 5.0)
    r = sim.robot()
    assert r.empty and r.v == 0.0 and r.x < 0.5 + 0.1 * 1.5


def test_determinism_same_trajectory():
    def run():
        sim = Simulator(World.load(os.path.join(WORLDS, "cluttered.yaml")), Bus())
        bus = sim.bus
        scans = latest(bus, "/robot1/proximity/center")
        for i in range(200):  # a simple reactive wander, deterministic
            near = scans and scans[-1].range < 0.1
            bus.publish("/robot1/cmd_vel", twist(0.0 if near else 0.12, 1.5 if near else 0.2 * math.sin(i / 7)))
            sim.run_until(sim.time + 0.1)
        return sim.trajectory()

    a, b = run(), run()
    assert a.shape == b.shape and np.array_equal(a, b)


def test_coverage_and_png(tmp_path):
    sim, bus = make(
        start=(0.5, 0.5, 0.0),
        size=[2.0, 2.0],
        holes=[{"min": [1.5, 1.5], "max": [2.0, 2.0]}],
        goal=[1.8, 0.2],
        charging_station=[0.2, 1.8],
    )
    assert sim.coverage() < 0.05
    drive(sim, bus, 0.14, 0.0, 8.0)
    cov = sim.coverage()
    assert 0.05 < cov < 0.5
    out = tmp_path / "run.png"
    labels = sim.render_png(str(out), program="COVERAGE")
    assert labels == [
        f"title: COVERAGE - world world - {sim.time:.1f} s simulated",
        "scale: 0.5 m",
        "r",
        "start",
        "end",
        "hole",
        "charging station",
        "goal",
    ]
    from PIL import Image

    with Image.open(out) as img:
        assert img.size[0] > 100 and img.format == "PNG"


def test_the_picture_labels_obstacles_collisions_and_falls(tmp_path):
    sim, bus = make(
        start=(0.5, 0.3, math.pi / 2),
        boxes=[{"min": [0.3, 1.0], "max": [0.7, 1.2]}],
        holes=[{"min": [2.0, 0.0], "max": [2.5, 4.0]}],
    )
    drive(sim, bus, 0.14, 0.0, 8.0)  # into the box
    sim.robots[0].fell_at = (sim.time, 2.2, 1.0)  # as a fall would leave it
    labels = sim.render_png(str(tmp_path / "run.png"))
    assert labels[0].startswith("title: world world - ") and labels[1].startswith("scale: ")
    assert labels[2:] == ["r", "start", "end", "obstacle", "hole", "collision", "fall"]


def test_two_robots_under_their_namespaces():
    data = {"size": [3, 3], "robots": [{"name": "a", "start": [0.5, 0.5, 0]}, {"name": "b", "start": [0.5, 2.5, 0]}]}
    bus = Bus()
    sim = Simulator(World.from_dict(data), bus)
    bus.publish("/a/cmd_vel", twist(0.1, 0.0))
    sim.run_until(0.3)
    assert sim.robot("a").x > 0.5 and sim.robot("b").x == 0.5


@pytest.mark.parametrize("path", sorted(glob.glob(os.path.join(WORLDS, "*.yaml"))), ids=os.path.basename)
def test_sample_worlds_load(path):
    world = World.load(path)
    sim = Simulator(world, Bus())
    assert world.robots and sim.reachable_grid().sum() > 100
    if os.path.basename(path) in ("open.yaml", "cluttered.yaml", "u_trap.yaml", "corridor.yaml"):
        assert world.goal is not None and world.station is not None


def test_only_topics_someone_hears_are_built():
    bus = Bus()
    sim = Simulator(World.from_dict({"size": [2, 2]}), bus)
    heard = []
    bus.subscribe("/robot1/proximity/center", lambda msg: heard.append("center"))
    sim.run_until(0.1)
    assert heard == ["center", "center"]  # 20 Hz: at 50 and 100 ms
    assert bus.wants("/robot1/proximity/center") and not bus.wants("/robot1/odom")
    tapped = []
    tap = bus.tap(lambda topic, msg: tapped.append(topic))
    sim.run_until(0.2)
    assert {"/clock", "/robot1/odom", "/robot1/ground/left", "/robot1/proximity/left"} <= set(tapped)
    tap.close()
    assert not bus.wants("/robot1/odom")
