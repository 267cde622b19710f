"""ROS 2 actions over DDS, as rcl_action makes them on rmw_cyclonedds_cpp: an `ActionServer` takes
goals, publishes their feedback and status and answers their results; an `ActionClient` sends goals
and follows each through a `ClientGoal` (status, feedback, result, cancel). Both are built on
scoopc.robots.services and belong to a DdsBus (its participant, its node in the ROS graph).

Facts followed (read, never run against ROS 2 here):
* ros2/rcl rcl_action/src/rcl_action/names.c: an action `/a` is the services `/a/_action/send_goal`,
  `/a/_action/cancel_goal`, `/a/_action/get_result` and the topics `/a/_action/feedback`,
  `/a/_action/status`;
* rcl_action/include/rcl_action/default_qos.h and action_server.c
  (rcl_action_server_get_default_options): the services with the services' QoS, the feedback topic
  with ROS's default QoS (reliable, volatile, keep last 10), the status topic reliable, transient
  local, keep last 1; a finished goal is forgotten `result_timeout` (10 s) after the stamp of its
  acceptance (rcl_action_expire_goals);
* ros2/rosidl rosidl_parser/definition.py (class Action): the types `<Action>_SendGoal` (request
  goal_id, goal; response accepted, stamp), `<Action>_GetResult` (request goal_id; response status,
  result), `<Action>_FeedbackMessage` (goal_id, feedback); action_msgs/srv/CancelGoal and
  action_msgs/msg/GoalStatusArray (ros2/rcl_interfaces);
* rcl_action/src/rcl_action/goal_state_machine.c: the goal states and their transitions;
  action_server.c rcl_action_process_cancel_request: which goals a cancel request names;
* ros2/rclpy rclpy/action/client.py and server.py: a goal id is a random UUID; the client takes
  feedback and status by goal id; the server answers a result request when the goal ends (at once
  with STATUS_UNKNOWN for an unknown goal).
"""

from __future__ import annotations

import logging
import threading
import time
import uuid

import numpy as np
from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import GuardCondition, InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from . import cdr, ros_messages
from .dds import dds_topic_name, frame, idl_type
from .services import ServiceClient, ServiceServer, ServiceTimeout

log = logging.getLogger(__name__)

# action_msgs/msg/GoalStatus
UNKNOWN, ACCEPTED, EXECUTING, CANCELING, SUCCEEDED, CANCELED, ABORTED = range(7)
TERMINAL = (SUCCEEDED, CANCELED, ABORTED)
STATUS_NAMES = ("unknown", "accepted", "executing", "canceling", "succeeded", "canceled", "aborted")
# goal_state_machine.c: (state, event) -> state
_TRANSITIONS = {
    (ACCEPTED, "execute"): EXECUTING,
    (ACCEPTED, "cancel"): CANCELING,
    (EXECUTING, "cancel"): CANCELING,
    (EXECUTING, "succeed"): SUCCEEDED,
    (EXECUTING, "abort"): ABORTED,
    (CANCELING, "succeed"): SUCCEEDED,
    (CANCELING, "abort"): ABORTED,
    (CANCELING, "canceled"): CANCELED,
}
# action_msgs/srv/CancelGoal's return codes
CANCEL_NONE, CANCEL_REJECTED, CANCEL_UNKNOWN_GOAL, CANCEL_TERMINATED = range(4)
STATUS_TYPE = "action_msgs/msg/GoalStatusArray"
RESULT_TIMEOUT = 10.0


class ActionError(RuntimeError):
    """A goal event its state does not allow (goal_state_machine.c)."""


def names(action: str) -> dict[str, str]:
    """The services and topics of the action `action` (names.c)."""
    if not action.startswith("/"):
        raise ValueError(f"action names are absolute here: {action!r}")
    return {
        part: f"{action}/_action/{part}" for part in ("send_goal", "cancel_goal", "get_result", "feedback", "status")
    }


def _qos(typename: str, store, distro: str, status: bool) -> Qos:
    """create_readwrite_qos of the status topic's QoS (status) or of ROS's default QoS."""
    history = Policy.History.KeepLast(1 if status else 10)
    policies = [
        Policy.WriterDataLifecycle(autodispose=False),
        history,
        Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
        Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
    ]
    if status:
        policies += [
            Policy.Durability.TransientLocal,
            Policy.DurabilityService(
                cleanup_delay=0, history=history, max_samples=-1, max_instances=-1, max_samples_per_instance=-1
            ),
        ]
    else:
        policies.append(Policy.Durability.Volatile)
    if distro != "humble":
        policies.append(Policy.Userdata(data=f"typehash={store.hash_rihs01(typename)};".encode()))
    return Qos(*policies)


