"""Checker, externals of the user's classes: the language string of each `external` routine
(EiffelStudio's forms, docs/LANGUAGE.md, Externals) -> an ExternalSpec, the Python modules an
`external "Python"` names, found beside the program's classes or on the .ecf's python_path, and
the C and C++ externals the driver builds. Output: diagnostics and a ProgramExternals.

The kernel's own externals (the library's `external "Python"` features, scoopc/kernel/ext/) are
not checked here: only classes of the program are.
"""

from __future__ import annotations

import ast
import importlib.util
import keyword
import re
from dataclasses import dataclass, field
from pathlib import Path

from .. import diagnostics, syntax
from ..project import Project

# Eiffel basic types and how they cross to Python and C (docs/LANGUAGE.md, Externals).
INTEGERS = {f"INTEGER_{n}": f"int{n}" for n in (8, 16, 32, 64)} | {f"NATURAL_{n}": f"uint{n}" for n in (8, 16, 32, 64)}
NUMBERS = INTEGERS | {"REAL_32": "float32", "REAL_64": "float64", "BOOLEAN": "bool"}
SCALARS = set(NUMBERS) | {"CHARACTER_8", "CHARACTER_32", "POINTER"}
C_TYPES = {name: f"{dtype}_t" for name, dtype in INTEGERS.items()} | {
    "REAL_32": "float",
    "REAL_64": "double",
    "BOOLEAN": "EIF_BOOLEAN",
    "CHARACTER_8": "char",
    "CHARACTER_32": "uint32_t",
    "POINTER": "void *",
    "STRING_8": "char *",
    "STRING_32": "char *",
}
_SYNONYMS = {"INTEGER": "INTEGER_32", "NATURAL": "NATURAL_32", "REAL": "REAL_32", "DOUBLE": "REAL_64"}
_SYNONYMS |= {"CHARACTER": "CHARACTER_8", "WIDE_CHARACTER": "CHARACTER_32", "STRING": "STRING_8"}
_STRINGS_8 = {"STRING_8", "READABLE_STRING_8", "IMMUTABLE_STRING_8"}
_STRINGS_32 = {"STRING_32", "READABLE_STRING_32", "IMMUTABLE_STRING_32", "READABLE_STRING_GENERAL", "STRING_GENERAL"}


@dataclass(frozen=True)
class ExternalSpec:
    """An `external` language string, parsed."""

    language: str  # "python" | "c" | "c++" | "built_in"
    inline: bool = False
    blocking: bool = False
    signature: tuple[str, ...] | None = None  # C argument types, when a signature is given
    result: str | None = None  # the signature's C result type
    headers: tuple[str, ...] = ()  # `<math.h>` or `"mine.h"`


def parse_spec(text: str) -> ExternalSpec:
    """EiffelStudio's external language forms: `Python [blocking]`, `built_in`, `C [blocking] [inline]
    [signature (T, ...)[: R]] [use H, ...]`, the older `C [blocking] [(T, ...)[: R]] [| H, ...]`
    and `C++ inline [use H, ...]`. ValueError (the reason) for anything else."""
    words = text.strip()
    head = re.match(r"(?i)(c\+\+|c|python|built_in)(?![\w+])", words)
    if head is None:
        raise ValueError(f'unknown external language "{text}": scoopc knows "C", "C++", "Python" and "built_in"')
    language = head.group(0).lower()
    rest = words[head.end() :].strip()
    blocking, rest = _keyword(rest, "blocking") if language != "built_in" else (False, rest)
    if language in ("python", "built_in"):
        if rest:
            raise ValueError(f'nothing may follow "{head.group(0)}" in an external language, found "{rest}"')
        return ExternalSpec(language, blocking=blocking)
    inline, rest = _keyword(rest, "inline")
    other = re.match(r"(?i)(macro|struct|dll|dllwin|class|delete|new|static|data_member)\b", rest)
    if other is not None:
        raise ValueError(f'the "{language.upper()} {other.group(1)}" form of external is not supported by scoopc')
    if language == "c++" and not inline:
        raise ValueError('scoopc supports C++ externals in the "C++ inline" form only')
    signature, result, rest = _signature(rest)
    headers, rest = _headers(rest)
    if rest:
        raise ValueError(f'unexpected "{rest}" in the external language "{text}"')
    if inline and signature is not None:
        raise ValueError("an inline external takes its types from the routine's signature, not a `signature` clause")
    return ExternalSpec(language, inline, blocking, signature, result, headers)


def _keyword(rest: str, word: str) -> tuple[bool, str]:
    found = re.match(rf"(?i){word}\b", rest)
    return (True, rest[found.end() :].strip()) if found else (False, rest)


