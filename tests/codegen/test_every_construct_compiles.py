"""Code generation covers the whole dialect the checker accepts: every construct-covering program
(tests/syntax/valid/) and every valid SCOOP program (tests/semantics/valid/) becomes Python that
compiles, with no internal error of the code generator."""

import ast
from pathlib import Path

import pytest

from scoopc import pipeline
from scoopc.codegen.context import Options
from scoopc.codegen.program import generate
from scoopc.project import collect

TESTS = Path(__file__).resolve().parents[1]
PROGRAMS = sorted(
    p
    for folder in (TESTS / "syntax" / "valid", TESTS / "semantics" / "valid")
    for p in folder.iterdir()
    if p.suffix == ".e" or p.is_dir()
)


@pytest.mark.parametrize("program", PROGRAMS, ids=lambda p: f"{p.parent.parent.name}/{p.name}")
def test_generated_python_compiles(program):
    checked = pipeline.check_project(collect([str(program)]))
    assert not checked.has_errors
    sem = checked.semantics
    modules = generate(sem.universe, sem.tables, Options(), lambda info: not info.from_library)
    assert modules
    for filename, (module, _) in modules.items():
        compile(ast.unparse(module), filename, "exec")
