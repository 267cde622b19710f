"""Driver, the program's own externals on disk: the user's Python modules copied into the
program's package (`_python/`), and the C and C++ externals built with cffi into one extension
module per language, cached by content like the rest (docs/LANGUAGE.md, Externals).

Each C external becomes a C wrapper function `scoopc_<class>_<feature>` (its body the call of
the C function, or the inline code with `$name` replaced by the argument), preceded by a `#line`
that points the compiler's messages at the Eiffel class. The build runs cffi in a child Python
so that the compiler's output is captured and turned into an EXTERNAL-BUILD diagnostic naming
the missing compiler, header or library.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path
from typing import Any, NoReturn

from .. import diagnostics
from ..exits import SourceErrors
from ..kernel.externals import PYTHON_FOLDER
from ..project import ExternalSettings, Project
from ..semantics.externals import CExternal, ProgramExternals, c_type
from ..semantics.library import cache_dir
from ..version import __version__

# C types of Eiffel's run time that signatures may name (EiffelStudio's eif_portable.h).
_PRELUDE = """#include <stdint.h>
#include <stddef.h>
typedef int8_t EIF_INTEGER_8; typedef int16_t EIF_INTEGER_16; typedef int32_t EIF_INTEGER_32;
typedef int64_t EIF_INTEGER_64; typedef int32_t EIF_INTEGER;
typedef uint8_t EIF_NATURAL_8; typedef uint16_t EIF_NATURAL_16; typedef uint32_t EIF_NATURAL_32;
typedef uint64_t EIF_NATURAL_64; typedef uint32_t EIF_NATURAL;
typedef float EIF_REAL_32; typedef double EIF_REAL_64; typedef float EIF_REAL; typedef double EIF_DOUBLE;
typedef unsigned char EIF_BOOLEAN; typedef char EIF_CHARACTER_8; typedef char EIF_CHARACTER;
typedef uint32_t EIF_CHARACTER_32; typedef uint32_t EIF_WIDE_CHAR; typedef void *EIF_POINTER;
"""
_C_WORDS = {"DOUBLE", "FLOAT", "INT", "LONG", "SHORT", "CHAR", "VOID", "UNSIGNED", "SIGNED", "CONST", "SIZE_T"}
_SOURCES = (".c", ".cc", ".cpp", ".cxx")
MODULE_PREFIX = {"c": "_c_", "c++": "_cpp_"}


# --- Python modules ---------------------------------------------------------------------------------
def python_files(dirs: list[Path]) -> list[tuple[str, Path]]:
    """(name, path) of every module file and package folder in `dirs`, the first of a name winning."""
    found: dict[str, Path] = {}
    for folder in dirs:
        if not folder.is_dir():
            continue
        for entry in sorted(folder.iterdir()):
            if entry.suffix == ".py" and entry.is_file():
                found.setdefault(entry.stem, entry)
            elif entry.is_dir() and (entry / "__init__.py").is_file():
                found.setdefault(entry.name, entry)
    return sorted(found.items())


def copy_python_modules(program: object, package: Path) -> None:
    """Copy the modules beside the program's classes (and on the .ecf's python_path) into the
    package, when a class of the program has an external "Python" of its own."""
    if not isinstance(program, ProgramExternals) or not program.python_modules:
        return
    target = package / PYTHON_FOLDER
    target.mkdir(exist_ok=True)
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    for name, path in python_files(program.python_dirs):
        if path.is_dir():
            shutil.copytree(path, target / name, ignore=ignore)
        else:
            shutil.copy2(path, target / path.name)


def inputs_digest(project: Project) -> str:
    """A key of what the externals read besides the classes: the Python modules beside the
    classes and on the .ecf's python_path, the .ecf's external settings and the files they name,
    the headers beside the classes and in the include folders."""
    digest = hashlib.sha256(repr(project.externals).encode())
    dirs = sorted({Path(f).resolve().parent for f in project.files}) + list(project.externals.python_paths)
    files = [p for _, p in python_files(dirs)]
    files += [p for d in dirs + list(project.externals.include_dirs) if d.is_dir() for p in sorted(d.glob("*.h*"))]
    files += [p for p in project.externals.objects if p.is_file()]
    for path in files:
        for item in sorted(path.rglob("*.py")) if path.is_dir() else [path]:
            digest.update(str(item).encode())
            try:
                digest.update(item.read_bytes())
            except OSError:
                continue
    return digest.hexdigest()[:16]


# --- C and C++ ---------------------------------------------------------------------------------------
class CPlan:
    """The extension module of one language: its name (keyed by content), cdef and source."""

    def __init__(self, language: str, items: list[CExternal], settings: ExternalSettings, include: list[Path]):
        self.language, self.items, self.settings = language, items, settings
        self.include_dirs = [str(p) for p in include + list(settings.include_dirs)]
        self.cdef = _PRELUDE_CDEF + "".join(_declaration(item) + ";\n" for item in items)
        headers = list(dict.fromkeys(h for item in items for h in item.spec.headers))
        self.source = _PRELUDE + "".join(f"#include {h}\n" for h in headers) + "".join(map(_wrapper, items))
        key = hashlib.sha256(
            json.dumps(
                [__version__, language, self.cdef, self.source, self.include_dirs, _settings_key(settings)]
            ).encode()
        )
        for path in settings.objects:
            if path.is_file():
                key.update(path.read_bytes())
        self.name = MODULE_PREFIX[language] + key.hexdigest()[:16]


_PRELUDE_CDEF = "\n".join(line for line in _PRELUDE.splitlines() if not line.startswith("#")) + "\n"


def _settings_key(settings: ExternalSettings) -> list[object]:
    return [
        [str(p) for p in settings.objects],
        settings.libraries,
        settings.cflags,
        settings.linker_flags,
        [str(p) for p in settings.include_dirs],
    ]


def plans(program: object, project: Project) -> list[CPlan]:
    if not isinstance(program, ProgramExternals) or not program.c:
        return []
    include = list(program.python_dirs)  # the classes' folders: `use "mine.h"` finds headers beside them
    found = []
    for language in ("c", "c++"):
        items = [item for item in program.c if item.spec.language == language]
        if items:
            found.append(CPlan(language, items, project.externals, include))
    return found


def _types(item: CExternal) -> tuple[list[str], str]:
    """The wrapper's argument types and result type."""
    spec = item.spec
    if spec.signature is not None:
        arguments = [_c_name(t) for t in spec.signature]
    else:
        arguments = [c_type(kind) or "void *" for _, kind in item.arguments]
    if spec.result is not None:
        result = _c_name(spec.result)
    else:
        result = (c_type(item.result) or "void *") if item.result is not None else "void"
    return arguments, result


