"""ROS_ACTION_SERVER's `external "Python"` features (stdlib/roboscoop/communication/ros_action_server.e).

A scoopc.robots.actions.ActionServer on the process's transport. Each goal request and each
cancel request, on a DDS thread, becomes an ASYNCHRONOUS call on the Eiffel server's processor
(`on_goal', `on_cancel'), logged by an outside client of the runtime as subscriptions deliver
messages; the DDS thread waits for that call's answer and sends it. An accepted goal's
ROS_SERVER_GOAL (made by `on_goal' in the server's region) is tied to its ServerGoal there, in
the same call, before the program can see it."""

import sys

import scoopc.runtime as rt
from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.kernel.ext.serving import Answer, Serving


def _goal(current, pending, server_goal):
    """On the server's processor: `on_goal' for one request."""
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    try:
        server = server_goal.server
        request = eiffel_bridge.from_message(server_goal.goal, current._region_, server.store)
        made = current.on_goal(request, strings.new_string_8(current._region_, server_goal.id.hex()))
        if made is not None:
            made._server_goal, server_goal.eiffel = server_goal, made
            pending.value = True
    except BaseException as e:
        sys.stderr.write(f"scoopc: action {strings.text(current.action)}: `on_goal' failed: {e}\n")
        raise
    finally:
        pending.done.set()


def _cancel(current, pending, server_goal):
    """On the server's processor: `on_cancel' for one goal."""
    try:
        pending.value = bool(current.on_cancel(server_goal.eiffel))
    finally:
        pending.done.set()


def start_serving(current):
    from scoopc.robots import actions  # deferred: start-up (cyclonedds loads only when actions are used)

    name = strings.text(current.action)
    serving = Serving(current, "ROS_ACTION_SERVER", name, "actions", f"action server {name}")

    def ask(routine, server_goal):
        pending = Answer()
        try:
            return serving.ask(routine, pending, server_goal) and bool(pending.value)
        except Exception:  # noqa: BLE001 - the runtime is shutting down: refuse
            return False

    try:
        server = actions.ActionServer(
            serving.bus,
            name,
            strings.text(current.action_type),
            on_goal=lambda server_goal: ask(_goal, server_goal),
            on_accepted=lambda server_goal: server_goal.start(),
            on_cancel=lambda server_goal: hasattr(server_goal, "eiffel") and ask(_cancel, server_goal),
        )
    except (TypeError, ValueError) as e:
        serving.close(None)
        raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_ACTION_SERVER: {e}") from None

    def stop():
        serving.close(server)

    current._action_stop = stop
    rt.add_shutdown_hook(stop)


def close(current):
    stop = current.__dict__.get("_action_stop")
    if stop is not None:
        stop()
