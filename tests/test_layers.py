"""No cycles between scoopc's packages: the import graph (function-level imports included) goes
down the layers docs/ARCHITECTURE.md draws, and every module imports on its own."""

import ast
import re
import subprocess
import sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor

import pytest

from harness import ROOT

PACKAGE = ROOT / "scoopc"
ROW = re.compile(r"^\| (\d+) [^|]*\| ([^|]+) \|")


def layers() -> list[list[str]]:
    """The layers of ARCHITECTURE.md's table, lowest first, each a list of units in their order."""
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    rows = [ROW.match(line) for line in text.split("## Layers", 1)[1].splitlines()]
    found = [(int(m.group(1)), re.findall(r"`(scoopc[\w.]*)`", m.group(2))) for m in rows if m]
    return [units for _, units in sorted(found)]


def modules() -> dict[str, object]:
    """Every module of the package: dotted name -> path."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        found[".".join(parts)] = path
    return found


def imports(name: str, path) -> set[str]:
    """The scoopc modules `name` imports anywhere in its text (inside functions too)."""
    is_package = path.name == "__init__.py"
    here = name.split(".") if is_package else name.split(".")[:-1]
    known = modules()
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = ".".join(here[: len(here) - node.level + 1]) if node.level else ""
            module = ".".join(p for p in (base, node.module) if p)
            for alias in node.names:  # `from package import module` imports the module
                sub = f"{module}.{alias.name}"
                found.add(sub if sub in known else module)
    return {m for m in found if m == "scoopc" or m.startswith("scoopc.")}


def unit_of(module: str, units: list[str]) -> str:
    """The longest unit that contains `module`."""
    owners = [u for u in units if module == u or module.startswith(u + ".")]
    assert owners, f"{module} belongs to no layer of docs/ARCHITECTURE.md"
    return max(owners, key=len)


def test_the_layers_cover_every_module():
    units = [u for layer in layers() for u in layer]
    assert len(units) == len(set(units)) and len(units) >= 10
    for name in modules():
        unit_of(name, units)


def test_every_import_goes_down_the_layers():
    order = [u for layer in layers() for u in layer]
    rank = {u: i for i, u in enumerate(order)}
    wrong = defaultdict(set)
    for name, path in modules().items():
        mine = unit_of(name, order)
        for target in imports(name, path):
            theirs = unit_of(target, order)
            if theirs != mine and rank[theirs] > rank[mine]:
                wrong[f"{mine} ({name})"].add(theirs)
    assert not wrong, "imports that go up the layers of docs/ARCHITECTURE.md: " + "; ".join(
        f"{k} -> {', '.join(sorted(v))}" for k, v in sorted(wrong.items())
    )


# One interpreter imports the modules in turn, forgetting every scoopc module before each: a module
# that works only because another scoopc module was imported first fails as it would alone. Modules
# outside scoopc (lark, numpy, cyclonedds) stay loaded; they have no part in scoopc's import order.
# An interpreter per module found the same and cost ten times the time.
_IMPORT_EACH = """
import importlib, sys, traceback
for name in sys.argv[1:]:
    for loaded in [m for m in sys.modules if m == "scoopc" or m.startswith("scoopc.")]:
        del sys.modules[loaded]
    try:
        importlib.import_module(name)
    except BaseException as e:  # noqa: BLE001 - reported by name
        print(f"{name}: {traceback.format_exception_only(type(e), e)[-1].strip()}")
"""


@pytest.mark.slow
def test_every_module_imports_on_its_own():
    """Each module with no other scoopc module imported first (to hide a cycle or a missing import)."""
    names = [n for n in modules() if not n.endswith("__main__")]
    half = len(names) // 2  # two interpreters: the work is spread over two cores where there are two
    with ThreadPoolExecutor(max_workers=2) as pool:
        failed = [line for out in pool.map(_import_each, [names[:half], names[half:]]) for line in out]
    assert not failed, "modules that fail to import alone:\n" + "\n".join(failed)


def test_a_module_that_needs_another_imported_first_is_found(tmp_path):
    """The check itself: a module using a scoopc module it never imports fails alone."""
    package = tmp_path / "scoopc_probe"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("import scoopc_probe\nVALUE = scoopc_probe.b.VALUE\n")
    (package / "b.py").write_text("VALUE = 1\n")
    script = _IMPORT_EACH.replace('"scoopc"', '"scoopc_probe"').replace('"scoopc."', '"scoopc_probe."')
    done = subprocess.run(
        [sys.executable, "-c", script, "scoopc_probe.b", "scoopc_probe.a"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=60,
    )
    assert done.stdout.startswith("scoopc_probe.a: AttributeError"), done.stdout + done.stderr


def _import_each(names: list[str]) -> list[str]:
    """The lines of the modules of `names` that fail to import with no other scoopc module loaded."""
    done = subprocess.run(
        [sys.executable, "-c", _IMPORT_EACH, *names], capture_output=True, text=True, cwd=ROOT, timeout=600
    )
    lines = done.stdout.splitlines()
    if done.returncode != 0:
        lines.append(f"the importing interpreter ended with {done.returncode}: {done.stderr.strip()[-500:]}")
    return lines
