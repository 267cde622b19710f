"""Packaging: the wheel built from the repository carries every module, the grammar and every
stdlib .e file, so a regular (non-editable) install works as the checkout does."""

import subprocess
import sys
import zipfile

import pytest

try:
    import tomllib
except ImportError:  # Python 3.10
    tomllib = pytest.importorskip("tomli")

from harness import ROOT


def test_every_python_package_is_listed_in_pyproject():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    listed = set(config["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "scoopc").rglob("__init__.py")}
    assert found <= listed, f"add to [tool.setuptools] packages: {sorted(found - listed)}"


@pytest.fixture(scope="module")
def wheel_names(tmp_path_factory):
    pytest.importorskip("setuptools")
    pytest.importorskip("wheel")
    out = tmp_path_factory.mktemp("wheel")
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--no-deps",
            "--no-build-isolation",
            "--quiet",
            "-w",
            str(out),
            str(ROOT),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    (wheel,) = out.glob("scoopc-*.whl")
    return set(zipfile.ZipFile(wheel).namelist())


def test_wheel_has_all_modules_and_the_grammar(wheel_names):
    expected = {p.relative_to(ROOT).as_posix() for p in (ROOT / "scoopc").rglob("*.py")}
    expected.add("scoopc/grammar.lark")
    assert expected <= wheel_names, sorted(expected - wheel_names)


def test_wheel_has_every_stdlib_class(wheel_names):
    expected = {"scoopc/stdlib/" + p.relative_to(ROOT / "stdlib").as_posix() for p in (ROOT / "stdlib").rglob("*.e")}
    assert expected <= wheel_names, sorted(expected - wheel_names)
