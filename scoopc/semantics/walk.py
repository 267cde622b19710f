"""Checker, small helpers over syntax trees: the child nodes of a node, and a short text
naming an expression in a message (`a.item`, `Current`, `"text"`).
"""

from __future__ import annotations

from .. import syntax


def children(node):
    """The syntax nodes directly below `node` (names and spans excluded)."""
    for name in getattr(node, "__dataclass_fields__", ()):
        value = getattr(node, name)
        if isinstance(value, tuple):
            yield from (v for v in value if hasattr(v, "__dataclass_fields__") and not isinstance(v, syntax.Identifier))
        elif (
            hasattr(value, "__dataclass_fields__")
            and not isinstance(value, (syntax.Identifier,))
            and not type(value).__name__ == "Span"
        ):
            yield value


def describe(node) -> str:
    if isinstance(node, syntax.UnqualifiedCall):
        return node.name.text
    if isinstance(node, syntax.QualifiedCall):
        return f"{describe(node.target)}.{node.name.text}"
    if isinstance(node, syntax.Current):
        return "Current"
    if isinstance(node, syntax.Result):
        return "Result"
    if isinstance(node, syntax.Parenthesized):
        return f"({describe(node.expression)})"
    if isinstance(node, (syntax.ManifestInteger, syntax.ManifestReal)):
        return node.text
    if isinstance(node, syntax.ManifestString):
        return '"' + node.value.replace("%", "%%").replace("\n", "%N")[:30] + '"'
    if isinstance(node, syntax.CreationExpression):
        return "create {...}"
    if isinstance(node, syntax.BracketExpression):
        return f"{describe(node.target)} [...]"
    return "this expression"
