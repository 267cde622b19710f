"""Checker, flattening pass: the feature table of each class from its own declarations and its
parents' tables, applying rename, export, undefine, redefine and select.

Input: classes in parents-first order. Output: ClassInfo.features, .aliases, .creators.
Rules: VMFN, VHRC(1), VDRS(1), VDRS(4), VDUS(1), VDUS(2), VMSS(1), VMRC(2), VCCH(1).
"""

from __future__ import annotations

from dataclasses import replace

from .. import syntax
from .features import Feature


def flatten(universe, info, report) -> None:
    own = _own_features(universe, info, report)
    _check_aliases(own, report)
    versions: dict[str, list] = {}
    listed: dict[str, list] = {}
    for parent, ty, _ in info.parents:
        parent_info = universe.get(ty.name)
        if parent_info is None:
            continue
        inherited = _adapt(universe, info, parent, parent_info, report)
        for name, feature in inherited.items():
            versions.setdefault(name, []).append((parent_info.name, feature))
        for ident in parent.redefines if parent else ():
            listed.setdefault(ident.key, []).append(ident)
    table = {}
    for name, found in versions.items():
        if name in own:
            _redeclare(own[name], found, name in listed, report)
        else:
            for ident in listed.get(name, ()):
                report("VDRS(4)", ident.span, name=ident.text)
            chosen = _join(info, name, found, report)
            if chosen is not None:
                table[name] = chosen
    table.update(own)
    _check_alias_clashes(own, table, report)
    _check_inherited_alias_clashes(info, own, table, report)
    _check_selection(info, table, report)
    info.features = table
    info.aliases = _aliases(table)
    info.creators = _creators(universe, info)
    _check_creators(info, report)
    _check_expanded(info, report)
    _check_effective(info, report)


def _own_features(universe, info, report) -> dict:
    own = {}
    for clause in info.decl.feature_clauses:
        exports = _clients(universe, clause.clients, info)
        for decl in clause.features:
            for fname in decl.names:
                key = fname.name.key
                if key in own:
                    report("VMFN", fname.name.span, name=fname.name.text, where="twice in this class")
                    continue
                deferred = isinstance(decl, syntax.Routine) and isinstance(decl.body.body, syntax.DeferredBody)
                own[key] = Feature(
                    key, fname.name.text, decl, fname, info.name, exports, deferred, seed=f"{info.name}.{key}"
                )
    return own


def _clients(universe, names, info=None):
    if names is None:
        return None
    return frozenset(universe.name_in(n.text, info) for n in names)


def _adapt(universe, info, parent, parent_info, report) -> dict:
    """The parent's features under their names in the heir, with the parent clause applied."""
    table = parent_info.features
    if parent is None:
        return dict(table)
    renames = {}
    for rename in parent.renames:
        if rename.old_name.key not in table:
            report("VHRC(1)", rename.old_name.span, name=rename.old_name.text, parent=parent_info.name)
        else:
            renames[rename.old_name.key] = rename.new_name
    inherited = {}
    for name, feature in table.items():
        new = renames.get(name)
        feature = feature.renamed(new) if new is not None else feature
        inherited[feature.name] = feature
    _check_names(parent, parent_info, inherited, report)
    # ECMA-367 8.7.10/8.7.12: a feature named in export items is exported to the union of their
    # clients, wherever the items stand; `all` sets the export status of the features no item
    # names (several `all` items: the union). EiffelStudio reads the clause the same way.
    named: dict = {}
    everything = None
    for item in parent.exports:
        clients = _clients(universe, item.clients, info)
        if item.features is None:
            everything = clients if everything is None else everything | clients
            continue
        for ident in item.features:
            if ident.key in inherited:
                named[ident.key] = clients if ident.key not in named else named[ident.key] | clients
    for name in list(inherited):
        clients = named.get(name, everything)
        if name in named or everything is not None:
            inherited[name] = replace(inherited[name], exports=clients)
    for ident in parent.undefines:
        feature = inherited.get(ident.key)
        if feature is not None and feature.is_routine and not feature.is_frozen:
            inherited[ident.key] = replace(feature, deferred=True)
    return inherited


def _check_names(parent, parent_info, inherited, report) -> None:
    for ident in parent.redefines:
        if ident.key not in inherited:
            report("VDRS(1)", ident.span, name=ident.text, parent=parent_info.name)
    for ident in parent.undefines:
        feature = inherited.get(ident.key)
        if feature is None:
            report("VDUS(1)", ident.span, name=ident.text, parent=parent_info.name)
        elif not feature.is_routine or feature.is_frozen:
            what = "frozen" if feature.is_frozen else f"an {feature.kind}"
            report("VDUS(2)", ident.span, name=ident.text, what=what)
    for ident in parent.selects:
        if ident.key not in inherited:
            report("VMSS(1)", ident.span, name=ident.text, parent=parent_info.name)


