"""Checker, hints for unknown names: "did you mean" and advice that fits what was named.

Input: the unknown name, the class or routine it was looked up in. Output: the hint text of a
VEEN or VTCT diagnostic. Names are compared in lower case (Eiffel names ignore case).
"""

from __future__ import annotations

import difflib

_CUTOFF = 0.7


def closest(name: str, candidates) -> str | None:
    """The candidate spelled most like `name` (case ignored), if one is close."""
    keys = {c.lower(): c for c in candidates}
    found = difflib.get_close_matches(name.lower(), list(keys), n=1, cutoff=_CUTOFF)
    return keys[found[0]] if found else None


def unknown_feature(ctx, name: str, info) -> str:
    """Hint for `x.name` where `info`'s class has no feature `name`."""
    if info is None:
        return "check the spelling"
    visible = {f.text for f in info.features.values() if ctx.available(f)}
    hidden = {f.text for f in info.features.values() if not ctx.available(f)}
    near = closest(name, visible)
    if near is not None:
        return f"did you mean `{near}`?"
    near = closest(name, hidden)
    if near is not None:
        return f"did you mean `{near}`? {info.name} has it but does not export it to {ctx.info.name}"
    return f"{info.name} has no feature of this name: check the spelling, or add the feature to class {info.name}"


def unknown_identifier(ctx, name: str, assigned: bool = False) -> str:
    """Hint for an unqualified `name` that is neither a local, an argument nor a feature."""
    entities = {e.name: kind_of(e.kind) for frame in ctx.scopes.frames for e in frame.values()}
    features = {f.text: f"a feature of {ctx.info.name}" for f in ctx.info.features.values()}
    written = {**features, **entities}
    if ctx.result_type is not None:
        written.setdefault("Result", "the function's result")
    near = closest(name, written)
    if near is not None:
        return f"did you mean `{near}` ({written[near]})?"
    elsewhere = _feature_elsewhere(ctx, name)
    if elsewhere is not None:
        return elsewhere
    if assigned:
        return (
            f"to keep a value in this routine, declare a local in the `local` clause (`{name}: TYPE`); "
            f"to keep it in the object, declare an attribute in class {ctx.info.name}"
        )
    return f"declare `{name}` as a local (`local {name}: TYPE`), an argument or a feature of class {ctx.info.name}"


def kind_of(kind: str) -> str:
    return {
        "argument": "an argument",
        "local": "a local",
        "object_test": "an object-test local",
        "across": "an across cursor",
        "separate": "a separate-block local",
    }.get(kind, kind)


def _feature_elsewhere(ctx, name: str) -> str | None:
    """ "`name` is a feature of T: call it on `x`" when an entity `x: T` in scope has it."""
    key = name.lower()
    for frame in ctx.scopes.frames:
        for entity in frame.values():
            info = ctx.universe.get(entity.ty.name) if entity.ty is not None and entity.ty.name else None
            feature = info.features.get(key) if info is not None else None
            if feature is not None and ctx.available(feature):
                call = f"{entity.name}.{feature.text}"
                return f"`{feature.text}` is a feature of {info.name}: call it on `{entity.name}` (`{call}`)"
    return None


def unknown_class(universe, name: str) -> str:
    """Hint for a type based on an unknown class."""
    near = closest(name, [info.name for info in universe.classes.values()])
    if near is not None and near.upper() != name.upper():
        return f"did you mean {near}?"
    return f"check the spelling, and that the file declaring {name.upper()} is in a cluster given to scoopc"
