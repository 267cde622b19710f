"""Parser, the last check of a class's syntax tree: no construct nested deeper than the compiler
promises to handle (docs/GUARANTEES.md, Limits). Later stages recurse on the tree; a class nested
deeper is reported here (SYNTAX-DEPTH) and goes no further. The walk itself is iterative."""

from __future__ import annotations

import typing

from .. import diagnostics, syntax
from ..diagnostics import Diagnostic
from ..source import Span

MAX_NESTING = 2000  # pairs of parentheses, `not`s, operators, `if`s ... inside one instruction
# What counts: expressions and instructions, not their parts (an `elseif` or `when` branch, an `across`
# iteration, a separate argument): an `inspect` in an `inspect` is one level deeper, as an `if` in an `if`.
_COUNTED = frozenset(typing.get_args(syntax.expressions.Expression) + typing.get_args(syntax.instructions.Instruction))


def too_deep(tree: object) -> Diagnostic | None:
    """SYNTAX-DEPTH at the first node with more than MAX_NESTING + 1 expressions and
    instructions around it (the outermost instruction does not count), else None."""
    stack: list[tuple[object, int]] = [(tree, 0)]
    while stack:
        node, around = stack.pop()
        if around > MAX_NESTING + 1:
            span = getattr(node, "span", None) or Span("?", 1, 1, 1, 1)
            return diagnostics.make("SYNTAX-DEPTH", span, limit=f"{MAX_NESTING:,}")
        inside = around + (1 if type(node) in _COUNTED else 0)
        stack.extend((child, inside) for child in _children(node))
    return None


def _children(node: object):
    for name in getattr(node, "__dataclass_fields__", ()):
        value = getattr(node, name)
        pending = [value]
        while pending:
            item = pending.pop()
            if isinstance(item, tuple):
                pending.extend(item)
            elif hasattr(item, "__dataclass_fields__") and not isinstance(item, (syntax.Identifier, Span)):
                yield item
