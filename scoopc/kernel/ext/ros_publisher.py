"""ROS_PUBLISHER's `external "Python"` features (stdlib/roboscoop/communication/ros_publisher.e).

A publication builds a message of the rosbags type store (scoopc.robots.ros_messages)
and puts it on the process's transport (scoopc.robots.transport.current()), synchronously, on
the publishing processor's thread. The Eiffel side passes plain values only.
"""

from scoopc.robots import transport
from scoopc.robots.velocity import new_message, twist, twist_stamped


def _text(obj):
    from scoopc.kernel import strings

    return strings.text(obj)


def publish_twist(current, linear_x, angular_z):
    topic = _text(current.topic)
    if current.is_stamped:
        msg = twist_stamped(linear_x, angular_z)
    else:
        msg = twist(linear_x, angular_z)
    transport.current().publish(topic, msg)


def publish_float64(current, value):
    transport.current().publish(_text(current.topic), new_message("std_msgs/msg/Float64", data=float(value)))


def publish_message(current, message):
    from scoopc.robots import eiffel_bridge

    transport.current().publish(_text(current.topic), eiffel_bridge.to_message(message))
