"""The language server's view of files: which program a file belongs to, and the standard
library's paths as this installation has them."""

from __future__ import annotations

from scoopc.lsp.analysis import program_paths
from scoopc.lsp.nodes import library_file
from scoopc.semantics.universe import stdlib_root


def test_a_file_belongs_to_the_ecf_above_it_else_to_its_folder(tmp_path):
    (tmp_path / ".git").mkdir()
    cluster = tmp_path / "app" / "src"
    cluster.mkdir(parents=True)
    (cluster / "a.e").write_text("class A end\n")
    assert program_paths(str(cluster / "a.e")) == (str(cluster),)
    (tmp_path / "app" / "app.ecf").write_text("<system/>\n")
    assert program_paths(str(cluster / "a.e")) == (str(tmp_path / "app" / "app.ecf"),)


def test_library_paths_of_another_copy_lead_to_this_one():
    here = stdlib_root() / "base" / "kernel" / "any.e"
    assert library_file(str(here)) == str(here)
    assert library_file("/elsewhere/checkout/stdlib/base/kernel/any.e") == str(here)
    assert library_file("/home/me/app/robot.e") == "/home/me/app/robot.e"
