"""Codegen, class layout: which Python names each generated class defines itself, so that
Python's method resolution order never changes Eiffel's meaning.

A generated class derives from its parents' classes (readable, and most features are found
there); for every name where Python's lookup along the MRO would find another version than the
one the Eiffel class has (repeated or multiple inheritance, joins, renaming), the class binds the
right one explicitly. The MRO is computed here (C3) from the layouts of the parents.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Layout:
    key: str
    bases: list[str]  # keys of the Python base classes, in order
    mro: list[str]  # keys, the class itself first
    own: dict = field(default_factory=dict)  # python name -> implementation id defined in the class body


def impl_id(feature) -> tuple:
    """What a name must resolve to: the version written in a class (one per declaration)."""
    return (feature.written_in, id(feature.decl), feature.kind == "attribute")


def c3(key: str, bases: list[str], layouts: dict) -> list[str] | None:
    sequences = [list(layouts[b].mro) for b in bases] + [list(bases)]
    result = [key]
    while True:
        sequences = [s for s in sequences if s]
        if not sequences:
            return result
        for seq in sequences:
            head = seq[0]
            if not any(head in s[1:] for s in sequences):
                break
        else:
            return None
        result.append(head)
        for s in sequences:
            if s and s[0] == head:
                s.pop(0)


def make_layout(universe, info, layouts: dict) -> Layout:
    bases = []
    for _, ty, _ in info.parents:
        parent = universe.get(ty.name)
        if parent is not None and parent.name in layouts and parent.name not in bases:
            bases.append(parent.name)
    mro = c3(info.name, bases, layouts)
    if mro is None:  # `inherit ANY; ARGUMENTS`: a parent that is another's ancestor adds nothing
        bases = [b for b in bases if not any(b in layouts[other].mro[1:] for other in bases if other != b)]
        mro = c3(info.name, bases, layouts)
    if mro is None:  # an order Python cannot linearise: keep the first parent
        bases = bases[:1]
        mro = c3(info.name, bases, layouts)
    return Layout(info.name, bases, mro)


def lookup(layout: Layout, name: str, layouts: dict):
    for key in layout.mro[1:]:
        found = layouts[key].own.get(name)
        if found is not None:
            return found
    return None
