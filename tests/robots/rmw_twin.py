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


class GraphReader:
    """The ROS graph as rmw_dds_common's GraphCache builds it (rmw_dds_common/src/graph_cache.cpp,
    jazzy): participants with `enclave=` user data (DCPSParticipant), endpoints (DCPSPublication,
    DCPSSubscription: topic, type, participant), and each participant's last
    rmw_dds_common/msg/ParticipantEntitiesInfo on `ros_discovery_info`, decoded with the
    distribution's store (its Gid: 24 bytes in Humble, 16 later). rmw_cyclonedds_cpp's reader of
    that topic (rmw_node.cpp, rmw_context_impl_s::init): reliable, transient local, keep all,
    ignoring its own participant; a gid is the 16-byte GUID, zero-filled to the Gid's size."""

    def __init__(self, node: Node):
        from cyclonedds.builtin import (
            BuiltinDataReader,
            BuiltinTopicDcpsParticipant,
            BuiltinTopicDcpsPublication,
            BuiltinTopicDcpsSubscription,
        )

        self.node = node
        history = Policy.History.KeepAll
        policies = [
            Policy.WriterDataLifecycle(autodispose=False),
            history,
            Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
            Policy.Durability.TransientLocal,
            Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
            Policy.IgnoreLocal.Participant,
        ]
        typename = "rmw_dds_common/msg/ParticipantEntitiesInfo"
        if node.distro != "humble":
            policies.append(Policy.Userdata(data=f"typehash={node.store.hash_rihs01(typename)};".encode()))
        self.topic = Topic(node.participant, "ros_discovery_info", node.idl(typename))
        self.reader = DataReader(node.participant, self.topic, qos=Qos(*policies))
        self.builtin = {
            kind: BuiltinDataReader(node.participant, topic)
            for kind, topic in (
                ("participant", BuiltinTopicDcpsParticipant),
                ("writer", BuiltinTopicDcpsPublication),
                ("reader", BuiltinTopicDcpsSubscription),
            )
        }
        self.alive = {
            kind: ReadCondition(reader, SampleState.Any | ViewState.Any | InstanceState.Alive)
            for kind, reader in self.builtin.items()
        }
        self.infos: dict = {}  # participant gid (16 bytes) -> the last ParticipantEntitiesInfo
        self.size = 24 if node.distro == "humble" else 16
        self.gid_sizes: list = []  # the Gid sizes seen on the wire

    def _gid(self, key) -> bytes:
        return key.bytes  # the GUID; the Gid of the message is this, zero-filled

    def refresh(self) -> None:
        samples = ddspy_take(self.reader._ref, 0xFFFFFFFF, 64)
        for data, info in samples if not isinstance(samples, int) else ():
            if not info.valid_data:
                continue
            msg = self.node.store.deserialize_cdr(bytes(data), "rmw_dds_common/msg/ParticipantEntitiesInfo")
            raw = bytes(msg.gid.data)
            self.gid_sizes.append(len(raw))
            self.infos[raw[:16]] = msg

    def enclaves(self) -> dict:
        """{participant GUID bytes: enclave} of the participants that said one."""
        found = {}
        for sample in self.builtin["participant"].read(N=256, condition=self.alive["participant"]) or ():
            text = bytes(sample.qos[Policy.Userdata].data).decode() if Policy.Userdata in sample.qos else ""
            for item in text.split(";"):
                if item.startswith("enclave="):
                    found[self._gid(sample.key)] = item[len("enclave=") :]
        return found

    def nodes(self) -> list:
        """Full names of the nodes of the graph (`ros2 node list`)."""
        self.refresh()
        names = []
        for info in self.infos.values():
            for n in info.node_entities_info_seq:
                names.append(n.node_namespace.rstrip("/") + "/" + n.node_name)
        return sorted(names)

    def endpoints(self, topic: str) -> list:
        """[(kind "writer"/"reader", ROS type, node name)] of `topic` as `ros2 topic info -v` names
        them (graph_cache.cpp __find_name_and_namespace_from_entity_gid)."""
        self.refresh()
        enclaves = self.enclaves()
        found = []
        for kind in ("writer", "reader"):
            for sample in self.builtin[kind].read(N=1024, condition=self.alive[kind]) or ():
                if sample.topic_name != "rt" + topic:
                    continue
                gid, owner = self._gid(sample.key), self._gid(sample.participant_key)
                name = "_CREATED_BY_BARE_DDS_APP_"
                if owner in enclaves:
                    name = "_NODE_NAME_UNKNOWN_"
                    for n in getattr(self.infos.get(owner), "node_entities_info_seq", ()):
                        gids = n.writer_gid_seq if kind == "writer" else n.reader_gid_seq
                        if any(bytes(g.data)[:16] == gid for g in gids):
                            name = n.node_namespace.rstrip("/") + "/" + n.node_name
                parts = sample.type_name.split("::")
                ros_type = f"{parts[0]}/{parts[1]}/{parts[3][:-1]}" if len(parts) == 4 else sample.type_name
                found.append((kind, ros_type, name))
        return sorted(found)

    def wait_for(self, predicate, timeout: float = 30.0) -> bool:
        """Until `predicate(self)` holds (discovery and the transient-local sample take a moment)."""
        deadline = time.monotonic() + timeout
        while not predicate(self):
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.02)
        return True

    def close(self):
        for kind, reader in self.builtin.items():
            self.alive[kind].__del__()
            reader.__del__()
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