def _redeclare(feature: Feature, found: list, listed: bool, report) -> None:
    effective = [f for _, f in found if not f.deferred]
    if effective and not listed:
        report(
            "VMFN",
            feature.fname.name.span,
            name=feature.text,
            where=f"also inherited from {found[0][0]}; list it in a `redefine` clause to redeclare it",
        )
    feature.precursors = feature.precursors + tuple(found)


def _join(info, name: str, found: list, report):
    distinct = []
    for parent, feature in found:
        if not any(feature.decl is other.decl and feature.deferred == other.deferred for _, other in distinct):
            distinct.append((parent, feature))
    if len(distinct) == 1:
        return distinct[0][1]
    effective = [(p, f) for p, f in distinct if not f.deferred]
    if len(effective) <= 1:
        info.joins.append((name, [f for _, f in distinct]))  # signatures checked later (VDJR)
        return effective[0][1] if effective else distinct[0][1]
    if len({f.seed for _, f in effective}) == 1 or all(f.decl is effective[0][1].decl for _, f in effective):
        selected = _selected(info, name, effective)
        if selected is not None:
            return selected
        report("VMRC(2)", info.decl.name.span, name=name, versions=", ".join(f"from {p}" for p, _ in effective))
        return effective[0][1]
    report(
        "VMFN",
        info.decl.name.span,
        name=name,
        where=f"inherited from both {effective[0][0]} and {effective[1][0]}; rename or undefine one",
    )
    return effective[0][1]


def _check_selection(info, table: dict, report) -> None:
    """VMRC(2): a feature inherited repeatedly that reaches the class in two different versions
    (under two names) needs one of them selected, for calls through the common ancestor."""
    if len(info.parents) < 2:
        return
    by_seed: dict = {}
    for feature in table.values():
        for seed in feature.seeds():
            by_seed.setdefault(seed, []).append(feature)
    selected = {i.key for parent, _, _ in info.parents if parent is not None for i in parent.selects}
    for versions in by_seed.values():
        distinct = {id(f.decl): f for f in versions}
        if len(distinct) > 1 and not any(f.name in selected for f in versions):
            names = sorted(f.name for f in distinct.values())
            report("VMRC(2)", info.decl.name.span, name=names[0], versions="as " + ", ".join(f"`{n}`" for n in names))
            return


def _selected(info, name: str, effective: list):
    for parent, ty, _ in info.parents:
        if parent is not None and any(i.key == name for i in parent.selects):
            for owner, feature in effective:
                if owner == ty.name:
                    return feature
    return None


def _aliases(table: dict) -> dict:
    found: dict = {}
    for feature in table.values():
        for alias in feature.aliases:
            found.setdefault(alias.lower(), []).append(feature)
    return found


def _creators(universe, info):
    clauses = info.decl.creation_clauses
    if not clauses:
        return None
    creators = {}
    for clause in clauses:
        for ident in clause.procedures:
            creators[ident.key] = _clients(universe, clause.clients, info)
    return creators


UNARY_ONLY = {"not"}
BINARY_ONLY = {
    "*",
    "/",
    "//",
    "\\\\",
    "^",
    "<",
    ">",
    "<=",
    ">=",
    "and",
    "or",
    "xor",
    "and then",
    "or else",
    "implies",
    "|..|",
}


def _check_aliases(own: dict, report) -> None:
    """VFAV(1): an operator alias names a query with one argument (binary) or none (unary);
    VFAV(2): a bracket alias names a query with at least one argument; VFAV(3): a parenthesis
    alias names a routine with at least one argument; a `convert` mark needs an operator alias
    (VFAV(5)) on a feature with one argument (VFAV(4))."""
    for feature in own.values():
        arity = len(feature.arguments)
        for alias in feature.fname.aliases:
            name = alias.name.lower()
            if name in ("()", "[]") and alias.convert:
                report("VFAV(5)", alias.span, name=feature.text, operator=alias.name)
            elif alias.convert and arity != 1:
                report("VFAV(4)", alias.span, name=feature.text, operator=alias.name, count=arity)
            if name == "()":
                if feature.kind not in ("procedure", "function") or arity == 0:
                    report(
                        "VFAV(3)",
                        alias.span,
                        name=feature.text,
                        operator=alias.name,
                        problem="it needs a routine with at least one argument",
                    )
                continue
            if name == "[]":
                if not feature.is_query or arity == 0:
                    report(
                        "VFAV(2)",
                        alias.span,
                        name=feature.text,
                        operator=alias.name,
                        problem="it needs a query with at least one argument",
                    )
                continue
            fits = feature.is_query and (
                arity == 0 and name not in BINARY_ONLY or arity == 1 and name not in UNARY_ONLY
            )
            if not fits:
                report(
                    "VFAV(1)",
                    alias.span,
                    name=feature.text,
                    operator=alias.name,
                    problem="an operator alias needs a query with one argument (binary operator) "
                    "or none (unary operator)",
                )


