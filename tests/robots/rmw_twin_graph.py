"""The ROS graph as a stock node reads it, for the tests: the twin of rmw_dds_common's GraphCache
(tests/robots/rmw_twin.py has the node itself)."""

from __future__ import annotations

import time

from cyclonedds._clayer import ddspy_take
from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration
from rmw_twin import Node


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
