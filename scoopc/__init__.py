"""scoopc: a compiler from Eiffel with SCOOP concurrency to Python, and its runtime.

The Python API (docs/API.md): `scoopc.check(paths)`, `scoopc.compile(paths, output)`,
`scoopc.run(paths, args)` and `scoopc.test(paths)`, with `scoopc.UsageError` for mistakes in how they are called.
"""

from .version import __version__

__all__ = ["__version__", "check", "compile", "run", "test", "UsageError"]
_API = (
    "check",
    "compile",
    "run",
    "test",
    "UsageError",
    "CheckResult",
    "CompileResult",
    "RunResult",
    "TestResult",
    "TestOutcome",
)


def __getattr__(name: str):
    if name in _API:
        from . import api  # deferred: `import scoopc` (the command line's start-up) stays light

        return getattr(api, name)
    raise AttributeError(f"module 'scoopc' has no attribute {name!r}")
