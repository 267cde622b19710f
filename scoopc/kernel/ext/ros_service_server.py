"""ROS_SERVICE_SERVER's `external "Python"` features (stdlib/roboscoop/communication/ros_service_server.e).

A scoopc.robots.services.ServiceServer on the process's transport. Each request, on the server's
DDS thread, becomes an ASYNCHRONOUS call of `answer' on the Eiffel server's processor, logged by
an outside client of the runtime (`rt.outside_client`), as subscriptions deliver messages; the
DDS thread waits for that call's result (the response) and sends it. A failing `answer' is told
on stderr and the request gets no response (the client's call times out). `close' (or the end of
the run) sends the response of a request already answered before it closes."""

import sys
import threading
import time

import scoopc.runtime as rt
from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.robots import transport

ANSWER_WAIT = 60.0  # seconds the DDS thread waits for the processor's answer


class _Answer:
    """One request's response, set on the server's processor, awaited on the DDS thread."""

    def __init__(self, request):
        self.request, self.response, self.done = request, None, threading.Event()


def _answer(current, pending, store, response_type):
    """On the server's processor: the Eiffel `answer' to one request."""
    from scoopc.robots import eiffel_bridge  # deferred: start-up (numpy and rosbags load only when this is used)

    try:
        request = eiffel_bridge.from_message(pending.request, current._region_, store)
        response = current.answer(request)
        pending.response = eiffel_bridge.to_message(response, response_type, store)
    except BaseException as e:
        sys.stderr.write(f"scoopc: service {strings.text(current.service)}: `answer' failed: {e}\n")
        raise
    finally:
        pending.done.set()


def start_serving(current):
    from scoopc.robots import services  # deferred: start-up (cyclonedds loads only when services are used)

    bus = transport.current()
    name = strings.text(current.service)
    if not hasattr(bus, "owned"):
        raise failure(
            current._region_,
            "DEVELOPER_EXCEPTION",
            f"ROS_SERVICE_SERVER {name}: ROS 2 services need a ROS 2 robot over DDS (scoopc run --robot ros2)",
        )
    source = rt.outside_client(f"service {name}")
    holder = {}
    made = threading.Event()  # a request can come before ServiceServer(...) has returned
    closing = threading.Event()  # close() joins this thread: an answer queued after it never comes

    def handle(request):
        pending = _Answer(request)
        made.wait()
        server = holder["server"]
        source.call(current, _answer, (pending, server.store, server.response_type))
        deadline = time.monotonic() + ANSWER_WAIT
        while not pending.done.wait(0.05):
            if closing.is_set() or time.monotonic() >= deadline:
                break
        if pending.response is None:
            raise RuntimeError(f"no answer from the server's processor for {name}")
        return pending.response

    try:
        holder["server"] = services.ServiceServer(bus, name, strings.text(current.service_type), handle)
    except (TypeError, ValueError) as e:
        source.close()
        raise failure(current._region_, "DEVELOPER_EXCEPTION", f"ROS_SERVICE_SERVER: {e}") from None
    finally:
        made.set()

    def stop():
        closing.set()
        holder["server"].close()  # after the reply to a request already answered
        source.close()

    current._service_stop = stop
    rt.add_shutdown_hook(stop)


def close(current):
    stop = current.__dict__.get("_service_stop")
    if stop is not None:
        stop()
