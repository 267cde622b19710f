"""Compiling and running golden programs in this process (shared by test_golden.py and
test_samples.py).

A program is checked and compiled with the compiler's driver (scoopc.driver.Compilation) into a package of its
own (named like its root class, as `scoopc compile` names it), then run by the kernel's launcher
with the output captured. Expected outputs are compared exactly, per processor (each
processor's lines in order, from `--trace-processors` prefixes) or as sorted lines.

case.toml (optional, a small subset of TOML: `key = value`, one per line, values are strings,
integers, booleans or lists of strings):
  compare = "exact" | "per_processor" | "sorted"    (default "exact")
  args = ["a", "b"]                                  the program's arguments (`-- a b`)
  stdin = "text"                                     its standard input
  exit = 3                                           its expected exit status (default 0)
  virtual_clock = true, strict = true, assertions = "require"
  stderr_lines = 2                                   lines of expected.err compared (default: all)
"""

from __future__ import annotations

import ast
import builtins
import importlib
import io
import re
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TRACE = re.compile(r"^\[P(\d+)\] ?(.*)$")


@dataclass
class Config:
    compare: str = "exact"
    args: list = field(default_factory=list)
    stdin: str | None = None
    exit: int = 0
    virtual_clock: bool = False
    strict: bool = False
    assertions: str = "all"

    @property
    def trace(self) -> bool:
        return self.compare == "per_processor"


def read_config(folder: Path) -> Config:
    path = folder / "case.toml"
    config = Config()
    if not path.exists():
        return config
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        key, sep, value = line.partition("=")
        if not sep or not hasattr(config, key.strip()):
            raise ValueError(f"{path}:{number}: expected `key = value` with a known key")
        text = value.strip().replace("true", "True").replace("false", "False")
        setattr(config, key.strip(), ast.literal_eval(text))
    if config.compare not in ("exact", "per_processor", "sorted"):
        raise ValueError(f"{path}: compare must be exact, per_processor or sorted")
    return config


_COMPILED: dict = {}
_LOCK = threading.Lock()


def relative_text(text: str) -> str:
    """Generated text with absolute paths of this checkout made relative to the repository."""
    return text.replace(str(REPO) + "/", "")


def compile_program(folder: Path, out_dir: Path, assertions: str = "all"):
    """Check and compile the program in `folder` (root: the class named like the folder).
    Returns (compiled, {module file name: text}); raises AssertionError on source errors."""
    from scoopc.driver import Compilation

    ecf = sorted(folder.glob("*.ecf"))  # a sample with an .ecf (C sources of its own, say) is compiled from it
    compilation = Compilation([(ecf[0] if ecf else folder).resolve()], assertions=assertions)
    checked = compilation.checked
    if checked.has_errors:
        errors = "\n".join(f"{d.span}: {d.code}: {d.message}" for d in checked.diagnostics if d.is_error)
        raise AssertionError(f"{folder.name} does not compile:\n{errors}")
    package = compilation.root.key.lower()
    compiled = compilation.write_package(out_dir, package)
    texts = {
        p.name: relative_text(p.read_text())
        for p in sorted((out_dir / package).glob("*.py"))
        if not p.name.startswith("__")
    }
    return compiled, texts


@dataclass
class Outcome:
    status: int
    out: str
    err: str


_REGISTRY: dict = {}  # the class registry as the compiled programs left it


def run_program(compiled, config: Config) -> Outcome:
    """Run a compiled program in this process (its package imported fresh). The kernel's class
    registry is swapped in and out around the run, so other tests see it as they left it."""
    from scoopc import kernel

    saved = dict(kernel.CLASSES)
    kernel.CLASSES.clear()
    kernel.CLASSES.update(_REGISTRY or _library_classes())
    try:
        return _run_program(compiled, config)
    finally:
        _REGISTRY.clear()
        _REGISTRY.update(kernel.CLASSES)
        kernel.CLASSES.clear()
        kernel.CLASSES.update(saved)


def _library_classes() -> dict:
    """The compiled standard library's classes, when an earlier test imported it already (its
    modules registered them then, and will not again)."""
    found = {}
    for name, module in list(sys.modules.items()):
        if name.startswith("eiffel_base.") and module is not None:
            for value in vars(module).values():
                if isinstance(value, type) and value.__module__ == name and hasattr(value, "_key_"):
                    found[value._key_] = value
    return found


def _run_program(compiled, config: Config) -> Outcome:
    from scoopc.codegen.names import class_name, module_name
    from scoopc.driver.packages import ensure_on_path
    from scoopc.kernel import launcher

    ensure_on_path(compiled.library, compiled.folder)
    package = compiled.package
    for name in [m for m in sys.modules if m == package or m.startswith(package + ".")]:
        del sys.modules[name]
    from scoopc.kernel import link

    link._LOADED.pop(package, None)
    importlib.invalidate_caches()
    module = importlib.import_module(f"{package}.{module_name(compiled.root.key)}")
    root_cls = getattr(module, class_name(compiled.root.key))
    out, err = io.StringIO(), io.StringIO()
    saved_stdin = sys.stdin
    sys.stdin = io.StringIO(config.stdin or "")
    try:
        status = launcher.main(
            root_cls,
            compiled.root.creator,
            [compiled.root.key.lower()] + list(config.args),
            trace_processors=config.trace,
            strict=config.strict,
            virtual_clock=config.virtual_clock,
            stdout=out,
            stderr=err,
        )
    finally:
        sys.stdin = saved_stdin
        sys.path.remove(str(compiled.folder))
    return Outcome(status, out.getvalue(), relative_text(err.getvalue()))


# What the user sees must never name a Python exception: every built-in exception class (from
# `builtins`, as whole words) and the header of a Python traceback.
HOST_EXCEPTION_NAMES = sorted(
    name for name, value in vars(builtins).items() if isinstance(value, type) and issubclass(value, BaseException)
)
HOST_EXCEPTION = re.compile(r"\b(?:" + "|".join(HOST_EXCEPTION_NAMES) + r")\b|Traceback \(most recent call last\)")


def host_exceptions(text: str) -> list:
    """The lines of `text` that show a Python exception to the user."""
    return [line for line in text.splitlines() if HOST_EXCEPTION.search(line)]


def assert_no_host_exception(out: str, err: str, where: str) -> None:
    shown = host_exceptions(out) + host_exceptions(err)
    assert not shown, f"{where}: a Python exception reaches the user:\n" + "\n".join(shown)


def per_processor(text: str) -> dict:
    """{processor id: its lines in order}; untagged lines under None."""
    found: dict = {}
    for line in text.splitlines():
        match = TRACE.match(line)
        key, rest = (int(match.group(1)), match.group(2)) if match else (None, line)
        found.setdefault(key, []).append(rest)
    return found


def assert_output(config: Config, expected: str, actual: str, where: str) -> None:
    if config.compare == "exact":
        assert actual == expected, f"{where}: output differs"
    elif config.compare == "sorted":
        assert sorted(actual.splitlines()) == sorted(expected.splitlines()), f"{where}: output lines differ"
    else:
        assert per_processor(actual) == per_processor(expected), f"{where}: output differs per processor"
