"""The root rules (ECMA-367's Root Type and Root Procedure rules, EiffelStudio's VSRT and VSRP):
the root class is neither deferred nor generic, and its root procedure is one of its creation
procedures, takes no argument and has no precondition. The checker applies them when the project
names its root (an .ecf's <root>); the driver applies the same function to the root it chooses."""

from __future__ import annotations

from collections.abc import Callable

from .universe import Universe

Report = Callable[..., None]


def check_root(universe: Universe, class_name: str, creator: str, report: Report) -> None:
    """Report VSRT and VSRP(1..3) for root `class_name`.`creator` (a class that is not there,
    or that failed an earlier pass, is left to others)."""
    info = universe.classes.get(class_name.upper())
    if info is None or info.failed or info.from_library:
        return
    where = info.decl.name.span
    if info.is_deferred:
        report("VSRT", where, name=info.name, what="deferred: it cannot be instantiated")
        return  # no creation procedures to speak of
    elif info.formals:
        report(
            "VSRT", where, name=info.name, what="generic: the root type must be a class type without actual generics"
        )
    creator = creator.lower()
    creators = info.creators
    allowed = (creators is None and creator == "default_create") or (creators is not None and creator in creators)
    feature = info.features.get(creator)
    if not allowed:
        listed = ", ".join(sorted(creators)) if creators is not None else "default_create"
        report("VSRP(1)", where, name=info.name, creator=creator, listed=listed or "none")
        return
    if feature is None:
        return
    span = feature.fname.span
    if feature.arguments:
        report("VSRP(2)", span, name=info.name, creator=creator)
    body = feature.body
    precondition = getattr(body, "precondition", None)
    if precondition is not None and precondition.clauses:
        report("VSRP(3)", span, name=info.name, creator=creator)
