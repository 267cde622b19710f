"""Helpers shared by the benchmark modules: result checks, thread utilities, running a program.

A benchmark module defines SIZES, ops(**params), baseline(**params) and scoop(**params);
each variant checks its own result and raises CheckFailed when it is wrong.
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


def where(cls, routine, line):
    """A codegen-style source position constant for the runtime's reports."""
    return (cls, routine, "benchmarks/" + cls.lower() + ".e", line)


def run_program(root_cls, args):
    """Run a SCOOP program as generated code would (rt.run_main); fail unless it exits 0."""
    import scoopc.runtime as rt
    status = rt.run_main(root_cls, root_cls.make, args=args)
    if status != 0:
        raise CheckFailed(f"run_main returned status {status}")
