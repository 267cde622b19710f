"""`--record run.mcap` on a simulated run: run.mcap stays a rosbag2 MCAP file (ROS 2 types only,
read back with rosbags) and the live channels go to run.scoop.mcap beside it (JSON, on the
recording's simulated clock)."""

import json
from pathlib import Path

from mcap.reader import make_reader
from rosbags.rosbag2 import Reader

from scoopc import cli
from scoopc.driver import live
from scoopc.exits import Exit

EXPLORATION = Path(__file__).parents[2] / "samples" / "exploration"


def test_record_keeps_the_rosbag_and_writes_the_live_channels_beside_it(tmp_path, capsys):
    bag = tmp_path / "run.mcap"
    code = cli.main(["run", str(EXPLORATION), "--duration", "1", "--no-png", "--record", str(bag)])
    assert code == Exit.OK, capsys.readouterr().err
    with Reader(bag) as reader:
        topics = {c.topic for c in reader.connections}
        assert "/robot1/odom" in topics and not any(t.startswith(("/scoop", "/sim")) for t in topics)
        assert reader.message_count > 0
    found: dict[str, list] = {}
    with open(tmp_path / "run.scoop.mcap", "rb") as f:
        for schema, channel, message in make_reader(f).iter_messages(log_time_order=True):
            assert (channel.message_encoding, schema.encoding) == ("json", "jsonschema")
            assert schema.name == live.SCHEMAS[channel.topic][0]
            found.setdefault(channel.topic, []).append((message.log_time, json.loads(message.data)))
    assert {"/scoop/processors", "/sim/scene", "/sim/robots"} <= set(found)
    assert all(t <= 1_100_000_000 for t, _ in found["/sim/robots"])  # the simulated clock
    assert any(p["class"] == "SIMPLE_CONTROLLER" for _, m in found["/scoop/processors"] for p in m["processors"])
