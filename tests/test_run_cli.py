"""`scoopc compile` and `scoopc run`: root selection, exit codes, arguments and stdin, Eiffel
traces of run-time failures, a compiled package runnable with `python -m` (DESIGN section 8)."""

import os
import subprocess
import sys

import pytest

from scoopc import cli
from scoopc.exits import Exit

HELLO = """class
	HELLO

create
	make

feature

	make
		do
			print ("Hello, " + (create {ARGUMENTS}).argument_count.out + " arguments%N")
			if (create {ARGUMENTS}).argument_count > 0 then
				print ((create {ARGUMENTS}).argument (1) + "%N")
			end
		end

end
"""

FAILING = """class
	FAILING

create
	make

feature

	make
		do
			withdraw (5)
		end

	withdraw (n: INTEGER)
		require
			positive: n < 0
		do
		end

end
"""

READER = """class
	READER

create
	make

feature

	make
		do
			io.read_line
			print ("read: " + io.last_string + "%N")
		end

end
"""


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_run_prints_what_the_program_prints_and_passes_arguments(tmp_path, capsys):
    path = write(tmp_path, "hello.e", HELLO)
    assert run(capsys, "run", path) == (0, "Hello, 0 arguments\n", "")
    assert run(capsys, "run", path, "--", "world") == (0, "Hello, 1 arguments\nworld\n", "")


def test_a_contract_violation_exits_3_with_an_eiffel_trace(tmp_path, capsys):
    code, out, err = run(capsys, "run", write(tmp_path, "failing.e", FAILING))
    assert code == Exit.RUNTIME and out == ""
    assert "precondition violated: `positive`" in err
    assert "in FAILING.withdraw (failing.e:" in err and "called by FAILING.make (failing.e:11)" in err
    assert "Traceback" not in err


def test_debug_adds_the_python_traceback(tmp_path, capsys):
    code, _, err = run(capsys, "run", "--debug", write(tmp_path, "failing.e", FAILING))
    assert code == Exit.RUNTIME and "Traceback" in err


def test_source_errors_exit_1_without_running(tmp_path, capsys):
    path = write(tmp_path, "broken.e", HELLO.replace("print (", "prin ("))
    code, out, err = run(capsys, "run", path)
    assert code == Exit.SOURCE and out == "" and "VEEN" in err


def test_an_unknown_root_is_a_usage_error(tmp_path, capsys):
    path = write(tmp_path, "hello.e", HELLO)
    code, _, err = run(capsys, "run", "--root", "NOPE", path)
    assert code == Exit.USAGE and "root class NOPE" in err
    code, _, err = run(capsys, "run", "--root", "HELLO.go", path)
    assert code == Exit.USAGE and "not a creation procedure of HELLO" in err


def test_arguments_after_dashes_belong_to_run_only(capsys):
    with pytest.raises(SystemExit) as exited:
        cli.main(["check", "x.e", "--", "y"])
    assert exited.value.code == Exit.USAGE


def test_run_reads_standard_input(tmp_path, capsys, monkeypatch):
    import io

    monkeypatch.setattr(sys, "stdin", io.StringIO("a line\nmore\n"))
    assert run(capsys, "run", write(tmp_path, "reader.e", READER)) == (0, "read: a line\n", "")


def test_compile_writes_a_package_runnable_with_python_m(tmp_path, capsys):
    path = write(tmp_path, "hello.e", HELLO)
    out_dir = tmp_path / "out"
    code, out, err = run(capsys, "compile", path, "-o", str(out_dir))
    assert code == 0 and out == "" and "python -m hello" in err
    assert (out_dir / "hello" / "hello.py").exists() and (out_dir / "eiffel_base" / "string_8.py").exists()
    assert not list(out_dir.rglob("__pycache__"))  # readable output only: no bytecode copied
    done = subprocess.run(
        [sys.executable, "-m", "hello", "x"],
        cwd=out_dir,
        capture_output=True,
        text=True,
        env=dict(os.environ),
        timeout=120,
    )
    assert (done.returncode, done.stdout) == (0, "Hello, 1 arguments\nx\n"), done.stderr


def test_a_second_run_uses_the_cached_compilation(tmp_path, capsys, monkeypatch):
    from scoopc import pipeline

    path = write(tmp_path, "hello.e", HELLO)
    assert run(capsys, "run", path)[0] == 0
    monkeypatch.setattr(pipeline, "check_project", lambda *a, **k: pytest.fail("checked again"))
    assert run(capsys, "run", path) == (0, "Hello, 0 arguments\n", "")


def test_cached_packages_are_byte_compiled_once(tmp_path, capsys, monkeypatch):
    """The cache holds .pyc files beside the library and the program, written when they are
    compiled: a run never compiles Python again, even where Python writes no bytecode itself."""
    from scoopc.driver import BASE_PACKAGE, compiled_library

    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")  # the library in the cache, even when the suite runs from a wheel
    path = write(tmp_path, "hello.e", HELLO)
    assert run(capsys, "run", path)[0] == 0
    base = compiled_library().path / BASE_PACKAGE
    assert len(list((base / "__pycache__").glob("string_8.*.pyc"))) == 1
    programs = list((tmp_path / "cache").rglob("program/__pycache__/hello.*.pyc"))
    assert len(programs) == 1
    done = subprocess.run(
        [sys.executable, "-v", "-m", "scoopc", "run", path],
        capture_output=True,
        text=True,
        env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"),
        timeout=120,
    )
    assert done.stdout == "Hello, 0 arguments\n", done.stderr[-2000:]
    loaded = [line for line in done.stderr.splitlines() if line.startswith("# code object from")]
    assert any("eiffel_base/__pycache__/string_8." in line for line in loaded)  # the library's bytecode
    assert any("program/__pycache__/hello." in line for line in loaded)  # the program's
