"""ROS_GOAL_HANDLE's `external "Python"` features (stdlib/roboscoop/communication/ros_goal_handle.e):
the goal's scoopc.robots.actions.ClientGoal, set by ROS_ACTION_CLIENT's `send'
(scoopc/kernel/ext/ros_action_client.py)."""


def request_cancel(current):
    """ROS_GOAL_HANDLE.request_cancel, on the handle's processor."""
    sent, link = current._action_goal
    sent.cancel(link.cancel_reply)
