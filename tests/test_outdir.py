"""`scoopc compile -o DIR` never deletes or overwrites what scoopc did not write (outdir.py): a folder
without scoopc's marker, or with files the marker does not list, is left exactly as it was."""

import pytest

from scoopc import cli, outdir

HELLO = """class
	HELLO

create
	make

feature

	make
		do
			print ("hi%N")
		end

end
"""


def snapshot(folder):
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def compile_(capsys, source, out):
    code = cli.main(["compile", str(source), "-o", str(out)])
    return code, capsys.readouterr().err


@pytest.fixture
def project(tmp_path, monkeypatch):
    """hello/hello.e in a fresh folder, which is the working directory."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "hello").mkdir()
    (tmp_path / "hello" / "hello.e").write_text(HELLO)
    (tmp_path / "hello" / "notes.txt").write_text("mine")
    return tmp_path


def test_compiling_into_the_sources_parent_keeps_the_sources(project, capsys):
    before = snapshot(project)
    code, err = compile_(capsys, "hello", ".")
    assert code == 2
    assert "hello exists and was not written by scoopc" in err and "Traceback" not in err
    assert snapshot(project) == before  # nothing deleted, nothing written


def test_an_unmarked_eiffel_base_folder_is_left_alone(project, capsys):
    (project / "out" / "eiffel_base").mkdir(parents=True)
    (project / "out" / "eiffel_base" / "mine.py").write_text("x = 1\n")
    code, err = compile_(capsys, "hello", "out")
    assert code == 2 and "eiffel_base exists and was not written by scoopc" in err
    assert not (project / "out" / "hello").exists()  # checked before anything is written
    assert (project / "out" / "eiffel_base" / "mine.py").read_text() == "x = 1\n"


def test_a_second_compile_replaces_its_own_output(project, capsys):
    assert compile_(capsys, "hello", "out")[0] == 0
    package = project / "out" / "hello"
    assert (package / outdir.MARKER).exists() and (project / "out" / "eiffel_base" / outdir.MARKER).exists()
    written = outdir.check(package)
    (package / "stale.py").write_text("")  # pretend an earlier compile wrote a module ...
    outdir.mark(package)  # ... and listed it
    assert outdir.check(package) == written | {"stale.py"}
    assert compile_(capsys, "hello", "out")[0] == 0
    assert not (package / "stale.py").exists() and (package / "hello.py").exists()


def test_a_file_added_to_the_output_stops_the_next_compile(project, capsys):
    assert compile_(capsys, "hello", "out")[0] == 0
    (project / "out" / "hello" / "mine.txt").write_text("keep me")
    before = snapshot(project / "out")
    code, err = compile_(capsys, "hello", "out")
    assert code == 2 and "holds files scoopc did not write (mine.txt)" in err
    assert snapshot(project / "out") == before


def test_output_that_is_a_file_or_a_link_is_refused(project, capsys):
    (project / "afile").write_text("data")
    code, err = compile_(capsys, "hello", "afile")
    assert code == 2 and "-o afile: is a file, not a folder" in err
    assert (project / "afile").read_text() == "data"
    (project / "out").mkdir()
    (project / "out" / "hello").symlink_to(project / "hello")
    code, err = compile_(capsys, "hello", "out")
    assert code == 2 and "is not a folder scoopc wrote" in err
    assert (project / "hello" / "hello.e").read_text() == HELLO


def test_a_marker_cannot_name_files_outside_its_folder(project, capsys):
    victim = project / "hello" / "hello.e"
    package = project / "out" / "hello"
    package.mkdir(parents=True)
    (package / outdir.MARKER).write_text(f'{{"files": ["../../hello/hello.e", "{victim}"]}}')
    assert compile_(capsys, "hello", "out")[0] == 0
    assert victim.read_text() == HELLO
