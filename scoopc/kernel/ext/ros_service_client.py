"""ROS_SERVICE_CLIENT's `external "Python"` features (stdlib/roboscoop/communication/ros_service_client.e):
a scoopc.robots.services.ServiceClient on the process's transport, made on the first call; the
request object converted by the generic bridge, the response made in the client's region."""

from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.robots import transport


def service_client(current, what):
    """The ServiceClient of `current` (made once), or an Eiffel exception when the transport has none."""
    from scoopc.robots import services  # deferred: start-up (cyclonedds loads only when services are used)

    client = current.__dict__.get("_service_client")
    if client is None:
        bus = transport.current()
        if not hasattr(bus, "owned"):
            raise failure(
                current._region_,
                "DEVELOPER_EXCEPTION",
                f"{what} {strings.text(current.service)}: ROS 2 services need a ROS 2 robot over DDS "
                "(scoopc run --robot ros2)",
            )
        srvtype = strings.text(current.service_type)
        try:
            client = services.ServiceClient(bus, strings.text(current.service), srvtype)
        except (TypeError, ValueError) as e:
            raise failure(current._region_, "DEVELOPER_EXCEPTION", f"{what}: {e}") from None
        current._service_client = client
    return client


def is_available(current, seconds):
    return service_client(current, "ROS_SERVICE_CLIENT").wait_for_service(max(0.0, float(seconds)))


def call_service(current, request):
    from scoopc.robots import (
        eiffel_bridge,  # deferred: start-up (numpy and rosbags load only when this is used)
        services,  # deferred: start-up (cyclonedds loads only when services are used)
    )

    client = service_client(current, "ROS_SERVICE_CLIENT")
    message = eiffel_bridge.to_message(request, client.request_type, client.store)
    try:
        reply = client.call(message, float(current.timeout))
    except services.ServiceTimeout as e:
        raise failure(current._region_, "DEVELOPER_EXCEPTION", str(e)) from None
    return eiffel_bridge.from_message(reply, current._region_, client.store)
