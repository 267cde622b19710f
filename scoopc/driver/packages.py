"""Driver, packages on disk: the modules codegen made -> a Python package, with the map from
Python lines back to Eiffel lines, bytecode, and the content keys of cached compilations.

A package's `__init__` loads its modules parents first (scoopc.kernel.link); `_lines.json` maps
every generated module's lines back to its Eiffel file and lines ({module: [eiffel file,
{python line: eiffel line}]}), which the launcher reads to print Eiffel traces.
"""

from __future__ import annotations

import ast
import compileall
import functools
import hashlib
import json
import shutil
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .. import version
from ..exits import UsageError
from ..semantics.library import cache_dir
from ..semantics.universe import stdlib_files
from ..version import __version__

BASE_PACKAGE = "eiffel_base"
MANIFEST = "_manifest.json"  # {module file: size}: a cached package is whole when these match
BYTECODE_DONE = "__pycache__/scoopc-complete"  # written last by a package's byte-compilation


class DamagedCache(Exception):
    """A cached package failed to load (a module missing, truncated or garbled, bad bytecode):
    it is compiled again."""

    def __init__(self, folder: Path, error: BaseException):
        super().__init__(f"{folder}: {type(error).__name__}: {error}")
        self.folder = folder


def writable_cache() -> Path:
    """scoopc's cache folder, made if needed; a UsageError when it cannot be written."""
    folder = cache_dir()
    try:
        if folder.exists() and not folder.is_dir():
            raise NotADirectoryError(0, "it is a file, not a folder")
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as problem:
        raise UsageError(
            f"cannot write scoopc's cache folder {folder} ({problem.strerror or problem}): set "
            f"SCOOPC_CACHE_DIR to a folder you can write"
        ) from None
    return folder


def write_manifest(package: Path) -> None:
    """Record the size of every module of a cached package, written last."""
    sizes = {p.name: p.stat().st_size for p in sorted(package.glob("*.py"))}
    (package / MANIFEST).write_text(json.dumps(sizes, separators=(",", ":")))


def is_whole(package: Path) -> bool:
    """Does a cached package still have every module, at the size it was written? (A stat per
    module: cheap enough for every run.)"""
    try:
        sizes = json.loads((package / MANIFEST).read_text())
        return all((package / name).stat().st_size == size for name, size in sizes.items())
    except (OSError, ValueError, AttributeError, TypeError):
        return False


def remove_cached(folder: Path) -> None:
    """Remove a folder of scoopc's cache (never anything outside it)."""
    root = cache_dir().resolve()
    if folder.resolve() != root and root in folder.resolve().parents:
        shutil.rmtree(folder, ignore_errors=True)


@functools.cache
def compiler_digest() -> str:
    """A key of everything a compiled package depends on: scoopc's version, the grammar, the
    parser and syntax tree, the checker, the code generator, the kernel, how packages are written
    and the standard library's sources (a few milliseconds, once per process: the code this
    process runs is the code it read at start-up)."""
    digest = hashlib.sha256(__version__.encode())
    root = Path(__file__).parents[1]
    digest.update((root / "grammar.lark").read_bytes())
    for folder in ("parse", "parse/builders", "syntax", "semantics", "codegen", "kernel", "kernel/ext"):
        for path in sorted((root / folder).glob("*.py")):
            digest.update(path.name.encode())
            digest.update(path.read_bytes())
    for path in (root / "driver" / "library.py", Path(__file__)):
        digest.update(path.read_bytes())
    for path in stdlib_files():
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:24]


def program_key(sources: list[Path], extra: str) -> str:
    """The cache key of a program: the compiler, the options in `extra`, each source's path and text."""
    digest = hashlib.sha256(compiler_digest().encode() + extra.encode())
    for path in sorted(sources):
        digest.update(str(path).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:24]


