"""The wheel's build step that compiles the standard library into the package (pyproject.toml,
[tool.setuptools.cmdclass]): setuptools' build_py, then scoopc itself, run from the copy of the
package about to be shipped, writes scoopc/prebuilt/ (driver/library.py, build_prebuilt): the
parser's tables, the library's checked declarations and the compiled library, named by the keys
the installed scoopc checks at start-up. A failure fails the build: a wheel never ships without
its library or with a broken one.

Editable installs skip it: their sources change, so they compile the library on first use.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from setuptools.command.build_py import build_py
from setuptools.errors import SetupError

STEP = (
    "import sys; from pathlib import Path; from scoopc.driver.library import build_prebuilt; "
    "print('scoopc: compiled the standard library into', build_prebuilt(Path(sys.argv[1]), print), flush=True)"
)


class BuildPy(build_py):
    def run(self) -> None:
        # a build folder left by an earlier build may hold files since removed from the sources
        # (a stdlib class moved elsewhere would then be compiled twice): start from nothing
        if not getattr(self, "editable_mode", False):
            shutil.rmtree(Path(self.build_lib) / "scoopc", ignore_errors=True)
        super().run()
        if not getattr(self, "editable_mode", False):
            build_prebuilt(Path(self.build_lib).resolve())


def build_prebuilt(build_lib: Path) -> None:
    """Compile the library with the package in `build_lib` (what the wheel ships, so the digests
    match the installed files), in a process of its own with an empty cache of its own."""
    target = build_lib / "scoopc" / "prebuilt"
    shutil.rmtree(target, ignore_errors=True)
    with tempfile.TemporaryDirectory(prefix="scoopc-build-") as cache:
        # build_lib first; what PYTHONPATH held stays after it: pip's isolated build environment
        # reaches its build requirements (lark) through it
        path = os.pathsep.join(p for p in (str(build_lib), os.environ.get("PYTHONPATH", "")) if p)
        env = dict(os.environ, SCOOPC_CACHE_DIR=cache, PYTHONPATH=path, PYTHONDONTWRITEBYTECODE="1")
        done = subprocess.run([sys.executable, "-c", STEP, str(target)], cwd=build_lib, env=env)
    if done.returncode != 0:
        shutil.rmtree(target, ignore_errors=True)
        raise SetupError(f"compiling scoopc's standard library failed (exit code {done.returncode}); see above")
