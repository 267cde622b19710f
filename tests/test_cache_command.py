"""`scoopc cache info` and `scoopc cache clean`: other compiler versions' entries removed, the
least recently used programs pruned past SCOOPC_CACHE_MAX, the current library kept."""

import json
import os
import re
import time

import pytest

from scoopc import cli
from scoopc.driver import cache
from scoopc.driver.packages import compiler_digest
from scoopc.semantics.library import library_key

OTHER = "base-0123456789abcdef01234567"


def _file(path, size):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(b"x" * size)


def _program(root, key, base, size, used):
    folder = root / "programs" / key
    _file(folder / "program" / "m.py", size)
    (folder / "program.json").write_text(json.dumps({"package": "program", "base": str(root / base)}))
    os.utime(folder / "program.json", (used, used))
    return folder


@pytest.fixture
def root(tmp_path, monkeypatch):
    root = tmp_path / "cache"
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(root))
    monkeypatch.delenv("SCOOPC_CACHE_MAX", raising=False)
    now = time.time()
    current = f"base-{compiler_digest()}"
    _file(root / current / "eiffel_base" / "any.py", 3000)
    _file(root / OTHER / "eiffel_base" / "any.py", 2000)
    _file(root / f"stdlib-{library_key()}.pickle", 1000)
    _file(root / "stdlib-00000000000000000000000000000000.pickle", 500)
    _program(root, "old", OTHER, 400, now - 10)
    for age, key in enumerate(("p1", "p2", "p3")):
        _program(root, key, current, 1000, now - 300 + 100 * age)
    staging = root / "base-tmpabcd"
    _file(staging / "eiffel_base" / "x.py", 10)
    os.utime(staging, (now - 7200, now - 7200))
    os.utime(staging / "eiffel_base" / "x.py", (now - 7200, now - 7200))
    _file(root / "programs" / "p4.123.tmp" / "program" / "m.py", 10)  # a run compiling it now
    return root


def test_clean_removes_other_versions_and_old_leftovers_only(root):
    removed = {e.path.name for e in cache.clean()}
    assert removed == {OTHER, "stdlib-00000000000000000000000000000000.pickle", "old", "base-tmpabcd"}
    left = {p.name for p in root.iterdir()} | {p.name for p in (root / "programs").iterdir()}
    assert {"p1", "p2", "p3", "p4.123.tmp", f"base-{compiler_digest()}"} <= left


def test_pruning_removes_the_least_recently_used_programs_past_the_limit(root, monkeypatch):
    monkeypatch.setenv("SCOOPC_CACHE_MAX", "5.5K")  # current library 3000 + declarations 1000 + programs of 1070
    removed = [e.path.name for e in cache.clean() if e.kind == "program"]
    assert removed == ["old", "p1", "p2"]  # p3, the latest used, fits
    assert (root / f"base-{compiler_digest()}").is_dir()


def test_a_use_moves_a_program_to_the_end_of_the_pruning_order(root, monkeypatch):
    cache.touch(root / "programs" / "p1" / "program.json")
    monkeypatch.setenv("SCOOPC_CACHE_MAX", "5.5K")
    assert [e.path.name for e in cache.clean() if e.kind == "program"] == ["old", "p2", "p3"]


def test_tidy_keeps_other_versions_used_recently(root):
    cache.tidy(keep=root / "programs" / "p3")
    assert (root / OTHER).is_dir() and (root / "programs" / "old").is_dir()  # another scoopc may use them
    assert not (root / "base-tmpabcd").exists()


def test_cache_info_and_clean_all_on_the_command_line(root, capsys):
    assert cli.main(["cache", "info"]) == 0
    out = capsys.readouterr().out
    assert f"cache folder: {root}" in out
    assert "libraries: 2, 5.0 kB, 1 of other compiler versions" in out
    assert re.search(r"programs: 4, \d\.\d kB, 1 of other compiler versions", out)  # program.json names the path
    assert "unfinished: 2, 20 B" in out
    assert cli.main(["cache", "clean", "--all"]) == 0
    assert "removed 10 cache entries" in capsys.readouterr().out
    assert not any(root.glob("base-*")) and not any(root.glob("*.pickle"))


def test_a_bad_limit_is_a_usage_error(root, monkeypatch, capsys):
    monkeypatch.setenv("SCOOPC_CACHE_MAX", "lots")
    assert cli.main(["cache", "clean"]) == 2
    assert "SCOOPC_CACHE_MAX=lots: expected a size such as 500M or 2G" in capsys.readouterr().err
    assert (root / OTHER).is_dir()


def test_a_program_on_the_library_the_wheel_ships_belongs_to_this_compiler(root):
    from scoopc import version

    folder = _program(root, "shipped", "x", 100, time.time())
    shipped = version.PREBUILT / f"base-{compiler_digest()}"
    (folder / "program.json").write_text(json.dumps({"package": "program", "base": str(shipped)}))
    found = {e.path.name: e for e in cache.entries()}
    assert found["shipped"].current and not found["old"].current
    assert "shipped" not in {e.path.name for e in cache.clean()}
