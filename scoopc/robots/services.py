"""ROS 2 services over DDS, in rmw_cyclonedds_cpp's request and reply format: a `ServiceServer`
answers requests with a handler, a `ServiceClient` calls and waits for the reply. Both belong to a
DdsBus (its participant, its node in the ROS graph) and are closed with it.

The format, from rmw_cyclonedds_cpp/src/rmw_node.cpp (jazzy branch) and serdata.hpp:
* the request topic is `rq` + the service name + `Request`, the reply topic `rr` + the service name
  + `Reply` (make_fqtopic with ROS_SERVICE_REQUESTER_PREFIX / ROS_SERVICE_RESPONSE_PREFIX);
  the types `pkg::srv::dds_::Name_Request_` and `pkg::srv::dds_::Name_Response_`;
* each sample is the CDR of `cdds_request_header_t` {uint64 guid; int64 seq} followed by the
  message (cdds_request_wrapper_t): the client's guid is its request writer's instance handle
  (`header.guid = info->client.pub->pubiid`), seq counts its requests from 1; the reply carries
  the request's header back (rmw_send_response), and a client takes only replies with its guid;
* the QoS is rmw_qos_profile_services_default (reliable, volatile, keep last 10) as
  create_readwrite_qos makes it, with `clientid=` or `serviceid=` and the id (get_unique_csid:
  the participant's 12-byte GUID prefix and a big-endian counter, as csid_to_string writes it:
  hexadecimal bytes joined by dots) in both endpoints' user data, then the type hash from Iron on;
* before replying, a server waits (a little) until its reply writer has matched the reader of the
  client that sent the request, recognised by that `clientid` (check_for_response_reader).

Services need rmw_cyclonedds_cpp on the other side: rmw_fastrtps_cpp carries the request id in
its own way, and services do not work across DDS vendors.

Service types are registered from their `.srv` definitions (`ros_messages.SRV_DEFINITIONS`) into a
type store of the distribution (`ros_messages.service_store`).
"""

from __future__ import annotations

import itertools
import logging
import struct
import threading
import time

from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import GuardCondition, InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.idl import make_idl_struct, types as idl
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from . import cdr, ros_messages
from .dds import _idl_field, dds_type_name, frame
from .ros_messages import SRV_DEFINITIONS, service_store  # noqa: F401 - the service types, re-exported

log = logging.getLogger(__name__)

_HEADER = struct.Struct("<Qq")  # cdds_request_header_t, little endian after `00 01 00 00`
_counter = itertools.count(1)  # client/service ids of this process (get_unique_csid's counter)
REPLY_WAIT = 1.0  # seconds a server waits for the client's reply reader before writing anyway


class ServiceTimeout(TimeoutError):
    """No reply within the time allowed."""


def request_bytes(guid: int, seq: int, body: bytes) -> bytes:
    """One wire sample: the encapsulation header, cdds_request_header_t, then the message's CDR
    (16 header bytes keep the message's alignment)."""
    return frame(body[:4] + _HEADER.pack(guid & (1 << 64) - 1, seq) + body[4:])


def parse_request(data: bytes) -> tuple[int, int, bytes]:
    """(guid, seq, the message's CDR with its encapsulation header) of a wire sample."""
    guid, seq = _HEADER.unpack_from(data, 4)
    return guid, seq, bytes(data[:4]) + bytes(data[20:])


def csid(participant) -> str:
    """A client/service id as get_unique_csid makes it and csid_to_string writes it."""
    raw = participant.guid.bytes[:12] + next(_counter).to_bytes(4, "big")
    return f"{raw[0]:02x}" + "".join(f".{b:x}" for b in raw[1:])


def _qos(kind: str, ident: str, typename: str, store, distro: str) -> Qos:
    policies = [
        Policy.WriterDataLifecycle(autodispose=False),
        Policy.History.KeepLast(10),
        Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
        Policy.Durability.Volatile,
        Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
    ]
    userdata = f"{kind}={ident};"
    if distro != "humble":
        userdata += f"typehash={store.hash_rihs01(typename)};"
    return Qos(*policies, Policy.Userdata(data=userdata.encode()))


def _wire_type(typename: str, store):
    """The DDS type of a request or reply: the request header's two fields, then the message's."""
    fields = {"_request_guid": idl.uint64, "_request_seq": idl.int64}
    fields.update({name: _idl_field(desc, store) for name, desc in ros_messages.fields(typename, store)})
    return make_idl_struct(typename.replace("/", "_") + "_wire", dds_type_name(typename), fields)


