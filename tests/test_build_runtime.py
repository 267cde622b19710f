"""The compiled runtime (tools/build_runtime.py, docs/RUNTIME.md section 10): when the build
compiles the runtime's hot modules with mypyc, when it keeps the pure-Python runtime instead,
that a failing C compiler leaves no half-built runtime behind, and that the pure-Python runtime
still passes the runtime's tests where the installed one is compiled."""

import importlib.util
import os
import subprocess
import sys

import pytest
from setuptools import Distribution, Extension

import scoopc.runtime as rt

from harness import ROOT

# the repository's tools/build_runtime.py, loaded from its file: putting the checkout on sys.path
# would mix its scoopc modules into a test process that runs the installed ones
_spec = importlib.util.spec_from_file_location("build_runtime", ROOT / "tools" / "build_runtime.py")
build_runtime = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(build_runtime)


def test_ci_installs_the_compiled_runtime():
    """.ci/run sets SCOOPC_REQUIRE_COMPILED_RUNTIME: a build that fell back to pure Python there
    (mypyc or the compiler failing) fails CI instead of passing unnoticed, slower."""
    if not os.environ.get("SCOOPC_REQUIRE_COMPILED_RUNTIME"):
        pytest.skip("only where SCOOPC_REQUIRE_COMPILED_RUNTIME is set (CI's regular install)")
    assert rt.COMPILED, f"the runtime imported from {rt._processor.__file__} is not compiled"


def test_the_runtime_kind_is_in_the_version():
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", "--version"], capture_output=True, text=True, timeout=60, cwd=ROOT.parent
    )
    assert done.returncode == 0, done.stderr
    kind = "compiled to C" if rt.COMPILED else "pure Python"
    assert done.stdout.strip().endswith(f"(runtime: {kind})")


def test_a_pure_build_is_asked_for_with_scoopc_pure_runtime(monkeypatch, capsys):
    monkeypatch.setenv("SCOOPC_PURE_RUNTIME", "1")
    assert build_runtime.ext_modules() == []
    assert "SCOOPC_PURE_RUNTIME is set" in capsys.readouterr().err


def test_setup_declares_a_placeholder_and_compiles_nothing_yet(monkeypatch):
    """Evaluating setup.py (every step of an install does) stays cheap: mypyc runs in build_ext."""
    monkeypatch.delenv("SCOOPC_PURE_RUNTIME", raising=False)
    monkeypatch.setitem(sys.modules, "mypyc.build", None)  # any use of mypyc would fail
    (ext,) = build_runtime.ext_modules()
    assert ext.name == build_runtime.PLACEHOLDER and ext.sources == []


def _build_ext(tmp_path, extensions, editable=False):
    dist = Distribution({"name": "probe", "ext_modules": extensions})
    cmd = build_runtime.BuildExt(dist)
    cmd.build_lib = str(tmp_path / "lib")
    cmd.build_temp = str(tmp_path / "tmp")
    cmd.editable_mode = editable
    cmd.ensure_finalized()
    return cmd


def test_editable_installs_keep_the_sources(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "mypyc.build", None)  # any use of mypyc would fail
    monkeypatch.chdir(tmp_path)  # an editable build removes compiled modules in place: not the checkout's
    cmd = _build_ext(tmp_path, [Extension(build_runtime.PLACEHOLDER, sources=[])], editable=True)
    cmd.run()
    assert cmd.extensions == []
    assert "an editable install" in capsys.readouterr().err


def test_without_mypyc_the_runtime_stays_pure_python(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "mypyc.build", None)  # an import of it fails
    cmd = _build_ext(tmp_path, [Extension(build_runtime.PLACEHOLDER, sources=[])])
    cmd.run()
    assert cmd.extensions == []
    assert "mypyc (from mypy) is not installed" in capsys.readouterr().err


def test_a_failing_c_compiler_leaves_no_compiled_module(tmp_path, monkeypatch, capsys):
    """Two modules, the second of which does not compile: neither is left in the build (a
    mypyc module without its group's shared library would not import), and the build goes on."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "good.c").write_text(
        "#include <Python.h>\n"
        'static struct PyModuleDef m = {PyModuleDef_HEAD_INIT, "good"};\n'
        "PyMODINIT_FUNC PyInit_good(void) { return PyModule_Create(&m); }\n"
    )
    (tmp_path / "bad.c").write_text("this is not C\n")
    cmd = _build_ext(tmp_path, [Extension("good", ["good.c"]), Extension("bad", ["bad.c"])])
    cmd.run()
    assert "compiling the runtime to C failed" in capsys.readouterr().err
    assert not [p for p in (tmp_path / "lib").rglob("*") if p.is_file()]
    assert cmd.extensions == []


@pytest.mark.slow
def test_the_pure_python_runtime_passes_the_runtime_tests():
    """Where the installed runtime is compiled, its Python source (the checkout's) still passes
    tests/runtime: robots without a C compiler run it."""
    if not rt.COMPILED:
        pytest.skip("the installed runtime is the pure-Python one: the whole suite tests it")
    if any((ROOT / "scoopc" / "runtime").glob("*.so")):
        pytest.skip("the checkout holds a compiled runtime (built in place): its source is not run alone")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    code = "import scoopc.runtime as r, sys; sys.exit(0 if not r.COMPILED else 1)"
    assert subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, timeout=60).returncode == 0
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", "0", "tests/runtime"],
        env=env,
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-2000:]


def test_a_pure_build_ships_no_compiled_module_of_an_earlier_build(tmp_path, monkeypatch, capsys):
    """A build folder reused from a compiled build: when this build keeps pure Python (here: no
    mypyc), the compiled runtime left there is removed, or the wheel would ship it."""
    monkeypatch.setitem(sys.modules, "mypyc.build", None)
    cmd = _build_ext(tmp_path, [Extension(build_runtime.PLACEHOLDER, sources=[])])
    stale = [cmd.get_ext_fullpath(f"{build_runtime.GROUP}__mypyc"), cmd.get_ext_fullpath("scoopc.runtime.processor")]
    for path in stale:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        open(path, "wb").close()
    cmd.run()
    assert not [path for path in stale if os.path.exists(path)]
