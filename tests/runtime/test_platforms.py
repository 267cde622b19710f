"""Supported platforms (docs/GUARANTEES.md): Linux, and macOS and Windows on students' laptops.
Code paths that use POSIX-only facilities fall back when the platform lacks them; these tests take
the facility away (as Windows lacks it) and check that the path still works."""

import os
import signal

import pytest

from scoopc.runtime import stop_signals
from scoopc.runtime.main import _install_dump_signal
from scoopc.source import SourceFile


def test_stop_signals_without_sighup_install_the_others_and_restore_them(monkeypatch):
    monkeypatch.delattr(signal, "SIGHUP", raising=False)  # Windows has no SIGHUP
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    with stop_signals.stop_on_signals():
        assert signal.getsignal(signal.SIGINT) is stop_signals._handler
        assert signal.getsignal(signal.SIGTERM) is stop_signals._handler
        with pytest.raises(stop_signals.Stopped) as caught:
            signal.raise_signal(signal.SIGTERM)
        assert caught.value.status == 128 + signal.SIGTERM
    assert {s: signal.getsignal(s) for s in before} == before


def test_without_sigusr1_there_is_no_dump_signal_and_nothing_breaks(monkeypatch):
    monkeypatch.delattr(signal, "SIGUSR1", raising=False)  # Windows has no SIGUSR1
    restore = _install_dump_signal(object())
    assert restore() is None


def test_source_files_are_read_without_o_nonblock(tmp_path, monkeypatch):
    monkeypatch.delattr(os, "O_NONBLOCK", raising=False)  # Windows has no O_NONBLOCK
    path = tmp_path / "a.e"
    path.write_text("class A end\n")
    assert SourceFile.read(path).text == "class A end\n"


def test_a_stop_signal_during_a_shielded_step_is_dropped_without_sighup(monkeypatch):
    monkeypatch.delattr(signal, "SIGHUP", raising=False)
    with stop_signals.stop_on_signals(), stop_signals.shielded():
        signal.raise_signal(signal.SIGINT)
    assert "SIGINT" in stop_signals._State.ignored
