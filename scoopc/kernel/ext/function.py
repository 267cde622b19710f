"""FUNCTION's `external "Python"` features (stdlib/base/agents/function.e); the representation
and the EiffelBase facts followed are in routine.py. `call`, `apply` (which keep the result in
`last_result`), `is_equal`, `copy` and `clear_last_result` are Eiffel. PREDICATE adds nothing."""

from .routine import run


def item(current, args):
    """Result of calling the function with the items of `args` (a TUPLE, a tuple-like, or Void
    when nothing is open) as open operands; `last_result` is left alone."""
    return run(current, args)


def flexible_item(current, a):
    """Like `item`, `a` being any tuple-like suitable for `valid_operands` (EiffelBase: `item` of
    `a` converted to OPEN_ARGS; `last_result` is left alone)."""
    return run(current, a)
