"""ROS 2 actions as rcl_action makes them over rmw_cyclonedds_cpp, for the tests: a twin action
server and client on the twin node of tests/robots/rmw_twin.py, and a stand-in Nav2 server."""

from __future__ import annotations

import json
import threading
import time

from cyclonedds.qos import Policy, Qos
from cyclonedds.util import duration
from rmw_twin import LATER, STORES, Node, Publisher, Subscription, new_message

#: `.action` definitions the twin knows: ros-navigation/navigation2 nav2_msgs (branch humble, branch
#: jazzy; Lyrical taken from main as of 2026-05-22) and ros2/example_interfaces
_POSE_GOAL = "geometry_msgs/PoseStamped pose\nstring behavior_tree"
_NAV_FEEDBACK = (
    "geometry_msgs/PoseStamped current_pose\nbuiltin_interfaces/Duration navigation_time\n"
    "builtin_interfaces/Duration estimated_time_remaining\nint16 number_of_recoveries\nfloat32 distance_remaining"
)
ACTIONS = {
    ("nav2_msgs/action/NavigateToPose", "humble"): (_POSE_GOAL, "std_msgs/Empty result", _NAV_FEEDBACK),
    ("nav2_msgs/action/NavigateToPose", "jazzy"): (
        _POSE_GOAL,
        "uint16 NONE=0\nuint16 error_code\nstring error_msg",
        _NAV_FEEDBACK,
    ),
    ("nav2_msgs/action/NavigateToPose", "lyrical"): (
        _POSE_GOAL,
        "uint16 NONE=0\nuint16 UNKNOWN=9000\nuint16 FAILED_TO_LOAD_BEHAVIOR_TREE=9001\nuint16 TF_ERROR=9002\n"
        "uint16 TIMEOUT=9003\nuint16 error_code\nstring error_msg",
        _NAV_FEEDBACK + "\nfloat32 position_tracking_error\nfloat32 heading_tracking_error",
    ),
    **{
        ("example_interfaces/action/Fibonacci", d): ("int32 order", "int32[] sequence", "int32[] sequence")
        for d in STORES
    },
}


def register_action(node: Node, actiontype: str) -> None:
    """The action's types in the node's store, as rosidl's Action derives them
    (rosidl_parser/definition.py): Goal, Result, Feedback, SendGoal_Request {goal_id, goal},
    SendGoal_Response {accepted, stamp}, GetResult_Request {goal_id}, GetResult_Response
    {status, result}, FeedbackMessage {goal_id, feedback}."""
    from rosbags.typesys import get_types_from_msg

    package, _, short = actiontype.split("/")
    goal, result, feedback = ACTIONS[(actiontype, node.distro)]
    texts = {
        "Goal": goal,
        "Result": result,
        "Feedback": feedback,
        "SendGoal_Request": f"unique_identifier_msgs/UUID goal_id\n{package}/{short}_Goal goal",
        "SendGoal_Response": "bool accepted\nbuiltin_interfaces/Time stamp",
        "GetResult_Request": "unique_identifier_msgs/UUID goal_id",
        "GetResult_Response": f"int8 status\n{package}/{short}_Result result",
        "FeedbackMessage": f"unique_identifier_msgs/UUID goal_id\n{package}/{short}_Feedback feedback",
    }
    found = {}
    for suffix, text in texts.items():
        for key, value in get_types_from_msg(text, f"{package}/msg/{short}_{suffix}").items():
            fields = [
                (
                    n,
                    (k, d.replace(f"{package}/msg/{short}_", f"{package}/action/{short}_"))
                    if isinstance(d, str)
                    else (k, d),
                )
                for n, (k, d) in value[1]
            ]
            found[key.replace("/msg/", "/action/") if key.endswith(f"{short}_{suffix}") else key] = (value[0], fields)
    node.store.register(found)


def _status_qos(node: Node, typename: str) -> Qos:
    """rcl_action_qos_profile_status_default (rcl_action/default_qos.h) through create_readwrite_qos:
    keep last 1, reliable, transient local (with Cyclone's durability service), automatic liveliness."""
    history = Policy.History.KeepLast(1)
    policies = [
        Policy.WriterDataLifecycle(autodispose=False),
        history,
        Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
        Policy.Durability.TransientLocal,
        Policy.DurabilityService(
            cleanup_delay=0, history=history, max_samples=-1, max_instances=-1, max_samples_per_instance=-1
        ),
        Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
    ]
    if node.distro != "humble":
        policies.append(Policy.Userdata(data=f"typehash={node.store.hash_rihs01(typename)};".encode()))
    return Qos(*policies)


