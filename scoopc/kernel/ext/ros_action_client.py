"""ROS_ACTION_CLIENT's and ROS_GOAL_HANDLE's `external "Python"` features
(stdlib/roboscoop/communication/ros_action_client.e, ros_goal_handle.e).

A scoopc.robots.actions.ActionClient on the process's transport, made on first use. What the
transport hears about a goal (status, feedback, result, the answer to a cancel request) becomes an
ASYNCHRONOUS call on the goal handle's processor, logged by the client's outside client of the
runtime, as subscriptions deliver messages: no Eiffel field is written from a transport thread.
Feedback is coalesced per goal: only the newest undelivered message is kept."""

import threading

import scoopc.runtime as rt
from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.robots import transport


def _over_dds(bus) -> bool:
    return hasattr(bus, "owned")  # a DdsBus: actions need its participant


def action_client(current):
    """The (ActionClient, outside client) of `current`, made once; an Eiffel exception when the
    transport has no DDS participant or the type is unknown."""
    from scoopc.robots import actions  # deferred: start-up (cyclonedds loads only when actions are used)

    made = current.__dict__.get("_action_client")
    if made is None:
        bus = transport.current()
        name = strings.text(current.action)
        if not _over_dds(bus):
            raise failure(
                current._region_,
                "DEVELOPER_EXCEPTION",
                f"ROS_ACTION_CLIENT {name}: ROS 2 actions need a ROS 2 robot over DDS (scoopc run --robot ros2)",
            )
        try:
            client = actions.ActionClient(bus, name, strings.text(current.action_type))
        except (TypeError, ValueError) as e:
            raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_ACTION_CLIENT: {e}") from None
        source = rt.outside_client(f"action {name}")

        def stop():
            client.close()
            source.close()

        rt.add_shutdown_hook(stop)
        made = current._action_client = (client, source)
    return made


def is_available(current, seconds):
    if not _over_dds(transport.current()):
        return False  # no ROS 2 action server can be there
    client, _ = action_client(current)
    return client.wait_for_server(max(0.0, float(seconds)))


class _GoalLink:
    """One goal's way to its handle's processor."""

    def __init__(self, handle, source, store):
        self.handle, self.source, self.store = handle, source, store
        self.lock = threading.Lock()
        self.pending = None  # [lock] the newest feedback not yet delivered
        self.scheduled = False  # [lock]

    def _log(self, routine, args=()):
        try:
            self.source.call(self.handle, routine, args)
        except Exception:  # noqa: BLE001 - the runtime is shutting down: drop it
            pass

    def status(self, code):
        self._log(_on_status, (int(code),))

    def feedback(self, msg):
        with self.lock:
            self.pending = msg
            if self.scheduled:
                return
            self.scheduled = True
        self._log(_on_feedback, (self,))

    def take(self):
        with self.lock:
            msg, self.pending, self.scheduled = self.pending, None, False
            return msg

    def result(self, code, msg):
        self._log(_on_result, (self, int(code), msg))

    def cancel_reply(self, code):
        self._log(_on_cancel_reply, (int(code),))


def _on_status(handle, code):
    handle.on_status(code)


def _on_feedback(handle, link):
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    msg = link.take()
    if msg is not None:
        handle.on_feedback(eiffel_bridge.from_message(msg, handle._region_, link.store))


def _on_result(handle, link, code, msg):
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    handle.on_result(code, eiffel_bridge.from_message(msg, handle._region_, link.store))


def _on_cancel_reply(handle, code):
    handle.on_cancel_reply(code)


def send(current, goal, handle):
    """Send `goal`; wait for the answer; from then on the goal's news go to `handle`."""
    from scoopc.robots import (
        eiffel_bridge,  # deferred: start-up (numpy and rosbags load only when this is used)
        services,  # deferred: start-up (cyclonedds loads only when actions are used)
    )

    client, source = action_client(current)
    message = eiffel_bridge.to_message(goal, client.types["goal"], client.store)
    link = _GoalLink(handle, source, client.store)
    try:
        sent = client.send_goal(
            message, float(current.timeout), on_feedback=link.feedback, on_status=link.status, on_result=link.result
        )
    except services.ServiceTimeout:
        raise failure(
            current._region_,
            "DEVELOPER_EXCEPTION",
            f"no answer from the action server {strings.text(current.action)} within {float(current.timeout):g} s",
        ) from None
    handle._action_goal = (sent, link)  # handle is controlled here: no other processor runs on it
    return sent.accepted
