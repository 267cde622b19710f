"""ROS_SERVICE_SERVER's `external "Python"` features (stdlib/roboscoop/communication/ros_service_server.e).

A scoopc.robots.services.ServiceServer on the process's transport. Each request, on the server's
DDS thread, becomes an ASYNCHRONOUS call of `answer' on the Eiffel server's processor, logged by
an outside client of the runtime (`rt.outside_client`), as subscriptions deliver messages; the
DDS thread waits for that call's result (the response) and sends it. A failing `answer' is told
on stderr and the request gets no response (the client's call times out). `close' (or the end of
the run) sends the response of a request already answered before it closes."""

import sys
import threading

import scoopc.runtime as rt
from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.kernel.ext.serving import Answer, Serving


def _answer(current, pending, store, response_type):
    """On the server's processor: the Eiffel `answer' to one request."""
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    try:
        request = eiffel_bridge.from_message(pending.request, current._region_, store)
        response = current.answer(request)
        pending.value = eiffel_bridge.to_message(response, response_type, store)
    except BaseException as e:
        sys.stderr.write(f"scoopc: service {strings.text(current.service)}: `answer' failed: {e}\n")
        raise
    finally:
        pending.done.set()


def start_serving(current):
    from scoopc.robots import services  # deferred: start-up (cyclonedds loads only when services are used)

    name = strings.text(current.service)
    serving = Serving(current, "ROS_SERVICE_SERVER", name, "services", f"service {name}")
    holder = {}
    made = threading.Event()  # a request can come before ServiceServer(...) has returned

    def handle(request):
        pending = Answer(request)
        made.wait()
        server = holder["server"]
        if not serving.ask(_answer, pending, server.store, server.response_type) or pending.value is None:
            raise RuntimeError(f"no answer from the server's processor for {name}")
        return pending.value

    try:
        holder["server"] = services.ServiceServer(serving.bus, name, strings.text(current.service_type), handle)
    except (TypeError, ValueError) as e:
        serving.close(None)
        raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_SERVICE_SERVER: {e}") from None
    finally:
        made.set()

    def stop():
        serving.close(holder["server"])

    current._service_stop = stop
    rt.add_shutdown_hook(stop)


def close(current):
    stop = current.__dict__.get("_service_stop")
    if stop is not None:
        stop()