def _signature(rest: str) -> tuple[tuple[str, ...] | None, str | None, str]:
    found = re.match(r"(?i)(?:signature\s*)?\(([^)]*)\)\s*(?::\s*([^|]+?))?\s*(?=$|\||use\b)", rest)
    if found is None:
        if re.match(r"(?i)signature\b", rest):
            raise ValueError("a `signature` clause is `signature (TYPE, ...)` or `signature (TYPE, ...): TYPE`")
        return None, None, rest
    arguments = tuple(a.strip() for a in found.group(1).split(",") if a.strip())
    result = found.group(2).strip() if found.group(2) else None
    return arguments, result, rest[found.end() :].strip()


def _headers(rest: str) -> tuple[tuple[str, ...], str]:
    found = re.match(r"(?i)(?:use\b|\|)\s*(.*)$", rest)
    if found is None:
        return (), rest
    headers = tuple(h.strip() for h in found.group(1).split(",") if h.strip())
    for header in headers:
        if not re.fullmatch(r'<[^<>"]+>|"[^"]+"|[\w./-]+\.h(?:pp)?', header):
            raise ValueError(f'a header is written <name.h> or %"name.h%", not {header}')
    return tuple(h if h[0] in '<"' else f'"{h}"' for h in headers), ""


# --- kinds: how a value crosses -------------------------------------------------------------------
def kind_of(universe, ty) -> str:
    """How a value of Eiffel type `ty` crosses to Python or C: a basic type's name, "STRING_8",
    "STRING_32", "ARRAY:<item>" or "SPECIAL:<item>" (items of a basic numeric type), "OBJECT"."""
    if ty is None or ty.is_formal:
        return "OBJECT"
    name = _SYNONYMS.get(ty.name, ty.name)
    if name in SCALARS:
        return name
    if name in _STRINGS_8:
        return "STRING_8"
    if name in _STRINGS_32:
        return "STRING_32"
    if name in ("ARRAY", "SPECIAL") and ty.generics and not ty.generics[0].is_formal:
        item = _SYNONYMS.get(ty.generics[0].name, ty.generics[0].name)
        if item in NUMBERS:
            return f"{name}:{item}"
    return "OBJECT"


def c_type(kind: str) -> str | None:
    """The C type of a kind when no signature is given (None: it cannot cross to C)."""
    if kind.startswith(("ARRAY:", "SPECIAL:")):
        return C_TYPES[kind.split(":")[1]] + " *"
    return C_TYPES.get(kind)


def c_symbol(class_name: str, feature: str) -> str:
    """The name of the C wrapper function generated for a C external."""
    return f"scoopc_{class_name.lower()}_{feature}"


# --- the program's externals ---------------------------------------------------------------------
@dataclass
class CExternal:
    """A C or C++ external routine of the program, for the driver to build."""

    symbol: str
    spec: ExternalSpec
    alias: str  # the C function's name, or the inline code
    arguments: tuple[tuple[str, str], ...]  # (name, kind)
    result: str | None  # kind
    span: object


@dataclass
class ProgramExternals:
    python_dirs: list[Path] = field(default_factory=list)  # where the program's Python modules are
    python_modules: dict[str, Path] = field(default_factory=dict)  # top-level module -> file or package
    c: list[CExternal] = field(default_factory=list)


def python_dirs(project: Project, universe) -> list[Path]:
    """The folders searched for the program's Python modules: each user class's folder, then the
    .ecf's python_path."""
    found: list[Path] = []
    for info in universe.classes.values():
        if not info.from_library:
            folder = Path(info.decl.span.file).resolve().parent
            if folder not in found:
                found.append(folder)
    for folder in project.externals.python_paths:
        if folder.resolve() not in found:
            found.append(folder.resolve())
    return found


def check(universe, project: Project) -> tuple[list, ProgramExternals]:
    """Every `external` routine of the program's classes: its language string, the Python module
    it names, the types a C external passes."""
    found: list = []
    program = ProgramExternals(python_dirs(project, universe))
    for info in universe.classes.values():
        if info.from_library or info.failed:
            continue
        for feature in info.features.values():
            if feature.written_in != info.name or not feature.is_routine:
                continue
            inner = getattr(feature.decl.body, "body", None)
            if isinstance(inner, syntax.ExternalBody):
                _check_one(universe, info, feature, inner, program, found)
    for folder in project.externals.python_paths:
        if not folder.is_dir():
            found.append(_error(None, f"the .ecf's python_path names {folder}, which is not a folder"))
    return found, program


def _check_one(universe, info, feature, inner, program: ProgramExternals, found: list) -> None:
    try:
        spec = parse_spec(inner.language)
    except ValueError as problem:
        found.append(_error(inner.span, str(problem)))
        return
    signature = feature.signature
    if signature is None:
        return
    if spec.language == "python":
        _check_python(info, feature, inner, program, found)
    elif spec.language in ("c", "c++"):
        _check_c(universe, info, feature, inner, spec, program, found)


