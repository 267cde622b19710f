"""The command line: help, exit codes, diagnostics on stderr, .ecf projects (DESIGN section 8)."""

import argparse
import os
import subprocess
import sys

import pytest

from scoopc import cli, cli_args
from scoopc.exits import Exit

from harness import ROOT

SAMPLE = ROOT / "samples" / "producer_consumer"


def test_every_subcommand_has_a_handler_and_every_handler_a_subcommand():
    """scoopc.cli_args builds the parser, scoopc.cli dispatches on the command's name."""
    (subcommands,) = [a for a in cli_args.build_parser()._actions if isinstance(a, argparse._SubParsersAction)]
    assert set(subcommands.choices) == set(cli.HANDLERS)


BROKEN = """class
	BROKEN

feature

	f (x: INTEGER)
		do
			if x > 0 then
				print (x)
		end

end
"""


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("argv", [["--help"], ["parse", "--help"], ["check", "--help"]])
def test_every_command_has_help(capsys, argv):
    with pytest.raises(SystemExit) as exited:
        cli.main(argv)
    assert exited.value.code == 0
    assert "usage: scoopc" in capsys.readouterr().out


def test_no_command_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as exited:
        cli.main([])
    assert exited.value.code == Exit.USAGE


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["check", "no/such/file.e"], "no such file or directory: no/such/file.e"),
        (["check", str(ROOT / "README.md")], "expected a .e file"),
        (["check"], "needs at least one PATH"),
        (["check", "--explain", "NO-SUCH-CODE"], "unknown diagnostic code"),
    ],
)
def test_usage_errors_exit_2_with_a_message(capsys, argv, fragment):
    code, out, err = run(capsys, *argv)
    assert code == Exit.USAGE and fragment in err and out == ""


def test_check_of_the_sample_is_clean(capsys):
    assert run(capsys, "check", str(SAMPLE)) == (0, "", "")


def test_parse_dump_prints_a_tree_on_stdout(capsys):
    code, out, err = run(capsys, "parse", "--dump", str(SAMPLE / "producer.e"))
    assert code == 0 and err == ""
    assert "PRODUCER" in out and "@" in out


def test_syntax_error_one_line_form_and_exit_1(capsys, tmp_path):
    (tmp_path / "broken.e").write_text(BROKEN)
    code, out, err = run(capsys, "check", "--format", "short", str(tmp_path / "broken.e"))
    assert code == Exit.SOURCE and out == ""
    first = err.splitlines()[0]
    assert first == f"{tmp_path / 'broken.e'}:8:4: error SYNTAX-END: missing `end` of the `if` opened at 8:4"


def test_pretty_form_shows_the_line_an_underline_and_a_hint(capsys, tmp_path):
    (tmp_path / "broken.e").write_text(BROKEN)
    code, _, err = run(capsys, "check", "--format", "pretty", str(tmp_path / "broken.e"))
    assert code == Exit.SOURCE
    assert "8 | \t\t\tif x > 0 then".expandtabs(1) in err and "^" in err and "hint:" in err and "1 error" in err


def test_unreadable_source_is_a_located_error(capsys, tmp_path):
    (tmp_path / "latin.e").write_bytes(b"class LATIN -- caf\xe9\nend\n")
    code, _, err = run(capsys, "check", "--format", "short", str(tmp_path / "latin.e"))
    assert code == Exit.SOURCE and "error SOURCE: cannot read" in err and "not UTF-8" in err


def test_explain_accepts_dashes_for_parentheses(capsys):
    code, out, _ = run(capsys, "check", "--explain", "vuta-3")
    assert code == 0 and out.startswith("VUTA(3): ") and "Wrong:" in out and "Fix:" in out


ECF = """<?xml version="1.0" encoding="ISO-8859-1"?>
<system xmlns="http://www.eiffel.com/developers/xml/configuration-1-16-0" name="pc" uuid="0">
	<target name="pc">
		<root class="producer_consumer" feature="make"/>
		<setting name="console_application" value="true"/>
		<capability><concurrency support="scoop"/></capability>
		<library name="base" location="$ISE_LIBRARY\\library\\base\\base.ecf"/>
		<library name="thread" location="$ISE_LIBRARY\\library\\thread\\thread.ecf"/>
		<cluster name="pc" location=".\\" recursive="true">
			<file_rule><exclude>/skipped$</exclude></file_rule>
		</cluster>
	</target>
</system>
"""


