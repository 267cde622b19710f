"""A twin of a stock ROS 2 node on rmw_cyclonedds_cpp, for the tests: cyclonedds and rosbags only
(nothing of scoopc), so that what it hears or sends is what a real node would.

`Node(distro)` is `rclpy.create_node` on rmw_cyclonedds_cpp; `node.create_subscription(typename, topic,
depth=10)` and `node.create_publisher(typename, topic, depth=10)` are rclpy's calls with a depth, that
is ROS's default QoS profile (rmw/include/rmw/qos_profiles.h rmw_qos_profile_default: reliable,
volatile, keep last). Each DDS setting copies rmw_cyclonedds_cpp/src/rmw_node.cpp (ros2/rmw_cyclonedds,
branches humble and jazzy; Lyrical is taken to be Jazzy's, not checked):

* participant user data `enclave=/;` (rmw_context_impl_s::init: `"enclave=" + options->enclave + ";"`,
  the enclave "/" by default);
* topic name `rt` + the ROS name (make_fqtopic with ROS_TOPIC_PREFIX, namespace_prefix.hpp);
* type name `pkg::msg::dds_::Name_` (the C++ type support's namespace and suffix, as
  rmw_cyclonedds_cpp's create_sertype names it), keyless;
* QoS (create_readwrite_qos): writer_data_lifecycle autodispose false; history keep last `depth`;
  reliability RELIABLE with max blocking time DDS_INFINITY; durability VOLATILE; liveliness
  AUTOMATIC with an infinite lease; no lifespan or deadline; user data `typehash=RIHS01_<hex>;` from
  Iron on (rmw_dds_common::encode_type_hash_for_user_data_qos; Humble's create_readwrite_qos sets
  no user data);
* data: XCDR1 plain CDR, little endian (encapsulation 00 01), written and taken as serialized bytes
  (rmw's serdata), here made and read by rosbags' `serialize_cdr` / `deserialize_cdr` of the
  distribution's type store.

The graph reader is in rmw_twin_graph.py, the actions (server, client, a stand-in Nav2 server) in
rmw_twin_actions.py.

Also a command line, for a twin in its own process (prints one JSON line per event, flushes):

    python tests/robots/rmw_twin.py --distro jazzy listen /robot1/odom nav_msgs/msg/Odometry
    python tests/robots/rmw_twin.py --distro jazzy publish /odom nav_msgs/msg/Odometry --rate 20
"""

from __future__ import annotations

import argparse
import json
import sys
import threading
import time

from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import make_idl_struct, types as idl
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration
from rosbags.typesys import Stores, get_typestore
from rosbags.typesys.base import Nodetype

STORES = {"humble": Stores.ROS2_HUMBLE, "jazzy": Stores.ROS2_JAZZY, "lyrical": Stores.ROS2_LYRICAL}
_BASES = {
    "bool": bool,
    "byte": idl.byte,
    "char": idl.uint8,
    "int8": idl.int8,
    "uint8": idl.uint8,
    "int16": idl.int16,
    "uint16": idl.uint16,
    "int32": idl.int32,
    "uint32": idl.uint32,
    "int64": idl.int64,
    "uint64": idl.uint64,
    "float32": idl.float32,
    "float64": idl.float64,
}


def dds_type(typename: str) -> str:
    package, kind, name = typename.split("/")
    return f"{package}::{kind}::dds_::{name}_"


