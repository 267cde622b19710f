"""Codegen, names: the Python name of every feature and class.

A feature is reached under the original name of its seed (the feature's name in the class that
introduced it), so that a call through any ancestor finds the version the object's class has
(Eiffel's dynamic binding through renaming). When two different features of one class would
get the same Python name, the seed whose class comes first (library before user, ancestor
before heir) keeps it and the other is qualified with its class: `f__b`.
"""

from __future__ import annotations

import hashlib
import keyword

from ..semantics.types import ALIASES

ONCE_CELL = "_once_"  # a once routine body's last parameter: its cell (runtime once.py)
RESERVED = frozenset(keyword.kwlist) | {"self", "here", "Result", "print", "type", "super", "object"}


def py_identifier(name: str) -> str:
    name = name.lower()
    return name + "_" if name in RESERVED or name.startswith("_") else name


def class_name(key: str) -> str:
    """The Python class of an Eiffel class key (`CELL@BASE` is the library's CELL): its Eiffel name,
    which never meets the generated module's own names (they start with `_`, classes.HEADER_IMPORTS)."""
    return key.split("@")[0]


def eiffel_class_name(key: str) -> str:
    """The Eiffel name of a class key, for traces and documentation."""
    return key.split("@")[0]


MODULE_NAME_MAX = 100  # characters: file systems allow 255 bytes per name; `.py`, `.pyc` tags come on top


def module_name(key: str) -> str:
    """The module (file) of a class: its name in lower case; a very long name is cut, with a digest
    of the whole name after it to keep it unique."""
    name = eiffel_class_name(key).lower()
    if len(name) <= MODULE_NAME_MAX:
        return name
    return f"{name[: MODULE_NAME_MAX - 17]}_{hashlib.sha256(name.encode()).hexdigest()[:16]}"


def seed_class(seed: str) -> str:
    return seed.rsplit(".", 1)[0]


def seed_name(seed: str) -> str:
    return seed.rsplit(".", 1)[1]


class Naming:
    """Python names of seeds for one universe (demotions computed over every class)."""

    def __init__(self, universe):
        self.universe = universe
        self.demoted: dict[str, str] = {}
        self.replicas: dict[str, dict[str, str]] = {}  # class key -> {final name: Python name}
        for info in universe.classes.values():
            self._resolve_class(info)
        done: set = set()
        for info in universe.classes.values():
            self._find_replicas(info, done)

    def _rank(self, seed: str) -> tuple:
        owner = self.universe.get(seed_class(seed))
        library = owner is not None and owner.from_library
        depth = len(owner.all_ancestors) if owner is not None else 0
        return (0 if library else 1, depth, seed)

    def _resolve_class(self, info) -> None:
        by_name: dict[str, dict] = {}
        for feature in info.features.values():
            for seed in self.feature_seeds(info, feature):
                by_name.setdefault(py_identifier(seed_name(seed)), {}).setdefault(id(feature.decl), set()).add(seed)
        for name, groups in by_name.items():
            if len(groups) < 2:
                continue
            ranked = sorted(groups.values(), key=lambda seeds: min(self._rank(s) for s in seeds))
            for seeds in ranked[1:]:
                for seed in seeds:
                    if seed not in ranked[0]:
                        self.demoted[seed] = f"{name}__{class_name(seed_class(seed)).lower()}"

    def _find_replicas(self, info, done: set) -> None:
        """Repeated inheritance: two features of `info` with a common seed (`speed` inherited as
        `road_speed` and as `water_speed`). The selected one keeps the seed's name (calls through
        the common ancestor reach it); the others get a name of their own in this class and its
        descendants."""
        if info.name in done:
            return
        done.add(info.name)
        parents = [(clause, self.universe.get(ty.name)) for clause, ty, _ in info.parents]
        found: dict = {}
        for _, parent in parents:
            if parent is None:
                continue
            self._find_replicas(parent, done)
            for pname, pyname in self.replicas.get(parent.name, {}).items():
                inherited = parent.features.get(pname)
                for feature in info.features.values():
                    if inherited is not None and feature.decl is inherited.decl and feature.shared is inherited.shared:
                        found.setdefault(feature.name, pyname)
        selected = {i.key for clause, _ in parents if clause is not None for i in clause.selects}
        if selected:
            by_seed: dict = {}
            for feature in info.features.values():
                if feature.name not in found:
                    for seed in feature.seeds():
                        by_seed.setdefault(seed, []).append(feature)
            for versions in by_seed.values():
                if len(versions) > 1 and any(f.name in selected for f in versions):
                    for feature in versions:
                        if feature.name not in selected:
                            found[feature.name] = f"{py_identifier(feature.name)}__{class_name(info.name).lower()}"
        if found:
            self.replicas[info.name] = found

    def name_in(self, class_key, feature) -> str:
        """The Python name of `feature` reached through an entity whose type's class is `class_key`."""
        table = self.replicas.get(class_key) if class_key is not None else None
        if table:
            found = table.get(feature.name)
            if found is not None:
                return found
        return self.primary(feature)

    def feature_seeds(self, info, feature) -> set:
        seeds = set(feature.seeds())
        for name, versions in info.joins:
            if name == feature.name:
                for version in versions:
                    seeds |= version.seeds()
        return seeds

    def seed(self, seed: str) -> str:
        return self.demoted.get(seed) or py_identifier(seed_name(seed))

    def primary(self, feature) -> str:
        """The name a feature is called by (and an attribute stored under): its oldest seed's."""
        seeds = feature.seeds()
        best = min(seeds, key=self._rank)
        return self.seed(best)

    def all_names(self, info, feature) -> list[str]:
        replica = self.replicas.get(info.name, {}).get(feature.name)
        if replica is not None:
            return [replica]
        names = {self.seed(s) for s in self.feature_seeds(info, feature)}
        primary = self.primary(feature)
        return [primary] + sorted(names - {primary})


def canonical(name: str) -> str:
    return ALIASES.get(name, name)
