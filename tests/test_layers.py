"""No cycles between scoopc's packages: the import graph (function-level imports included) goes
down the layers docs/ARCHITECTURE.md draws, and every module imports on its own."""

import ast
import os
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


@pytest.mark.slow
def test_every_module_imports_on_its_own():
    """Each module in a fresh interpreter (no other import first to hide a cycle)."""
    names = [n for n in modules() if not n.endswith("__main__")]
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        failed = [f"{name}: {error}" for name, error in zip(names, pool.map(_import_alone, names)) if error]
    assert not failed, "modules that fail to import alone:\n" + "\n".join(failed)


def _import_alone(name: str) -> str:
    """'' when `import name` works in a fresh interpreter, else the last line of its error."""
    done = subprocess.run(
        [sys.executable, "-c", f"import {name}"], capture_output=True, text=True, cwd=ROOT, timeout=120
    )
    return "" if done.returncode == 0 else (done.stderr.strip().splitlines() or ["?"])[-1]