class Node:
    """One participant, as rclpy's `create_node` makes it on rmw_cyclonedds_cpp."""

    def __init__(self, distro: str = "jazzy", domain: int | None = None):
        import os

        self.distro = distro
        self.store = get_typestore(STORES[distro])
        self.domain = int(os.environ.get("ROS_DOMAIN_ID", "0") or 0) if domain is None else domain
        self.participant = DomainParticipant(self.domain, qos=Qos(Policy.Userdata(data=b"enclave=/;")))
        self._structs: dict = {}
        self._topics: dict = {}
        self.entities = []

    # -- types ----------------------------------------------------------------------------------
    def _field(self, desc):
        kind, detail = desc
        if kind == Nodetype.BASE:
            name, bound = detail
            if name == "string":
                return idl.bounded_str[bound] if bound else str
            return _BASES[name]
        if kind == Nodetype.NAME:
            return self.idl(detail)
        element, size = detail
        if kind == Nodetype.ARRAY:
            return idl.array[self._field(element), size]
        return idl.sequence[self._field(element), size] if size else idl.sequence[self._field(element)]

    def idl(self, typename: str):
        if typename not in self._structs:
            fields = {name: self._field(desc) for name, desc in self.store.fielddefs[typename][1]}
            self._structs[typename] = make_idl_struct(typename.replace("/", "_"), dds_type(typename), fields)
        return self._structs[typename]

    def qos(self, typename: str, depth: int) -> Qos:
        """create_readwrite_qos for rmw_qos_profile_default with `depth`."""
        policies = [
            Policy.WriterDataLifecycle(autodispose=False),
            Policy.History.KeepLast(depth),
            Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
            Policy.Durability.Volatile,
            Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
        ]
        if self.distro != "humble":
            policies.append(Policy.Userdata(data=f"typehash={self.store.hash_rihs01(typename)};".encode()))
        return Qos(*policies)

    def _topic(self, topic: str, typename: str):
        if topic not in self._topics:
            self._topics[topic] = Topic(self.participant, "rt" + topic, self.idl(typename))
        return self._topics[topic]

    # -- rclpy's two calls ------------------------------------------------------------------------
    def create_subscription(self, typename: str, topic: str, depth: int = 10, callback=None) -> Subscription:
        return Subscription(self, typename, topic, depth, callback)

    def create_publisher(self, typename: str, topic: str, depth: int = 10) -> Publisher:
        return Publisher(self, typename, topic, depth)

    def create_service(self, srvtype: str, name: str, handler) -> ServiceEnd:
        return ServiceEnd(self, srvtype, name, handler)

    def create_client(self, srvtype: str, name: str) -> ServiceEnd:
        return ServiceEnd(self, srvtype, name)

    def close(self):
        for entity in reversed(self.entities):
            entity.close()
        self.participant.__del__()


class Publisher:
    def __init__(self, node: Node, typename: str, topic: str, depth: int, qos: Qos | None = None):
        self.node, self.typename, self.topic = node, typename, topic
        self.writer = DataWriter(node.participant, node._topic(topic, typename), qos=qos or node.qos(typename, depth))
        node.entities.append(self)

    def new(self, **fields):
        return new_message(self.node.store, self.typename, **fields)

    def publish(self, msg) -> None:
        data = bytes(self.node.store.serialize_cdr(msg, self.typename))
        pad = -len(data) % 4  # XCDR padding count in the options' low bits
        if pad:
            data = data[:3] + bytes([data[3] | pad]) + data[4:] + bytes(pad)
        ret = ddspy_write(self.writer._ref, data)
        if ret < 0:
            raise RuntimeError(f"write on {self.topic} failed ({ret})")

    def matched(self) -> int:
        return self.writer.get_publication_matched_status().current_count

    def incompatible(self) -> int:
        return self.writer.get_offered_incompatible_qos_status().total_count

    def close(self):
        self.writer.__del__()


class Subscription:
    """Takes every sample on a thread of its own: `messages` (decoded with the distribution's
    store), `raw` (the bytes), `received_at` (time.time() of each), `wait_for(pred, timeout)`."""

    def __init__(self, node: Node, typename: str, topic: str, depth: int, callback=None, qos: Qos | None = None):
        self.node, self.typename, self.topic, self.callback = node, typename, topic, callback
        self.reader = DataReader(node.participant, node._topic(topic, typename), qos=qos or node.qos(typename, depth))
        self.condition = ReadCondition(self.reader, SampleState.NotRead | ViewState.Any | InstanceState.Any)
        self.waitset = WaitSet(node.participant)
        self.waitset.attach(self.condition)
        self.messages, self.raw, self.received_at = [], [], []
        self.cond = threading.Condition()
        self._stop = False
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()
        node.entities.append(self)

    def _run(self):
        while not self._stop:
            self.waitset.wait(duration(milliseconds=100))
            samples = ddspy_take(self.reader._ref, self.condition.mask, 64)
            if isinstance(samples, int) or not samples:
                continue
            now = time.time()
            for data, info in samples:
                if not info.valid_data:
                    continue
                msg = self.node.store.deserialize_cdr(bytes(data), self.typename)
                with self.cond:
                    self.messages.append(msg)
                    self.raw.append(bytes(data))
                    self.received_at.append(now)
                    self.cond.notify_all()
                if self.callback is not None:
                    self.callback(msg)

    def wait_for(self, predicate, timeout: float = 30.0) -> bool:
        with self.cond:
            return self.cond.wait_for(lambda: predicate(self), timeout)

    def matched(self) -> int:
        return self.reader.get_subscription_matched_status().current_count

    def incompatible(self) -> int:
        return self.reader.get_requested_incompatible_qos_status().total_count

    def close(self):
        self._stop = True
        self.thread.join(2.0)
        self.waitset.detach(self.condition)
        self.condition.__del__()
        self.reader.__del__()