class _Endpoint:
    """A reader and a writer of one service on a DdsBus, with a thread taking what the reader gets."""

    def __init__(self, bus, service: str, srvtype: str, is_server: bool, store=None):
        if not service.startswith("/"):
            raise ValueError(f"service names are absolute here: {service!r}")
        self.bus, self.service, self.srvtype = bus, service, srvtype
        self.store = store or service_store(bus.distro)
        self.request_type, self.response_type = f"{srvtype}_Request", f"{srvtype}_Response"
        for typename in (self.request_type, self.response_type):
            if not ros_messages.has_type(typename, self.store):
                raise TypeError(f"unknown service type {srvtype}")
        self.id = csid(bus.participant)
        kind = "serviceid" if is_server else "clientid"
        mine, theirs = (self.response_type, self.request_type) if is_server else (self.request_type, self.response_type)
        request_topic = Topic(bus.participant, f"rq{service}Request", _wire_type(self.request_type, self.store))
        reply_topic = Topic(bus.participant, f"rr{service}Reply", _wire_type(self.response_type, self.store))
        self.topics = [request_topic, reply_topic]
        read_topic, write_topic = (request_topic, reply_topic) if is_server else (reply_topic, request_topic)
        self.reader = DataReader(bus.participant, read_topic, qos=_qos(kind, self.id, theirs, self.store, bus.distro))
        self.writer = DataWriter(bus.participant, write_topic, qos=_qos(kind, self.id, mine, self.store, bus.distro))
        self.condition = ReadCondition(self.reader, SampleState.NotRead | ViewState.Any | InstanceState.Any)
        self.waitset = WaitSet(bus.participant)
        self.wake = GuardCondition(bus.participant)
        self.waitset.attach(self.condition)
        self.waitset.attach(self.wake)
        self._closed = False  # no more requests or replies taken
        self._gone = threading.Lock()  # held while writing and while deleting the DDS entities
        self._deleted = False  # [_gone]
        self._thread = threading.Thread(target=self._run, name=f"service {service}", daemon=True)
        self._thread.start()
        bus.owned.append(self)
        bus._entities_changed()

    def guids(self) -> tuple[list, list]:
        return [self.reader.guid], [self.writer.guid]

    def _run(self):
        while not self._closed:
            self.waitset.wait(duration(seconds=1))
            if self._closed:
                return
            samples = ddspy_take(self.reader._ref, self.condition.mask, 16)
            if isinstance(samples, int):
                continue
            for data, info in samples:
                if info.valid_data:
                    try:
                        self._received(bytes(data), info)
                    except Exception:  # a malformed sample or a failing handler: keep serving
                        log.exception("service %s", self.service)

    def _write(self, guid: int, seq: int, msg, typename: str) -> None:
        data = request_bytes(guid, seq, cdr.serialize(msg, typename, self.store))
        with self._gone:
            if self._deleted:  # a reply computed after close: its client hears nothing, as in rmw
                return
            ret = ddspy_write(self.writer._ref, data)
        if ret < 0:
            raise RuntimeError(f"DDS write on service {self.service} failed ({ret})")

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        self.wake.set(True)
        if self._thread is not threading.current_thread():
            self._thread.join()  # a request being answered is answered first
        with self._gone:
            self._deleted = True
            self.waitset.detach(self.condition)
            self.waitset.detach(self.wake)
            for entity in (self.condition, self.wake, self.waitset, self.reader, self.writer, *self.topics):
                entity.__del__()
        if self in self.bus.owned:
            self.bus.owned.remove(self)
            self.bus._entities_changed()


