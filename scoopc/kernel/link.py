"""Loading a compiled package: import its modules parents first (each generated module imports
the classes it uses itself: its ancestors by name at the top, the others' modules at the bottom)."""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path

from . import register

_LOADED: dict = {}

#: The file, in a compiled program's package, naming the library routines that are leaves in that
#: program (scoopc.codegen.scoop.library_leaves); `load` reads it.
LIBRARY_LEAVES_FILE = "_library_leaves.json"
_LIBRARY_LEAVES: set = set()  # "CLASS.routine" of the program loaded in this process


def load(package: str, modules: list[str], uses: tuple[str, ...] = ()) -> dict:
    """Import the packages of `uses` (e.g. the standard library), then `package`'s modules in
    order; {class name: class} of the package's own classes."""
    if package in _LOADED:
        return _LOADED[package]
    if uses:  # a program (the library itself uses nothing)
        _read_library_leaves(package)
    for other in uses:
        importlib.import_module(other)
    loaded = [importlib.import_module(f"{package}.{m}") for m in modules]
    own = {}
    for module in loaded:
        for key, value in vars(module).items():
            if isinstance(value, type) and getattr(value, "__module__", None) == module.__name__:
                own[key] = value
    _LOADED[package] = own
    return own


def forget(package: str) -> None:
    """A package is to be loaded afresh (another program of the same package name)."""
    _LOADED.pop(package, None)


def register_again(package: str) -> None:
    """Register a loaded package's classes again (a caller may have reset the registry: tests)."""

    for cls in _LOADED.get(package, {}).values():
        key = getattr(cls, "_key_", None)
        if key is not None:
            register(key, cls)


def _read_library_leaves(package: str) -> None:
    """The program being loaded replaces the list (tests run one program after another in a
    process: a routine that is a leaf in one may not be in the next)."""
    module = sys.modules.get(package)
    path = Path(getattr(module, "__file__", None) or ".").parent / LIBRARY_LEAVES_FILE
    try:
        leaves = set(json.loads(path.read_text()))
    except (OSError, ValueError):  # a package compiled without the list: no library leaves
        leaves = set()
    _LIBRARY_LEAVES.clear()
    _LIBRARY_LEAVES.update(leaves)


def is_leaf_routine(cls: type, name: str) -> bool:
    """Is routine `name` of (generated) class `cls` a leaf (no loop, no separate call, nothing
    that blocks: scoopc.codegen.scoop) in the loaded program? A program's own routine says so
    by its `@_rt.leaf` mark; a library routine by the program's list of library leaves."""
    for owner in cls.__mro__:
        function = owner.__dict__.get(name)
        if function is not None:
            return bool(getattr(function, "_scoop_leaf_", False)) or f"{owner.__name__}.{name}" in _LIBRARY_LEAVES
    return False
