"""World files and robot profiles are read against one schema (scoopc/robots/yamlschema.py): every
mistake names file:line:col and the key's path, the run ends with exit 2, never a traceback or a hang."""

from pathlib import Path

import pytest

from scoopc import cli
from scoopc.robots import profile, yamlschema
from scoopc.robots.sim import world_schema
from scoopc.robots.sim.world import World, WorldError

from harness import check_golden

ROOT = Path(__file__).resolve().parents[2]

MISTAKES = [
    (
        "size: [5, 5\n",
        "world.yaml:2:1: not valid YAML",
    ),
    (
        "- a\n- b\n",
        "world.yaml:1:1: must be a mapping (key: value lines), not a list",
    ),
    (
        "robots:\n  - name: r\n    battery: 5\n",
        "world.yaml:3:14: robots[0].battery: must be a mapping (key: value lines), not 5",
    ),
    (
        "step: 0\n",
        "world.yaml:1:7: step: must be a number greater than 0 and at most 1, not 0",
    ),
    (
        "step: -0.01\n",
        "world.yaml:1:7: step: must be a number greater than 0",
    ),
    (
        "step: .nan\n",
        "world.yaml:1:7: step: must be a number",
    ),
    (
        "robots:\n  - kind: diff_drive\n    laser: {beams: 0}\n",
        "world.yaml:3:20: robots[0].laser.beams: must be a whole",
    ),
    (
        "robots:\n  - laser: {beams: 100000000}\n",
        "world.yaml:2:20: robots[0].laser.beams: must be a whole number from 1",
    ),
    (
        "a: &x [1, 2]\nsize: *x\n",
        "world.yaml:1:4: YAML anchors and aliases",
    ),
    (
        "boxs: []\n",
        "world.yaml:1:1: boxs: unknown key (did you mean `boxes`?",
    ),
    (
        "robots:\n  - battery: {capacty: 2}\n",
        "world.yaml:2:15: robots[0].battery.capacty: unknown key (did you mean `capacity`?",
    ),
    (
        "size: [-5, 5]\n",
        "world.yaml:1:8: size[0]: must be a number greater than 0",
    ),
    (
        "boxes:\n  - {center: [1, 1], size: [-1, 0.5]}\n",
        "world.yaml:2:29: boxes[0].size[0]: must be a number of at least 0",
    ),
    (
        "size: [2, 2]\nrobots:\n  - start: [3, 1, 0]\n",
        "world.yaml:3:12: robots[0].start: (3.0, 1.0) is outside the arena",
    ),
    (
        "robots:\n  - kind: tank\n",
        "world.yaml:2:11: robots[0].kind: must be one of thymio, diff_drive, turtlebot3",
    ),
    (
        "walls:\n  - {from: [0, 0]}\n",
        "world.yaml:2:5: walls[0]: needs to",
    ),
    (
        "holes:\n  - {polygon: [[0, 0], [1, 1]]}\n",
        "world.yaml:2:15: holes[0].polygon: must be a list of 3 to 10000 items",
    ),
    (
        "goal: [1, 2, 3]\n",
        "world.yaml:1:7: goal: must be a list of 2 items, not 3",
    ),
    (
        "charging_station: yes\n",
        "world.yaml:1:19: charging_station: must be a point [x, y] or a mapping",
    ),
    (
        "robots: []\n",
        "world.yaml:1:9: robots: must be a list of 1 to 64 items, not 0",
    ),
    (
        "seed: 1.5\n",
        "world.yaml:1:7: seed: must be a whole number, not 1.5",
    ),
    (
        "border: 0\n",
        "world.yaml:1:9: border: must be true or false, not 0",
    ),
]


@pytest.mark.parametrize(("text", "message"), MISTAKES, ids=[m[1].split(": ", 1)[1][:40] for m in MISTAKES])
def test_a_mistake_in_a_world_file_names_its_place(tmp_path, text, message):
    path = tmp_path / "world.yaml"
    path.write_text(text)
    with pytest.raises(WorldError) as caught:
        World.load(str(path))
    assert str(caught.value).replace(f"{tmp_path}/", "").startswith(message), str(caught.value)


def test_a_world_over_one_mebibyte_is_refused_before_it_is_parsed(tmp_path):
    path = tmp_path / "world.yaml"
    path.write_text("# " + "x" * yamlschema.MAX_BYTES + "\n")
    with pytest.raises(WorldError, match="larger than 1 MiB"):
        World.load(str(path))


def test_an_alias_bomb_is_refused_at_its_first_anchor(tmp_path):
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [*a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}]" for i in range(1, 30)]
    path = tmp_path / "world.yaml"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(WorldError, match=r"world.yaml:1:5: YAML anchors and aliases"):
        World.load(str(path))


def test_a_robot_profile_shares_the_loader(tmp_path):
    with pytest.raises(profile.ProfileError, match="robot.yaml:1:9: YAML anchors"):
        profile.parse("limits: &l {max_linear: 1}\n", "robot.yaml")
    with pytest.raises(profile.ProfileError, match=r"limits.max_lineer: unknown key \(did you mean `max_linear`"):
        profile.parse("limits: {max_lineer: 1}\n", "robot.yaml")


def test_plain_data_is_checked_by_the_same_schema():
    with pytest.raises(WorldError, match=r"^the given world: robots\[0\].battery: must be a mapping"):
        World.from_dict({"robots": [{"battery": 5}]})


def test_every_sample_world_is_valid():
    worlds = [p for p in ROOT.glob("samples/**/*.yaml") if p.name != "robot.yaml"]
    assert len(worlds) >= 4
    for path in worlds:
        World.load(str(path))


def test_a_bad_world_ends_the_run_with_exit_2(tmp_path, capsys):
    (tmp_path / "world.yaml").write_text("robots:\n  - battery: 5\n")
    assert cli.main(["run", str(ROOT / "samples" / "exploration"), "--world", str(tmp_path / "world.yaml")]) == 2
    err = capsys.readouterr().err
    assert "world.yaml:2:14: robots[0].battery: must be a mapping" in err and "Traceback" not in err


def test_the_json_schema_comes_from_the_same_definitions():
    schema = world_schema.WORLD.json()
    assert schema["additionalProperties"] is False
    assert schema["properties"]["step"] == {"type": "number", "exclusiveMinimum": 0.0, "maximum": 1.0}
    laser = schema["properties"]["robots"]["items"]["properties"]["laser"]["anyOf"][1]
    assert laser["properties"]["beams"] == {"type": "integer", "minimum": 1, "maximum": world_schema.MAX_BEAMS}


@pytest.mark.parametrize(
    ("name", "schema"),
    [("world", world_schema.WORLD), ("robot", profile.SCHEMA)],
)
def test_the_shipped_json_schemas_are_generated_from_the_definitions(request, name, schema):
    """docs/schemas/*.schema.json (for editors: a YAML language server reads them) are what the
    definitions give; `pytest --update-golden` writes them again after a change."""
    text = yamlschema.json_schema(schema, f"scoopc {name} file")
    check_golden(request, ROOT / "docs" / "schemas" / f"{name}.schema.json", text)
