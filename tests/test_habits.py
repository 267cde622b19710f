"""The habits that keep the code the way it is (issue 23): the runtime's API is fully typed and
checked strictly by mypy, and the tree passes ruff's lint. Both tools read their settings from
pyproject.toml; each test fails with the tool's own report."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

# The packages checked strictly ([[tool.mypy.overrides]] in pyproject.toml); the driver's is
# checked once it exists.
STRICT_PACKAGES = ("scoopc.runtime", "scoopc.driver")

# What ruff lints ([tool.ruff] in pyproject.toml says how, and which generated files it skips).
LINTED = ("scoopc", "tests", "benchmarks", "tools")


def _run(args: list[str], timeout: float) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", *args], cwd=ROOT, capture_output=True, text=True, timeout=timeout)


def _present(package: str) -> bool:
    return (ROOT / package.replace(".", "/") / "__init__.py").is_file()


def test_mypy_strict_on_the_runtime_and_the_driver(tmp_path):
    pytest.importorskip("mypy", reason="mypy is in the test extra")
    packages = [p for p in STRICT_PACKAGES if _present(p)]
    args = ["mypy", "--config-file", "pyproject.toml", "--cache-dir", str(tmp_path / "mypy_cache")]
    for package in packages:
        args += ["-p", package]
    result = _run(args, timeout=300)
    assert result.returncode == 0, f"mypy on {', '.join(packages)}:\n{result.stdout}{result.stderr}"


def test_ruff_lint():
    pytest.importorskip("ruff", reason="ruff is in the test extra")
    result = _run(["ruff", "check", "--no-cache", "--output-format", "concise", *LINTED], timeout=300)
    assert result.returncode == 0, f"ruff check:\n{result.stdout}{result.stderr}"