#: `.srv` definitions the twin knows (ros2/common_interfaces std_srvs, ros2/rcl_interfaces)
SRVS = {
    "std_srvs/srv/Trigger": ("", "bool success\nstring message"),
    "std_srvs/srv/SetBool": ("bool data", "bool success\nstring message"),
    "rcl_interfaces/srv/GetParameters": ("string[] names", "ParameterValue[] values"),
    "rcl_interfaces/srv/SetParameters": ("Parameter[] parameters", "SetParametersResult[] results"),
    "rcl_interfaces/srv/SetParametersAtomically": ("Parameter[] parameters", "SetParametersResult result"),
    "rcl_interfaces/srv/ListParameters": ("string[] prefixes\nuint64 depth", "ListParametersResult result"),
    "rcl_interfaces/srv/DescribeParameters": ("string[] names", "ParameterDescriptor[] descriptors"),
    "rcl_interfaces/srv/GetParameterTypes": ("string[] names", "uint8[] types"),
    # for the actions (rmw_twin_actions.py): action_msgs/srv/CancelGoal (ros2/rcl_interfaces)
    "action_msgs/srv/CancelGoal": (
        "action_msgs/GoalInfo goal_info",
        "int8 ERROR_NONE=0\nint8 ERROR_REJECTED=1\nint8 ERROR_UNKNOWN_GOAL_ID=2\nint8 ERROR_GOAL_TERMINATED=3\n"
        "int8 return_code\naction_msgs/GoalInfo[] goals_canceling",
    ),
}


LATER = object()  # a service handler's "the reply comes later, by ServiceEnd.reply"


