"""Checker, recorded results: the side tables codegen reads (keyed by syntax node identity).

Nothing here decides validity; the passes fill these tables as they prove things.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .types import Ty


@dataclass
class Entity:
    """What a name denotes inside a routine."""

    name: str
    kind: str  # argument, local, result, object_test, across, separate, attribute, feature
    ty: Ty | None
    span: object = None
    handler: str | None = None  # the controlling entity's name for controlled separate values


@dataclass
class Tables:
    types: dict = field(default_factory=dict)  # expression -> Ty
    features: dict = field(default_factory=dict)  # call / operator / creation -> Feature
    entities: dict = field(default_factory=dict)  # UnqualifiedCall naming an entity -> Entity
    separate_calls: set = field(default_factory=set)  # calls whose target is separate
    lock_passing: dict = field(default_factory=dict)  # separate call -> indices of arguments that can pass locks
    wait_args: dict = field(default_factory=dict)  # precondition AssertionClause -> separate formals used as targets
    conversions: dict = field(default_factory=dict)  # expression -> (feature name, target Ty) of a conversion
    controlled: set = field(default_factory=set)  # separate expressions that are controlled
    agent_calls: set = field(default_factory=set)  # `f (a, b)` on an agent: call of its "()" feature with [a, b]
    agent_labels: dict = field(default_factory=dict)  # `agent t.x` on a TUPLE label -> x's item index
    rewrites: dict = field(default_factory=dict)  # `x (a)` -> `x.f (a)`, f x's "()" alias, checked in its place
