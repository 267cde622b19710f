"""Codegen, the program: names and layouts for the whole universe, then one module per class.

Input: what the checker proved (semantics.Checked). Output: {module path: Python source} for the
classes asked for, each also as an `ast.Module` whose statements carry Eiffel line numbers.
"""

from __future__ import annotations

import ast

from .classes import ClassGen, plan_bindings
from .context import CodegenError, Options, Program
from .layout import make_layout
from .names import Naming, module_name
from .scoop_calls import finish_module


def parents_first(universe) -> list:
    order, seen = [], set()

    def visit(info):
        if info.name in seen:
            return
        seen.add(info.name)
        for _, ty, _ in info.parents:
            parent = universe.get(ty.name)
            if parent is not None:
                visit(parent)
        order.append(info)

    for info in universe.classes.values():
        visit(info)
    return order


def prepare(universe, tables, options: Options, library_facts=None, which=None) -> Program:
    """Names and layouts; the layouts (and their bindings) only of the classes `which(info)`
    selects and their ancestors when it is given: a program's classes need the library's
    ancestors of theirs, not the whole library."""
    program = Program(universe, tables, options, Naming(universe), library_facts=library_facts)
    order = parents_first(universe)
    needed = _with_ancestors(universe, [info for info in order if which(info)]) if which is not None else None
    for info in order:
        if needed is None or info.name in needed:
            program.layouts[info.name] = layout = make_layout(universe, info, program.layouts)
            layout.plan = plan_bindings(program, info, layout)
        info._has_invariant = bool(info.decl.invariant) or any(
            getattr(universe.get(ty.name), "_has_invariant", False) for _, ty, _ in info.parents
        )
        if info._has_invariant and not info.from_library:
            program.invariant_classes.update(info.ancestors)
            program.invariant_classes.add(info.name)
    return program


def _with_ancestors(universe, chosen: list) -> set:
    found: set = set()
    pending = list(chosen)
    while pending:
        info = pending.pop()
        if info.name not in found:
            found.add(info.name)
            pending += [parent for _, ty, _ in info.parents if (parent := universe.get(ty.name)) is not None]
    return found


def generate_class(program: Program, info) -> ast.Module:
    layout = program.layouts[info.name]
    try:
        module = ClassGen(program, info, layout).generate(layout.plan)
        finish_module(program, info, module)
        return module
    except CodegenError:
        raise
    except Exception as problem:  # a surprise is a compiler bug, named with the class
        raise CodegenError(f"class {info.name}: {type(problem).__name__}: {problem}") from problem


def generate(
    universe, tables, options: Options, which, library_leaves: list | None = None, library_facts=None, on_class=None
) -> dict:
    """{module file name: (ast.Module, Eiffel source path)} for the classes `which(info)` selects.
    `library_facts`: the compiled library's SCOOP facts (Program.library_facts). `library_leaves`,
    if given, receives the library routines that are leaves in this program (scoop.library_leaves).
    `on_class()` is called after each class (progress)."""
    program = prepare(universe, tables, options, library_facts, which)
    modules = {}
    for info in parents_first(universe):
        if which(info):
            modules[module_name(info.name) + ".py"] = (
                generate_class(program, info),
                program.shown_path(info.decl.span.file),
            )
            if on_class is not None:
                on_class()
    if library_leaves is not None:
        from .scoop import library_leaves as leaves_of  # deferred: start-up (loaded on first use only)

        library_leaves.extend(leaves_of(program))
    return modules
