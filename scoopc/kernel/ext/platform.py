"""PLATFORM's `external "Python"` features (stdlib/base/kernel/platform.e): the host's."""

import os
import sys


def is_windows(current):
    return os.name == "nt"


def is_unix(current):
    """Any system that is not Windows (Linux, macOS, BSD, ...), as EiffelStudio's."""
    return os.name != "nt"


def is_mac(current):
    return sys.platform == "darwin"


def is_little_endian(current):
    return sys.byteorder == "little"


def is_64_bits(current):
    return sys.maxsize > 2**32