class ServiceEnd:
    """A service or a client as rmw_cyclonedds_cpp's rmw_create_service / rmw_create_client make
    them (rmw_node.cpp, jazzy): topics `rq<name>Request` and `rr<name>Reply`, types
    `pkg::srv::dds_::Name_Request_`/`_Response_`, each sample the cdds_request_header_t
    {uint64 guid; int64 seq} then the message (serdata.hpp), the client's guid its request
    writer's instance handle; QoS rmw_qos_profile_services_default with `clientid=`/`serviceid=`
    user data (csid_to_string: 16 bytes in hexadecimal joined by dots)."""

    count = 0

    def __init__(self, node: Node, srvtype: str, name: str, handler=None):
        from rosbags.typesys import get_types_from_msg

        self.node, self.name, self.handler = node, name, handler
        package, _, short = srvtype.split("/")
        found = {}
        for half, text in zip(("Request", "Response"), SRVS.get(srvtype, ())):  # else an action registered them
            for key, value in get_types_from_msg(text, f"{package}/msg/{short}_{half}").items():
                found[key.replace("/msg/", "/srv/") if key.endswith(f"_{half}") else key] = value
        node.store.register(found)
        self.request, self.response = f"{srvtype}_Request", f"{srvtype}_Response"
        ServiceEnd.count += 1
        raw = node.participant.guid.bytes[:12] + ServiceEnd.count.to_bytes(4, "big")
        ident = f"{raw[0]:02x}" + "".join(f".{b:x}" for b in raw[1:])
        server = handler is not None
        kind = "serviceid" if server else "clientid"
        rq = Topic(node.participant, f"rq{name}Request", self._wire(self.request))
        rr = Topic(node.participant, f"rr{name}Reply", self._wire(self.response))
        self.writer = DataWriter(node.participant, rr if server else rq, qos=self._qos(kind, ident))
        self.reader = DataReader(node.participant, rq if server else rr, qos=self._qos(kind, ident))
        self.guid = self.writer.get_instance_handle() & ((1 << 64) - 1)
        self.replies, self.seq, self.cond = {}, 0, threading.Condition()
        self._stop = False
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()
        node.entities.append(self)

    def _wire(self, typename):
        fields = {"_request_guid": idl.uint64, "_request_seq": idl.int64}
        fields.update({n: self.node._field(d) for n, d in self.node.store.fielddefs[typename][1]})
        return make_idl_struct(typename.replace("/", "_") + "_twin", dds_type(typename), fields)

    def _qos(self, kind, ident):
        return Qos(
            Policy.WriterDataLifecycle(autodispose=False),
            Policy.History.KeepLast(10),
            Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
            Policy.Durability.Volatile,
            Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
            Policy.Userdata(data=f"{kind}={ident};".encode()),
        )

    def _send(self, guid, seq, msg, typename):
        body = bytes(self.node.store.serialize_cdr(msg, typename))
        data = body[:4] + guid.to_bytes(8, "little") + seq.to_bytes(8, "little", signed=True) + body[4:]
        pad = -len(data) % 4
        data = data[:3] + bytes([data[3] | pad]) + data[4:] + bytes(pad)
        ddspy_write(self.writer._ref, data)

    def _run(self):
        while not self._stop:
            samples = ddspy_take(self.reader._ref, 0xFFFFFFFF, 16)
            if isinstance(samples, int) or not samples:
                time.sleep(0.005)
                continue
            for data, info in samples:
                if not info.valid_data:
                    continue
                data = bytes(data)
                guid, seq = int.from_bytes(data[4:12], "little"), int.from_bytes(data[12:20], "little", signed=True)
                body = data[:4] + data[20:]
                if self.handler is not None:
                    self.asking = (info.publication_handle, guid, seq)
                    reply = self.handler(self.node.store.deserialize_cdr(body, self.request))
                    if reply is not LATER:
                        self.reply(self.asking, reply)
                elif guid == self.guid:
                    with self.cond:
                        self.replies[seq] = self.node.store.deserialize_cdr(body, self.response)
                        self.cond.notify_all()

    def reply(self, asking, msg):
        """Answer the request `asking` (the `asking` of the handler that returned LATER)."""
        handle, guid, seq = asking
        self._client_reader(handle)
        self._send(guid, seq, msg, self.response)

    def _client_reader(self, handle, timeout=1.0):
        """rmw_send_response's check_for_response_reader: until the reply writer matched the reader
        whose `clientid` is the requesting writer's."""

        def clientid(endpoint):
            text = bytes(endpoint.qos[Policy.Userdata].data).decode() if Policy.Userdata in endpoint.qos else ""
            return next((i for i in text.split(";") if i.startswith("clientid=")), None)

        try:
            wanted = clientid(self.reader.get_matched_publication_data(handle))
        except Exception:
            return
        deadline = time.monotonic() + timeout
        while wanted and time.monotonic() < deadline:
            for h in self.writer.get_matched_subscriptions():
                try:
                    if clientid(self.writer.get_matched_subscription_data(h)) == wanted:
                        return
                except Exception:
                    pass
            time.sleep(0.005)

    def new_request(self, **fields):
        return new_message(self.node.store, self.request, **fields)

    def new_response(self, **fields):
        return new_message(self.node.store, self.response, **fields)

    def ready(self) -> bool:
        return bool(
            self.writer.get_publication_matched_status().current_count
            and self.reader.get_subscription_matched_status().current_count
        )

    def call(self, request, timeout: float = 30.0):
        """rclpy's Client.call: send, then wait for the reply with this request's seq."""
        deadline = time.monotonic() + timeout
        while not self.ready():
            if time.monotonic() >= deadline:
                raise TimeoutError(f"no service {self.name}")
            time.sleep(0.005)
        with self.cond:
            self.seq += 1
            seq = self.seq
        self._send(self.guid, seq, request, self.request)
        with self.cond:
            if not self.cond.wait_for(lambda: seq in self.replies, max(0.0, deadline - time.monotonic())):
                raise TimeoutError(f"no reply from {self.name}")
            return self.replies.pop(seq)

    def close(self):
        self._stop = True
        self.thread.join(2.0)
        self.reader.__del__()
        self.writer.__del__()