#: `.action` definitions the twin knows: ros-navigation/navigation2 nav2_msgs (branch humble, branch
#: jazzy; Lyrical taken from main as of 2026-05-22) and ros2/example_interfaces
_POSE_GOAL = "geometry_msgs/PoseStamped pose\nstring behavior_tree"
_NAV_FEEDBACK = (
    "geometry_msgs/PoseStamped current_pose\nbuiltin_interfaces/Duration navigation_time\n"
    "builtin_interfaces/Duration estimated_time_remaining\nint16 number_of_recoveries\nfloat32 distance_remaining"
)
ACTIONS = {
    ("nav2_msgs/action/NavigateToPose", "humble"): (_POSE_GOAL, "std_msgs/Empty result", _NAV_FEEDBACK),
    ("nav2_msgs/action/NavigateToPose", "jazzy"): (
        _POSE_GOAL,
        "uint16 NONE=0\nuint16 error_code\nstring error_msg",
        _NAV_FEEDBACK,
    ),
    ("nav2_msgs/action/NavigateToPose", "lyrical"): (
        _POSE_GOAL,
        "uint16 NONE=0\nuint16 UNKNOWN=9000\nuint16 FAILED_TO_LOAD_BEHAVIOR_TREE=9001\nuint16 TF_ERROR=9002\n"
        "uint16 TIMEOUT=9003\nuint16 error_code\nstring error_msg",
        _NAV_FEEDBACK + "\nfloat32 position_tracking_error\nfloat32 heading_tracking_error",
    ),
    **{
        ("example_interfaces/action/Fibonacci", d): ("int32 order", "int32[] sequence", "int32[] sequence")
        for d in STORES
    },
}
#: action_msgs/srv/CancelGoal (ros2/rcl_interfaces)
SRVS["action_msgs/srv/CancelGoal"] = (
    "action_msgs/GoalInfo goal_info",
    "int8 ERROR_NONE=0\nint8 ERROR_REJECTED=1\nint8 ERROR_UNKNOWN_GOAL_ID=2\nint8 ERROR_GOAL_TERMINATED=3\n"
    "int8 return_code\naction_msgs/GoalInfo[] goals_canceling",
)


def register_action(node: Node, actiontype: str) -> None:
    """The action's types in the node's store, as rosidl's Action derives them
    (rosidl_parser/definition.py): Goal, Result, Feedback, SendGoal_Request {goal_id, goal},
    SendGoal_Response {accepted, stamp}, GetResult_Request {goal_id}, GetResult_Response
    {status, result}, FeedbackMessage {goal_id, feedback}."""
    from rosbags.typesys import get_types_from_msg

    package, _, short = actiontype.split("/")
    goal, result, feedback = ACTIONS[(actiontype, node.distro)]
    texts = {
        "Goal": goal,
        "Result": result,
        "Feedback": feedback,
        "SendGoal_Request": f"unique_identifier_msgs/UUID goal_id\n{package}/{short}_Goal goal",
        "SendGoal_Response": "bool accepted\nbuiltin_interfaces/Time stamp",
        "GetResult_Request": "unique_identifier_msgs/UUID goal_id",
        "GetResult_Response": f"int8 status\n{package}/{short}_Result result",
        "FeedbackMessage": f"unique_identifier_msgs/UUID goal_id\n{package}/{short}_Feedback feedback",
    }
    found = {}
    for suffix, text in texts.items():
        for key, value in get_types_from_msg(text, f"{package}/msg/{short}_{suffix}").items():
            fields = [
                (
                    n,
                    (k, d.replace(f"{package}/msg/{short}_", f"{package}/action/{short}_"))
                    if isinstance(d, str)
                    else (k, d),
                )
                for n, (k, d) in value[1]
            ]
            found[key.replace("/msg/", "/action/") if key.endswith(f"{short}_{suffix}") else key] = (value[0], fields)
    node.store.register(found)


