"""Checker, universe: the class table of a program (user clusters plus the standard library).

Input: the parsed units of the project and of stdlib/. Output: Universe, name -> ClassInfo.
Duplicate class names are reported (VSCN); the user's class wins over the library's.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .. import diagnostics, syntax
from ..diagnostics import Diagnostic
from .types import ALIASES, Ty


@dataclass(eq=False)
class ClassInfo:
    """One class and everything the passes learn about it (filled pass by pass)."""

    name: str
    decl: syntax.ClassDeclaration
    from_library: bool
    failed: bool = False  # a pass reported an error: later passes skip it
    formals: tuple[str, ...] = ()
    parents: list = field(default_factory=list)  # [(syntax.Parent, Ty, conforming)]
    ancestors: dict = field(default_factory=dict)  # conforming ancestors: name -> Ty in this class's context
    all_ancestors: dict = field(default_factory=dict)  # every ancestor, conforming or not
    features: dict = field(default_factory=dict)  # final name -> Feature
    aliases: dict = field(default_factory=dict)  # (operator, arity) -> Feature
    creators: dict | None = None  # name -> clients (None: default_create)
    constraints: tuple = ()  # per formal: tuple of constraint Ty
    formal_creators: tuple = ()  # per formal: creation procedure names
    constraint_renames: tuple = ()  # per formal: {constraint class: {new name: old name}}
    joins: list = field(default_factory=list)  # (name, features) inherited versions joined into one

    @property
    def is_deferred(self) -> bool:
        return self.decl.is_deferred

    @property
    def is_expanded(self) -> bool:
        return self.decl.is_expanded

    def own_type(self) -> Ty:
        """The class's type in its own context: `C [G, H]` with G, H its formals."""
        return Ty(self.name, tuple(Ty(f, formal=i) for i, f in enumerate(self.formals)))


@dataclass
class Universe:
    classes: dict[str, ClassInfo] = field(default_factory=dict)
    void_safe: bool = True
    shadowed: dict[str, str] = field(
        default_factory=dict
    )  # library class name -> its key when a user class has the name
    operator_memo: dict = field(default_factory=dict)  # (type, operator, arity, context) -> candidate features

    def get(self, name: str) -> ClassInfo | None:
        key = name.upper()
        return self.classes.get(ALIASES.get(key, key))

    def canonical(self, name: str) -> str:
        key = name.upper()
        return ALIASES.get(key, key)

    def name_in(self, name: str, info: ClassInfo | None) -> str:
        """The key of class `name` as written in `info`: library code keeps seeing its own classes
        when a user class has the same name."""
        key = self.canonical(name)
        if info is not None and info.from_library:
            return self.shadowed.get(key, key)
        return key


def stdlib_root() -> Path:
    """stdlib/ installed beside the package (a wheel) or at the top of the source tree."""
    here = Path(__file__).resolve().parent.parent
    installed = here / "stdlib"
    return installed if (installed / "base").is_dir() else here.parent / "stdlib"


def stdlib_files(clusters: tuple[str, ...] = ("base", "thread", "time", "testing", "roboscoop")) -> list[Path]:
    root = stdlib_root()
    return sorted(p for cluster in clusters for p in (root / cluster).rglob("*.e"))


def build(
    trees: list[tuple[syntax.ClassDeclaration, bool]], found: list[Diagnostic], base: Universe | None = None
) -> Universe:
    """The class table of `trees` (declaration, from_library); the user's classes first.
    `base`: classes already prepared (the library's, from the cache) to start from."""
    universe = Universe(dict(base.classes) if base is not None else {})
    for decl, from_library in sorted(trees, key=lambda t: t[1]):
        name = decl.name.key.upper()
        known = universe.classes.get(name)
        if known is not None and not (base is not None and name in base.classes):
            if not from_library:
                found.append(diagnostics.make("VSCN", decl.name.span, name=name, other=str(known.decl.name.span)))
                continue
            universe.shadowed[name] = f"{name}@BASE"  # the user's class has the name
            name = universe.shadowed[name]
        info = ClassInfo(name, decl, from_library)
        info.formals = tuple(g.name.key.upper() for g in decl.formal_generics)
        universe.classes[name] = info
    return universe
