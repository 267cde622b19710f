"""Shared helpers for the benchmark modules: result checks and small threading utilities.

Each benchmark module defines SIZES, describe(params), ops(params), baseline(**p) and scoop(**p).
"""
import threading


class CheckFailed(AssertionError):
    """A benchmark computed a wrong result: its time must not be reported."""


def check(label, got, expected):
    """Fail loudly when `got` differs from `expected`."""
    if got != expected:
        raise CheckFailed(f"{label}: got {got!r}, expected {expected!r}")


def start_all(targets):
    """Start one thread per (callable, args) pair and return the threads."""
    threads = [threading.Thread(target=fn, args=args) for fn, args in targets]
    for thread in threads:
        thread.start()
    return threads


def join_all(threads):
    for thread in threads:
        thread.join()