def _c_name(text: str) -> str:
    words = text.split()
    return " ".join(w.lower() if w.upper() in _C_WORDS and w.isupper() else w for w in words).replace("* ", "*")


def _declaration(item: CExternal) -> str:
    arguments, result = _types(item)
    params = ", ".join(f"{t} e_{name}" for t, (name, _) in zip(arguments, item.arguments)) or "void"
    return f"{result} {item.symbol}({params})"


def _wrapper(item: CExternal) -> str:
    arguments, result = _types(item)
    span: Any = item.span
    line = f'#line {span.line} "{span.file}"\n' if span is not None else ""
    if item.spec.inline:
        code = item.alias
        for name, _ in item.arguments:
            code = re.sub(rf"\${name}\b", f"e_{name}", code, flags=re.IGNORECASE)
        code = code.strip()
        if result != "void" and not re.search(r"\breturn\b", code):
            code = f"return ({code.rstrip(';')});"
        elif not code.endswith((";", "}")):
            code += ";"
    else:
        call = f"{item.alias}({', '.join(f'e_{name}' for name, _ in item.arguments)})"
        code = f"{call};" if result == "void" else f"return {call};"
    return f"static {_declaration(item)} {{\n{line}{code}\n}}\n"


def build(plan: CPlan, spans: list[Any]) -> Path:
    """The extension module of `plan`, from the cache or built now; SourceErrors naming what is
    missing when it cannot be built."""
    folder = cache_dir() / "c" / plan.name
    built = _built(folder, plan.name)
    if built is not None:
        return built
    compiler = _compiler(plan.language)
    if compiler is None:
        variable, default = ("CXX", "c++") if plan.language == "c++" else ("CC", "cc")
        _fail(
            spans,
            f"no {'C++' if plan.language == 'c++' else 'C'} compiler: `{os.environ.get(variable, default)}` was not "
            f"found, and scoopc builds the program's {plan.language.upper()} externals with it",
            f"install gcc (or clang), or set {variable} to the compiler's path",
        )
    staging = folder.with_name(f"{plan.name}.{os.getpid()}.tmp")
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    result = subprocess.run(
        [sys.executable, "-c", _BUILD_SCRIPT, json.dumps(_build_request(plan, staging))],
        capture_output=True,
        text=True,
        cwd=staging,
    )
    if result.returncode != 0:
        shutil.rmtree(staging, ignore_errors=True)
        reason, hint = explain_failure(result.stdout + result.stderr, plan)
        _fail([s for item, s in zip(plan.items, spans) if _names_header(item, reason)] or spans, reason, hint)
    for leftover in list(staging.iterdir()):
        if not leftover.name.startswith(plan.name + "."):
            shutil.rmtree(leftover, ignore_errors=True) if leftover.is_dir() else leftover.unlink()
    try:
        staging.rename(folder)
    except OSError:  # another process built it first
        shutil.rmtree(staging, ignore_errors=True)
    found = _built(folder, plan.name)
    assert found is not None, "the build wrote the module"
    return found


