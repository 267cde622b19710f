"""The user's module of tests/externals/permits: reads the runtime from inside an external."""

from scoopc import runtime


def holds_permit():
    """Does the processor inside this external hold its run permit?"""
    [inside] = runtime.inside_externals(runtime.current())
    return inside.proc.exec.permit
