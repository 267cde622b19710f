"""Packaging: the wheel built from the repository carries every module, the grammar and every
stdlib .e file, so a regular (non-editable) install works as the checkout does; and the standard
library compiled when the wheel was built (tools/build_stdlib.py), which a run from the wheel uses
instead of compiling it: nothing of the library is written to the cache, no progress is shown."""

import ast
import os
import subprocess
import sys
import zipfile

import pytest

try:
    import tomllib
except ImportError:  # Python 3.10
    tomllib = pytest.importorskip("tomli")

from harness import ROOT


def test_every_python_package_and_stdlib_folder_is_listed_in_pyproject():
    """A folder setuptools is not told about is not shipped (it warns now, and will drop it)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    listed = set(config["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "scoopc").rglob("__init__.py")}
    found |= {".".join(("scoopc",) + p.parent.relative_to(ROOT).parts) for p in (ROOT / "stdlib").rglob("*.e")}
    assert found <= listed, f"add to [tool.setuptools] packages: {sorted(found - listed)}"


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    pytest.importorskip("setuptools")
    pytest.importorskip("wheel")
    out = tmp_path_factory.mktemp("wheel")
    # the pure-Python runtime: compiling it (tools/build_runtime.py) costs a minute, and CI's
    # own install is the compiled build (test_build_runtime.py checks it is)
    env = dict(os.environ, SCOOPC_PURE_RUNTIME="1")
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--no-deps",
            "--no-build-isolation",
            "--quiet",
            "-w",
            str(out),
            str(ROOT),
        ],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )
    assert done.returncode == 0, done.stderr
    (built,) = out.glob("scoopc-*.whl")
    return built


@pytest.fixture(scope="module")
def wheel_names(wheel):
    return set(zipfile.ZipFile(wheel).namelist())


@pytest.mark.slow
def test_wheel_has_all_modules_and_the_grammar(wheel_names):
    expected = {p.relative_to(ROOT).as_posix() for p in (ROOT / "scoopc").rglob("*.py")}
    expected.add("scoopc/grammar.lark")
    assert expected <= wheel_names, sorted(expected - wheel_names)


@pytest.mark.slow
def test_wheel_has_every_stdlib_class(wheel_names):
    expected = {"scoopc/stdlib/" + p.relative_to(ROOT / "stdlib").as_posix() for p in (ROOT / "stdlib").rglob("*.e")}
    assert expected <= wheel_names, sorted(expected - wheel_names)


@pytest.mark.slow
def test_wheel_has_the_compiled_library_of_its_own_compiler(wheel_names):
    from scoopc.driver.packages import compiler_digest
    from scoopc.parse.parser import GRAMMAR_PATH, parser_file
    from scoopc.semantics.library import library_key
    from scoopc.semantics.universe import stdlib_files

    prebuilt = "scoopc/prebuilt/"
    base = f"{prebuilt}base-{compiler_digest()}/eiffel_base/"
    made = ("__init__.py", "_lines.json", "_manifest.json", "_scoop_facts.json")
    assert {base + name for name in made} <= wheel_names
    assert len([n for n in wheel_names if n.startswith(base) and n.endswith(".py")]) == len(stdlib_files()) + 1
    assert f"{prebuilt}stdlib-{library_key()}.pickle" in wheel_names
    assert prebuilt + parser_file(GRAMMAR_PATH.read_text(encoding="utf-8")) in wheel_names
    assert not [n for n in wheel_names if "__pycache__" in n or n.endswith(".pyc")]


@pytest.mark.slow
def test_a_run_from_the_wheel_compiles_nothing_of_the_library(wheel, tmp_path):
    """The wheel's files first on the path (its dependencies from this environment), an empty
    cache: the program runs, the cache holds the program only, stderr stays empty."""
    site = tmp_path / "site"
    zipfile.ZipFile(wheel).extractall(site)
    cache = tmp_path / "cache"
    env = dict(os.environ, PYTHONPATH=str(site), SCOOPC_CACHE_DIR=str(cache))
    env.pop("SCOOPC_NO_PREBUILT", None)
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", "run", str(ROOT / "samples" / "producer_consumer")],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        timeout=300,
    )
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert "consumers took items adding up to" in done.stdout
    assert sorted(p.name for p in cache.iterdir()) == ["programs"]
    (meta,) = cache.glob("programs/*/program.json")
    assert str(site / "scoopc" / "prebuilt" / "base-") in meta.read_text()


# The wheel's build step runs in pip's isolated build environment, which has only what
# [build-system] requires (setuptools, wheel, lark): scoopc's other dependencies (yaml, numpy,
# cyclonedds, rosbags, ...) are absent there. These run the step's imports, and the step itself,
# with every module outside the standard library, lark and scoopc refused.
ONLY_BUILD_REQUIREMENTS = """
import sys
class Refuse:
    def find_spec(self, name, path=None, target=None):
        top = name.partition(".")[0]
        # scoopc_runtime__mypyc: the shared library of a runtime compiled in place (ours)
        if top in sys.stdlib_module_names or top in ("lark", "scoopc", "scoopc_runtime__mypyc", "_distutils_hack"):
            return None
        raise ModuleNotFoundError(f"No module named {name!r} (not a build requirement)")
sys.meta_path.insert(0, Refuse())
"""


def _with_build_requirements_only(code: str, *args: str, env=None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", ONLY_BUILD_REQUIREMENTS + code, *args],
        capture_output=True,
        text=True,
        cwd=ROOT,
        env=env,
        timeout=600,
    )


def test_the_build_step_imports_with_the_build_requirements_only():
    done = _with_build_requirements_only("from scoopc.driver.library import build_prebuilt")
    assert done.returncode == 0, done.stderr


@pytest.mark.slow
def test_the_build_step_builds_with_the_build_requirements_only(tmp_path):
    tree = ast.parse((ROOT / "tools" / "build_stdlib.py").read_text(encoding="utf-8"))
    (step,) = [ast.literal_eval(n.value) for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "STEP"]
    env = dict(os.environ, SCOOPC_CACHE_DIR=str(tmp_path / "cache"), PYTHONDONTWRITEBYTECODE="1")
    done = _with_build_requirements_only(step.replace("; ", "\n"), str(tmp_path / "prebuilt"), env=env)
    assert done.returncode == 0, done.stdout + done.stderr
    assert list((tmp_path / "prebuilt").glob("base-*/eiffel_base/any.py"))
