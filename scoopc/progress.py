"""Progress of a long step in stages (reading or compiling the standard library: seconds, once per
compiler). The caller's `progress` callback hears one line as each stage begins ("compiling the
standard library: 2/4 generating Python"); a callback that draws a bar (the command line's, on a
terminal) has a `bar` method too, which hears how far the stage has gone, and an `end` method."""

from __future__ import annotations

from collections.abc import Callable, Sequence

Progress = Callable[[str], None] | None


class Steps:
    """The stages of one step, reported to `progress` (None: nobody listens)."""

    def __init__(self, progress: Progress, title: str, stages: Sequence[str]):
        self.progress, self.title, self.stages = progress, title, tuple(stages)
        self.index, self.done, self.total = -1, 0, 0

    def stage(self, total: int = 0) -> None:
        """The next stage begins; `total`: how many items it goes through (0: not counted)."""
        self.index += 1
        self.done, self.total = 0, total
        if self.progress is not None:
            self.progress(f"{self.title}: {self.index + 1}/{len(self.stages)} {self.stages[self.index]}")
        self._draw()

    def advance(self, count: int = 1) -> None:
        self.done += count
        self._draw()

    def end(self) -> None:
        finish = getattr(self.progress, "end", None)
        if finish is not None:
            finish()

    def __enter__(self) -> Steps:
        return self

    def __exit__(self, *exception: object) -> None:
        self.end()  # also when a stage fails: the bar's line is ended before the error is told

    def _draw(self) -> None:
        bar = getattr(self.progress, "bar", None)
        if bar is not None:
            bar(self.title, self.index, len(self.stages), self.stages[self.index], self.done, self.total)
