"""Test-suite options: `--update-golden` rewrites expected outputs; hypothesis profiles."""

import os
import tempfile

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("thorough", max_examples=5000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("SCOOPC_HYPOTHESIS_PROFILE", "ci"))

# One compiled standard library per test session, never the user's own cache.
os.environ.setdefault("SCOOPC_CACHE_DIR", tempfile.mkdtemp(prefix="scoopc-tests-"))


def pytest_addoption(parser):
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="rewrite golden files (expected dumps, generated code, outputs) from the current results",
    )


@pytest.fixture(autouse=True)
def _class_registry_restored():
    """Programs run in-process register their classes; each test leaves the registry as it found it."""
    from scoopc import kernel

    saved = dict(kernel.CLASSES)
    yield
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)
