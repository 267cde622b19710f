"""The AST: what the parser builds and every later stage reads.

Input: built by scoopc/parse_tree from parser reductions. Output: frozen dataclasses, one per
construct, each with a `span`; `dump(node)` gives a stable indented text form for tests.

Conventions:
- Nodes are named with Eiffel's own terms (ECMA-367) and compare by identity (`eq=False`), so
  later passes keep their results in side tables keyed by node.
- Names are `Identifier` nodes: `text` as written, `key` lowercased. Eiffel names are
  case-insensitive: compare and look up by `key`, print `text`.
- Optional parts are None when absent; lists are tuples (empty when absent).
- Type marks (`attached`, `detachable`, `separate`, `frozen`, `variant`) are fields of the type.
"""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Optional, Union

from .source import Span

node = dataclass(frozen=True, eq=False)


@node
class Identifier:
    text: str
    key: str
    span: Span


# ---- types ---------------------------------------------------------------------------------
@node
class ClassType:
    """`NAME [generics]`; formal generic parameters are ClassTypes too (the checker tells)."""
    name: Identifier
    generics: tuple["Type", ...]
    attachment: Optional[str]      # "attached", "detachable" or None
    separate: bool
    variance: Optional[str]        # "frozen", "variant" or None
    span: Span


@node
class TupleType:
    """`TUPLE [...]`; `labels` is empty or has one label per generic (`TUPLE [a: X; b: Y]`)."""
    generics: tuple["Type", ...]
    labels: tuple[Identifier, ...]
    attachment: Optional[str]
    separate: bool
    variance: Optional[str]
    span: Span


@node
class AnchoredType:
    """`like anchor`: anchor is Current, an UnqualifiedCall, a QualifiedCall chain or a StaticCall."""
    anchor: "Expression"
    attachment: Optional[str]
    separate: bool
    variance: Optional[str]
    span: Span


Type = Union[ClassType, TupleType, AnchoredType]


@node
class FormalGeneric:
    name: Identifier
    mark: Optional[str]            # "frozen", "expanded" or None
    constraints: tuple["Constraint", ...]
    creators: Optional[tuple[Identifier, ...]]   # `create make end`; None when absent
    span: Span


@node
class Constraint:
    type: Type
    renames: tuple["Rename", ...]
    span: Span


# ---- expressions ---------------------------------------------------------------------------
@node
class UnqualifiedCall:
    """`f` or `f (args)`: a feature, local, argument or object-test local (resolved later)."""
    name: Identifier
    arguments: tuple["Expression", ...]
    span: Span


@node
class QualifiedCall:
    target: "Expression"
    name: Identifier
    arguments: tuple["Expression", ...]
    span: Span


@node
class StaticCall:
    """`{T}.f (args)`."""
    type: Type
    name: Identifier
    arguments: tuple["Expression", ...]
    span: Span


@node
class Precursor:
    parent: Optional[Identifier]
    arguments: tuple["Expression", ...]
    span: Span


@node
class BracketExpression:
    """`target [arguments]`: a call of the feature aliased `[]`."""
    target: "Expression"
    arguments: tuple["Expression", ...]
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
    expression: "Expression"
    span: Span


@node
class BinaryExpression:
    """`left operator right`; operator lowercased, `and then`/`or else` as two words."""
    operator: str
    left: "Expression"
    right: "Expression"
    operator_span: Span
    span: Span


@node
class UnaryExpression:
    operator: str                  # "not", "-", "+" or a free operator
    operand: "Expression"
    span: Span


@node
class Old:
    expression: "Expression"
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
    value: str                     # escapes decoded
    verbatim: bool
    once: bool                     # `once "..."`
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
    constant: "Expression"
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
    items: tuple["Expression", ...]
    span: Span


@node
class ManifestArray:
    items: tuple["Expression", ...]
    span: Span


@node
class ObjectTest:
    """`attached [{T}] expression [as local]`."""
    type: Optional[Type]
    expression: "Expression"
    local: Optional[Identifier]
    span: Span


@node
class OpenOperand:
    """`?` or `{T}` among an agent's operands; `type` is None for `?`."""
    type: Optional[Type]
    span: Span


@node
class Agent:
    """`agent [target.]f [(operands)]`. target None: unqualified (Current); a ManifestType
    target is an open target of that type. arguments None: every argument open."""
    target: Optional["Expression"]
    name: Identifier
    arguments: Optional[tuple["Expression", ...]]
    span: Span


@node
class InlineAgent:
    arguments: tuple["EntityDeclaration", ...]
    type: Optional[Type]
    body: "RoutineBody"
    actuals: Optional[tuple["Expression", ...]]
    span: Span


@node
class CreationExpression:
    processor: Optional[Identifier]   # `create <NONE> {T}`
    type: Type
    procedure: Optional[Identifier]
    arguments: tuple["Expression", ...]
    span: Span


