"""Test-suite options: `--update-golden` rewrites expected outputs; hypothesis profiles."""

import contextlib
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


@contextlib.contextmanager
def _registry_kept():
    """The kernel's class registry as it was, afterwards (programs run in-process register classes)."""
    from scoopc import kernel  # deferred: importing the kernel at collection would load it for every worker

    saved = dict(kernel.CLASSES)
    yield
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)


@pytest.fixture(autouse=True, scope="module")
def _class_registry_restored_per_module():
    """A module's fixtures may run programs too (a run shared by its tests): restored after each module,
    whichever worker and order the modules run in."""
    with _registry_kept():
        yield


@pytest.fixture(autouse=True)
def _class_registry_restored():
    """Each test leaves the registry as it found it."""
    with _registry_kept():
        yield
