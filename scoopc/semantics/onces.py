"""Checker, once routines: the once keys EiffelStudio knows ("PROCESS", "THREAD", "OBJECT";
anything else is ONCE-KEY), a once function's type may not depend on the object (VFFD(7)), and
`once ("PROCESS")` results through scoop.py (VFFD(8)).
"""

from __future__ import annotations

from . import scoop
from .features import CURRENT
from .types import has_formal

KEYS = {"PROCESS", "THREAD", "OBJECT"}


def check_once(ctx, feature, result) -> None:
    if not feature.is_once:
        return
    for key in feature.once_keys:
        if key.upper() not in KEYS:
            ctx.report("ONCE-KEY", feature.body.body.span, key=key)
    declared = feature.signature.result if feature.signature is not None else None
    per_object = any(k.upper() == "OBJECT" for k in feature.once_keys)
    if declared is not None and not per_object and (has_formal(declared) or _anchored(declared)):
        ctx.report("VFFD(7)", feature.fname.name.span, name=feature.text)
        return
    scoop.check_process_once(ctx, feature, result)


def _anchored(ty) -> bool:
    return ty.name == CURRENT.name or any(_anchored(g) for g in ty.generics)
