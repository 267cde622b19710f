"""`scoopc run --status [N]`: the processors and the wait conditions waited on, as text on stderr,
every N seconds or on SIGUSR1 (tests/live/waits: a consumer waits until the root fills a cell)."""

import io
import os
import signal
import threading
import time
from pathlib import Path

import pytest

import scoopc
from scoopc import cli
from scoopc.exits import Exit
from scoopc.runtime import main as runtime_main, snapshot

WAITS = Path(__file__).parent / "waits"
WAIT_LINE = "CONSUMER.consume (consumer.e"  # relative to the program's folder


def _wait_line(err: str) -> list[str]:
    return [line for line in err.splitlines() if line.startswith("  wait: P3 in CONSUMER.consume")]


def test_status_every_n_seconds_names_the_wait_condition_and_its_clause(capsys):
    code = cli.main(["run", str(WAITS), "--status", "0.1", "--", "1500"])
    out, err = capsys.readouterr()
    assert code == Exit.OK and out == "consumed 1\n"
    waits = _wait_line(err)
    assert waits, err
    assert waits[0].startswith(f"  wait: P3 in {WAIT_LINE}:22): has_value: c.value > 0 is false, for ")
    assert "  P3(CONSUMER) waiting on a wait condition: wait condition has_value over P2(CELL)" in err
    assert "  P1(APP) sleeping, 0 queued" in err


def _signal_once_waiting() -> None:
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        rt = runtime_main._current
        if rt is not None and snapshot.take(rt).waits:
            os.kill(os.getpid(), signal.SIGUSR1)
            return
        time.sleep(0.01)


@pytest.mark.slow
@pytest.mark.skipif(not hasattr(signal, "SIGUSR1"), reason="no SIGUSR1 on this platform")
def test_status_on_sigusr1(capsys):
    sender = threading.Thread(target=_signal_once_waiting)
    sender.start()
    code = cli.main(["run", str(WAITS), "--status", "--", "3000"])
    sender.join()
    _, err = capsys.readouterr()
    assert code == Exit.OK
    assert len(_wait_line(err)) == 1, err
    assert "scoop runtime dump" not in err


def test_status_refuses_a_period_that_is_not_a_number(capsys):
    with pytest.raises(SystemExit) as ended:
        cli.main(["run", "--status", str(WAITS)])
    assert ended.value.code == Exit.USAGE
    assert "put --status after the program's paths" in capsys.readouterr().err


def test_live_refuses_a_value_that_is_not_a_port(capsys):
    with pytest.raises(SystemExit) as ended:
        cli.main(["run", str(WAITS), "--live", "70000"])
    assert ended.value.code == Exit.USAGE
    assert "not a port (1 to 65535): '70000'" in capsys.readouterr().err


def test_the_api_takes_status_as_the_command_line_does():
    err = io.StringIO()
    result = scoopc.run([WAITS], ["600"], status=0.05, stdout=io.StringIO(), stderr=err)
    assert result.status == Exit.OK
    assert _wait_line(err.getvalue()), err.getvalue()
