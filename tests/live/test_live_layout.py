"""docs/foxglove/scoopc-layout.json, the Foxglove layout of docs/LIVE.md: every panel is of a type
Foxglove has, every topic it reads is one a `--live` run publishes, and every message path names
a field of that channel's JSON schema."""

import json
import re
from pathlib import Path

from scoopc.driver import live

LAYOUT = Path(__file__).parents[2] / "docs" / "foxglove" / "scoopc-layout.json"

# Panel types of Foxglove's layout files (the part of a panel's id before "!", as Foxglove exports a
# layout), for the panels documented under https://docs.foxglove.dev/docs/visualization/panels/
# (3d, plot, table, state-transitions, raw-messages, log): the Log panel's type is "RosOut".
PANEL_TYPES = {"3D", "Plot", "Table", "StateTransitions", "RawMessages", "RosOut"}
LIVE_TOPICS = set(live.SCHEMAS)


def _layout():
    return json.loads(LAYOUT.read_text())


def _leaves(node):
    if isinstance(node, str):
        return [node]
    return _leaves(node["first"]) + _leaves(node["second"])


def _paths(config_by_id):
    """(panel, message path) for every message path the panels read."""
    for panel, config in config_by_id.items():
        for path in config.get("paths", []):
            yield panel, path["value"]
        for key in ("topicPath", "topicToRender"):
            if key in config:
                yield panel, config[key]
        for topic in config.get("topics", {}):
            yield panel, topic


def _field(schema, steps):
    """Follow `steps` (field names; [n] and [:] index arrays) in a JSON schema; None if absent."""
    for step in steps:
        if schema.get("type") == "array":
            schema = schema["items"]
        schema = schema.get("properties", {}).get(step)
        if schema is None:
            return None
    return schema


def test_the_layout_has_only_known_panel_types_laid_out_once_each():
    layout = _layout()
    panels = layout["configById"]
    assert {panel.split("!")[0] for panel in panels} <= PANEL_TYPES
    assert sorted(_leaves(layout["layout"])) == sorted(panels)


def test_the_layout_reads_only_channels_and_fields_a_live_run_publishes():
    seen = set()
    for panel, path in _paths(_layout()["configById"]):
        topic, _, rest = path.partition(".")
        assert topic in LIVE_TOPICS, f"{panel} reads {topic}, which a --live run does not publish"
        seen.add(topic)
        steps = [s for s in re.sub(r"\[[^\]]*\]|\{[^}]*\}", "", rest).split(".") if s]
        assert _field(live.SCHEMAS[topic][1], steps) is not None, f"{panel}: no field {rest} in {topic}"
    assert {"/sim/scene", "/sim/robots", "/scoop/processors", "/scoop/waits", "/scoop/events"} <= seen


def test_the_log_panel_reads_a_foxglove_log_channel():
    (config,) = [c for p, c in _layout()["configById"].items() if p.startswith("RosOut!")]
    assert live.SCHEMAS[config["topicToRender"]][0] == "foxglove.Log"