def _uuid_msg(store, raw: bytes):
    import numpy as np

    return new_message(store, "unique_identifier_msgs/msg/UUID", uuid=np.frombuffer(raw, dtype=np.uint8).copy())


class TwinGoal:
    """A goal on the twin's action server: `goal`, `id`, `status`, `cancel_requested`."""

    def __init__(self, server, goal_id: bytes, goal, stamp):
        self.server, self.id, self.goal, self.stamp = server, goal_id, goal, stamp
        self.status, self.result, self.asking = 2, None, []  # executing at once (rclpy's default)

    @property
    def cancel_requested(self) -> bool:
        return self.status == 3

    def publish_feedback(self, **fields):
        server = self.server
        feedback = new_message(server.node.store, server.types["Feedback"], **fields)
        server.feedback.publish(
            new_message(
                server.node.store,
                server.types["FeedbackMessage"],
                goal_id=_uuid_msg(server.node.store, self.id),
                feedback=feedback,
            )
        )

    def finish(self, status: int, **fields):
        """4 succeeded, 5 canceled, 6 aborted; the result's fields."""
        server = self.server
        with server.lock:
            self.status = status
            self.result = new_message(
                server.node.store,
                server.types["GetResult_Response"],
                status=status,
                result=new_message(server.node.store, server.types["Result"], **fields),
            )
            asking, self.asking = self.asking, []
        server.publish_status()
        for each in asking:
            server.get_result.reply(each, self.result)


class TwinActionServer:
    """An action server as rcl_action makes one on rmw_cyclonedds_cpp (rcl_action/names.c,
    action_server.c, default_qos.h): three services `<name>/_action/send_goal|cancel_goal|get_result`,
    the feedback topic (ROS's default QoS) and the status topic (transient local, keep last 1).
    `execute(goal)` runs on a thread of its own for each accepted goal (every goal is accepted);
    every cancel request of an executing goal is accepted."""

    def __init__(self, node: Node, actiontype: str, name: str, execute):
        register_action(node, actiontype)
        self.node, self.name, self.execute = node, name, execute
        self.types = {
            s: f"{actiontype}_{s}"
            for s in ("Goal", "Result", "Feedback", "FeedbackMessage", "GetResult_Response", "SendGoal_Response")
        }
        self.lock = threading.RLock()
        self.goals: dict = {}
        self.events: list = []  # ("goal", id), ("cancel", id), ...
        prefix = f"{name}/_action/"
        self.send_goal = node.create_service(f"{actiontype}_SendGoal", prefix + "send_goal", self._send_goal)
        self.cancel_goal = node.create_service("action_msgs/srv/CancelGoal", prefix + "cancel_goal", self._cancel)
        self.get_result = node.create_service(f"{actiontype}_GetResult", prefix + "get_result", self._get_result)
        self.feedback = node.create_publisher(self.types["FeedbackMessage"], prefix + "feedback")
        status_type = "action_msgs/msg/GoalStatusArray"
        self.status = Publisher(node, status_type, prefix + "status", 1, qos=_status_qos(node, status_type))
        self.publish_status()

    def publish_status(self):
        store = self.node.store
        with self.lock:
            entries = [
                new_message(
                    store,
                    "action_msgs/msg/GoalStatus",
                    goal_info=new_message(
                        store, "action_msgs/msg/GoalInfo", goal_id=_uuid_msg(store, g.id), stamp=g.stamp
                    ),
                    status=g.status,
                )
                for g in self.goals.values()
            ]
            self.status.publish(new_message(store, "action_msgs/msg/GoalStatusArray", status_list=entries))

    def _send_goal(self, request):
        store = self.node.store
        now = time.time()
        stamp = new_message(store, "builtin_interfaces/msg/Time", sec=int(now), nanosec=int((now % 1) * 1e9))
        goal = TwinGoal(self, bytes(request.goal_id.uuid), request.goal, stamp)
        with self.lock:
            self.goals[goal.id] = goal
            self.events.append(("goal", goal.id))
        self.publish_status()
        threading.Thread(target=self.execute, args=(goal,), daemon=True).start()
        return new_message(store, self.types["SendGoal_Response"], accepted=True, stamp=stamp)

    def _cancel(self, request):
        wanted = bytes(request.goal_info.goal_id.uuid)
        with self.lock:
            self.events.append(("cancel", wanted))
            goal = self.goals.get(wanted)
            code = 2 if goal is None else 3 if goal.status not in (1, 2) else 0
            if code == 0:
                goal.status = 3
        self.publish_status()
        infos = [] if code else [request.goal_info]
        return new_message(
            self.node.store, "action_msgs/srv/CancelGoal_Response", return_code=code, goals_canceling=infos
        )

    def _get_result(self, request):
        with self.lock:
            goal = self.goals.get(bytes(request.goal_id.uuid))
            if goal is not None and goal.result is None:
                goal.asking.append(self.get_result.asking)
                return LATER
        if goal is None:
            return new_message(self.node.store, self.types["GetResult_Response"], status=0)
        return goal.result


