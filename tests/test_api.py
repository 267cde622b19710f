"""The Python API (scoopc.check, scoopc.compile, scoopc.run; docs/API.md): the same results as the
command line on the samples, result records instead of printed diagnostics, UsageError for
mistakes in the call."""

import io
import os
import subprocess
import sys

import pytest

import scoopc
from scoopc import cli
from scoopc.exits import Exit

from harness import ROOT

SAMPLES = ROOT / "samples"
# a sample with an .ecf (its C externals, say) is given as its .ecf, as its README says
PLAIN = sorted(
    next(iter(p.glob("*.ecf")), p)
    for p in SAMPLES.iterdir()
    if p.is_dir() and any(p.glob("*.e")) and not (p / "world.yaml").exists()
)
ROBOT = sorted(p for p in SAMPLES.iterdir() if (p / "world.yaml").exists())

BROKEN = """class
	BROKEN

create
	make

feature

	make
		do
			x := 1
		end

end
"""


def python_m(*argv, cwd=None):
    """`python -m scoopc ARGV` in a fresh interpreter: (status, stdout, stderr)."""
    done = subprocess.run(
        [sys.executable, "-m", "scoopc", *map(str, argv)],
        capture_output=True,
        text=True,
        cwd=cwd or ROOT,
        timeout=300,
        env=dict(os.environ),
    )
    return done.returncode, done.stdout, done.stderr


def cli_main(capsys, *argv):
    """The command line (what `python -m scoopc` runs), in this process: (status, stdout, stderr)."""
    status = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.slow  # every sample, checked twice: the full run's, not the quick selection's
@pytest.mark.parametrize("sample", PLAIN + ROBOT, ids=lambda p: p.name)
def test_check_agrees_with_the_command_line(sample, capsys):
    result = scoopc.check([sample])
    assert capsys.readouterr() == ("", "")  # the API prints nothing
    status, out, err = cli_main(capsys, "check", sample, "--format", "short")
    assert (result.status, out) == (status, "")
    assert [str(d) for d in result.diagnostics] == err.splitlines()


@pytest.mark.slow  # every plain sample, run twice
@pytest.mark.parametrize("sample", PLAIN, ids=lambda p: p.name)
def test_run_agrees_with_the_command_line(sample, capsys):
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([sample], virtual_clock=True, stdout=out, stderr=err)
    status, cli_out, _ = cli_main(capsys, "run", sample, "--virtual-clock")
    assert result.status == status == Exit.OK, err.getvalue()
    assert sorted(out.getvalue().splitlines()) == sorted(cli_out.splitlines())  # concurrent: order may vary


def test_python_m_scoopc_is_the_command_line():
    status, out, err = python_m("check", SAMPLES / "producer_consumer", "--format", "short")
    assert (status, out, err) == (Exit.OK, "", "")


def test_a_robot_sample_runs_on_the_simulator_through_the_api():
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([SAMPLES / "first_controller"], duration=5, stdout=out, stderr=err)
    assert result.status == Exit.OK, err.getvalue()
    assert result.sim is not None and result.sim.time == pytest.approx(5.0) and result.stopped_by == "duration"
    assert result.png is None  # no picture unless asked (png=True or a path)


def test_compile_writes_a_runnable_package(tmp_path):
    result = scoopc.compile([SAMPLES / "producer_consumer"], tmp_path / "out")
    assert result.status == Exit.OK and result.errors == []
    assert result.package == tmp_path / "out" / "producer_consumer"
    assert result.library == tmp_path / "out" / "eiffel_base"
    done = subprocess.run(
        [sys.executable, "-m", "producer_consumer"], cwd=tmp_path / "out", capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0 and "consumers took items adding up to" in done.stdout, done.stderr


def test_source_errors_come_back_as_diagnostics(tmp_path, capsys):
    source = tmp_path / "broken.e"
    source.write_text(BROKEN)
    for result in (scoopc.check([source]), scoopc.compile([source], tmp_path / "out"), scoopc.run([source])):
        assert result.status == Exit.SOURCE
        assert [d.code for d in result.diagnostics if d.is_error] == ["VEEN"]
    assert not (tmp_path / "out").exists()
    assert capsys.readouterr() == ("", "")  # the API prints nothing of its own


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: scoopc.check([]), "no PATH given"),
        (lambda: scoopc.check(["/nonexistent/x.e"]), "no such file or directory"),
        (lambda: scoopc.run([SAMPLES / "producer_consumer"], assertions="some"), "assertions must be one of"),
        (lambda: scoopc.run([SAMPLES / "producer_consumer"], robot="tank"), "robot must be sim, ros2 or none"),
        (lambda: scoopc.run([SAMPLES / "producer_consumer"], root="NOPE"), "root class NOPE is not among"),
    ],
)
def test_usage_mistakes_raise_usage_error(call, message):
    with pytest.raises(scoopc.UsageError, match=message):
        call()


def test_importing_scoopc_loads_no_compiler():
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys, scoopc; print(scoopc.__version__); "
            "print(sorted(m for m in sys.modules if m.startswith('scoopc')))",
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    version, loaded = done.stdout.splitlines()
    assert version == scoopc.__version__ and loaded == "['scoopc', 'scoopc.version']"


@pytest.mark.slow
def test_a_first_run_reports_its_slow_steps(tmp_path, monkeypatch):
    """With an empty cache and no library shipped (a checkout) the standard library is read and
    compiled (seconds): the progress callback hears of each stage before it starts; a second run
    has nothing slow to report."""
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")  # as in a checkout, even when the suite runs from a wheel
    heard = []
    out = io.StringIO()
    assert scoopc.run([SAMPLES / "parallel_sum"], progress=heard.append, stdout=out).status == Exit.OK
    assert [h.split(" (")[0] + h.split(":")[-1] for h in heard] == [
        "reading the standard library 1/2 parsing",
        "reading the standard library 2/2 preparing",
        "compiling the standard library 1/4 checking",
        "compiling the standard library 2/4 generating Python",
        "compiling the standard library 3/4 writing eiffel_base",
        "compiling the standard library 4/4 byte-compiling",
    ]
    heard.clear()
    assert scoopc.run([SAMPLES / "parallel_sum"], progress=heard.append, stdout=io.StringIO()).status == Exit.OK
    assert heard == []
