"""Simulated sensors and the ROS 2 messages they produce (rosbags type store dataclasses).

Proximity (Thymio II-like, 7 horizontal IR), ground (2 downward IR), laser scanner, odometry, battery.
Range conventions (REP 117): a sensor that detects nothing reports +inf.
Ground sensors: 0.01 m over the floor, +inf over a hole (nothing reflects).
"""

import math

import numpy as np

from ..ros_messages import new
from .world import ray_cast


def stamp(t_ns):
    return new("builtin_interfaces/msg/Time", sec=int(t_ns // 1_000_000_000), nanosec=int(t_ns % 1_000_000_000))


def header(t_ns, frame):
    return new("std_msgs/msg/Header", stamp=stamp(t_ns), frame_id=frame)


def quaternion_yaw(theta):
    return new("geometry_msgs/msg/Quaternion", x=0.0, y=0.0, z=math.sin(theta / 2), w=math.cos(theta / 2))


# ---- Thymio proximity ------------------------------------------------------------------------------

PROXIMITY = {  # name: (mount angle on the body, beam direction), radians in the robot frame
    "left": (math.radians(40), math.radians(40)),
    "center_left": (math.radians(20), math.radians(20)),
    "center": (0.0, 0.0),
    "center_right": (math.radians(-20), math.radians(-20)),
    "right": (math.radians(-40), math.radians(-40)),
    "rear_left": (math.radians(150), math.pi),
    "rear_right": (math.radians(-150), math.pi),
}
PROXIMITY_RANGE = 0.12
PROXIMITY_MIN = 0.0
PROXIMITY_FOV = 0.3
GROUND = {"left": (0.05, 0.02), "right": (0.05, -0.02)}  # mount points (forward, left) in the robot frame
GROUND_FLOOR = 0.01
GROUND_MAX = 0.03


def obstacles_for(robot, robots):
    """Circles (x, y, r) of the other robots, seen by this one's range sensors."""
    return np.array([[o.x, o.y, o.spec.radius] for o in robots if o is not robot]).reshape(-1, 3)


def proximity_ranges(robot, world, robots):
    """{name: distance from the body surface to the nearest obstacle along the beam, or inf}."""
    r = robot.spec.radius
    names = list(PROXIMITY)
    origins, dirs = [], []
    for n in names:
        mount, beam = PROXIMITY[n]
        origins.append(robot.to_world(r * math.cos(mount), r * math.sin(mount)))
        a = robot.theta + beam
        dirs.append((math.cos(a), math.sin(a)))
    d = ray_cast(np.array(origins), np.array(dirs), world.segments, PROXIMITY_RANGE, obstacles_for(robot, robots))
    return dict(zip(names, d.tolist()))


def proximity_msg(robot, name, value, t_ns):
    ns = robot.namespace
    return new(
        "sensor_msgs/msg/Range",
        header=header(t_ns, f"{ns}/proximity_{name}_link"),
        radiation_type=1,
        field_of_view=PROXIMITY_FOV,
        min_range=PROXIMITY_MIN,
        max_range=PROXIMITY_RANGE,
        range=float(value),
    )


def ground_ranges(robot, world):
    pts = np.array([robot.to_world(*GROUND[n]) for n in GROUND])
    holes = (
        world.in_hole(pts) | (pts[:, 0] < 0) | (pts[:, 1] < 0) | (pts[:, 0] > world.width) | (pts[:, 1] > world.height)
    )
    return {n: (math.inf if h else GROUND_FLOOR) for n, h in zip(GROUND, holes.tolist())}


def ground_msg(robot, name, value, t_ns):
    return new(
        "sensor_msgs/msg/Range",
        header=header(t_ns, f"{robot.namespace}/ground_{name}_link"),
        radiation_type=1,
        field_of_view=0.1,
        min_range=0.0,
        max_range=GROUND_MAX,
        range=float(value),
    )


# ---- laser -----------------------------------------------------------------------------------------


def laser_angles(spec):
    full = abs(spec.fov - 2 * math.pi) < 1e-9
    inc = spec.fov / spec.beams if full else spec.fov / max(1, spec.beams - 1)
    start = -math.pi if full else -spec.fov / 2
    return start, inc, start + inc * np.arange(spec.beams)


def laser_ranges(robot, world, robots):
    spec = robot.spec.laser
    _, _, angles = laser_angles(spec)
    a = robot.theta + angles
    dirs = np.stack([np.cos(a), np.sin(a)], axis=1)
    origins = np.tile([robot.x, robot.y], (len(a), 1))
    return ray_cast(origins, dirs, world.segments, spec.range, obstacles_for(robot, robots))


def scan_msg(robot, ranges, t_ns):
    spec = robot.spec.laser
    start, inc, angles = laser_angles(spec)
    return new(
        "sensor_msgs/msg/LaserScan",
        header=header(t_ns, f"{robot.namespace}/laser_link"),
        angle_min=float(start),
        angle_max=float(angles[-1]),
        angle_increment=float(inc),
        time_increment=0.0,
        scan_time=1.0 / spec.rate,
        range_min=0.0,
        range_max=float(spec.range),
        ranges=np.asarray(ranges, dtype=np.float32),
        intensities=np.zeros(0, dtype=np.float32),
    )


# ---- odometry, battery, clock ----------------------------------------------------------------------


def odom_msg(robot, t_ns):
    ns = robot.namespace
    pose = new(
        "geometry_msgs/msg/Pose",
        position=new("geometry_msgs/msg/Point", x=robot.x, y=robot.y, z=0.0),
        orientation=quaternion_yaw(robot.theta),
    )
    twist = new(
        "geometry_msgs/msg/Twist",
        linear=new("geometry_msgs/msg/Vector3", x=robot.v, y=0.0, z=0.0),
        angular=new("geometry_msgs/msg/Vector3", x=0.0, y=0.0, z=robot.w),
    )
    return new(
        "nav_msgs/msg/Odometry",
        header=header(t_ns, f"{ns}/odom"),
        child_frame_id=f"{ns}/base_link",
        pose=new("geometry_msgs/msg/PoseWithCovariance", pose=pose),
        twist=new("geometry_msgs/msg/TwistWithCovariance", twist=twist),
    )


def battery_msg(robot, t_ns):
    b = robot.spec.battery
    status = 1 if robot.charging else 2  # CHARGING / DISCHARGING
    if robot.charging and robot.battery >= 1.0:
        status = 4  # FULL
    return new(
        "sensor_msgs/msg/BatteryState",
        header=header(t_ns, f"{robot.namespace}/base_link"),
        voltage=float(3.3 + 0.9 * robot.battery),
        temperature=math.nan,
        current=math.nan,
        charge=float(b.capacity * robot.battery),
        capacity=float(b.capacity),
        design_capacity=float(b.capacity),
        percentage=float(robot.battery),
        power_supply_status=status,
        power_supply_health=3 if robot.empty else 1,
        power_supply_technology=2,
        present=True,
    )


def clock_msg(t_ns):
    return new("rosgraph_msgs/msg/Clock", clock=stamp(t_ns))
