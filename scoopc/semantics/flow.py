"""Checker, flow facts for void safety (ECMA-367 8.19): which entities are known attached and
which attached locals are not yet set, at one point of a routine body.

Facts are immutable; branches are joined (attached: intersection, unset: union).
"""

from __future__ import annotations

from dataclasses import dataclass, replace


@dataclass(frozen=True)
class Facts:
    attached: frozenset = frozenset()  # entity names known attached here
    unset: frozenset = frozenset()  # attached locals (and Result) not yet given a value

    def with_attached(self, names) -> Facts:
        return replace(self, attached=self.attached | frozenset(names)) if names else self

    def without(self, name: str) -> Facts:
        return replace(self, attached=self.attached - {name}) if name in self.attached else self

    def set(self, name: str, attached: bool) -> Facts:
        facts = replace(self, unset=self.unset - {name})
        return facts.with_attached((name,)) if attached else facts.without(name)

    def join(self, other: Facts) -> Facts:
        return Facts(self.attached & other.attached, self.unset | other.unset)


# After `retry`, `raise` (a routine that never returns) or the end of a branch that cannot fall
# through, a branch contributes nothing to the join.
UNREACHABLE = None


def join(a, b):
    if a is UNREACHABLE:
        return b
    if b is UNREACHABLE:
        return a
    return a.join(b)