def _status_qos(node: Node, typename: str) -> Qos:
    """rcl_action_qos_profile_status_default (rcl_action/default_qos.h) through create_readwrite_qos:
    keep last 1, reliable, transient local (with Cyclone's durability service), automatic liveliness."""
    history = Policy.History.KeepLast(1)
    policies = [
        Policy.WriterDataLifecycle(autodispose=False),
        history,
        Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
        Policy.Durability.TransientLocal,
        Policy.DurabilityService(
            cleanup_delay=0, history=history, max_samples=-1, max_instances=-1, max_samples_per_instance=-1
        ),
        Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
    ]
    if node.distro != "humble":
        policies.append(Policy.Userdata(data=f"typehash={node.store.hash_rihs01(typename)};".encode()))
    return Qos(*policies)


def _uuid_msg(store, raw: bytes):
    import numpy as np

    return new_message(store, "unique_identifier_msgs/msg/UUID", uuid=np.frombuffer(raw, dtype=np.uint8).copy())


class TwinGoal:
    """A goal on the twin's action server: `goal`, `id`, `status`, `cancel_requested`."""

    def __init__(self, server, goal_id: bytes, goal, stamp):
        self.server, self.id, self.goal, self.stamp = server, goal_id, goal, stamp
        self.status, self.result, self.asking = 2, None, []  # executing at once (rclpy's default)

    @property
    def cancel_requested(self) -> bool:
        return self.status == 3

    def publish_feedback(self, **fields):
        server = self.server
        feedback = new_message(server.node.store, server.types["Feedback"], **fields)
        server.feedback.publish(
            new_message(
                server.node.store,
                server.types["FeedbackMessage"],
                goal_id=_uuid_msg(server.node.store, self.id),
                feedback=feedback,
            )
        )

    def finish(self, status: int, **fields):
        """4 succeeded, 5 canceled, 6 aborted; the result's fields."""
        server = self.server
        with server.lock:
            self.status = status
            self.result = new_message(
                server.node.store,
                server.types["GetResult_Response"],
                status=status,
                result=new_message(server.node.store, server.types["Result"], **fields),
            )
            asking, self.asking = self.asking, []
        server.publish_status()
        for each in asking:
            server.get_result.reply(each, self.result)


class TwinActionServer:
    """An action server as rcl_action makes one on rmw_cyclonedds_cpp (rcl_action/names.c,
    action_server.c, default_qos.h): three services `<name>/_action/send_goal|cancel_goal|get_result`,
    the feedback topic (ROS's default QoS) and the status topic (transient local, keep last 1).
    `execute(goal)` runs on a thread of its own for each accepted goal (every goal is accepted);
    every cancel request of an executing goal is accepted."""

    def __init__(self, node: Node, actiontype: str, name: str, execute):
        register_action(node, actiontype)
        self.node, self.name, self.execute = node, name, execute
        self.types = {
            s: f"{actiontype}_{s}"
            for s in ("Goal", "Result", "Feedback", "FeedbackMessage", "GetResult_Response", "SendGoal_Response")
        }
        self.lock = threading.RLock()
        self.goals: dict = {}
        self.events: list = []  # ("goal", id), ("cancel", id), ...
        prefix = f"{name}/_action/"
        self.send_goal = node.create_service(f"{actiontype}_SendGoal", prefix + "send_goal", self._send_goal)
        self.cancel_goal = node.create_service("action_msgs/srv/CancelGoal", prefix + "cancel_goal", self._cancel)
        self.get_result = node.create_service(f"{actiontype}_GetResult", prefix + "get_result", self._get_result)
        self.feedback = node.create_publisher(self.types["FeedbackMessage"], prefix + "feedback")
        status_type = "action_msgs/msg/GoalStatusArray"
        self.status = Publisher(node, status_type, prefix + "status", 1, qos=_status_qos(node, status_type))
        self.publish_status()

    def publish_status(self):
        store = self.node.store
        with self.lock:
            entries = [
                new_message(
                    store,
                    "action_msgs/msg/GoalStatus",
                    goal_info=new_message(
                        store, "action_msgs/msg/GoalInfo", goal_id=_uuid_msg(store, g.id), stamp=g.stamp
                    ),
                    status=g.status,
                )
                for g in self.goals.values()
            ]
            self.status.publish(new_message(store, "action_msgs/msg/GoalStatusArray", status_list=entries))

    def _send_goal(self, request):
        store = self.node.store
        now = time.time()
        stamp = new_message(store, "builtin_interfaces/msg/Time", sec=int(now), nanosec=int((now % 1) * 1e9))
        goal = TwinGoal(self, bytes(request.goal_id.uuid), request.goal, stamp)
        with self.lock:
            self.goals[goal.id] = goal
            self.events.append(("goal", goal.id))
        self.publish_status()
        threading.Thread(target=self.execute, args=(goal,), daemon=True).start()
        return new_message(store, self.types["SendGoal_Response"], accepted=True, stamp=stamp)

    def _cancel(self, request):
        wanted = bytes(request.goal_info.goal_id.uuid)
        with self.lock:
            self.events.append(("cancel", wanted))
            goal = self.goals.get(wanted)
            code = 2 if goal is None else 3 if goal.status not in (1, 2) else 0
            if code == 0:
                goal.status = 3
        self.publish_status()
        infos = [] if code else [request.goal_info]
        return new_message(
            self.node.store, "action_msgs/srv/CancelGoal_Response", return_code=code, goals_canceling=infos
        )

    def _get_result(self, request):
        with self.lock:
            goal = self.goals.get(bytes(request.goal_id.uuid))
            if goal is not None and goal.result is None:
                goal.asking.append(self.get_result.asking)
                return LATER
        if goal is None:
            return new_message(self.node.store, self.types["GetResult_Response"], status=0)
        return goal.result


