"""How a ROS 2 participant finds others: the discovery settings rcl reads from the environment
(ROS_LOCALHOST_ONLY, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS) turned into a Cyclone DDS
configuration as rmw_cyclonedds_cpp builds it, the process's DDS domains (one per id, reference
counted), and the loopback configuration the tests and benchmarks use."""

from __future__ import annotations

import os
import threading
from pathlib import Path

RANGES = ("SUBNET", "LOCALHOST", "OFF", "SYSTEM_DEFAULT")


class DiscoveryError(ValueError):
    """Discovery settings that cannot be used (two buses of one process asking different ones)."""


def discovery_settings(distro: str, environ=None) -> tuple[str, list[str], list[str]]:
    """(range, static peers, warnings) from the environment, as rcl reads it for `distro`.

    Humble (rcl/src/rcl/localhost.c, rcl_get_localhost_only, humble branch): only
    ROS_LOCALHOST_ONLY exists; "1" is "LOCALHOST_ONLY", else "SUBNET" (Humble's default).
    Jazzy and later (rcl/src/rcl/init.c rcl_init and discovery_options.c, rcl 9.2):
    ROS_LOCALHOST_ONLY=1 still wins (deprecated) and means LOCALHOST without static peers;
    else ROS_AUTOMATIC_DISCOVERY_RANGE ("" is SUBNET, an unknown value LOCALHOST with a warning)
    and ROS_STATIC_PEERS (";"-separated, not read when the range is OFF)."""
    environ = os.environ if environ is None else environ
    warnings = []
    localhost = environ.get("ROS_LOCALHOST_ONLY", "")
    if distro == "humble":
        if "ROS_AUTOMATIC_DISCOVERY_RANGE" in environ or "ROS_STATIC_PEERS" in environ:
            warnings.append(
                "ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS do not exist in Humble: "
                "ignored (ROS_LOCALHOST_ONLY=1 keeps discovery on this machine)"
            )
        return ("LOCALHOST_ONLY" if localhost == "1" else "SUBNET"), [], warnings
    if localhost.startswith("1"):
        warnings.append(
            "ROS_LOCALHOST_ONLY is deprecated but still honored: discovery range LOCALHOST, "
            "ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS ignored"
        )
        return "LOCALHOST", [], warnings
    value = environ.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "")
    if value == "":
        rng = "SUBNET"
    elif value in RANGES:
        rng = value
    else:
        warnings.append(
            f"invalid ROS_AUTOMATIC_DISCOVERY_RANGE={value!r}: assuming LOCALHOST (valid: {', '.join(RANGES)})"
        )
        rng = "LOCALHOST"
    peers = [] if rng == "OFF" else [p for p in environ.get("ROS_STATIC_PEERS", "").split(";") if p]
    if peers and rng == "SYSTEM_DEFAULT":
        warnings.append(f"{len(peers)} static peers were given, but the discovery range is SYSTEM_DEFAULT: ignored")
    return rng, peers, warnings


def discovery_config(distro: str, environ=None, pid: int | None = None) -> tuple[str, str, list[str]]:
    """(Cyclone DDS configuration, a short description, warnings) of a participant's domain, built
    as rmw_cyclonedds_cpp builds it (rmw_cyclonedds_cpp/src/rmw_node.cpp, check_create_domain:
    humble branch for ROS_LOCALHOST_ONLY, jazzy branch for the discovery range and static peers),
    CYCLONEDDS_URI appended after our fragment (so its settings win where both set one)."""
    environ = os.environ if environ is None else environ
    rng, peers, warnings = discovery_settings(distro, environ)
    if rng == "LOCALHOST_ONLY":  # humble: bind to the loopback interface
        config = (
            '<CycloneDDS><Domain><General><Interfaces><NetworkInterface address="127.0.0.1"/>'
            "</Interfaces></General></Domain></CycloneDDS>,"
        )
        text = "localhost only (ROS_LOCALHOST_ONLY=1)"
    elif distro == "humble":  # humble: nothing but CYCLONEDDS_URI
        config, text = "", "discovery as Cyclone DDS's configuration says"
    else:
        localhost_peer = rng == "LOCALHOST"
        add_peers = rng in ("SUBNET", "LOCALHOST")
        no_multicast = rng in ("LOCALHOST", "OFF")
        config = ""
        if localhost_peer or add_peers or no_multicast:
            config = "<CycloneDDS><Domain>"
            if no_multicast:
                config += "<General><AllowMulticast>false</AllowMulticast></General>"
            if no_multicast and not localhost_peer and not add_peers:  # OFF
                pid = os.getpid() if pid is None else pid
                config += f"<Discovery><ParticipantIndex>none</ParticipantIndex><Tag>ros_discovery_off_{pid}</Tag>"
            else:
                config += "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
                config += "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"
            if (add_peers and peers) or localhost_peer:
                config += "<Peers>"
                if localhost_peer:
                    config += '<Peer address="localhost"/>'
                config += "".join(f'<Peer address="{peer}"/>' for peer in peers if add_peers)
                config += "</Peers>"
            config += "</Discovery></Domain></CycloneDDS>,"
        text = f"discovery {rng}" + (f", static peers {', '.join(peers)}" if peers and add_peers else "")
    uri = environ.get("CYCLONEDDS_URI", "")
    config += uri
    if uri:
        text += ", CYCLONEDDS_URI"
    return config, text, warnings


_domains: dict = {}  # [_domains_lock] domain id -> [Domain, refcount, config]
_domains_lock = threading.Lock()


def _acquire_domain(domain: int, config: str):
    """Create the DDS domain with `config` (once per process and id, reference counted; a second
    bus asking other settings is refused, as rmw_cyclonedds_cpp's check_create_domain does)."""
    from cyclonedds.domain import Domain  # deferred: start-up (cyclonedds loads only when this is used)

    with _domains_lock:
        entry = _domains.get(domain)
        if entry is not None:
            if entry[2] != config:
                raise DiscoveryError(f"domain {domain} is already open in this process with other discovery settings")
            entry[1] += 1
            return True
        try:
            made = Domain(domain, config)
        except Exception:  # noqa: BLE001 - a participant made without us holds it
            return False
        _domains[domain] = [made, 1, config]
        return True


def _release_domain(domain: int) -> None:
    with _domains_lock:
        entry = _domains.get(domain)
        if entry is None:
            return
        entry[1] -= 1
        if entry[1] == 0:
            del _domains[domain]
            entry[0].__del__()


#: Cyclone DDS settings that keep every participant on 127.0.0.1 (no multicast, unicast discovery)
LOOPBACK_CONFIG = """<?xml version="1.0" encoding="UTF-8"?>
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain Id="any">
    <General>
      <Interfaces><NetworkInterface address="127.0.0.1"/></Interfaces>
      <AllowMulticast>false</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>50</MaxAutoParticipantIndex>
      <Peers><Peer address="127.0.0.1"/></Peers>
    </Discovery>
  </Domain>
</CycloneDDS>
"""


def loopback_environment(folder, domain: int) -> dict:
    """Environment variables binding DDS to loopback in `domain`: writes `folder`/cyclonedds.xml and
    returns {"CYCLONEDDS_URI": its file URI, "ROS_DOMAIN_ID": str(domain)} (set them before the
    first participant of a process exists, or pass them to a child process)."""
    path = Path(folder) / "cyclonedds.xml"
    path.write_text(LOOPBACK_CONFIG)
    return {"CYCLONEDDS_URI": path.resolve().as_uri(), "ROS_DOMAIN_ID": str(domain)}