@node
class ConditionalExpression:
    condition: "Expression"
    then_part: "Expression"
    elseif_parts: tuple["ElseifExpression", ...]
    else_part: "Expression"
    span: Span


@node
class ElseifExpression:
    condition: "Expression"
    then_part: "Expression"
    span: Span


@node
class AcrossExpression:
    """`across e as c ... all|some expression end`."""
    iteration: "Iteration"
    invariant: tuple["AssertionClause", ...]
    until: Optional["Expression"]
    quantifier: str                # "all" or "some"
    body: "Expression"
    variant: Optional["Variant"]
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


Expression = Union[UnqualifiedCall, QualifiedCall, StaticCall, Precursor, BracketExpression,
                   Current, Result, Void, Parenthesized, BinaryExpression, UnaryExpression,
                   Old, ManifestInteger, ManifestReal, ManifestString, ManifestCharacter,
                   ManifestBoolean, TypedConstant, ManifestType, TupleExpression, ManifestArray,
                   ObjectTest, OpenOperand, Agent, InlineAgent, CreationExpression,
                   ConditionalExpression, AcrossExpression, Address]


# ---- instructions --------------------------------------------------------------------------
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
    processor: Optional[Identifier]   # `create <NONE> x`
    type: Optional[Type]
    target: Expression                # UnqualifiedCall without arguments, or Result
    procedure: Optional[Identifier]
    arguments: tuple[Expression, ...]
    span: Span


@node
class Conditional:
    condition: Expression
    then_part: tuple["Instruction", ...]
    elseif_parts: tuple["ElseifPart", ...]
    else_part: Optional[tuple["Instruction", ...]]
    span: Span


@node
class ElseifPart:
    condition: Expression
    then_part: tuple["Instruction", ...]
    span: Span


@node
class MultiBranch:
    """`inspect`."""
    expression: Expression
    when_parts: tuple["WhenPart", ...]
    else_part: Optional[tuple["Instruction", ...]]
    span: Span


@node
class WhenPart:
    choices: tuple["Choice", ...]
    then_part: tuple["Instruction", ...]
    span: Span


@node
class Choice:
    """One value, or an interval `lower..upper`."""
    lower: Expression
    upper: Optional[Expression]
    span: Span


@node
class Loop:
    initialization: tuple["Instruction", ...]
    invariant: tuple["AssertionClause", ...]
    until: Expression
    body: tuple["Instruction", ...]
    variant: Optional["Variant"]
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
    initialization: tuple["Instruction", ...]
    invariant: tuple["AssertionClause", ...]
    until: Optional[Expression]
    body: tuple["Instruction", ...]
    variant: Optional["Variant"]
    span: Span


@node
class Check:
    assertions: tuple["AssertionClause", ...]
    then_part: Optional[tuple["Instruction", ...]]
    span: Span


@node
class Debug:
    keys: tuple[str, ...]
    body: tuple["Instruction", ...]
    span: Span


@node
class SeparateInstruction:
    """`separate e as x, f as y do ... end`."""
    arguments: tuple["SeparateArgument", ...]
    body: tuple["Instruction", ...]
    span: Span


@node
class SeparateArgument:
    expression: Expression
    name: Identifier
    span: Span


@node
class Retry:
    span: Span


Instruction = Union[Assignment, AssignerCall, AssignmentAttempt, CallInstruction,
                    CreationInstruction, Conditional, MultiBranch, Loop, Across, Check, Debug,
                    SeparateInstruction, Retry]


# ---- contracts -----------------------------------------------------------------------------
@node
class AssertionClause:
    """`[tag:] expression`; expression None for a tag followed only by a comment."""
    tag: Optional[Identifier]
    expression: Optional[Expression]
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
    tag: Optional[Identifier]
    expression: Expression
    span: Span


# ---- features ------------------------------------------------------------------------------
@node
class Alias:
    """`alias "+"` (operator or bracket alias) with its `convert` mark."""
    name: str
    convert: bool
    span: Span


@node
class FeatureName:
    name: Identifier
    frozen: bool
    aliases: tuple[Alias, ...]
    span: Span


@node
class EntityDeclaration:
    """One formal argument or local: a group `a, b: T` gives one per name, sharing the type."""
    name: Identifier
    type: Type
    span: Span


@node
class Note:
    tag: Identifier
    values: tuple[Union[Identifier, Expression], ...]
    span: Span


@node
class InternalBody:
    """`do` or `once [("KEY", ...)]` with its instructions."""
    once: bool
    once_keys: tuple[str, ...]
    instructions: tuple[Instruction, ...]
    span: Span


@node
class DeferredBody:
    span: Span


@node
class ExternalBody:
    language: str                  # e.g. "C", "Python", "built_in"
    alias: Optional[str]
    span: Span


@node
class AttributeBody:
    """`attribute` with the instructions that compute a self-initializing attribute."""
    instructions: tuple[Instruction, ...]
    span: Span


