"""What ROS_SERVICE_SERVER and ROS_ACTION_SERVER share (ros_service_server.py, ros_action_server.py):
the DDS bus they need, and the way a request on a DDS thread is answered on the Eiffel server's
processor: an ASYNCHRONOUS call logged by an outside client of the runtime (`rt.outside_client`),
whose answer the DDS thread waits for. Closing stops the waits at once: a call queued behind the
server's `close' would never run before close joins the DDS thread."""

import threading
import time

import scoopc.runtime as rt
from scoopc.kernel.ext.exception import failure
from scoopc.robots import transport

ANSWER_WAIT = 60.0  # seconds a DDS thread waits for the processor's answer


class Answer:
    """One call's answer (`value`, set on the server's processor before `done`), awaited on a DDS
    thread; `request` is what the call answers, when the call needs it."""

    def __init__(self, request=None):
        self.request, self.value, self.done = request, None, threading.Event()


class Serving:
    """The DDS side of one server object `current`: its outside client (named `client`), and
    whether it is closing. `kind` and `what` name it when there is no DDS bus."""

    def __init__(self, current, kind: str, name: str, what: str, client: str):
        bus = transport.current()
        if not hasattr(bus, "owned"):
            raise failure(
                current._region_,
                "DEVELOPER_EXCEPTION",
                f"{kind} {name}: ROS 2 {what} need a ROS 2 robot over DDS (scoopc run --robot ros2)",
            )
        self.current, self.bus = current, bus
        self.source = rt.outside_client(client)
        self.closing = threading.Event()

    def ask(self, routine, pending: Answer, *args) -> bool:
        """Call `routine (current, pending, *args)` on the server's processor and wait for it:
        whether it answered (within ANSWER_WAIT seconds, and before the server began closing)."""
        self.source.call(self.current, routine, (pending, *args))
        deadline = time.monotonic() + ANSWER_WAIT
        while not pending.done.wait(0.05):
            if self.closing.is_set() or time.monotonic() >= deadline:
                return False
        return True

    def close(self, endpoint) -> None:
        """Stop waiting for answers, close `endpoint` (its replies in progress go out first), then
        the outside client."""
        self.closing.set()
        if endpoint is not None:
            endpoint.close()
        self.source.close()
