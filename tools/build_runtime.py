"""The wheel's build step that compiles the runtime's hot modules to C with mypyc (setup.py).

Which: the modules every separate call, reservation and wait goes through (RUNTIME_MODULES).
They stay plain Python source as well: the package imports the compiled module where one was
built and the source elsewhere, with the same behaviour (docs/RUNTIME.md section 10).

When not: editable installs (their sources change; a compiled module would hide an edit), a
build with SCOOPC_PURE_RUNTIME=1, and wherever mypyc or a C compiler is missing or fails: then
the build says so in one line and installs the pure-Python runtime, which is complete.
"""

from __future__ import annotations

import os
import sys

from setuptools import Extension
from setuptools.command.build_ext import build_ext

RUNTIME_MODULES = ("session", "fast", "processor", "reservation", "sched", "permits")
GROUP = "scoopc_runtime"  # the name of the compiled modules' shared library (mypyc's group)


def _say(text: str) -> None:
    print(f"scoopc build: {text}", file=sys.stderr, flush=True)


def wanted() -> bool:
    """Is a compiled runtime to be built by this setup run?"""
    if os.environ.get("SCOOPC_PURE_RUNTIME", "") not in ("", "0"):
        _say("SCOOPC_PURE_RUNTIME is set: the runtime stays pure Python")
        return False
    return "editable_wheel" not in sys.argv and "develop" not in sys.argv


def ext_modules() -> list[Extension]:
    """The compiled runtime's extension modules, or none (then the pure-Python runtime)."""
    if not wanted():
        return []
    try:
        from mypyc.build import mypycify
    except ImportError:
        _say("mypyc (from mypy) is not installed: the runtime stays pure Python")
        return []
    paths = [f"scoopc/runtime/{name}.py" for name in RUNTIME_MODULES]
    try:
        return list(mypycify(paths, opt_level="3", group_name=GROUP, verbose=False))
    except (Exception, SystemExit) as e:  # mypyc stops the process on a type error
        _say(f"mypyc could not compile the runtime ({type(e).__name__}: {e}): the runtime stays pure Python")
        return []


class BuildExt(build_ext):
    """build_ext that falls back to the pure-Python runtime when the C compiler fails."""

    def run(self) -> None:
        try:
            super().run()
        except Exception as e:  # no compiler, missing headers, ...
            _say(f"compiling the runtime to C failed ({type(e).__name__}: {e}): the runtime stays pure Python")
            # all or nothing: a module built without its group's shared library would not import
            for ext in self.extensions:
                built = self.get_ext_fullpath(ext.name)
                if os.path.exists(built):
                    os.remove(built)
            self.extensions = []