def new_message(store, typename: str, **fields):
    """A message of `store` with ROS defaults for the omitted fields."""
    import numpy as np

    args = {}
    for name, (kind, detail) in store.fielddefs[typename][1]:
        if name in fields:
            args[name] = fields[name]
        elif kind == Nodetype.BASE:
            args[name] = (
                ""
                if detail[0] == "string"
                else False
                if detail[0] == "bool"
                else 0.0
                if detail[0].startswith("float")
                else 0
            )
        elif kind == Nodetype.NAME:
            args[name] = new_message(store, detail)
        else:
            element, size = detail
            if element[0] == Nodetype.BASE and element[1][0] != "string":
                dtype = {"float32": np.float32, "float64": np.float64, "bool": np.bool_}.get(element[1][0], np.int64)
                args[name] = np.zeros(size if kind == Nodetype.ARRAY else 0, dtype=dtype)
            else:
                args[name] = [
                    new_message(store, element[1]) if element[0] == Nodetype.NAME else ""
                    for _ in range(size if kind == Nodetype.ARRAY else 0)
                ]
    return store.types[typename](**args)


def summary(msg) -> dict:
    """A few fields of a message, for the command line's JSON lines."""
    out = {"type": msg.__msgtype__}
    header = getattr(msg, "header", None)
    if header is not None:
        out["stamp"] = header.stamp.sec + header.stamp.nanosec * 1e-9
        out["frame_id"] = header.frame_id
    twist = getattr(msg, "twist", None)
    if msg.__msgtype__ == "geometry_msgs/msg/Twist":
        twist = msg
    elif msg.__msgtype__ == "nav_msgs/msg/Odometry":
        out["x"] = float(msg.pose.pose.position.x)
        twist = msg.twist.twist
    if twist is not None and hasattr(twist, "linear"):
        out["linear"], out["angular"] = float(twist.linear.x), float(twist.angular.z)
    if hasattr(msg, "range"):
        out["range"] = float(msg.range)
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--distro", default="jazzy", choices=tuple(STORES))
    commands = parser.add_subparsers(dest="command", required=True)
    listen = commands.add_parser("listen", help="print each message heard (a JSON line)")
    listen.add_argument("topic")
    listen.add_argument("type")
    publish = commands.add_parser("publish", help="publish default messages of TYPE at RATE Hz")
    publish.add_argument("topic")
    publish.add_argument("type")
    publish.add_argument("--rate", type=float, default=20.0)
    navigate = commands.add_parser("navigate", help="a stand-in Nav2 server of /navigate_to_pose")
    navigate.add_argument("--steps", type=int, default=10, help="feedback messages before the goal succeeds")
    navigate.add_argument("--period", type=float, default=0.1, help="seconds between feedback messages")
    args = parser.parse_args(argv)
    node = Node(args.distro)
    try:
        if args.command == "listen":

            def show(msg):
                print(json.dumps({**summary(msg), "received": time.time()}), flush=True)

            node.create_subscription(args.type, args.topic, callback=show)
            print(json.dumps({"ready": True}), flush=True)
            threading.Event().wait()
        elif args.command == "navigate":
            from rmw_twin_actions import navigate_server  # a cycle: the actions are built on this module's node

            navigate_server(node, args.steps, args.period)
            print(json.dumps({"ready": True}), flush=True)
            threading.Event().wait()
        else:
            pub = node.create_publisher(args.type, args.topic)
            print(json.dumps({"ready": True}), flush=True)
            while True:
                pub.publish(pub.new())
                time.sleep(1.0 / args.rate)
    except KeyboardInterrupt:
        return 0
    finally:
        node.close()


if __name__ == "__main__":
    sys.exit(main())
