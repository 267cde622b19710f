"""MEMORY's `external "Python"` features (stdlib/base/kernel/memory.e): Python's collector
(`gc`) does the work. Reference counting always runs; these control the cycle collector."""

import gc


def collecting(current):
    return gc.isenabled()


def collection_on(current):
    gc.enable()


def collection_off(current):
    gc.disable()


def collect(current):
    """A partial collection: the youngest generation."""
    gc.collect(0)


def full_collect(current):
    gc.collect()


def full_coalesce(current):
    gc.collect()