def _check_python(info, feature, inner, program: ProgramExternals, found: list) -> None:
    if not inner.alias and kernel_provides(info.name, feature.name):
        return  # a class of the program that replaces a library class keeps the kernel's externals
    alias = python_alias(info.name, feature.name, inner.alias)
    if not alias or not re.fullmatch(r"[A-Za-z_]\w*(\.[A-Za-z_]\w*)+", alias):
        wrong = f", not {alias!r}" if alias else ""
        reason = f'`{feature.text}`: an external "Python" names its function with alias "module.function" or '
        found.append(_error(inner.span, reason + f'"module.Class.method"{wrong}'))
        return
    parts = alias.split(".")
    for split in range(len(parts) - 1, 0, -1):
        location = _find_module(program.python_dirs, parts[:split])
        if location is not None:
            top = location[1]
            program.python_modules.setdefault(parts[0], top)
            missing = _missing_name(location[0], parts[split])
            if missing:
                found.append(_error(inner.span, f"module `{'.'.join(parts[:split])}` ({location[0]}) {missing}"))
            return
    if _installed(parts[0]):
        return
    searched = ", ".join(str(d) for d in program.python_dirs)
    found.append(
        _error(
            inner.span,
            f"no Python module `{parts[0]}` for external `{feature.text}`: not beside the program's classes "
            f"({searched}), not on the .ecf's python_path and not installed",
        )
    )


def python_alias(class_name: str, feature: str, alias: str | None) -> str:
    """What an external "Python" calls: its alias, or without one the function named like the
    feature in the module named like the class, in lower case (as the kernel's own externals)."""
    return alias or f"{class_name.split('@')[0].lower()}.{feature}"


def kernel_provides(class_name: str, feature: str) -> bool:
    """Does scoopc's kernel have the `external "Python"` of a library class's `feature` (for a
    program class named like a library class)? Read from the kernel's source, not imported."""
    try:
        spec = importlib.util.find_spec(f"scoopc.kernel.ext.{class_name.split('@')[0].lower()}")
    except (ImportError, ValueError):
        return False
    if spec is None or spec.origin is None:
        return False
    name = feature + "_" if keyword.iskeyword(feature) else feature
    return _missing_name(Path(spec.origin), name) is None


def _find_module(dirs: list[Path], dotted: list[str]) -> tuple[Path, Path] | None:
    """(the module's file, the top-level file or package folder) of `a.b.c` in one of `dirs`."""
    for folder in dirs:
        base = folder.joinpath(*dotted)
        for candidate in (base.with_suffix(".py"), base / "__init__.py"):
            if candidate.is_file():
                top = folder / dotted[0]
                return candidate, (top if top.is_dir() else top.with_suffix(".py"))
    return None


def _missing_name(module_file: Path, name: str) -> str | None:
    """Why `name` is not defined at the top of the module (None when it is, or when it cannot
    be told without running the module: `from x import *`, `__getattr__`, a syntax error)."""
    try:
        tree = ast.parse(module_file.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, UnicodeDecodeError, ValueError):
        return None
    defined: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            defined.add(node.name)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            defined.add(node.id)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name == "*":
                    return None
                defined.add((alias.asname or alias.name).split(".")[0])
    if name in defined or "__getattr__" in defined:
        return None
    return f"defines no `{name}`"


def _installed(top: str) -> bool:
    try:
        return importlib.util.find_spec(top) is not None
    except (ImportError, ValueError):
        return False


def _check_c(universe, info, feature, inner, spec: ExternalSpec, program: ProgramExternals, found: list) -> None:
    signature = feature.signature
    names = [a.name.key for a in feature.decl.arguments]
    kinds = [kind_of(universe, t) for t in signature.arguments]
    result = kind_of(universe, signature.result) if signature.result is not None else None
    if spec.inline and not inner.alias:
        found.append(_error(inner.span, f"`{feature.text}`: an inline external holds its C code in its alias"))
        return
    if spec.signature is not None and len(spec.signature) != len(names):
        found.append(
            _error(
                inner.span,
                f"`{feature.text}` has {len(names)} argument(s) but its signature lists {len(spec.signature)} type(s)",
            )
        )
        return
    crossing = list(zip(names, kinds)) + ([("Result", result)] if result is not None else [])
    for name, kind in crossing:
        if c_type(kind) is None or (name == "Result" and kind.startswith(("ARRAY:", "SPECIAL:"))):
            found.append(
                _error(
                    inner.span,
                    f"`{feature.text}`: {name} of type {kind.split(':')[0] if kind != 'OBJECT' else 'a class type'} "
                    f"cannot cross to C (basic types, POINTER, strings and arrays of numbers can"
                    f"{'' if name != 'Result' else ', arrays as arguments only'})",
                )
            )
            return
    symbol = c_symbol(info.name, feature.name)
    alias = inner.alias or feature.name
    program.c.append(CExternal(symbol, spec, alias, tuple(zip(names, kinds)), result, inner.span))


def _error(span, reason: str):
    return diagnostics.make("EXTERNAL", span, reason=reason)