@node
class RoutineBody:
    """Everything from `obsolete`/`require` to `end` of a routine, attribute body or agent."""
    obsolete: Optional[str]
    precondition: Optional[Precondition]
    locals: tuple[EntityDeclaration, ...]
    body: Union[InternalBody, DeferredBody, ExternalBody, AttributeBody]
    postcondition: Optional[Postcondition]
    rescue: Optional[tuple[Instruction, ...]]
    span: Span


@node
class Routine:
    names: tuple[FeatureName, ...]
    arguments: tuple[EntityDeclaration, ...]
    type: Optional[Type]           # None for a procedure
    assigner: Optional[Identifier]
    notes: tuple[Note, ...]
    body: RoutineBody
    span: Span


@node
class Attribute:
    names: tuple[FeatureName, ...]
    type: Type
    assigner: Optional[Identifier]
    notes: tuple[Note, ...]
    body: Optional[RoutineBody]    # with an AttributeBody, or None for a plain attribute
    span: Span


@node
class Constant:
    names: tuple[FeatureName, ...]
    type: Type
    value: Expression              # a manifest constant, TypedConstant or Unique
    notes: tuple[Note, ...]
    span: Span


Feature = Union[Routine, Attribute, Constant]


@node
class FeatureClause:
    """`feature {A, B}`; clients None when unrestricted."""
    clients: Optional[tuple[Identifier, ...]]
    features: tuple[Feature, ...]
    span: Span


# ---- classes -------------------------------------------------------------------------------
@node
class Rename:
    old_name: Identifier
    new_name: FeatureName
    span: Span


@node
class ExportItem:
    """`{A, B} f, g`; features None for `all`."""
    clients: tuple[Identifier, ...]
    features: Optional[tuple[Identifier, ...]]
    span: Span


@node
class Parent:
    type: ClassType
    renames: tuple[Rename, ...]
    exports: tuple[ExportItem, ...]
    undefines: tuple[Identifier, ...]
    redefines: tuple[Identifier, ...]
    selects: tuple[Identifier, ...]
    span: Span


@node
class InheritClause:
    """`inherit [{NONE}] parents`; conforming False for `inherit {NONE}`."""
    conforming: bool
    parents: tuple[Parent, ...]
    span: Span


@node
class CreationClause:
    """`create {A} make, make_from`; clients None when unrestricted."""
    clients: Optional[tuple[Identifier, ...]]
    procedures: tuple[Identifier, ...]
    span: Span


@node
class Converter:
    """`make ({T})` (creation_mode) or `to_t: {T}`."""
    name: Identifier
    types: tuple[Type, ...]
    creation_mode: bool
    span: Span


@node
class ClassDeclaration:
    name: Identifier
    marks: tuple[str, ...]         # "deferred", "expanded", "frozen", "external"
    formal_generics: tuple[FormalGeneric, ...]
    obsolete: Optional[str]
    inherit_clauses: tuple[InheritClause, ...]
    creation_clauses: tuple[CreationClause, ...]
    converters: tuple[Converter, ...]
    feature_clauses: tuple[FeatureClause, ...]
    invariant: tuple[AssertionClause, ...]
    notes: tuple[Note, ...]        # the leading and the trailing note clauses together
    span: Span

    @property
    def is_deferred(self) -> bool:
        return "deferred" in self.marks

    @property
    def is_expanded(self) -> bool:
        return "expanded" in self.marks


# ---- dump ----------------------------------------------------------------------------------
def where(span: Span) -> str:
    return f"@{span.line}:{span.column}-{span.end_line}:{span.end_column}"


def dump(tree: object) -> str:
    """A deterministic indented text form: one node per line with its span, then its fields
    (None, False and empty fields are left out)."""
    lines: list[str] = []
    _dump_node(tree, 0, "", lines)
    return "\n".join(lines) + "\n"


def _dump_node(value: object, depth: int, label: str, lines: list[str]) -> None:
    pad = "  " * depth
    if isinstance(value, Identifier):
        lines.append(f"{pad}{label}{value.text!r} {where(value.span)}")
        return
    span = getattr(value, "span", None)
    if span is None:
        lines.append(f"{pad}{label}{value!r}")
        return
    lines.append(f"{pad}{label}{type(value).__name__} {where(span)}")
    for f in fields(value):  # type: ignore[arg-type]
        if f.name in ("span", "key"):
            continue
        _dump_field(getattr(value, f.name), depth + 1, f.name, lines)


def _dump_field(value: object, depth: int, name: str, lines: list[str]) -> None:
    if value is None or value == () or (value is False and name != "value"):
        return
    pad = "  " * depth
    if isinstance(value, tuple):
        lines.append(f"{pad}{name}:")
        for item in value:
            _dump_node(item, depth + 1, "- ", lines)
    elif isinstance(value, Span):
        lines.append(f"{pad}{name}: {where(value)}")
    elif hasattr(value, "span"):
        _dump_node(value, depth, f"{name}: ", lines)
    else:
        lines.append(f"{pad}{name}: {value!r}")
