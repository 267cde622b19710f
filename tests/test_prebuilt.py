"""The files a wheel ships in scoopc/prebuilt/ are used only while they match the compiler: the
compiled library by its compiler digest (else it is compiled into the cache), and never with
SCOOPC_NO_PREBUILT. The wheel itself: tests/test_packaging.py."""

import json

import pytest

from scoopc import version
from scoopc.driver import library
from scoopc.driver.packages import BASE_PACKAGE, compiler_digest, write_manifest


def ship(folder, digest):
    package = folder / f"base-{digest}" / BASE_PACKAGE
    package.mkdir(parents=True)
    (package / "any.py").write_text("")
    (package / "_scoop_facts.json").write_text(json.dumps({"format": -1}))
    write_manifest(package)
    return package.parent


@pytest.fixture
def prebuilt(tmp_path, monkeypatch):
    monkeypatch.setattr(version, "PREBUILT", tmp_path / "prebuilt")
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("SCOOPC_NO_PREBUILT", raising=False)
    monkeypatch.setattr(library, "_build", lambda *a, **k: pytest.fail("the library was compiled"))
    return tmp_path / "prebuilt"


def test_the_library_of_this_compiler_is_used_as_shipped(prebuilt):
    shipped = ship(prebuilt, compiler_digest())
    assert library.compiled_library().path == shipped


def test_the_library_of_another_compiler_is_not(prebuilt, monkeypatch):
    ship(prebuilt, "0" * 24)
    built = []
    monkeypatch.setattr(library, "_build", lambda target, *a, **k: built.append(target))
    library.compiled_library()
    assert len(built) == 1 and prebuilt not in built[0].parents


def test_no_prebuilt_ignores_what_the_wheel_ships(prebuilt, monkeypatch):
    ship(prebuilt, compiler_digest())
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")
    assert version.prebuilt(f"base-{compiler_digest()}") is None


def test_cache_info_names_the_library_installed_with_scoopc(prebuilt):
    from scoopc.driver import cache

    shipped = ship(prebuilt, compiler_digest())
    text = cache.describe([], prebuilt.parent / "cache", 1000)
    assert f"standard library: the one installed with scoopc, outside the cache ({shipped})" in text
