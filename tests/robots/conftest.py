"""Shared fixtures of the robot tests."""

import pytest

from scoopc.robots import transport
from scoopc.robots.bus import Bus


@pytest.fixture
def bus():
    """A fresh in-process bus as the process's transport (programs run with `--robot none`)."""
    fresh = Bus()
    previous = transport.use(fresh)
    yield fresh
    transport.use(previous)