def _stamp(store, seconds: float):
    sec = int(seconds)
    return ros_messages.new(
        "builtin_interfaces/msg/Time", store=store, sec=sec, nanosec=int(round((seconds - sec) * 1e9)) % 10**9
    )


def _seconds(stamp) -> float:
    return int(stamp.sec) + int(stamp.nanosec) * 1e-9


def _uuid(store, raw: bytes):
    return ros_messages.new(
        "unique_identifier_msgs/msg/UUID", store=store, uuid=np.frombuffer(raw, dtype=np.uint8).copy()
    )


def _goal_info(store, goal_id: bytes, stamp: float):
    return ros_messages.new(
        "action_msgs/msg/GoalInfo", store=store, goal_id=_uuid(store, goal_id), stamp=_stamp(store, stamp)
    )


class _Channel:
    """One topic of an action on a DdsBus: its writer, or its reader with a thread calling
    `callback(msg)` for each sample."""

    def __init__(self, bus, topic: str, typename: str, store, status: bool, callback=None):
        self.bus, self.topic, self.typename, self.store, self.callback = bus, topic, typename, store, callback
        self.dds_topic = Topic(bus.participant, dds_topic_name(topic), idl_type(typename, store))
        qos = _qos(typename, store, bus.distro, status)
        self.entity = (DataReader if callback else DataWriter)(bus.participant, self.dds_topic, qos=qos)
        self._closed = False
        self._thread = None
        if callback is not None:
            self.condition = ReadCondition(self.entity, SampleState.NotRead | ViewState.Any | InstanceState.Any)
            self.waitset = WaitSet(bus.participant)
            self.wake = GuardCondition(bus.participant)
            self.waitset.attach(self.condition)
            self.waitset.attach(self.wake)
            self._thread = threading.Thread(target=self._run, name=f"action topic {topic}", daemon=True)
            self._thread.start()
        bus.owned.append(self)
        bus._entities_changed()

    def guids(self) -> tuple[list, list]:
        return ([self.entity.guid], []) if self.callback else ([], [self.entity.guid])

    def matched(self) -> int:
        """Endpoints of other participants matched with this one."""
        if self.callback:
            return self.entity.get_subscription_matched_status().current_count
        return self.entity.get_publication_matched_status().current_count

    def write(self, msg) -> None:
        ret = ddspy_write(self.entity._ref, frame(cdr.serialize(msg, self.typename, self.store)))
        if ret < 0:
            raise RuntimeError(f"DDS write on {self.topic} failed ({ret})")

    def _run(self) -> None:
        while not self._closed:
            self.waitset.wait(duration(seconds=1))
            if self._closed:
                return
            samples = ddspy_take(self.entity._ref, self.condition.mask, 16)
            for data, info in samples if not isinstance(samples, int) else ():
                if info.valid_data:
                    try:
                        self.callback(cdr.deserialize(bytes(data), self.typename, self.store))
                    except Exception:  # a malformed sample or a failing callback: keep reading
                        log.exception("action topic %s", self.topic)

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        entities = [self.entity, self.dds_topic]
        if self._thread is not None:
            self.wake.set(True)
            if self._thread is not threading.current_thread():
                self._thread.join()
            self.waitset.detach(self.condition)
            self.waitset.detach(self.wake)
            entities = [self.condition, self.wake, self.waitset, *entities]
        for entity in entities:
            entity.__del__()
        if self in self.bus.owned:
            self.bus.owned.remove(self)
            self.bus._entities_changed()


# -- the server ------------------------------------------------------------------------------------