class ServiceServer(_Endpoint):
    """Answers `service` (absolute name) of type `srvtype` (`std_srvs/srv/Trigger`): `handler(request)`
    returns the response message; it runs on the server's thread, one request at a time.
    `deferred=True`: `handler(request, reply)` returns nothing and the response is sent by calling
    `reply(response)`, then or later, from any thread (an action's get_result)."""

    def __init__(self, bus, service: str, srvtype: str, handler, store=None, deferred: bool = False):
        self.handler, self.deferred = handler, deferred
        super().__init__(bus, service, srvtype, True, store)

    def new_response(self, **fields):
        return ros_messages.new(self.response_type, store=self.store, **fields)

    def _received(self, data: bytes, info) -> None:
        guid, seq, body = parse_request(data)
        request = cdr.deserialize(body, self.request_type, self.store)
        handle = info.publication_handle
        if self.deferred:
            self.handler(request, lambda response: self._reply(handle, guid, seq, response))
        else:
            self._reply(handle, guid, seq, self.handler(request))

    def _reply(self, handle, guid: int, seq: int, response) -> None:
        if self._deleted:
            return
        self._wait_for_client(handle)
        self._write(guid, seq, response, self.response_type)

    def _wait_for_client(self, handle) -> None:
        """check_for_response_reader: until our reply writer matched the client's reply reader."""
        try:
            endpoint = self.reader.get_matched_publication_data(handle)
        except Exception:  # noqa: BLE001 - the client is gone: reply anyway, as rmw does
            return
        wanted = _userdata_value(endpoint, "clientid")
        if wanted is None:
            return
        deadline = time.monotonic() + REPLY_WAIT
        while time.monotonic() < deadline and not self._deleted:
            for h in self.writer.get_matched_subscriptions():
                try:
                    if _userdata_value(self.writer.get_matched_subscription_data(h), "clientid") == wanted:
                        return
                except Exception:  # noqa: BLE001 - unmatched meanwhile
                    continue
            time.sleep(0.005)


def _userdata_value(endpoint, key: str) -> str | None:
    qos = getattr(endpoint, "qos", None)
    if qos is None or Policy.Userdata not in qos:
        return None
    for item in bytes(qos[Policy.Userdata].data).decode(errors="replace").split(";"):
        if item.startswith(key + "="):
            return item[len(key) + 1 :]
    return None


class ServiceClient(_Endpoint):
    """Calls `service` of type `srvtype`: `call(request, timeout)` sends a request and waits for its
    reply (ServiceTimeout when none comes); several threads may call at once."""

    def __init__(self, bus, service: str, srvtype: str, store=None):
        self._lock = threading.Lock()
        self._seq = 0  # [_lock]
        self._replies: dict = {}  # [_lock] seq -> reply message, or None while waiting
        self._later: dict = {}  # [_lock] seq -> callback of call_async
        self._arrived = threading.Condition(self._lock)
        super().__init__(bus, service, srvtype, False, store)
        self.guid = self.writer.get_instance_handle() & ((1 << 64) - 1)

    def new_request(self, **fields):
        return ros_messages.new(self.request_type, store=self.store, **fields)

    def wait_for_service(self, timeout: float | None = None) -> bool:
        """Until a server's request reader and reply writer both matched ours."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while not (
            self.writer.get_publication_matched_status().current_count
            and self.reader.get_subscription_matched_status().current_count
        ):
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.005)
        return True

    def call_async(self, request, callback) -> None:
        """Send a request; `callback(reply)` runs on the client's thread when the reply comes."""
        with self._lock:
            self._seq += 1
            seq = self._seq
            self._later[seq] = callback
        self._write(self.guid, seq, request, self.request_type)

    def call(self, request, timeout: float | None = 10.0):
        with self._lock:
            self._seq += 1
            seq = self._seq
            self._replies[seq] = None
        try:
            self._write(self.guid, seq, request, self.request_type)
            with self._arrived:
                if not self._arrived.wait_for(lambda: self._replies[seq] is not None or self._closed, timeout):
                    raise ServiceTimeout(f"no reply from {self.service} within {timeout:g} s")
                if self._replies[seq] is None:
                    raise ServiceTimeout(f"{self.service}: the client was closed")
                return self._replies[seq]
        finally:
            with self._lock:
                self._replies.pop(seq, None)

    def _received(self, data: bytes, info) -> None:
        guid, seq, body = parse_request(data)
        if guid != self.guid:
            return  # another client's reply
        with self._lock:
            callback = self._later.pop(seq, None)
        if callback is not None:
            callback(cdr.deserialize(body, self.response_type, self.store))
            return
        with self._arrived:
            if seq in self._replies:
                self._replies[seq] = cdr.deserialize(body, self.response_type, self.store)
                self._arrived.notify_all()

    def close(self) -> None:
        super().close()
        with self._arrived:  # callers waiting for a reply see the client closed
            self._arrived.notify_all()