def _check_alias_clashes(own: dict, table: dict, report) -> None:
    """The uniqueness conditions of VFAV(1)..(3): no two queries of a class have one operator
    alias with one number of arguments, no two features a bracket alias, nor a parenthesis alias.
    Reported at the alias of the class's own feature (two inherited ones are the parents' matter)."""
    for feature in own.values():
        for alias in feature.fname.aliases:
            name = alias.name.lower()
            code = {"[]": "VFAV(2)", "()": "VFAV(3)"}.get(name, "VFAV(1)")
            for other in table.values():
                if other.name == feature.name or name not in (a.lower() for a in other.aliases):
                    continue
                if code == "VFAV(1)" and (
                    not other.is_query or not feature.is_query or len(other.arguments) != len(feature.arguments)
                ):
                    continue
                here, there = feature.fname.span, other.fname.span
                if other.name in own and (there.line, there.column) > (here.line, here.column):
                    continue  # two own features: reported once, at the later one
                report(
                    code,
                    alias.span,
                    name=feature.text,
                    operator=alias.name,
                    problem=f"`{other.text}` has this alias too"
                    + (" with as many arguments" if code == "VFAV(1)" else ""),
                )
                break


def _check_inherited_alias_clashes(info, own: dict, table: dict, report) -> None:
    """Two features the class inherits under different names with one alias (and, for an
    operator, one number of arguments): VFAV(1), (2) or (3) in the heir, as EiffelStudio's
    INHERIT_TABLE.check_alias_name_conflict reports it while it builds the heir's feature table
    (a rename or an undefinition in the inherit clause resolves it). Reported at the class name."""
    seen: dict = {}
    for feature in table.values():
        if feature.name in own:
            continue
        for alias in feature.aliases:
            name = alias.lower()
            code = {"[]": "VFAV(2)", "()": "VFAV(3)"}.get(name, "VFAV(1)")
            if code == "VFAV(1)" and not feature.is_query:
                continue  # VFAV(1) of the parent's own text
            key = (name, len(feature.arguments) if code == "VFAV(1)" else None)
            other = seen.setdefault(key, feature)
            if other is not feature and other.name != feature.name:
                report(
                    code,
                    info.decl.name.span,
                    name=feature.text,
                    operator=alias,
                    problem=f"the inherited `{other.text}` has this alias too"
                    + (" with as many arguments" if code == "VFAV(1)" else "")
                    + "; rename one of them in the inherit clause",
                )


def _check_creators(info, report) -> None:
    """VGCP(2): each name of a creation clause is a procedure of the class; VGCP(3): once."""
    seen = set()
    for clause in info.decl.creation_clauses:
        for ident in clause.procedures:
            feature = info.features.get(ident.key)
            if ident.key in seen:
                report("VGCP(3)", ident.span, name=ident.text)
            elif feature is None or feature.is_query:
                what = (
                    "not a feature of the class"
                    if feature is None
                    else f"{'an' if feature.kind[0] in 'aeiou' else 'a'} {feature.kind}, not a procedure"
                )
                report("VGCP(2)", ident.span, name=ident.text, what=what)
            seen.add(ident.key)


def _check_expanded(info, report) -> None:
    """VTEC(1): an expanded class is not deferred; VTEC(2): its objects are made without
    arguments, so `default_create` is a creation procedure (or there is no creation clause)."""
    if not info.is_expanded:
        return
    if info.is_deferred:
        report("VTEC(1)", info.decl.name.span, name=info.name)
    elif info.creators is not None and "default_create" not in info.creators:
        report("VTEC(2)", info.decl.name.span, name=info.name)


def _check_effective(info, report) -> None:
    if info.is_deferred:
        return
    missing = sorted(n for n, f in info.features.items() if f.deferred)
    if missing:
        report("VCCH(1)", info.decl.name.span, name=info.name, features=", ".join(missing))