class ServerGoal:
    """An accepted goal on the server: `goal` (the goal message), `id` (16 bytes), `status`;
    `execute()`, `publish_feedback(feedback)`, and one of `succeed(result)`, `abort(result)`,
    `canceled(result)` to end it. Each change is published on the status topic."""

    def __init__(self, server: ActionServer, goal_id: bytes, goal, stamp: float):
        self.server, self.id, self.goal, self.stamp = server, goal_id, goal, stamp
        self.status = ACCEPTED  # [server._lock]
        self.result = None  # [server._lock] the GetResult response, once the goal ended
        self.waiting = []  # [server._lock] reply callbacks of result requests that came before the end

    @property
    def is_active(self) -> bool:
        return self.status not in TERMINAL

    def execute(self) -> None:
        self.server._event(self, "execute")

    def start(self) -> None:
        """Execute the goal if it is still only accepted (whoever comes first: the server's
        on_accepted or the program ending it)."""
        with self.server._lock:
            if self.status == ACCEPTED:
                self.execute()

    def mark_canceling(self) -> bool:
        """A cancel request taken: CANCELING if still active; whether the goal is (or ended) cancelled."""
        with self.server._lock:
            if self.status in (ACCEPTED, EXECUTING):
                self.server._event(self, "cancel")
            return self.status in (CANCELING, CANCELED)

    def publish_feedback(self, feedback) -> None:
        server = self.server
        message = ros_messages.new(
            server.types["feedback_message"],
            store=server.store,
            goal_id=_uuid(server.store, self.id),
            feedback=feedback,
        )
        server.feedback.write(message)

    def succeed(self, result) -> None:
        self.server._event(self, "succeed", result)

    def abort(self, result) -> None:
        self.server._event(self, "abort", result)

    def canceled(self, result) -> None:
        self.server._event(self, "canceled", result)


class ActionServer:
    """Offers the action `action` (absolute name) of type `actiontype`
    (`nav2_msgs/action/NavigateToPose`). `on_goal(server_goal)` decides on each new goal (True:
    accepted; its `id` and `goal` are set, it is not yet among the server's goals);
    `on_accepted(server_goal)` is told each accepted goal once the client has the answer
    (default: execute it, as rclpy's default handle_accepted_callback does); `on_cancel(server_goal)`
    decides on a cancel request of an active goal (default: accepted). The callbacks run on the
    services' threads and must not block: a goal that takes time runs on a thread of the caller's."""

    def __init__(
        self,
        bus,
        action: str,
        actiontype: str,
        on_goal=None,
        on_accepted=None,
        on_cancel=None,
        store=None,
        result_timeout: float = RESULT_TIMEOUT,
    ):
        self.bus, self.action, self.actiontype = bus, action, actiontype
        self.store = store or ros_messages.action_store(bus.distro)
        self.types = ros_messages.action_types(actiontype)
        if not ros_messages.has_type(self.types["goal"], self.store):
            raise TypeError(f"unknown action type {actiontype}")
        self.on_goal = on_goal or (lambda server_goal: True)
        self.on_accepted = on_accepted or (lambda server_goal: server_goal.execute())
        self.on_cancel = on_cancel or (lambda server_goal: True)
        self.result_timeout = result_timeout
        self._closing = threading.Lock()
        self._lock = threading.RLock()
        self.goals: dict[bytes, ServerGoal] = {}  # [_lock] by goal id, until they expire
        parts = names(action)
        self.status = _Channel(bus, parts["status"], STATUS_TYPE, self.store, True)
        self.feedback = _Channel(bus, parts["feedback"], self.types["feedback_message"], self.store, False)
        self.servers = [
            ServiceServer(bus, parts["send_goal"], f"{actiontype}_SendGoal", self._send_goal, self.store, True),
            ServiceServer(bus, parts["cancel_goal"], ros_messages.CANCEL_GOAL, self._cancel_goal, self.store),
            ServiceServer(bus, parts["get_result"], f"{actiontype}_GetResult", self._get_result, self.store, True),
        ]
        self._publish_status()

    def new_result(self, **fields):
        return ros_messages.new(self.types["result"], store=self.store, **fields)

    def new_feedback(self, **fields):
        return ros_messages.new(self.types["feedback"], store=self.store, **fields)

    # -- the services ----------------------------------------------------------------------------
    def _send_goal(self, request, reply) -> None:
        goal_id = bytes(request.goal_id.uuid)
        with self._lock:
            self._expire()
            known = goal_id in self.goals
        now = time.time()
        server_goal = ServerGoal(self, goal_id, request.goal, now)
        accepted = not known and bool(self.on_goal(server_goal))
        if accepted:
            with self._lock:
                self.goals[goal_id] = server_goal
            self._publish_status()
        response = ros_messages.new(
            self.types["send_goal_response"],
            store=self.store,
            accepted=accepted,
            stamp=_stamp(self.store, now if accepted else 0.0),
        )
        reply(response)
        if accepted:  # after the response: the client knows the goal before it moves
            self.on_accepted(server_goal)

    def _cancel_goal(self, request):
        """rcl_action_process_cancel_request, then the server's own decision per goal."""
        wanted = bytes(request.goal_info.goal_id.uuid)
        before = _seconds(request.goal_info.stamp)
        with self._lock:
            self._expire()
            goals = list(self.goals.values())
        code, chosen = CANCEL_NONE, []
        if any(wanted) and before == 0.0:
            found = [g for g in goals if g.id == wanted]
            if not found:
                code = CANCEL_UNKNOWN_GOAL
            elif not found[0].is_active:
                code = CANCEL_TERMINATED
            else:
                chosen = found
        else:
            limit = float("inf") if before == 0.0 else before
            chosen = [g for g in goals if g.is_active and (g.stamp <= limit or g.id == wanted)]
        canceling = []
        for server_goal in chosen:
            if self.on_cancel(server_goal) and server_goal.mark_canceling():  # False: it ended meanwhile
                canceling.append(server_goal)
        if chosen and not canceling and code == CANCEL_NONE and any(wanted):
            code = CANCEL_REJECTED
        info = [
            ros_messages.new(
                "action_msgs/msg/GoalInfo",
                store=self.store,
                goal_id=_uuid(self.store, g.id),
                stamp=_stamp(self.store, g.stamp),
            )
            for g in canceling
        ]
        return ros_messages.new(
            "action_msgs/srv/CancelGoal_Response", store=self.store, return_code=code, goals_canceling=info
        )

    def _get_result(self, request, reply) -> None:
        goal_id = bytes(request.goal_id.uuid)
        with self._lock:
            server_goal = self.goals.get(goal_id)
            if server_goal is not None and server_goal.result is None:
                server_goal.waiting.append(reply)
                return
        if server_goal is None:
            reply(ros_messages.new(self.types["get_result_response"], store=self.store, status=UNKNOWN))
        else:
            reply(server_goal.result)

    # -- goal events -----------------------------------------------------------------------------
    def _event(self, server_goal: ServerGoal, event: str, result=None) -> None:
        with self._lock:
            state = _TRANSITIONS.get((server_goal.status, event))
            if state is None:
                raise ActionError(f"a goal {STATUS_NAMES[server_goal.status]} cannot {event}")
            server_goal.status = state
            waiting = []
            if state in TERMINAL:
                result = result if result is not None else self.new_result()
                server_goal.result = ros_messages.new(
                    self.types["get_result_response"], store=self.store, status=state, result=result
                )
                waiting, server_goal.waiting = server_goal.waiting, []
        self._publish_status()
        for reply in waiting:
            reply(server_goal.result)

    def _expire(self) -> None:  # [_lock]
        """rcl_action_expire_goals, checked at each request and status change rather than on a timer."""
        now = time.time()
        for goal_id, server_goal in list(self.goals.items()):
            if not server_goal.is_active and now - server_goal.stamp > self.result_timeout:
                del self.goals[goal_id]

    def _publish_status(self) -> None:
        with self._lock:
            self._expire()
            status_list = [
                ros_messages.new(
                    "action_msgs/msg/GoalStatus",
                    store=self.store,
                    goal_info=_goal_info(self.store, g.id, g.stamp),
                    status=g.status,
                )
                for g in self.goals.values()
            ]
            self.status.write(ros_messages.new(STATUS_TYPE, store=self.store, status_list=status_list))

    def close(self) -> None:
        """Close the services and topics (idempotent; a program's `close' and the runtime's
        shutdown hook may call it at once)."""
        with self._closing:
            for server in self.servers:
                server.close()
            self.feedback.close()
            self.status.close()


