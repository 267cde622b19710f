"""Checker, creation validity: creation instructions and expressions (VGCC(1), VGCC(3), VGCC(5),
VGCC(6)), creation through formal generics' `create` constraints, and separate creation (the
new object's processor receives the arguments: the separate-argument rules apply).
"""

from __future__ import annotations

from .. import syntax
from .features import member_signature
from .types import Ty
from .values import Value


class CreationChecks:
    def creation(self, node, ty: Ty, procedure: syntax.Identifier | None, arguments) -> None:
        if ty.is_formal:
            self._formal_creation(node, ty, procedure, arguments)
            return
        info = self.universe.get(ty.name)
        if info is None or info.failed:
            self.evaluate(arguments)
            return  # a broken class's errors are reported in the class
        if info.is_deferred:
            self.report("VGCC(1)", node.span, cls=info.name)
            self.evaluate(arguments)
            return
        name = procedure.key if procedure is not None else None
        creators = info.creators
        if name is None:
            if creators is not None and "default_create" not in creators and not info.is_expanded:
                self.report("VGCC(5)", node.span, cls=info.name, procedures=", ".join(sorted(creators)) or "none")
            feature = info.features.get("default_create")
            if feature is not None:
                self.tables.features[node] = feature
            return
        feature = info.features.get(name)
        allowed = (creators is None and name == "default_create") or (creators is not None and name in creators)
        if feature is None or not allowed or not self._creation_available(creators, name):
            listed = "default_create" if creators is None else (", ".join(sorted(creators)) or "none")
            self.report("VGCC(6)", procedure.span, name=procedure.text, cls=info.name, procedures=listed)
            self.evaluate(arguments)
            return
        self.tables.features[node] = feature
        signature = member_signature(self.universe, ty.with_marks(attached=True), feature)
        target = Value(ty, "<new>") if ty.separate else None
        values = self.actuals(node, arguments, signature.arguments, target)
        if ty.separate:
            from . import scoop  # deferred: a cycle (scoopc.semantics.scoop imports this module)

            self.tables.separate_calls.add(node)
            scoop.lock_passing(self, node, values, signature.arguments)

    def _creation_available(self, creators, name: str) -> bool:
        clients = creators.get(name) if creators is not None else None
        return clients is None or any(c in self.info.ancestors for c in clients)

    def _formal_creation(self, node, ty: Ty, procedure, arguments) -> None:
        allowed = self.info.formal_creators[ty.formal] if ty.formal < len(self.info.formal_creators) else ()
        name = procedure.key if procedure is not None else "default_create"
        if name not in allowed:
            self.report(
                "VGCC(6)",
                procedure.span if procedure is not None else node.span,
                name=name,
                cls=self.info.formals[ty.formal],
                procedures=", ".join(allowed) or "none",
            )
        elif procedure is not None:
            # the constraint's procedure (through its renaming): what runs, and its arguments
            base, feature = self._find_feature(ty, procedure)
            if feature is not None:
                self.tables.features[node] = feature
                self.actuals(node, arguments, member_signature(self.universe, base, feature).arguments, None)
                return
        self.evaluate(arguments)
