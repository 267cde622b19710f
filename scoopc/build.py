"""The compile stage of the pipeline: checked program -> Python packages on disk.

The standard library is compiled once into the package `eiffel_base`, cached by the contents of
stdlib/ and of the compiler (`$SCOOPC_CACHE_DIR/base-<key>/`); a program's own classes go to a
package of their own, which imports eiffel_base. `scoopc run` caches programs by content too.
"""
from __future__ import annotations

import ast
import hashlib
import json
import os
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from . import __version__, outdir
from .codegen.context import Options
from .kernel.link import LIBRARY_LEAVES_FILE
from .semantics.library import cache_dir
from .semantics.universe import stdlib_files

BASE_PACKAGE = "eiffel_base"


def _compiler_digest() -> str:
    digest = hashlib.sha256(__version__.encode())
    root = Path(__file__).parent
    for folder in ("codegen", "kernel", "kernel/ext", "semantics"):
        for path in sorted((root / folder).glob("*.py")):
            digest.update(path.name.encode())
            digest.update(path.read_bytes())
    for path in stdlib_files():
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:24]


@dataclass
class Compiled:
    package: str
    path: Path                    # the folder holding the program's package
    base_path: Path               # the folder holding eiffel_base
    root_key: str
    creator: str


def write_modules(folder: Path, modules: dict, init_doc: str, uses: tuple[str, ...] = ()) -> None:
    """Write the modules of one package (readable Python text) and its __init__, which loads
    them parents first (scoopc.kernel.link)."""
    folder.mkdir(parents=True, exist_ok=True)
    order = [name[:-3] for name in modules]
    (folder / "__init__.py").write_text(
        f'"""{init_doc}"""\nfrom scoopc.kernel import link\n\n'
        f"CLASSES_BY_NAME = link.load(__name__, {order!r}, uses={uses!r})\n")
    lines = {}
    for filename, (module, source) in modules.items():
        text = ast.unparse(module) + "\n"
        (folder / filename).write_text(text)
        lines[filename[:-3]] = [source, line_map(module, text)]
    (folder / "_lines.json").write_text(json.dumps(lines, separators=(",", ":")))


def line_map(module: ast.Module, text: str) -> dict:
    """Python line -> Eiffel line: the written text parses back to the same tree shape."""
    found = {}
    for original, written in zip(_statements(module), _statements(ast.parse(text))):
        line = getattr(original, "lineno", None)
        if line is not None:
            found.setdefault(str(written.lineno), line)
    return found


def _statements(node):
    """Every statement below `node`, in order, without visiting expressions."""
    for field in ("body", "handlers", "orelse", "finalbody"):
        for child in getattr(node, field, None) or ():
            if isinstance(child, (ast.stmt, ast.excepthandler)):
                if isinstance(child, ast.stmt):
                    yield child
                yield from _statements(child)


def base_package(progress=None) -> Path:
    """The folder that holds the compiled standard library (built on first use)."""
    target = cache_dir() / f"base-{_compiler_digest()}"
    if (target / BASE_PACKAGE / "__init__.py").exists():
        return target
    from .codegen.program import generate
    from .pipeline import check_project
    from .project import Project

    if progress:
        progress("compiling the standard library (once)")
    checked = check_project(Project(), use_cache=False, library_bodies=True)
    if checked.has_errors:
        raise RuntimeError("the standard library does not check: " + str(checked.diagnostics[0]))
    sem = checked.semantics
    options = Options(package=BASE_PACKAGE)
    modules = generate(sem.universe, sem.tables, options, lambda info: info.from_library)
    staging = Path(tempfile.mkdtemp(prefix="base-", dir=_ensure(cache_dir())))
    write_modules(staging / BASE_PACKAGE, modules, "The standard library, compiled by scoopc.")
    from .codegen.scoop import write_library_facts       # what programs' leaf analysis needs

    write_library_facts(staging / BASE_PACKAGE, sem.universe, sem.tables, options)
    try:
        staging.rename(target)
    except OSError:                            # another process won the race: use its copy
        shutil.rmtree(staging, ignore_errors=True)
    return target


def write_bytecode(folder: Path) -> None:
    """Byte-compile a cached package once, so that every run imports it from its .pyc files: about
    0.3 s per run for the standard library's 320 modules, which Python would otherwise compile
    again on every run where it does not write bytecode itself (PYTHONDONTWRITEBYTECODE, a
    read-only install). Imports from the .pyc name the package's final folder in tracebacks
    (importlib fixes `co_filename`), so a staging folder's name does not leak. Each .pyc is
    written atomically: processes doing it at once do no harm."""
    import compileall

    compileall.compile_dir(str(folder), quiet=2)


def ensure_bytecode(base: Path) -> None:
    """The compiled library's bytecode, written by the first run that needs it (`scoopc compile`
    never does: it copies the sources only)."""
    package = base / BASE_PACKAGE
    done = package / "__pycache__" / "scoopc-complete"     # written last: an interrupted run redoes it
    if not done.exists():
        write_bytecode(package)
        done.touch()


def _ensure(path: Path) -> Path:
    path.mkdir(parents=True, exist_ok=True)
    return path


def compile_program(checked, out_dir: Path, package: str, root_key: str, creator: str,
                    assertions: str = "all", progress=None) -> Compiled:
    from .codegen.program import generate

    sem = checked.semantics
    options = Options(assertions=assertions, package=package)
    leaves: list[str] = []
    modules = generate(sem.universe, sem.tables, options, lambda info: not info.from_library, leaves)
    folder = out_dir / package          # the caller made room for it (outdir.clear, or a fresh staging folder)
    write_modules(folder, modules, f"A program compiled by scoopc (root class {root_key}).", (BASE_PACKAGE,))
    (folder / LIBRARY_LEAVES_FILE).write_text(json.dumps(leaves, separators=(",", ":")))
    (folder / "__main__.py").write_text(_main_text(package, root_key, creator, sem.universe))
    outdir.mark(folder)
    return Compiled(package, out_dir, base_package(progress), root_key, creator)


def _main_text(package: str, root_key: str, creator: str, universe) -> str:
    from .codegen.names import class_name, module_name

    shadowed = {k: v for k, v in universe.shadowed.items()}
    return (f'"""Run the program: python -m {package} [ARGS]."""\n'
            f"import sys\n\n"
            f"from scoopc.kernel import launcher\n\n"
            f"if __name__ == '__main__':\n"
            f"    from {package}.{module_name(root_key)} import {class_name(root_key)}\n"
            f"    sys.exit(launcher.main({class_name(root_key)}, {creator!r}, sys.argv, shadowed={shadowed!r}))\n")


def ensure_on_path(*folders: Optional[Path]) -> None:
    for folder in folders:
        if folder is not None:
            if str(folder) in sys.path:
                sys.path.remove(str(folder))
            sys.path.insert(0, str(folder))


def program_key(sources: list[Path], extra: str) -> str:
    digest = hashlib.sha256(_compiler_digest().encode() + extra.encode())
    for path in sorted(sources):
        digest.update(str(path).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:24]


__all__ = ["base_package", "compile_program", "ensure_on_path", "os"]
