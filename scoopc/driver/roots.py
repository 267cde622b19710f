"""Driver, the root: which class and creation procedure start the program (DESIGN section 8):
`--root CLASS[.creation]`, else the .ecf's root, else the class named like the single file or
directory given, else the one class with a `make` that no other given class mentions."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from .. import diagnostics
from ..diagnostics import Diagnostic
from ..exits import UsageError
from ..project import Project
from ..semantics.roots import check_root
from ..semantics.universe import ClassInfo, Universe


@dataclass(frozen=True)
class Root:
    key: str  # the class name, upper case
    creator: str  # the creation procedure, lower case


def parse_root_option(text: str | None) -> tuple[str, str] | None:
    """`CLASS[.creation]` -> (CLASS, creation); None for no option."""
    if not text:
        return None
    name, _, creator = text.partition(".")
    return name.upper(), (creator or "make").lower()


def choose_root(project: Project, universe: Universe, option: str | None, paths: Sequence[str]) -> Root:
    """The root of a checked program (its universe), or a UsageError that says why there is none."""
    user = {i.name: i for i in universe.classes.values() if not i.from_library}
    wanted = parse_root_option(option)
    if wanted is None and project.root is not None:
        wanted = (project.root.class_name.upper(), project.root.creation.lower())
    if wanted is None and len(paths) == 1:
        stem = Path(str(paths[0]).rstrip("/")).stem.upper()
        if stem in user:
            wanted = (stem, "make")
    if wanted is None:
        wanted = (_only_candidate(user), "make")
    name, creator = wanted
    info = user.get(name)
    if info is None:
        raise UsageError(f"root class {name} is not among the given classes")
    found: list[Diagnostic] = []
    check_root(
        universe, name, creator, lambda code, span, **arguments: found.append(diagnostics.make(code, span, **arguments))
    )
    if found:  # the checker's root rules (VSRT, VSRP), for a root it was not told of
        raise UsageError("; ".join(f"{d.code}: {d.message}" for d in found))
    return Root(name, creator)


def _only_candidate(user: dict[str, ClassInfo]) -> str:
    candidates = [n for n, i in user.items() if "make" in i.features and (i.creators is None or "make" in i.creators)]
    used = {ty.name for i in user.values() for _, ty, _ in i.parents}
    unused = [n for n in candidates if n not in used and not _mentioned_elsewhere(n, user)]
    if len(unused) == 1:
        return str(unused[0])
    listed = ", ".join(sorted(candidates)) or "none"
    raise UsageError(f"cannot tell which class is the root: use --root CLASS (candidates: {listed})")


def _mentioned_elsewhere(name: str, user: dict[str, ClassInfo]) -> bool:
    pattern = re.compile(r"\b" + name + r"\b", re.IGNORECASE)
    for other in user.values():
        if other.name != name and pattern.search(Path(other.decl.span.file).read_text(errors="replace")):
            return True
    return False
