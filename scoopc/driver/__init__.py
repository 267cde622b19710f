"""The driver: the pipeline's phases owned by one Compilation (compilation.py), the compiled
standard library (library.py), packages on disk (packages.py), the root (roots.py), the run
(running.py) and the tests (testing.py, junit.py). The command line (scoopc.cli) and the Python
API (scoopc.api) are thin layers over it; nothing below it imports it."""

from ..exits import SourceErrors
from .compilation import Compilation, CompiledProgram
from .library import Library, LibraryError, compiled_library
from .packages import BASE_PACKAGE
from .roots import Root, choose_root
from .running import RunOptions, run_compilation, run_program
from .testing import TestOptions, find_tests, run_tests

__all__ = [
    "BASE_PACKAGE",
    "Compilation",
    "CompiledProgram",
    "Library",
    "LibraryError",
    "Root",
    "RunOptions",
    "SourceErrors",
    "TestOptions",
    "choose_root",
    "compiled_library",
    "find_tests",
    "run_compilation",
    "run_program",
    "run_tests",
]
