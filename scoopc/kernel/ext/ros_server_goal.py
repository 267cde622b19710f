"""ROS_SERVER_GOAL's `external "Python"` features (stdlib/roboscoop/communication/ros_server_goal.e):
the goal's scoopc.robots.actions.ServerGoal, attached by ROS_ACTION_SERVER's transport
(scoopc/kernel/ext/ros_action_server.py) when the goal was accepted."""

from scoopc.kernel.ext.exception import failure


def send_feedback(current, feedback):
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    server_goal = current._server_goal
    server = server_goal.server
    server_goal.publish_feedback(eiffel_bridge.to_message(feedback, server.types["feedback"], server.store))


def finish(current, result, status):
    from scoopc.robots import (
        actions,  # deferred: start-up (cyclonedds loads only when actions are used)
        eiffel_bridge,  # deferred: start-up (numpy and rosbags load only when this is used)
    )

    server_goal = current._server_goal
    server = server_goal.server
    message = eiffel_bridge.to_message(result, server.types["result"], server.store)
    server_goal.start()  # still only accepted: executing first, as the state machine wants
    if int(status) == actions.CANCELED:
        server_goal.mark_canceling()  # the program may end it before the cancel request's thread marks it
    ending = {actions.SUCCEEDED: server_goal.succeed, actions.ABORTED: server_goal.abort}
    try:
        ending.get(int(status), server_goal.canceled)(message)
    except actions.ActionError as e:
        raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_SERVER_GOAL: {e}") from None
