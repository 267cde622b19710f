"""Checker, once routines: the once keys EiffelStudio knows ("PROCESS", "THREAD", "OBJECT";
anything else is ONCE-KEY), and `once ("PROCESS")` results through scoop.py (VFFD(8)).
"""
from __future__ import annotations

from . import scoop

KEYS = {"PROCESS", "THREAD", "OBJECT"}


def check_once(ctx, feature, result) -> None:
    if not feature.is_once:
        return
    for key in feature.once_keys:
        if key.upper() not in KEYS:
            ctx.report("ONCE-KEY", feature.body.body.span, key=key)
    scoop.check_process_once(ctx, feature, result)