# -- the client ------------------------------------------------------------------------------------


class ClientGoal:
    """A goal sent by an ActionClient: `id`, `accepted`, `status` (the latest heard: from the status
    topic, then the result's), `feedback` (the latest), `result` (once it came), `done` (an Event
    set with the result); `cancel()` asks the server to cancel it. The callbacks given to
    `send_goal` run on the client's threads."""

    def __init__(self, client: ActionClient, goal_id: bytes, on_feedback, on_status, on_result):
        self.client, self.id = client, goal_id
        self.on_feedback, self.on_status, self.on_result = on_feedback, on_status, on_result
        self.accepted = False
        self.stamp = 0.0
        self.status = UNKNOWN
        self.feedback = None
        self.result = None
        self.done = threading.Event()
        self.cancel_code = None  # the cancel response's return code, once it came

    def _status(self, status: int) -> None:
        if self.done.is_set() or status == self.status:
            return
        self.status = status
        if self.on_status is not None:
            self.on_status(status)

    def _feedback(self, feedback) -> None:
        self.feedback = feedback
        if self.on_feedback is not None:
            self.on_feedback(feedback)

    def _result(self, response) -> None:
        self._status(int(response.status))
        self.result = response.result
        self.done.set()
        self.client._forget(self.id)
        if self.on_result is not None:
            self.on_result(int(response.status), response.result)

    def cancel(self, on_reply=None) -> None:
        """Send a cancel request for this goal; `on_reply(return_code)` when the server answers."""
        store = self.client.store
        info = _goal_info(store, self.id, 0.0)
        request = ros_messages.new("action_msgs/srv/CancelGoal_Request", store=store, goal_info=info)

        def replied(response):
            self.cancel_code = int(response.return_code)
            if on_reply is not None:
                on_reply(self.cancel_code)

        self.client.cancel_goal.call_async(request, replied)


