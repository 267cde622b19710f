"""Checker, ancestors pass: parent types, inheritance cycles (VHPR(1)), and for every class its
ancestors as types in its own context.

Input: the universe. Output: ClassInfo.parents, .ancestors (conforming), .all_ancestors, the
formal generics' constraints; the classes in an order where parents come before heirs.
"""

from __future__ import annotations

from .typeresolve import TypeResolver
from .types import Ty, substitute


def compute(universe, report, infos=None) -> list:
    """Ancestors of `infos` (default: every class); classes outside `infos` are already done."""
    infos = list(universe.classes.values()) if infos is None else infos
    for info in infos:
        _resolve_parents(universe, info, report)
    order = _topological(universe, report, infos)
    for info in order:
        _collect_ancestors(universe, info)
    return order


def _resolve_parents(universe, info, report) -> None:
    resolver = TypeResolver(universe, info, report, constraints=False)
    constraints, creators, renames = [], [], []
    for formal in info.decl.formal_generics:
        resolved = [(c, resolver.resolve(c.type)) for c in formal.constraints]
        bounds = tuple(t for _, t in resolved if t is not None)
        constraints.append(bounds)
        creators.append(tuple(c.key for c in formal.creators or ()))
        # `G -> A rename f as g end`: on a G, A's `f` is called `g` (and no longer `f`).
        renames.append(
            {
                t.name: {r.new_name.name.key: r.old_name.key for r in c.renames}
                for c, t in resolved
                if t is not None and c.renames
            }
        )
    info.constraints, info.formal_creators = tuple(constraints), tuple(creators)
    info.constraint_renames = tuple(renames)
    for clause in info.decl.inherit_clauses:
        for parent in clause.parents:
            ty = resolver.resolve(parent.type)
            if ty is None:
                info.failed = True
                continue
            info.parents.append((parent, ty.with_marks(attached=True), clause.conforming))
    if not info.decl.inherit_clauses and info.name != "ANY" and universe.get("ANY") is not None:
        info.parents.append((None, Ty("ANY"), True))


def _topological(universe, report, infos) -> list:
    order, state = [], {}
    mine = {id(info) for info in infos}

    def visit(info, path):
        mark = state.get(info.name)
        if mark == "done" or id(info) not in mine:
            return
        if mark == "active":
            return
        state[info.name] = "active"
        for parent, ty, _ in info.parents:
            other = universe.get(ty.name)
            if other is None:
                continue
            if state.get(other.name) == "active":
                report(
                    "VHPR(1)", parent.type.span if parent else info.decl.name.span, name=info.name, parent=other.name
                )
                info.failed = True
                continue
            visit(other, path + [info.name])
        state[info.name] = "done"
        order.append(info)

    for info in infos:
        visit(info, [])
    return order


def _collect_ancestors(universe, info) -> None:
    own = info.own_type()
    info.ancestors = {info.name: own}
    info.all_ancestors = {info.name: own}
    for _parent, ty, conforming in info.parents:
        other = universe.get(ty.name)
        if other is None or not other.all_ancestors:
            continue
        for name, seen in other.all_ancestors.items():
            info.all_ancestors.setdefault(name, substitute(seen, ty.generics))
        if conforming:
            for name, seen in other.ancestors.items():
                info.ancestors.setdefault(name, substitute(seen, ty.generics))
