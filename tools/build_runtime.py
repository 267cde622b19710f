"""The wheel's build step that compiles the runtime's hot modules to C with mypyc (setup.py).

Which: the modules every separate call, reservation and wait goes through (RUNTIME_MODULES).
They stay plain Python source as well: the package imports the compiled module where one was
built and the source elsewhere, with the same behaviour (docs/RUNTIME.md section 10).

When: only when build_ext runs for a wheel. Until then the distribution lists one placeholder
extension (which makes the wheel platform-specific), so the metadata steps of an install do not
pay mypyc's minute. Not for editable installs (their sources change; a compiled module would
hide an edit), not with SCOOPC_PURE_RUNTIME=1, and not where mypyc or a C compiler is missing
or fails: then the build says so in one line and installs the pure-Python runtime, which is
complete.
"""

from __future__ import annotations

import os
import sys
import tempfile

from setuptools import Extension
from setuptools.command.build_ext import build_ext

RUNTIME_MODULES = ("session", "direct", "fast", "processor", "reservation", "sched", "permits")
GROUP = "scoopc_runtime"  # the name of the compiled modules' shared library (mypyc's group)
PLACEHOLDER = "scoopc.runtime._compiled"  # stands for the compiled modules until build_ext runs
# The type check mypyc compiles from. It checks the compiled modules and what they import from the
# runtime; the rest of scoopc (reached through scoopc.exits) is followed silently, and what the
# build environment lacks (pip's isolated one has only the build requirements: no foxglove, no
# mcap) is not an error. The strict check of the whole runtime is tests/test_habits.py's.
MYPYC_CONFIG = """\
[mypy]
ignore_missing_imports = True
warn_unused_ignores = False

[mypy-scoopc.*]
follow_imports = silent

[mypy-scoopc.runtime.*]
follow_imports = normal
"""


def _say(text: str) -> None:
    print(f"scoopc build: {text}", file=sys.stderr, flush=True)


def ext_modules() -> list[Extension]:
    """What setup.py declares: the placeholder, or nothing when a pure build is asked for."""
    if os.environ.get("SCOOPC_PURE_RUNTIME", "") not in ("", "0"):
        _say("SCOOPC_PURE_RUNTIME is set: the runtime stays pure Python")
        return []
    return [Extension(PLACEHOLDER, sources=[])]


def compiled_extensions(root: str = ".") -> list[Extension]:
    """The runtime's modules as mypyc extensions, or none (then the pure-Python runtime)."""
    try:
        from mypyc.build import mypycify
    except ImportError:
        _say("mypyc (from mypy) is not installed: the runtime stays pure Python")
        return []
    paths = [os.path.join(root, "scoopc", "runtime", f"{name}.py") for name in RUNTIME_MODULES]
    with tempfile.TemporaryDirectory(prefix="scoopc-mypyc-") as tmp:
        config = os.path.join(tmp, "mypy.ini")
        with open(config, "w", encoding="utf-8") as f:
            f.write(MYPYC_CONFIG)
        try:
            return list(mypycify([*paths, "--config-file", config], opt_level="3", group_name=GROUP, verbose=False))
        except (Exception, SystemExit) as e:  # mypyc stops the process on a type error
            _say(f"mypyc could not compile the runtime ({type(e).__name__}: {e}): the runtime stays pure Python")
            return []


class BuildExt(build_ext):
    """build_ext that puts the compiled runtime in place of the placeholder, and falls back to the
    pure-Python runtime when the C compiler fails."""

    def _prepared(self, ext: Extension) -> Extension:
        """`ext` as setuptools' finalize_options prepares a declared extension (mypyc's are made
        after it ran: making them costs a minute, and the metadata steps of an install finalize
        build_ext too). Should a setuptools need more, the build falls back to pure Python, and
        CI, which requires the compiled runtime, fails."""
        name = ext._full_name = self.get_ext_fullname(ext.name)  # type: ignore[attr-defined]
        self.ext_map[name] = self.ext_map[name.split(".")[-1]] = ext
        ext._links_to_dynamic = ext._needs_stub = False  # type: ignore[attr-defined]
        ext._file_name = self.get_ext_filename(name)  # type: ignore[attr-defined]
        return ext

    def run(self) -> None:
        if any(ext.name == PLACEHOLDER for ext in self.extensions):
            others = [ext for ext in self.extensions if ext.name != PLACEHOLDER]
            if self.editable_mode:
                _say("an editable install: the runtime stays pure Python (its sources change)")
                self.extensions = others
            else:
                self.extensions = others + [self._prepared(ext) for ext in compiled_extensions()]
            if len(self.extensions) == len(others):  # pure Python: no module of an earlier build
                self._remove_compiled_runtime()
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
            self._remove_compiled_runtime()

    def _remove_compiled_runtime(self) -> None:
        """Remove the compiled runtime an earlier build left in the build folder: a pure-Python
        build must not ship it (stale, or without its group's shared library)."""
        names = [f"scoopc.runtime.{name}" for name in RUNTIME_MODULES] + [f"{GROUP}__mypyc"]
        for name in names:
            built = self.get_ext_fullpath(name)
            if os.path.exists(built):
                os.remove(built)
