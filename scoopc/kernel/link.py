"""Loading a compiled package: import its modules parents first, then give every module the
names of the classes it may use (a generated module refers to other classes by their plain
names, `ARRAY`, `STRING_8`; importing them module by module would make import cycles)."""
from __future__ import annotations

import importlib

_LOADED: dict = {}


def load(package: str, modules: list[str], uses: tuple[str, ...] = ()) -> dict:
    """Import `package`'s modules in order; inject into each the classes of `uses` (packages
    loaded before, e.g. the standard library) and of this package (which take precedence)."""
    if package in _LOADED:
        return _LOADED[package]
    names: dict = {}
    for other in uses:
        names.update(importlib.import_module(other).CLASSES_BY_NAME)
    loaded = [importlib.import_module(f"{package}.{m}") for m in modules]
    own = {}
    for module in loaded:
        for key, value in vars(module).items():
            if isinstance(value, type) and getattr(value, "__module__", None) == module.__name__:
                own[key] = value
    names.update(own)
    for module in loaded:
        for key, value in names.items():
            module.__dict__.setdefault(key, value)
    _LOADED[package] = own
    return own


def forget(package: str) -> None:
    """A package is to be loaded afresh (another program of the same package name)."""
    _LOADED.pop(package, None)


def register_again(package: str) -> None:
    """Register a loaded package's classes again (a caller may have reset the registry: tests)."""
    from . import register

    for cls in _LOADED.get(package, {}).values():
        key = getattr(cls, "_key_", None)
        if key is not None:
            register(key, cls)
