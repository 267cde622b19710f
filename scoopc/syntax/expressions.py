"""Syntax tree, expressions: calls, operators, manifest constants, agents, object tests."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..source import Span
from .base import Identifier, node

if TYPE_CHECKING:  # names used only in annotations (strings at run time)
    from .declarations import EntityDeclaration, RoutineBody
    from .instructions import AssertionClause, Iteration, Variant
    from .types import Type


__all__ = [
    "UnqualifiedCall",
    "QualifiedCall",
    "StaticCall",
    "Precursor",
    "BracketExpression",
    "Current",
    "Result",
    "Void",
    "Parenthesized",
    "BinaryExpression",
    "UnaryExpression",
    "Old",
    "ManifestInteger",
    "ManifestReal",
    "ManifestString",
    "ManifestCharacter",
    "ManifestBoolean",
    "TypedConstant",
    "Unique",
    "ManifestType",
    "TupleExpression",
    "ManifestArray",
    "ObjectTest",
    "OpenOperand",
    "Agent",
    "InlineAgent",
    "CreationExpression",
    "ConditionalExpression",
    "InspectExpression",
    "WhenExpression",
    "ElseifExpression",
    "AcrossExpression",
    "Address",
    "ClassAssertion",
    "Expression",
]


@node
class UnqualifiedCall:
    """`f` or `f (args)`: a feature, local, argument or object-test local (resolved later)."""

    name: Identifier
    arguments: tuple[Expression, ...]
    span: Span


@node
class QualifiedCall:
    target: Expression
    name: Identifier
    arguments: tuple[Expression, ...]
    span: Span


@node
class StaticCall:
    """`{T}.f (args)`."""

    type: Type
    name: Identifier
    arguments: tuple[Expression, ...]
    span: Span


@node
class Precursor:
    parent: Identifier | None
    arguments: tuple[Expression, ...]
    span: Span


@node
class BracketExpression:
    """`target [arguments]`: a call of the feature aliased `[]`."""

    target: Expression
    arguments: tuple[Expression, ...]
    span: Span


@node
class Current:
    span: Span


@node
class Result:
    span: Span


@node
class Void:
    span: Span


@node
class Parenthesized:
    expression: Expression
    span: Span


@node
class BinaryExpression:
    """`left operator right`; operator lowercased, `and then`/`or else` as two words."""

    operator: str
    left: Expression
    right: Expression
    operator_span: Span
    span: Span


@node
class UnaryExpression:
    operator: str  # "not", "-", "+" or a free operator
    operand: Expression
    span: Span


@node
class Old:
    expression: Expression
    span: Span


@node
class ManifestInteger:
    value: int
    text: str
    span: Span


@node
class ManifestReal:
    value: float
    text: str
    span: Span


@node
class ManifestString:
    value: str  # escapes decoded
    verbatim: bool
    once: bool  # `once "..."`
    span: Span


@node
class ManifestCharacter:
    value: str
    span: Span


@node
class ManifestBoolean:
    value: bool
    span: Span


@node
class TypedConstant:
    """`{INTEGER_64} 1`: a manifest constant with an explicit type."""

    type: Type
    constant: Expression
    span: Span


@node
class Unique:
    """The value `unique` of a constant attribute."""

    span: Span


@node
class ManifestType:
    """`{T}` as an expression (an object of TYPE [T])."""

    type: Type
    span: Span


@node
class TupleExpression:
    items: tuple[Expression, ...]
    span: Span


@node
class ManifestArray:
    items: tuple[Expression, ...]
    span: Span


@node
class ObjectTest:
    """`attached [{T}] expression [as local]`."""

    type: Type | None
    expression: Expression
    local: Identifier | None
    span: Span


@node
class OpenOperand:
    """`?` or `{T}` among an agent's operands; `type` is None for `?`."""

    type: Type | None
    span: Span


@node
class Agent:
    """`agent [target.]f [(operands)]`. target None: unqualified (Current); a ManifestType
    target is an open target of that type. arguments None: every argument open."""

    target: Expression | None
    name: Identifier
    arguments: tuple[Expression, ...] | None
    span: Span


@node
class InlineAgent:
    arguments: tuple[EntityDeclaration, ...]
    type: Type | None
    body: RoutineBody
    actuals: tuple[Expression, ...] | None
    span: Span


@node
class CreationExpression:
    processor: Identifier | None  # `create <NONE> {T}`
    type: Type
    procedure: Identifier | None
    arguments: tuple[Expression, ...]
    span: Span


@node
class ConditionalExpression:
    condition: Expression
    then_part: Expression
    elseif_parts: tuple[ElseifExpression, ...]
    else_part: Expression
    span: Span


@node
class ElseifExpression:
    condition: Expression
    then_part: Expression
    span: Span


@node
class InspectExpression:
    """`inspect e when 1 then x when 2, 3 then y else z end` (EiffelStudio 22.05+)."""

    expression: Expression
    when_parts: tuple[WhenExpression, ...]
    else_part: Expression | None
    span: Span


@node
class WhenExpression:
    choices: tuple  # of instructions.Choice
    then_part: Expression
    span: Span


@node
class AcrossExpression:
    """`across e as c ... all|some expression end`."""

    iteration: Iteration
    invariant: tuple[AssertionClause, ...]
    until: Expression | None
    quantifier: str  # "all" or "some"
    body: Expression
    variant: Variant | None
    span: Span


@node
class Address:
    """`$name`: the address of a feature or entity (for externals)."""

    name: Identifier
    span: Span


@node
class ClassAssertion:
    """The postcondition `class` (a feature that does not use Current)."""

    span: Span


Expression = (
    UnqualifiedCall
    | QualifiedCall
    | StaticCall
    | Precursor
    | BracketExpression
    | Current
    | Result
    | Void
    | Parenthesized
    | BinaryExpression
    | UnaryExpression
    | Old
    | ManifestInteger
    | ManifestReal
    | ManifestString
    | ManifestCharacter
    | ManifestBoolean
    | TypedConstant
    | ManifestType
    | TupleExpression
    | ManifestArray
    | ObjectTest
    | OpenOperand
    | Agent
    | InlineAgent
    | CreationExpression
    | ConditionalExpression
    | InspectExpression
    | AcrossExpression
    | Address
)
