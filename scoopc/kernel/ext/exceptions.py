"""EXCEPTIONS' `external "Python"` feature (stdlib/base/exceptions/exceptions.e): `die`."""

import os
import sys

_exit = os._exit  # replaced by tests


def die(current, code):
    """End the program at once with exit status `code`, without an exception (as C's `exit`:
    buffered output is written first; no rescue clause, no once, no shutdown hook runs)."""
    region = current._region_
    flush = getattr(region, "flush_output", None)
    try:
        rt = getattr(region, "rt", None)
        out = getattr(rt, "out", None)
        if out is not None:
            out.flush()  # unfinished traced lines too: the run ends here
        if flush is not None:
            flush()
        for stream in (sys.stdout, sys.stderr):
            stream.flush()
    except (OSError, ValueError):
        pass
    _exit(code)