def _built(folder: Path, name: str) -> Path | None:
    suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
    path = folder / f"{name}{suffix}"
    return path if path.is_file() else None


def _compiler(language: str) -> str | None:
    variable, defaults = ("CXX", ("c++", "g++")) if language == "c++" else ("CC", ("cc", "gcc"))
    named = os.environ.get(variable, "").split()
    if named:
        return shutil.which(named[0])
    return next((found for name in defaults if (found := shutil.which(name)) is not None), None)


def _build_request(plan: CPlan, staging: Path) -> dict[str, Any]:
    settings = plan.settings
    sources = [str(p) for p in settings.objects if p.suffix.lower() in _SOURCES]
    objects = [str(p) for p in settings.objects if p.suffix.lower() not in _SOURCES]
    rpath = sorted({str(Path(p).parent) for p in objects if ".so" in Path(p).name})
    return {
        "name": plan.name,
        "cdef": plan.cdef,
        "source": plan.source,
        "cpp": plan.language == "c++",
        "folder": str(staging),
        "options": {
            "include_dirs": plan.include_dirs,
            "sources": sources,
            "extra_objects": objects,
            "libraries": settings.libraries,
            "extra_compile_args": settings.cflags,
            "extra_link_args": settings.linker_flags + [f"-Wl,-rpath,{d}" for d in rpath],
        },
    }


# The child's work: cffi's compile, then an import (undefined symbols show only then).
_BUILD_SCRIPT = """
import importlib, json, sys
request = json.loads(sys.argv[1])
import cffi
ffi = cffi.FFI()
try:
    ffi.cdef(request["cdef"])
except cffi.CDefError as problem:
    print("scoopc-cdef-error:", problem)
    sys.exit(3)
ffi.set_source(request["name"], request["source"], source_extension=".cpp" if request["cpp"] else ".c",
               **request["options"])
ffi.compile(tmpdir=request["folder"], verbose=False)
sys.path.insert(0, request["folder"])
try:
    importlib.import_module(request["name"])
except ImportError as problem:
    print("scoopc-import-error:", problem)
    sys.exit(4)
"""


def explain_failure(output: str, plan: CPlan) -> tuple[str, str]:
    """The reason and hint of a failed build, from the compiler's and cffi's output."""
    header = re.search(r"fatal error: ([^:\n]+): No such file or directory", output)
    if header is not None and not header.group(1).endswith(_SOURCES):
        return f"C header {header.group(1)} not found", "check the name in `use`, or name its folder in the .ecf"
    if header is not None:
        return f"C source {header.group(1)} not found", "check the .ecf's <external_object>"
    library = re.search(r"cannot find -l([\w.+-]+)", output) or re.search(r"cannot find (\S+):", output)
    if library is not None:
        return (
            f"library {library.group(1)} not found when linking the program's C externals",
            "check the .ecf's <external_library>/<external_object>",
        )
    missing = re.search(r"scoopc-import-error: .*undefined symbol: (\w+)", output)
    if missing is not None:
        return (
            f"the C function {missing.group(1)} is defined in no header, object or library the program names",
            "name the library that defines it in the .ecf (<external_library>, <external_object>)",
        )
    cdef = re.search(r"scoopc-cdef-error: (.*)", output)
    if cdef is not None:
        return f"a C type in a signature is not known: {cdef.group(1)}", "write C's own types or EIF_* types"
    errors = [line.strip() for line in output.splitlines() if re.search(r":\d+(:\d+)?: (fatal )?error:", line)][:6]
    text = "; ".join(errors) if errors else (output.strip().splitlines() or ["no output"])[-1]
    return (
        f"the program's {plan.language.upper()} externals do not compile: {text}",
        "fix the C code the message quotes",
    )


def _names_header(item: CExternal, reason: str) -> bool:
    return any(f"header {h[1:-1]} " in reason for h in item.spec.headers)


def _fail(spans: list[Any], reason: str, hint: str) -> NoReturn:
    raise SourceErrors([diagnostics.make("EXTERNAL-BUILD", spans[0] if spans else None, reason=reason, hint=hint)])


def build_all(program: object, project: Project) -> list[Path]:
    """Build (or take from the cache) each C/C++ module of the program."""
    return [build(plan, [item.span for item in plan.items]) for plan in plans(program, project)]
