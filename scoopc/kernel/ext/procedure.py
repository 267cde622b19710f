"""PROCEDURE's `external "Python"` feature (stdlib/base/agents/procedure.e); the representation
and the EiffelBase facts followed are in routine.py."""

from .routine import run


def call(current, args):
    """Call the procedure with the items of `args` (a TUPLE, a tuple-like, or Void when nothing
    is open) as open operands; items beyond `open_count` are ignored."""
    run(current, args)
