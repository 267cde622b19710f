"""A DdsBus as a node of the ROS graph: the participant's `ros_discovery_info` sample
(rmw_dds_common/msg/ParticipantEntitiesInfo) listing the node and its readers and writers, as
rmw_dds_common's graph cache expects it, so that `ros2 node list` shows the node and
`ros2 topic info -v` names it.

Facts followed (read, never run against ROS 2 here):
* rmw_cyclonedds_cpp/src/rmw_node.cpp (jazzy and humble branches), rmw_context_impl_s::init: the
  topic `ros_discovery_info` (no `rt/` prefix: avoid_ros_namespace_conventions), its writer reliable,
  transient local, keep last 1 (readers keep all and ignore their own participant); QoS as
  create_readwrite_qos makes it (autodispose off, infinite blocking time and lease, the type hash in
  the user data from Iron on).
* rmw_node.cpp convert_guid_to_gid: a gid is the 16-byte DDS GUID followed by zeros;
  rmw_dds_common/msg/Gid.msg is `char[24] data` in Humble and `char[16] data` from Jazzy on.
* rmw_dds_common/src/graph_cache.cpp: update_participant_entities keeps the last sample of each
  participant; an endpoint is named after the node whose reader_gid_seq or writer_gid_seq lists
  its gid; a participant without `enclave=` user data is a bare DDS application.
* rcl: a node without a namespace has the namespace "/".
"""

from __future__ import annotations

import threading

import numpy as np
from cyclonedds._clayer import ddspy_write
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from . import cdr, ros_messages
from .dds import frame, idl_type

TOPIC = "ros_discovery_info"
TYPE = "rmw_dds_common/msg/ParticipantEntitiesInfo"


def node_namespace(namespace: str | None) -> str:
    """rcl's form of a node namespace: "/" for none, else "/a/b" (no trailing slash)."""
    parts = [p for p in (namespace or "").split("/") if p]
    return "/" + "/".join(parts)


def gid_bytes(guid, distro: str) -> bytes:
    """A DDS GUID (uuid.UUID or 16 bytes) as the distribution's Gid data (24 bytes in Humble)."""
    raw = guid.bytes if hasattr(guid, "bytes") else bytes(guid)
    return raw + bytes(24 - len(raw)) if distro == "humble" else raw


def discovery_qos(distro: str, reader: bool = False) -> Qos:
    """The QoS of ros_discovery_info's writer (reader: keep all, ignoring its own participant)."""
    history = Policy.History.KeepAll if reader else Policy.History.KeepLast(1)
    policies = [
        Policy.WriterDataLifecycle(autodispose=False),
        history,
        Policy.Reliability.Reliable(max_blocking_time=duration(infinite=True)),
        Policy.Durability.TransientLocal,
        Policy.DurabilityService(
            cleanup_delay=0,
            history=history,
            max_samples=-1,
            max_instances=-1,
            max_samples_per_instance=-1,
        ),
        Policy.Liveliness.Automatic(lease_duration=duration(infinite=True)),
    ]
    if reader:
        policies.append(Policy.IgnoreLocal.Participant)
    if distro != "humble":
        store = ros_messages.store_of(distro)
        policies.append(Policy.Userdata(data=f"typehash={store.hash_rihs01(TYPE)};".encode()))
    return Qos(*policies)


def entities_info(participant_gid: bytes, nodes, distro: str):
    """A ParticipantEntitiesInfo of the distribution: `nodes` is [(namespace, name, reader gids,
    writer gids)] with gids as the distribution's Gid bytes."""
    store = ros_messages.store_of(distro)

    def gid(data):
        return ros_messages.new("rmw_dds_common/msg/Gid", store=store, data=_octets(data))

    return ros_messages.new(
        TYPE,
        store=store,
        gid=gid(participant_gid),
        node_entities_info_seq=[
            ros_messages.new(
                "rmw_dds_common/msg/NodeEntitiesInfo",
                store=store,
                node_namespace=namespace,
                node_name=name,
                reader_gid_seq=[gid(g) for g in readers],
                writer_gid_seq=[gid(g) for g in writers],
            )
            for namespace, name, readers, writers in nodes
        ],
    )


def _octets(data: bytes):
    return np.frombuffer(data, dtype=np.uint8).copy()


class GraphNode:
    """The node of one DdsBus in the ROS graph: publishes the participant's entities on
    ros_discovery_info now and after every change of its readers and writers (`changed()`)."""

    def __init__(self, bus, name: str, namespace: str | None = None):
        self.bus, self.name, self.namespace = bus, name, node_namespace(namespace)  # the name checked by the caller
        self.distro = bus.distro
        self.store = ros_messages.store_of(self.distro)
        self._lock = threading.Lock()
        self._last = None  # [_lock] the last sample written
        self.topic = Topic(bus.participant, TOPIC, idl_type(TYPE, self.store))
        self.writer = DataWriter(bus.participant, self.topic, qos=discovery_qos(self.distro))
        self.participant_gid = gid_bytes(bus.participant.guid, self.distro)
        bus.entity_hooks.append(self.changed)
        bus.owned.append(self)
        self.changed()

    def sample(self):
        readers, writers = self.bus.endpoint_guids()
        nodes = [
            (
                self.namespace,
                self.name,
                [gid_bytes(g, self.distro) for g in readers],
                [gid_bytes(g, self.distro) for g in writers],
            )
        ]
        return entities_info(self.participant_gid, nodes, self.distro)

    def changed(self) -> None:
        """Publish the node's entities if they differ from the last sample written."""
        data = cdr.serialize(self.sample(), TYPE, self.store)
        with self._lock:
            if data == self._last:
                return
            self._last = data
            ret = ddspy_write(self.writer._ref, frame(data))
        if ret < 0:
            raise RuntimeError(f"DDS write on {TOPIC} failed ({ret})")

    def close(self) -> None:
        if self.changed in self.bus.entity_hooks:
            self.bus.entity_hooks.remove(self.changed)
        self.writer.__del__()
        self.topic.__del__()
