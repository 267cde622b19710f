"""Helpers shared by the benchmark modules: result checks, thread utilities, running a program,
compiling and running the dialect versions.

A benchmark module defines SIZES, ops(**params), baseline(**params) and scoop(**params);
each variant checks its own result and raises CheckFailed when it is wrong. For the compiled
variant (benchmarks/<name>/*.e, compiled by scoopc) it also defines program_args(**params),
the program's command-line arguments, and program_output(**params), the exact output of a
correct run.
"""

import io
import json
import os
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def use_scoopc():
    """Import scoopc as installed (a regular install's runtime may be compiled, docs/RUNTIME.md
    section 10), or as PYTHONPATH gives it (compare.py's trees); from this checkout only when
    it is not installed."""
    import importlib.util

    if importlib.util.find_spec("scoopc") is None and ROOT not in sys.path:
        sys.path.insert(0, ROOT)


class CheckFailed(AssertionError):
    """A benchmark computed a wrong result: its time must not be reported."""


def check(label, got, expected):
    """Fail loudly when `got` differs from `expected`."""
    if got != expected:
        raise CheckFailed(f"{label}: got {got!r}, expected {expected!r}")


def start_all(targets):
    """Start one thread per (callable, args) pair and return the threads."""
    threads = [threading.Thread(target=fn, args=args) for fn, args in targets]
    for thread in threads:
        thread.start()
    return threads


def join_all(threads):
    for thread in threads:
        thread.join()


def where(cls, routine, line):
    """A codegen-style source position constant for the runtime's reports."""
    return (cls, routine, "benchmarks/" + cls.lower() + ".e", line)


def run_program(root_cls, args):
    """Run a SCOOP program as generated code would (rt.run_main); fail unless it exits 0."""
    import scoopc.runtime as rt

    status = rt.run_main(root_cls, root_cls.make, args=args)
    if status != 0:
        raise CheckFailed(f"run_main returned status {status}")


# --- the dialect versions, compiled by scoopc -----------------------------------


class CompileFailed(Exception):
    """scoopc rejected or could not compile a benchmark's dialect version."""


def compiled_library():
    """Seconds to get scoopc's compiled standard library (compiled once per compiler version,
    then taken from scoopc's cache)."""
    use_scoopc()
    from scoopc import driver

    start = time.perf_counter()
    driver.compiled_library()
    return time.perf_counter() - start


def compile_benchmark(name, out_dir, assertions="none"):
    """Compile benchmarks/<name>/ with scoopc's API (parse, check, codegen; the standard library
    comes from scoopc's cache) into `out_dir`; write and return what a child needs to run it."""
    use_scoopc()
    from pathlib import Path

    from scoopc.driver import Compilation

    source = os.path.join(HERE, name)
    start = time.perf_counter()
    compilation = Compilation([source], assertions=assertions)
    errors = [d for d in compilation.checked.diagnostics if d.is_error]
    if errors:
        raise CompileFailed(f"{name}: {errors[0]}")
    package = "compiled_" + name
    compiled = compilation.write_package(Path(out_dir), package)
    info = {
        "path": str(compiled.folder),
        "base": str(compiled.library),
        "package": package,
        "root": compiled.root.key,
        "creator": compiled.root.creator,
        "assertions": assertions,
        "seconds": time.perf_counter() - start,
    }
    with open(os.path.join(out_dir, name + ".json"), "w") as f:
        json.dump(info, f)
    return info


def run_compiled(build_dir, name, module, params, on_start=None):
    """Run the compiled dialect version of benchmark `name` once in this process (as
    `scoopc run` does: the launcher, then rt.run_main); check its output; return its times.
    `on_start(rt)`: attached to the run as `scoopc run` attaches `--live` (benchmarks/live_cost.py)."""
    with open(os.path.join(build_dir, name + ".json")) as f:
        info = json.load(f)
    for path in (info["base"], info["path"]):
        if path not in sys.path:
            sys.path.insert(0, path)
    import importlib

    from scoopc.codegen.names import class_name, module_name
    from scoopc.kernel import launcher

    root = importlib.import_module(f"{info['package']}.{module_name(info['root'])}")
    root_cls = getattr(root, class_name(info["root"]))
    argv = [info["root"].lower()] + module.program_args(**params)
    out = io.StringIO()
    start, cpu = time.perf_counter(), time.process_time()
    status = launcher.main(root_cls, info["creator"], argv, stdout=out, on_start=on_start)
    seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
    if status != 0:
        raise CheckFailed(f"{name} compiled: exit status {status}")
    check(f"{name} compiled output", out.getvalue(), module.program_output(**params))
    return {"seconds": seconds, "cpu": cpu}
