"""Driver, `scoopc run --status [N]`: the runtime's processors and the wait conditions waited on
(scoopc/runtime/snapshot.py) as text on the run's stderr, on SIGUSR1 or every N seconds; and the
source text of a wait condition's clause, found from the program's .e files."""

from __future__ import annotations

import functools
import signal
import threading
from collections.abc import Callable, Sequence
from pathlib import Path

from ..runtime import snapshot
from ..runtime.protocols import Where
from ..runtime.sched import Runtime
from ..semantics.universe import stdlib_root


class ClauseSource:
    """A wait condition's position -> its clause's text (the line of the .e file it names, which
    generated code gives as the file's name only: looked up in the program's folders, then in the
    standard library's)."""

    def __init__(self, program_paths: Sequence[str]) -> None:
        self.roots = [Path(p) for p in program_paths] + [stdlib_root()]
        self._files: dict[str, Path] | None = None

    def __call__(self, where: Where) -> str | None:
        file, line = str(where[2]), where[3]
        path = Path(file) if Path(file).is_file() else self.files().get(Path(file).name)
        if path is None or not isinstance(line, int):
            return None
        lines = _lines(path)
        return lines[line - 1].strip() if 0 < line <= len(lines) else None

    def files(self) -> dict[str, Path]:
        if self._files is None:
            found: dict[str, Path] = {}
            for root in self.roots:
                candidates = [root] if root.is_file() else sorted(root.rglob("*.e")) if root.is_dir() else []
                for path in candidates:
                    found.setdefault(path.name, path)
            self._files = found
        return self._files


@functools.lru_cache(maxsize=256)
def _lines(path: Path) -> list[str]:
    try:
        return path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return []


class StatusPrinter:
    """`--status`: the status text on the run's stderr on SIGUSR1 (`every` 0), or every `every`
    seconds from a thread of its own, stopped by the run's shutdown hooks."""

    def __init__(self, every: float, clause_text: Callable[[Where], str | None]) -> None:
        self.every = every
        self.clause_text = clause_text
        self.stopped = threading.Event()
        self.thread: threading.Thread | None = None

    def attach(self, rt: Runtime) -> None:
        """On the run's start (the main thread, before the root object exists)."""
        if self.every > 0:
            self.thread = threading.Thread(target=self._run, args=(rt,), name="scoop-status", daemon=True)
            self.thread.start()
            with rt.glock:
                rt.shutdown_hooks.append(self.stop)
        elif hasattr(signal, "SIGUSR1") and threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGUSR1, lambda *_: self.print(rt))  # run_main restores its own at the end

    def print(self, rt: Runtime) -> None:
        rt.out.write_other(rt.stderr, snapshot.render(snapshot.take(rt, self.clause_text)))

    def _run(self, rt: Runtime) -> None:
        while not self.stopped.wait(self.every):
            self.print(rt)

    def stop(self) -> None:
        self.stopped.set()
        if self.thread is not None:
            self.thread.join()
