"""Exit codes of scoopc and of compiled programs (DESIGN section 8), and the usage error: the one
place both are defined. Every layer may import this module; it imports nothing of scoopc."""

from __future__ import annotations

import enum


class Exit(enum.IntEnum):
    OK = 0  # success
    SOURCE = 1  # errors in the source (diagnostics on stderr)
    USAGE = 2  # bad usage: a missing path, a wrong option, a folder scoopc will not touch
    RUNTIME = 3  # a run-time failure: uncaught exception, contract violation, deadlock
    INTERNAL = 4  # a bug in scoopc (reported with its Python traceback)
    INTERRUPTED = 130  # Ctrl-C; other signals that stop a run give 128 + their number


class UsageError(Exception):
    """A mistake in how scoopc was called (exit code 2): a path that does not exist, a wrong
    extension, an output folder scoopc did not write, a world file that is not valid."""


class SourceErrors(Exception):
    """The program has errors in its source (exit code 1): nothing was compiled; `diagnostics`
    says why (the command line has printed them already)."""

    def __init__(self, diagnostics: list):
        super().__init__(f"{sum(1 for d in diagnostics if d.is_error)} errors in the source")
        self.diagnostics = diagnostics
