"""Checker, features: one feature of a class as the passes see it (after renaming), and the
signature of a feature (argument and result types) in the context of a class.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from .. import syntax
from .types import Ty, substitute

CURRENT = Ty("<Current>")  # `like Current` until a call site says what Current is


@dataclass(eq=False)
class Feature:
    name: str  # final name (lower case)
    text: str  # the final name as written
    decl: object  # syntax.Routine, Attribute or Constant
    fname: syntax.FeatureName  # the name's declaration (span, aliases)
    written_in: str  # the class that declares this version
    exports: frozenset | None = None  # client class names; None: every class
    deferred: bool = False
    seed: str = ""  # "CLASS.name" where the feature was introduced
    precursors: tuple = ()  # (parent class name, Feature) this version redeclares
    shared: dict = field(default_factory=dict)  # shared by renamed/re-exported copies: the signature

    @property
    def signature(self) -> Signature | None:
        """Cached, in the context of written_in (set by the signatures pass)."""
        return self.shared.get("signature")

    @signature.setter
    def signature(self, value: Signature) -> None:
        self.shared["signature"] = value

    @property
    def aliases(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.fname.aliases)

    @property
    def kind(self) -> str:
        if isinstance(self.decl, syntax.Constant):
            return "constant"
        if isinstance(self.decl, syntax.Attribute):
            return "attribute"
        return "function" if self.decl.type is not None else "procedure"

    @property
    def is_query(self) -> bool:
        return self.kind != "procedure"

    @property
    def is_routine(self) -> bool:
        return isinstance(self.decl, syntax.Routine)

    @property
    def is_frozen(self) -> bool:
        return self.fname.frozen

    @property
    def arguments(self) -> tuple:
        return self.decl.arguments if isinstance(self.decl, syntax.Routine) else ()

    @property
    def body(self):
        return getattr(self.decl, "body", None)

    @property
    def is_once(self) -> bool:
        body = self.body
        return body is not None and isinstance(getattr(body, "body", None), syntax.InternalBody) and body.body.once

    @property
    def once_keys(self) -> tuple[str, ...]:
        return self.body.body.once_keys if self.is_once else ()

    @property
    def assigner(self) -> str | None:
        a = getattr(self.decl, "assigner", None)
        return a.key if a is not None else None

    def seeds(self) -> frozenset:
        """The seed of this feature and of every version it redeclares."""
        found = {self.seed}
        for _, precursor in self.precursors:
            found |= precursor.seeds()
        return frozenset(found)

    def renamed(self, name: syntax.FeatureName) -> Feature:
        return replace(self, name=name.name.key, text=name.name.text, fname=name)


@dataclass(frozen=True)
class Signature:
    arguments: tuple[Ty | None, ...]
    result: Ty | None
    # For each argument then the result: (feature name, attachment mark) when the type is
    # `like feature`, re-anchored at each call to the target class's version of that feature.
    anchors: tuple = ()

    @property
    def complete(self) -> bool:
        return all(a is not None for a in self.arguments)


def member_signature(universe, target: Ty, feature: Feature, current: Ty | None = None, depth: int = 0) -> Signature:
    """The signature of `feature` at a call on `target` (a type whose class has the feature);
    `like Current` becomes `current` (default: the target; a formal generic when the target is
    its constraint)."""
    info = universe.get(target.name)
    seen = info.all_ancestors.get(feature.written_in) if info is not None else None
    written = feature.signature or Signature((), None)
    via = seen.generics if seen is not None else ()
    current = target if current is None else current

    def move(ty):
        return None if ty is None else _at_target(substitute(substitute(ty, via), target.generics), current)

    types = [move(a) for a in written.arguments] + [move(written.result)]
    for index, anchor in enumerate(written.anchors):
        if anchor is not None and info is not None and depth < 8:
            types[index] = _reanchored(universe, info, target, current, anchor, depth) or types[index]
    return Signature(tuple(types[:-1]), types[-1], written.anchors)


def _reanchored(universe, info, target: Ty, current: Ty, anchor, depth: int) -> Ty | None:
    """`like name` seen from the target's class, which may have redeclared `name`."""
    name, mark = anchor
    other = info.features.get(name)
    if other is None or not other.is_query:
        return None
    found = member_signature(universe, target, other, current, depth + 1).result
    if found is None or mark is None:
        return found
    return found.with_marks(attached=mark != "detachable")


def _at_target(ty: Ty, target: Ty) -> Ty:
    if ty.name == CURRENT.name:
        return target.with_marks(attached=ty.attached, separate=target.separate or ty.separate)
    if not ty.generics:
        return ty
    return replace(ty, generics=tuple(_at_target(g, target) for g in ty.generics))
