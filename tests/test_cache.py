"""scoopc's cache repairs itself: a cached package with a module deleted, truncated or garbled, or
with damaged bytecode, is compiled again (a note on stderr when it had to be loaded to find out),
never an internal error; a cache folder scoopc cannot write is a usage error (exit 2)."""

import os
import shutil
import subprocess
import sys

import pytest

from scoopc import cli
from scoopc.driver import BASE_PACKAGE

HELLO = """class
	HELLO

create
	make

feature

	make
		do
			print ("hi%N")
		end

end
"""
NOTE = "scoopc: note: the compiled program in scoopc's cache was damaged"


@pytest.fixture(scope="module")
def warm(tmp_path_factory):
    """A cache with the library and hello compiled, to copy for each test."""
    folder = tmp_path_factory.mktemp("warm")
    (folder / "hello.e").write_text(HELLO)
    mp = pytest.MonkeyPatch()
    mp.setenv("SCOOPC_CACHE_DIR", str(folder / "cache"))
    mp.setenv("SCOOPC_NO_PREBUILT", "1")  # the library in the cache, even when the suite runs from a wheel
    assert cli.main(["run", str(folder / "hello.e")]) == 0
    mp.undo()
    return folder


@pytest.fixture
def cache(warm, tmp_path, monkeypatch):
    shutil.copytree(warm / "cache", tmp_path / "cache")
    for meta in (tmp_path / "cache").glob("programs/*/program.json"):  # it names its library's folder
        meta.write_text(meta.read_text().replace(str(warm / "cache"), str(tmp_path / "cache")))
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")
    return tmp_path / "cache"


def run(capsys, warm, *options):
    """`scoopc run` in a fresh interpreter (this one has the library's modules loaded already)."""
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", "run", *options, str(warm / "hello.e")],
        capture_output=True,
        text=True,
        timeout=300,
        env=dict(os.environ),
    )
    return done.returncode, done.stdout, done.stderr


def library(cache):
    (base,) = cache.glob("base-*")
    return base / BASE_PACKAGE


def program(cache):
    (folder,) = cache.glob("programs/*/program")
    return folder


def truncate(path, size):
    path.write_bytes(path.read_bytes()[:size])


@pytest.mark.slow
def test_damaged_library_bytecode_is_compiled_again(cache, warm, capsys):
    (pyc,) = (library(cache) / "__pycache__").glob("string_8.*.pyc")
    truncate(pyc, 100)
    code, out, err = run(capsys, warm)
    assert (code, out) == (0, "hi\n") and NOTE in err and "Error" not in err
    assert run(capsys, warm) == (0, "hi\n", "")  # repaired for good


@pytest.mark.slow
def test_a_deleted_library_module_is_compiled_again(cache, warm, capsys):
    (library(cache) / "string_8.py").unlink()
    assert run(capsys, warm) == (0, "hi\n", "")  # seen before loading: no note needed
    assert (library(cache) / "string_8.py").exists()


@pytest.mark.slow
def test_a_garbled_program_module_of_the_same_size_is_compiled_again(cache, warm, capsys):
    module = program(cache) / "hello.py"
    module.write_text("x" * len(module.read_bytes()))
    for pyc in (program(cache) / "__pycache__").glob("hello.*.pyc"):
        pyc.unlink()
    code, out, err = run(capsys, warm)
    assert (code, out) == (0, "hi\n") and NOTE in err


@pytest.mark.slow
def test_no_cache_compiles_the_library_again(cache, warm, capsys):
    manifest = library(cache) / "_manifest.json"
    manifest.write_text(manifest.read_text())  # a mark the rebuild removes
    before = manifest.stat().st_mtime_ns
    assert run(capsys, warm, "--no-cache")[:2] == (0, "hi\n")
    assert library(cache).joinpath("_manifest.json").stat().st_mtime_ns != before


def test_a_cache_path_that_is_a_file_is_a_usage_error(tmp_path, monkeypatch, capsys):
    (tmp_path / "hello.e").write_text(HELLO)
    (tmp_path / "cache").write_text("not a folder")
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path / "cache"))
    code, out, err = run(capsys, tmp_path)
    assert code == 2 and out == ""
    assert f"scoopc: error: cannot write scoopc's cache folder {tmp_path / 'cache'} (it is a file" in err
