"""Progress of building the standard library: a line per stage for any callback; on a terminal,
the command line's bar, one line of stderr redrawn with the stage and how far it has gone."""

import io

import pytest

from scoopc.cli import ProgressBar
from scoopc.progress import Steps


def build(progress):
    steps = Steps(progress, "compiling the standard library", ("checking", "generating Python"))
    steps.stage()
    steps.stage(4)
    for _ in range(4):
        steps.advance()
    steps.end()


def test_a_plain_callback_hears_one_line_per_stage():
    heard = []
    build(heard.append)
    title = "compiling the standard library"
    assert heard == [f"{title}: 1/2 checking", f"{title}: 2/2 generating Python"]


def test_the_bar_redraws_one_line_and_ends_it():
    stream = io.StringIO()
    build(ProgressBar(stream))
    text = stream.getvalue()
    assert text.endswith("\n") and text.count("\n") == 1
    frames = [frame.removeprefix("\x1b[K") for frame in text.rstrip("\n").split("\r") if frame]
    title = "scoopc: compiling the standard library"
    assert f"{title} [{'.' * 24}] 1/2 checking" in frames
    assert f"{title} [{'#' * 12}{'.' * 12}] 2/2 generating Python 2/4" in frames
    assert frames[-1] == f"{title} [{'#' * 24}] 2/2 generating Python 4/4"
    assert len(frames) == len(set(frames))  # a frame is drawn only when it changes


def test_nothing_is_drawn_for_nobody():
    build(None)  # no callback: no output, no error


def test_a_failing_stage_ends_the_bar_line_before_the_error_is_told():
    stream = io.StringIO()
    with pytest.raises(RuntimeError), Steps(ProgressBar(stream), "compiling", ("checking",)) as steps:
        steps.stage()
        raise RuntimeError("the library does not check")
    assert stream.getvalue().endswith("checking\n")
