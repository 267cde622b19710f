"""The semantic checker: passes over the universe of classes, in order, each a module:
universe -> ancestors -> flatten -> signatures (+ VDRD) -> bodies (expressions, calls, agents,
creation, instructions, contracts, onces; SCOOP rules in scoop.py; void safety via flow.py).

A class that fails a pass is skipped by later passes, so one mistake gives one diagnostic.
Output: Checked (the universe, the recorded tables, the diagnostics).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .. import diagnostics
from . import ancestors, body, contracts, flatten, roots, signatures, universe as universe_module
from .tables import Tables

VOID_LEVELS = {"none": 0, "conformance": 1, "initialization": 2, "transitional": 3, "complete": 3, "all": 3}


@dataclass
class Checked:
    universe: universe_module.Universe
    tables: Tables
    diagnostics: list = field(default_factory=list)


def prepare(trees, found: list, base=None, scoop: bool = True, visible=None):
    """The universe of `trees` with ancestors, feature tables and signatures (no bodies checked);
    with `base` (a prepared universe of library classes), only the new classes are prepared.
    `scoop` False: a `thread` or `none` system, where the program's `separate` marks mean nothing.
    `visible`: which classes a class of the program sees (project.Project.visibility)."""
    universe = universe_module.build(trees, found, base)
    universe.scoop, universe.visible = scoop, visible
    fresh = [i for i in universe.classes.values() if base is None or base.classes.get(i.name) is not i]
    order = ancestors.compute(universe, _reporter(universe, found, None), fresh)
    for info in order:  # after an unknown parent, its features are missing: stay silent
        flatten.flatten(universe, info, _reporter(universe, found, info) if not info.failed else _silent)
        if any((parent := universe.get(ty.name)) is not None and parent.failed for _, ty, _ in info.parents):
            info.failed = True  # an heir of a broken class would only repeat its errors
    for info in order:  # a bad signature skips that feature's body, not the class
        signatures.resolve_all(universe, info, _reporter(universe, found, None))
    for info in order:
        if not info.failed:
            signatures.check_redeclarations(universe, info, _reporter(universe, found, info))
            signatures.check_assigners(universe, info, _reporter(universe, found, info))
            signatures.check_converters(universe, info, _reporter(universe, found, info))
            signatures.check_joins(universe, info, _reporter(universe, found, info))
            signatures.check_constraint_creators(universe, info, _reporter(universe, found, info))
    return universe, order


def check(
    trees,
    void_safety=None,
    library_bodies: bool = True,
    base=None,
    root: tuple[str, str] | None = None,
    concurrency: str = "scoop",
    visible=None,
) -> Checked:
    """`trees`: [(ClassDeclaration, from_library)]. library_bodies False skips the routine
    bodies of library classes (already known clean, e.g. from the cache). `base`: the library's
    prepared universe (its classes are then not in `trees`). `root`: (class, creation procedure)
    when the project names its root, checked against VSRT and VSRP. `concurrency`: the system's
    (scoop, thread or none); SCOOP's rules apply only under scoop. `visible`: see `prepare`."""
    found: list = []
    level = VOID_LEVELS.get((void_safety or "complete").lower(), 3)
    if base is not None and any(base.get(tree.name.text) is not None for tree, _ in trees):
        base = None  # a user class replaces a library class: start afresh
    universe, order = prepare(trees, found, base, scoop=concurrency == "scoop", visible=visible)
    universe.void_safe = level >= 1
    tables = Tables()
    checked = order if base is not None else list(universe.classes.values())
    for info in checked:
        if info.failed or (info.from_library and not library_bodies):
            continue
        body.check_class(universe, info, tables, found, level)
    for info in checked:  # after every class: an inherited precondition's calls are recorded
        if not info.failed and not info.from_library:
            contracts.check_inherited_preconditions(universe, info, tables, found)
    if root is not None:
        roots.check_root(universe, root[0], root[1], _reporter(universe, found, None))
    unique = list({(d.code, d.span, d.message): d for d in found}.values())
    unique.sort(key=diagnostics.sort_key)
    return Checked(universe, tables, unique)


def _silent(code: str, span, **arguments) -> None:
    pass


def _reporter(universe, found: list, info):
    def report(code: str, span, **arguments) -> None:
        found.append(diagnostics.make(code, span, **arguments))
        if info is not None:
            info.failed = True

    return report
