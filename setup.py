"""setuptools reads the project from pyproject.toml; this adds what pyproject.toml cannot say:
the runtime's modules compiled with mypyc, when they can be (tools/build_runtime.py)."""

import os
import sys

from setuptools import setup

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from tools.build_runtime import ext_modules  # noqa: E402  (after the path is set)

# pyproject.toml names the build_ext that turns the placeholder into the compiled modules
setup(ext_modules=ext_modules())