class TwinActionClient:
    """An action client as rcl_action makes one (rclpy's ActionClient's calls, blocking)."""

    def __init__(self, node: Node, actiontype: str, name: str):
        register_action(node, actiontype)
        self.node, self.actiontype = node, actiontype
        prefix = f"{name}/_action/"
        self.send_goal_end = node.create_client(f"{actiontype}_SendGoal", prefix + "send_goal")
        self.cancel_end = node.create_client("action_msgs/srv/CancelGoal", prefix + "cancel_goal")
        self.result_end = node.create_client(f"{actiontype}_GetResult", prefix + "get_result")
        self.feedback = node.create_subscription(f"{actiontype}_FeedbackMessage", prefix + "feedback")
        status_type = "action_msgs/msg/GoalStatusArray"
        self.status = Subscription(node, status_type, prefix + "status", 1, qos=_status_qos(node, status_type))

    def send_goal(self, timeout=30.0, **fields) -> bytes:
        """Send a goal (its fields); its id once accepted (AssertionError if rejected). Waits first
        until the server's feedback and status writers matched (no early feedback missed)."""
        import uuid

        deadline = time.monotonic() + timeout
        while not (self.feedback.matched() and self.status.matched()):
            assert time.monotonic() < deadline, "no action server"
            time.sleep(0.005)
        store = self.node.store
        goal_id = uuid.uuid4().bytes
        goal = new_message(store, f"{self.actiontype}_Goal", **fields)
        request = self.send_goal_end.new_request(goal_id=_uuid_msg(store, goal_id), goal=goal)
        assert self.send_goal_end.call(request, timeout).accepted
        return goal_id

    def result(self, goal_id: bytes, timeout=30.0):
        """The GetResult response (status, result) of a goal, waiting until it ended."""
        return self.result_end.call(self.result_end.new_request(goal_id=_uuid_msg(self.node.store, goal_id)), timeout)

    def cancel(self, goal_id: bytes, timeout=30.0):
        store = self.node.store
        info = new_message(store, "action_msgs/msg/GoalInfo", goal_id=_uuid_msg(store, goal_id))
        return self.cancel_end.call(self.cancel_end.new_request(goal_info=info), timeout)

    def feedback_of(self, goal_id: bytes, count: int = 0, timeout: float = 30.0) -> list:
        """The feedback of a goal received so far; with `count`, once that many came (or at
        `timeout`): the result (a service) can overtake feedback (a topic) on the way."""
        deadline = time.monotonic() + timeout
        while True:
            found = [m.feedback for m in list(self.feedback.messages) if bytes(m.goal_id.uuid) == goal_id]
            if len(found) >= count or time.monotonic() >= deadline:
                return found
            time.sleep(0.005)

    def statuses_of(self, goal_id: bytes) -> list:
        """Each status the status topic said for the goal, in order, repeats left out."""
        seen = []
        for array in list(self.status.messages):
            for entry in array.status_list:
                if bytes(entry.goal_info.goal_id.uuid) == goal_id and (not seen or seen[-1] != entry.status):
                    seen.append(int(entry.status))
        return seen


def navigate_server(node: Node, steps: int, period: float) -> TwinActionServer:
    """A stand-in of Nav2's bt_navigator: /navigate_to_pose accepts every goal, publishes `steps`
    feedback messages `period` s apart (distance_remaining shrinking to 0), then succeeds; a
    cancel request ends the goal CANCELED at the next step. Each event is a JSON line."""

    def execute(goal):
        position = goal.goal.pose.pose.position
        print(
            json.dumps({"goal": [float(position.x), float(position.y)], "frame": goal.goal.pose.header.frame_id}),
            flush=True,
        )
        distance = (float(position.x) ** 2 + float(position.y) ** 2) ** 0.5
        for step in range(steps):
            if goal.cancel_requested:
                goal.finish(5)
                print(json.dumps({"canceled": step}), flush=True)
                return
            goal.publish_feedback(distance_remaining=distance * (1 - (step + 1) / steps))
            time.sleep(period)
        goal.finish(4)
        print(json.dumps({"succeeded": steps}), flush=True)

    return TwinActionServer(node, "nav2_msgs/action/NavigateToPose", "/navigate_to_pose", execute)
