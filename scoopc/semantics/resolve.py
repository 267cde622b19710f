"""Checker, name resolution: what an unqualified name denotes in a routine (argument, local,
Result, object-test/across/separate-block local, or a feature of the class), and the rules on
declaring names: VRFA, VRLE(1), VRLE(2), VREG, and the clash test used by VUOT(1), VOIT(2), FRESH_IDENTIFIER.
"""

from __future__ import annotations

from .scoop import separate_by_constraint
from .tables import Entity


class Scopes:
    """Entities of one routine: arguments and locals, then nested scopes pushed by object tests,
    across loops and separate blocks."""

    def __init__(self):
        self.frames: list[dict[str, Entity]] = [{}]

    def lookup(self, name: str) -> Entity | None:
        for frame in reversed(self.frames):
            found = frame.get(name)
            if found is not None:
                return found
        return None

    def push(self, entities=()) -> None:
        self.frames.append({e.name: e for e in entities})

    def pop(self) -> None:
        self.frames.pop()

    def add(self, entity: Entity) -> None:
        self.frames[-1][entity.name] = entity


def declare_routine_entities(ctx, arguments, locals_, signature_args, resolve_local) -> None:
    """Arguments then locals of a routine (or inline agent) into ctx.scopes, with VRFA, VRLE, VREG."""
    seen = {}
    for decl, ty in zip(arguments, signature_args):
        name = decl.name.key
        if name in seen:
            ctx.report("VREG", decl.name.span, name=decl.name.text)
        elif ctx.info.features.get(name) is not None:
            ctx.report("VRFA", decl.name.span, name=decl.name.text, cls=ctx.info.name)
        seen[name] = "argument"
        ctx.scopes.add(
            Entity(
                name,
                "argument",
                ty,
                decl.name.span,
                handler=name if ty is not None and (ty.separate or separate_by_constraint(ctx, ty)) else None,
            )
        )
    for decl in locals_:
        name = decl.name.key
        ty = resolve_local(decl.type)
        if name == "result":
            ctx.report("VRLE(1)", decl.name.span, name=decl.name.text, cls=ctx.info.name)
        elif seen.get(name) == "argument":
            ctx.report("VRLE(2)", decl.name.span, name=decl.name.text)
        elif name in seen:
            ctx.report("VREG", decl.name.span, name=decl.name.text)
        elif ctx.info.features.get(name) is not None:
            ctx.report("VRLE(1)", decl.name.span, name=decl.name.text, cls=ctx.info.name)
        seen[name] = "local"
        ctx.scopes.add(
            Entity(
                name,
                "local",
                ty,
                decl.name.span,
                handler="?" if ty is not None and (ty.separate or separate_by_constraint(ctx, ty)) else None,
            )
        )


def clashes(ctx, name: str) -> bool:
    """Whether a new scoped entity `name` would hide a feature, argument, local or another one."""
    return ctx.scopes.lookup(name) is not None or ctx.info.features.get(name) is not None