class TwinActionClient:
    """An action client as rcl_action makes one (rclpy's ActionClient's calls, blocking)."""

    def __init__(self, node: Node, actiontype: str, name: str):
        register_action(node, actiontype)
        self.node, self.actiontype = node, actiontype
        prefix = f"{name}/_action/"
        self.send_goal_end = node.create_client(f"{actiontype}_SendGoal", prefix + "send_goal")
        self.cancel_end = node.create_client("action_msgs/srv/CancelGoal", prefix + "cancel_goal")
        self.result_end = node.create_client(f"{actiontype}_GetResult", prefix + "get_result")
        self.feedback = node.create_subscription(f"{actiontype}_FeedbackMessage", prefix + "feedback")
        status_type = "action_msgs/msg/GoalStatusArray"
        self.status = Subscription(node, status_type, prefix + "status", 1, qos=_status_qos(node, status_type))

    def send_goal(self, timeout=30.0, **fields) -> bytes:
        """Send a goal (its fields); its id once accepted (AssertionError if rejected). Waits first
        until the server's feedback and status writers matched (no early feedback missed)."""
        import uuid

        deadline = time.monotonic() + timeout
        while not (self.feedback.matched() and self.status.matched()):
            assert time.monotonic() < deadline, "no action server"
            time.sleep(0.005)
        store = self.node.store
        goal_id = uuid.uuid4().bytes
        goal = new_message(store, f"{self.actiontype}_Goal", **fields)
        request = self.send_goal_end.new_request(goal_id=_uuid_msg(store, goal_id), goal=goal)
        assert self.send_goal_end.call(request, timeout).accepted
        return goal_id

    def result(self, goal_id: bytes, timeout=30.0):
        """The GetResult response (status, result) of a goal, waiting until it ended."""
        return self.result_end.call(self.result_end.new_request(goal_id=_uuid_msg(self.node.store, goal_id)), timeout)

    def cancel(self, goal_id: bytes, timeout=30.0):
        store = self.node.store
        info = new_message(store, "action_msgs/msg/GoalInfo", goal_id=_uuid_msg(store, goal_id))
        return self.cancel_end.call(self.cancel_end.new_request(goal_info=info), timeout)

    def feedback_of(self, goal_id: bytes) -> list:
        return [m.feedback for m in list(self.feedback.messages) if bytes(m.goal_id.uuid) == goal_id]

    def statuses_of(self, goal_id: bytes) -> list:
        """Each status the status topic said for the goal, in order, repeats left out."""
        seen = []
        for array in list(self.status.messages):
            for entry in array.status_list:
                if bytes(entry.goal_info.goal_id.uuid) == goal_id and (not seen or seen[-1] != entry.status):
                    seen.append(int(entry.status))
        return seen


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


def navigate_server(node: Node, steps: int, period: float) -> TwinActionServer:
    """A stand-in of Nav2's bt_navigator: /navigate_to_pose accepts every goal, publishes `steps`
    feedback messages `period` s apart (distance_remaining shrinking to 0), then succeeds; a
    cancel request ends the goal CANCELED at the next step. Each event is a JSON line."""

    def execute(goal):
        position = goal.goal.pose.pose.position
        print(
            json.dumps({"goal": [float(position.x), float(position.y)], "frame": goal.goal.pose.header.frame_id}),
            flush=True,
        )
        distance = (float(position.x) ** 2 + float(position.y) ** 2) ** 0.5
        for step in range(steps):
            if goal.cancel_requested:
                goal.finish(5)
                print(json.dumps({"canceled": step}), flush=True)
                return
            goal.publish_feedback(distance_remaining=distance * (1 - (step + 1) / steps))
            time.sleep(period)
        goal.finish(4)
        print(json.dumps({"succeeded": steps}), flush=True)

    return TwinActionServer(node, "nav2_msgs/action/NavigateToPose", "/navigate_to_pose", execute)


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
