"""Codegen, shared state: the program being compiled (universe, tables, names, layouts, options)
and, per module, what it must import and the constants it defines at module level."""

from __future__ import annotations

import ast
import os
from dataclasses import dataclass, field

from . import pyast as P
from .names import Naming, class_name, module_name


class CodegenError(Exception):
    """Codegen met something the checker should have rejected or recorded: an internal error."""


@dataclass
class Options:
    assertions: str = "all"  # all | require | none (wait conditions always)
    library_assertions: str = "require"
    base_package: str = "eiffel_base"
    package: str = "program"
    c_modules: tuple = ()  # (language, module name): the cffi modules of the program's C/C++ externals
    # the folder source paths are written relative to in the generated code (None: as given), so
    # that compiled output names no absolute path and can be moved
    source_root: str | None = None


@dataclass
class Program:
    universe: object
    tables: object
    options: Options
    naming: Naming
    layouts: dict = field(default_factory=dict)
    leaves: dict = field(default_factory=dict)  # id(decl) -> bool
    sources: dict = field(default_factory=dict)  # class key -> source path
    invariant_classes: set = field(default_factory=set)  # classes with an invariant in themselves or a descendant
    # the compiled library's SCOOP facts (dict, see scoop.library_facts); True: compute them from the
    # library's bodies (when compiling the library itself); None: none (library routines are non-leaves)
    library_facts: object = None

    def package_of(self, key: str) -> str:
        info = self.universe.get(key)
        return self.options.base_package if info is not None and info.from_library else self.options.package

    def shown_path(self, path: str) -> str:
        """`path` as generated code names it: relative to the options' source root."""
        root = self.options.source_root
        if root is None:
            return path
        try:
            return os.path.relpath(os.path.abspath(path), root).replace(os.sep, "/")
        except ValueError:  # another drive (Windows): the name alone
            return os.path.basename(path)

    def assertions_for(self, info) -> str:
        return self.options.library_assertions if info.from_library else self.options.assertions


class ModuleContext:
    """Imports and module-level constants of one generated module."""

    def __init__(self, program: Program, info):
        self.program = program
        self.info = info
        self.parents: list[str] = []  # keys imported at the top (base classes)
        self.ancestors: set[str] = set()  # keys of other ancestors it names (imported by name at the top)
        self.others: set[str] = set()  # keys of the other classes it uses, whose modules it imports
        self.constants: list[ast.stmt] = []  # module-level assignments (positions, clause tables, types)
        self._const_names: dict = {}
        self.counter = 0

    def class_ref(self, key: str) -> ast.expr:
        """The class itself and its ancestors by name (imported by name at the top: a class's
        ancestors are defined before it); any other class through its module
        (`_bounded_buffer.BOUNDED_BUFFER`), imported whole at the bottom, after the class is defined:
        classes use each other in cycles (ANY uses OPERATING_ENVIRONMENT, an heir of ANY), and a
        module imported whole is found even while it is still loading (the name is looked up when
        the code runs)."""
        if key == self.info.name or key in self.parents:
            return P.name(class_name(key))
        if key in self.info.all_ancestors:
            self.ancestors.add(key)
            return P.name(class_name(key))
        self.others.add(key)
        return P.attr(P.name(self.module_alias(key)), class_name(key))

    def module_alias(self, key: str) -> str:
        """`_M_<module>` for a class of the same package; `_L_<module>` for a library class used by a
        program (module names are lower case: these never meet each other, the module's other names
        or the functions' temporaries, `_t`, `_agent_1`, ...)."""
        own = self.program.package_of(key) == self.program.package_of(self.info.name)
        return f"_M_{module_name(key)}" if own else f"_L_{module_name(key)}"

    def module_imports(self) -> list[ast.stmt]:
        """`import package.module as _module` for every other class used (in key order)."""
        found = {}
        for key in sorted(self.others):
            found.setdefault(self.module_alias(key), f"{self.program.package_of(key)}.{module_name(key)}")
        return [ast.Import([ast.alias(path, alias)]) for alias, path in found.items()]

    def known_constant(self, key) -> ast.Name | None:
        """The constant interned by `key`, if made already."""
        ident = self._const_names.get(key)
        return None if ident is None else P.name(ident)

    def constant(self, prefix: str, value: ast.expr, key=None) -> ast.Name:
        """A module-level constant (interned by `key` when given)."""
        if key is not None and key in self._const_names:
            return P.name(self._const_names[key])
        self.counter += 1
        ident = f"_{prefix}_{self.counter}"  # the module's own names start with `_`: no Eiffel name does
        self.constants.append(P.assign(P.name(ident), value))
        if key is not None:
            self._const_names[key] = ident
        return P.name(ident)

    def import_lines(self, keys, top: bool) -> list[ast.stmt]:
        out = []
        for key in sorted(keys):
            out.append(
                ast.ImportFrom(f"{self.program.package_of(key)}.{module_name(key)}", [ast.alias(class_name(key))], 0)
            )
        return out


def fail(message: str, span=None):
    where = f" at {span.file}:{span.line}:{span.column}" if span is not None else ""
    raise CodegenError(message + where)


def first(items, default=None) -> object | None:
    return next(iter(items), default)
