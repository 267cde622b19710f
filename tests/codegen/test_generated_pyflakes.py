"""Generated code is code: pyflakes finds no undefined name in the compiled standard library, the
golden cases' expected modules or the samples (every class a module uses is imported by the module
itself; nothing is injected into its globals when it loads)."""

import ast
from pathlib import Path

import pytest
from pyflakes import api, messages, reporter

from scoopc.driver import BASE_PACKAGE, Compilation, compiled_library

REPO = Path(__file__).resolve().parents[2]


class Collect(reporter.Reporter):
    def __init__(self):
        self.found = []

    def flake(self, message):
        if isinstance(message, (messages.UndefinedName, messages.UndefinedLocal, messages.UndefinedExport)):
            self.found.append(str(message))

    def syntaxError(self, filename, msg, lineno, offset, text):  # noqa: N802 (pyflakes' name)
        self.found.append(f"{filename}:{lineno}: {msg}")

    def unexpectedError(self, filename, msg):  # noqa: N802 (pyflakes' name)
        self.found.append(f"{filename}: {msg}")


def undefined(texts: dict) -> list:
    found = Collect()
    for name, text in texts.items():
        api.check(text, name, found)
    return found.found


def test_the_compiled_standard_library_names_nothing_undefined():
    package = compiled_library().path / BASE_PACKAGE
    texts = {str(p): p.read_text() for p in sorted(package.glob("*.py"))}
    assert len(texts) > 100
    assert undefined(texts) == []


def test_the_golden_cases_expected_modules_name_nothing_undefined():
    texts = {str(p): p.read_text() for p in sorted((REPO / "tests" / "golden").glob("*/expected/*.py"))}
    assert texts
    assert undefined(texts) == []


@pytest.mark.slow
@pytest.mark.parametrize("sample", sorted(p.name for p in (REPO / "samples").iterdir() if any(p.glob("*.e"))))
def test_a_sample_names_nothing_undefined(sample):
    folder = REPO / "samples" / sample
    compilation = Compilation([next(iter(folder.glob("*.ecf")), folder)])  # a sample's .ecf names its C
    assert not compilation.checked.has_errors
    modules, _ = compilation.modules()
    assert undefined({name: ast.unparse(module) for name, (module, _) in modules.items()}) == []