def _ecf_project(tmp_path):
    for file in SAMPLE.glob("*.e"):
        (tmp_path / file.name).write_text(file.read_text())
    (tmp_path / "skipped").mkdir()
    (tmp_path / "skipped" / "junk.e").write_text("this is not Eiffel")
    (tmp_path / "pc.ecf").write_text(ECF)
    return tmp_path / "pc.ecf"


def test_ecf_reads_root_clusters_and_notes_ignored_settings(capsys, tmp_path):
    from scoopc.project import collect

    project = collect([str(_ecf_project(tmp_path))])
    assert project.root.class_name == "PRODUCER_CONSUMER" and project.root.creation == "make"
    assert sorted(p.name for p in project.files) == sorted(p.name for p in SAMPLE.glob("*.e"))
    assert project.settings.concurrency == "scoop"
    notes = [d.message for d in project.notes]
    assert any("console_application" in n for n in notes) and project.libraries == ["base", "thread"]
    assert not project.errors
    code, out, err = run(capsys, "check", "--format", "short", str(tmp_path / "pc.ecf"))
    assert code == 0 and "note ECF-NOTE" in err


def test_ecf_unknown_target_is_an_error(capsys, tmp_path):
    code, _, err = run(capsys, "check", "--target", "nope", str(_ecf_project(tmp_path)))
    assert code == Exit.SOURCE and "has no target `nope`; its targets are: pc" in err


def test_internal_errors_are_not_blamed_on_the_user(capsys, monkeypatch):
    from scoopc.parse import parser

    def explode(source):
        raise RuntimeError("boom")

    monkeypatch.setattr(parser, "parse", explode)
    code, _, err = run(capsys, "check", str(SAMPLE))
    assert code == Exit.INTERNAL and "internal error" in err and "RuntimeError: boom" in err


def test_the_console_script_runs():
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", "check", str(SAMPLE)], capture_output=True, text=True, cwd=ROOT, timeout=120
    )
    assert done.returncode == 0, done.stderr


def test_malformed_ecf_is_located_at_the_xml_error(capsys, tmp_path):
    (tmp_path / "bad.ecf").write_text('<system name="x">\n\t<target name="t">\n\t\t<root class=APP/>\n')
    code, _, err = run(capsys, "check", "--format", "short", str(tmp_path / "bad.ecf"))
    assert code == Exit.SOURCE and f"{tmp_path / 'bad.ecf'}:3:15: error ECF: " in err


def test_semantic_errors_exit_1_each_with_its_code_and_a_hint(capsys, tmp_path):
    (tmp_path / "robot.e").write_text(
        "class ROBOT\ncreate\n\tmake\nfeature\n\tmotor: separate ROBOT\n\tmake\n\t\tdo\n"
        '\t\t\tcreate motor.make\n\t\t\tmotor.stop\n\t\t\tcount := "x"\n\t\tend\n'
        "\tstop do end\n\tcount: INTEGER\nend\n",
        encoding="utf-8",
    )
    code, _, err = run(capsys, "check", "--format", "pretty", str(tmp_path))
    assert code == Exit.SOURCE
    assert "robot.e:9:4: error VUTA(3)" in err and "robot.e:10:13: error VJAR" in err
    assert "hint: pass `motor` as an argument" in err and "2 errors" in err


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this platform")
def test_a_fifo_a_device_and_a_huge_file_are_reported_not_read(tmp_path, capsys):
    os.mkfifo(tmp_path / "fifo.e")  # reading it would block for ever
    (tmp_path / "zero.e").symlink_to("/dev/zero")  # reading it would never end
    with open(tmp_path / "huge.e", "wb") as huge:
        huge.truncate(17 * 2**20)  # sparse: no disk used
    for name, reason in (
        ("fifo.e", "not a regular file"),
        ("zero.e", "not a regular file"),
        ("huge.e", "larger than 16 MiB"),
    ):
        code, out, err = run(capsys, "check", str(tmp_path / name), "--format", "short")
        assert code == Exit.SOURCE and out == ""
        assert err.startswith(f"{tmp_path / name}:1:1: error SOURCE: cannot read {tmp_path / name}: {reason}")