class ActionClient:
    """Sends goals to the action `action` (absolute name) of type `actiontype`."""

    def __init__(self, bus, action: str, actiontype: str, store=None):
        self.bus, self.action, self.actiontype = bus, action, actiontype
        self.store = store or ros_messages.action_store(bus.distro)
        self.types = ros_messages.action_types(actiontype)
        if not ros_messages.has_type(self.types["goal"], self.store):
            raise TypeError(f"unknown action type {actiontype}")
        self._lock = threading.Lock()
        self._closing = threading.Lock()
        self._goals: dict[bytes, ClientGoal] = {}  # [_lock] goals whose result has not come
        parts = names(action)
        self.send_goal_client = ServiceClient(bus, parts["send_goal"], f"{actiontype}_SendGoal", self.store)
        self.cancel_goal = ServiceClient(bus, parts["cancel_goal"], ros_messages.CANCEL_GOAL, self.store)
        self.get_result = ServiceClient(bus, parts["get_result"], f"{actiontype}_GetResult", self.store)
        self.feedback = _Channel(
            bus, parts["feedback"], self.types["feedback_message"], self.store, False, self._on_feedback
        )
        self.status = _Channel(bus, parts["status"], STATUS_TYPE, self.store, True, self._on_status)

    def new_goal(self, **fields):
        return ros_messages.new(self.types["goal"], store=self.store, **fields)

    def wait_for_server(self, timeout: float | None = None) -> bool:
        """Until the server's three services are there (rclpy's server_is_ready), and its feedback
        and status writers have matched our readers (so that no early feedback is missed)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        for client in (self.send_goal_client, self.cancel_goal, self.get_result):
            left = None if deadline is None else max(0.0, deadline - time.monotonic())
            if not client.wait_for_service(left):
                return False
        while not (self.feedback.matched() and self.status.matched()):
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.005)
        return True

    def send_goal(self, goal, timeout: float | None = 10.0, on_feedback=None, on_status=None, on_result=None):
        """Send `goal` and wait for the server's answer (ServiceTimeout when none comes): the
        ClientGoal, `accepted` or not; an accepted goal's result is asked for at once."""
        goal_id = uuid.uuid4().bytes
        handle = ClientGoal(self, goal_id, on_feedback, on_status, on_result)
        with self._lock:
            self._goals[goal_id] = handle  # before the request: feedback may come before the response
        request = ros_messages.new(
            self.types["send_goal_request"], store=self.store, goal_id=_uuid(self.store, goal_id), goal=goal
        )
        try:
            response = self.send_goal_client.call(request, timeout)
        except ServiceTimeout:
            self._forget(goal_id)
            raise
        handle.accepted, handle.stamp = bool(response.accepted), _seconds(response.stamp)
        if not handle.accepted:
            self._forget(goal_id)
            return handle
        handle._status(ACCEPTED)
        asked = ros_messages.new(self.types["get_result_request"], store=self.store, goal_id=_uuid(self.store, goal_id))
        self.get_result.call_async(asked, handle._result)
        return handle

    def _forget(self, goal_id: bytes) -> None:
        with self._lock:
            self._goals.pop(goal_id, None)

    def _on_feedback(self, message) -> None:
        with self._lock:
            handle = self._goals.get(bytes(message.goal_id.uuid))
        if handle is not None:
            handle._feedback(message.feedback)

    def _on_status(self, message) -> None:
        for each in message.status_list:
            with self._lock:
                handle = self._goals.get(bytes(each.goal_info.goal_id.uuid))
            if handle is not None and handle.accepted:
                handle._status(int(each.status))

    def close(self) -> None:
        with self._closing:  # idempotent, and safe from two threads
            for part in (self.send_goal_client, self.cancel_goal, self.get_result, self.feedback, self.status):
                part.close()
