"""The driver: the pipeline's phases owned by one Compilation (compilation.py), the compiled
standard library (library.py), packages on disk (packages.py), the root (roots.py) and the run
(running.py). The command line (scoopc.cli) and the Python API (scoopc.api) are thin layers over
it; nothing below it imports it."""

from ..exits import SourceErrors
from .compilation import Compilation, CompiledProgram
from .library import Library, LibraryError, compiled_library
from .packages import BASE_PACKAGE
from .roots import Root, choose_root
from .running import RunOptions, run_compilation, run_program

__all__ = [
    "BASE_PACKAGE",
    "Compilation",
    "CompiledProgram",
    "Library",
    "LibraryError",
    "Root",
    "RunOptions",
    "SourceErrors",
    "choose_root",
    "compiled_library",
    "run_compilation",
    "run_program",
]
