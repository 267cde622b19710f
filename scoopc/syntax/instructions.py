"""Syntax tree, instructions and contracts: assignments, creation, control structures,
separate blocks, assertion clauses."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..source import Span
from .base import Identifier, node

if TYPE_CHECKING:  # names used only in annotations (strings at run time)
    from .expressions import Expression
    from .types import Type


__all__ = [
    "Assignment",
    "AssignerCall",
    "AssignmentAttempt",
    "CallInstruction",
    "CreationInstruction",
    "Conditional",
    "ElseifPart",
    "MultiBranch",
    "WhenPart",
    "Choice",
    "Loop",
    "Iteration",
    "Across",
    "Check",
    "Debug",
    "SeparateInstruction",
    "SeparateArgument",
    "Retry",
    "AssertionClause",
    "Precondition",
    "Postcondition",
    "Variant",
    "Instruction",
]


@node
class Assignment:
    """`variable := expression`; target is an UnqualifiedCall without arguments or Result."""

    target: Expression
    source: Expression
    span: Span


@node
class AssignerCall:
    """`a.f (i) := v` or `a [i] := v`: a call of the assigner command of the target query."""

    target: Expression
    source: Expression
    span: Span


@node
class AssignmentAttempt:
    """`variable ?= expression` (obsolete Eiffel)."""

    target: Expression
    source: Expression
    span: Span


@node
class CallInstruction:
    call: Expression
    span: Span


@node
class CreationInstruction:
    processor: Identifier | None  # `create <NONE> x`
    type: Type | None
    target: Expression  # UnqualifiedCall without arguments, or Result
    procedure: Identifier | None
    arguments: tuple[Expression, ...]
    span: Span


@node
class Conditional:
    condition: Expression
    then_part: tuple[Instruction, ...]
    elseif_parts: tuple[ElseifPart, ...]
    else_part: tuple[Instruction, ...] | None
    span: Span


@node
class ElseifPart:
    condition: Expression
    then_part: tuple[Instruction, ...]
    span: Span


@node
class MultiBranch:
    """`inspect`."""

    expression: Expression
    when_parts: tuple[WhenPart, ...]
    else_part: tuple[Instruction, ...] | None
    span: Span


@node
class WhenPart:
    choices: tuple[Choice, ...]
    then_part: tuple[Instruction, ...]
    span: Span


@node
class Choice:
    """One value, or an interval `lower..upper`."""

    lower: Expression
    upper: Expression | None
    span: Span


@node
class Loop:
    initialization: tuple[Instruction, ...]
    invariant: tuple[AssertionClause, ...]
    until: Expression
    body: tuple[Instruction, ...]
    variant: Variant | None
    span: Span


@node
class Iteration:
    """`expression as cursor` (cursor_mode) or `expression is item`."""

    expression: Expression
    name: Identifier
    cursor_mode: bool
    span: Span


@node
class Across:
    iteration: Iteration
    initialization: tuple[Instruction, ...]
    invariant: tuple[AssertionClause, ...]
    until: Expression | None
    body: tuple[Instruction, ...]
    variant: Variant | None
    span: Span


@node
class Check:
    assertions: tuple[AssertionClause, ...]
    then_part: tuple[Instruction, ...] | None
    span: Span


@node
class Debug:
    keys: tuple[str, ...]
    body: tuple[Instruction, ...]
    span: Span


@node
class SeparateInstruction:
    """`separate e as x, f as y do ... end`."""

    arguments: tuple[SeparateArgument, ...]
    body: tuple[Instruction, ...]
    span: Span


@node
class SeparateArgument:
    expression: Expression
    name: Identifier
    span: Span


@node
class Retry:
    span: Span


Instruction = (
    Assignment
    | AssignerCall
    | AssignmentAttempt
    | CallInstruction
    | CreationInstruction
    | Conditional
    | MultiBranch
    | Loop
    | Across
    | Check
    | Debug
    | SeparateInstruction
    | Retry
)


@node
class AssertionClause:
    """`[tag:] expression`; expression None for a tag followed only by a comment."""

    tag: Identifier | None
    expression: Expression | None
    span: Span


@node
class Precondition:
    require_else: bool
    clauses: tuple[AssertionClause, ...]
    span: Span


@node
class Postcondition:
    ensure_then: bool
    clauses: tuple[AssertionClause, ...]
    span: Span


@node
class Variant:
    tag: Identifier | None
    expression: Expression
    span: Span