def write_modules(
    folder: Path,
    modules: dict[str, tuple[ast.Module, str]],
    init_doc: str,
    uses: tuple[str, ...] = (),
    no_scoopc: str | None = None,
) -> None:
    """Write the modules of one package (readable Python text) and its __init__, which loads
    them parents first (scoopc.kernel.link). With `no_scoopc`, a Python that cannot import scoopc
    gets that message (`{}`: the import error) on stderr and exit code 2 instead of a traceback."""
    folder.mkdir(parents=True, exist_ok=True)
    order = [name[:-3] for name in modules]
    load = "from scoopc.kernel import link\n"
    if no_scoopc is not None:
        load = (
            "try:\n"
            "    from scoopc.kernel import link\n"
            "except ImportError as missing:  # scoopc is the program's runtime: say so, without a traceback\n"
            "    import sys\n\n"
            f"    sys.stderr.write({no_scoopc!r}.format(missing))\n"
            "    raise SystemExit(2) from None\n"
        )
    (folder / "__init__.py").write_text(
        f'"""{init_doc}"""\n{load}\nCLASSES_BY_NAME = link.load(__name__, {order!r}, uses={uses!r})\n'
    )
    lines: dict[str, list[object]] = {}
    for filename, (module, source) in modules.items():
        text = ast.unparse(module) + "\n"
        found = line_map(module, text)
        (folder / filename).write_text(with_positions(text, found, source))
        lines[filename[:-3]] = [source, found]
    (folder / "_lines.json").write_text(json.dumps(lines, separators=(",", ":")))


def line_map(module: ast.Module, text: str) -> dict[str, int]:
    """Python line -> Eiffel line: the written text parses back to the same tree shape."""
    found: dict[str, int] = {}
    for original, written in zip(_statements(module), _statements(ast.parse(text))):
        line = getattr(original, "lineno", None)
        if line is not None:
            found.setdefault(str(written.lineno), line)
    return found


def with_positions(text: str, found: dict[str, int], source: str) -> str:
    """`text` with `# file.e:line` after the first line of each routine and of each statement
    that starts another Eiffel line (the lines stay where they are: `found` still holds)."""
    written = ast.parse(text)
    starts, inside = set(), set()
    for node in _statements(written):
        if isinstance(node, ast.FunctionDef):
            starts.add(node.lineno)
            inside |= {s.lineno for s in _statements(node) if not _is_docstring(s)}
    out = text.split("\n")
    name, previous = Path(source).name, None
    for key, line in sorted(found.items(), key=lambda item: int(item[0])):
        number = int(key)
        if number not in starts and (number not in inside or line == previous):
            continue
        out[number - 1] += f"  # {name}:{line}"
        previous = line
    return "\n".join(out)


def _is_docstring(node: ast.stmt) -> bool:
    return isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)


def _statements(node: ast.AST) -> Iterator[ast.stmt]:
    """Every statement below `node`, in order, without visiting expressions."""
    for field in ("body", "handlers", "orelse", "finalbody"):
        for child in getattr(node, field, None) or ():
            if isinstance(child, (ast.stmt, ast.excepthandler)):
                if isinstance(child, ast.stmt):
                    yield child
                yield from _statements(child)


def write_bytecode(folder: Path) -> None:
    """Byte-compile a cached package once, so that every run imports it from its .pyc files: about
    0.3 s per run for the standard library's 320 modules, which Python would otherwise compile
    again on every run where it does not write bytecode itself (PYTHONDONTWRITEBYTECODE, a
    read-only install). Imports from the .pyc name the package's final folder in tracebacks
    (importlib fixes `co_filename`), so a staging folder's name does not leak. Each .pyc is
    written atomically: processes doing it at once do no harm."""
    compileall.compile_dir(str(folder), quiet=2)


def ensure_bytecode(base: Path) -> None:
    """The compiled library's bytecode, written when it is compiled into the cache; an interrupted
    byte-compilation is done again here. A wheel's library is left to its installer."""
    package = base / BASE_PACKAGE
    done = package / BYTECODE_DONE
    if base.parent != version.PREBUILT and not done.exists():
        write_bytecode(package)
        done.touch()


def ensure_on_path(*folders: Path | None) -> None:
    """Put each folder first on sys.path (once), so that its packages import."""
    for folder in folders:
        if folder is not None:
            if str(folder) in sys.path:
                sys.path.remove(str(folder))
            sys.path.insert(0, str(folder))
