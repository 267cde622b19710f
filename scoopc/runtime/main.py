"""The program entry point for generated code: run the root creation procedure as the root
processor on the main thread, wait for termination, and shut down (Ctrl-C, deadlock,
failure) with every thread joined and every failure reported."""

from __future__ import annotations

import signal
import threading
import traceback
from collections.abc import Callable
from typing import TYPE_CHECKING, TextIO, TypedDict

from ..exits import Exit
from .errors import Shutdown, fmt_where
from .externals import interrupted_lines
from .monitor import Monitor, dump
from .processor import Processor
from .protocols import Args, Routine, Separate
from .sched import Exec, Runtime
from .session import RUNNING
from .stop_signals import Stopped, status_of

if TYPE_CHECKING:
    from typing_extensions import Unpack  # in typing from Python 3.11

_current: Runtime | None = None  # the runtime of the running program (one at a time)


class Options(TypedDict, total=False):
    """The keyword options of `start` and `run_main`: those of `Runtime`."""

    virtual_clock: bool
    trace_processors: bool
    strict: bool
    stdout: TextIO | None
    stderr: TextIO | None
    deadlock_tick: float


def current() -> Runtime:
    if _current is None:
        raise RuntimeError("no SCOOP runtime is running (use rt.run_main or rt.start)")
    return _current


def start(**options: Unpack[Options]) -> tuple[Runtime, Processor]:
    """Create the runtime and the root processor, run by the calling thread. For tests and
    embedding; `run_main` is start + root creation + finish."""
    global _current
    rt = Runtime(**options)
    _current = rt
    root = Processor(rt, name="ROOT")
    ex = Exec("main")
    root.exec = ex
    root.state = RUNNING
    with rt.glock:
        rt.n_running += 1
    rt.permits.acquire(ex)
    rt.monitor = Monitor(rt)
    rt.monitor.start()
    return rt, root


def finish(rt: Runtime, root: Processor, interrupted: KeyboardInterrupt | None = None) -> int:
    """The root routine returned (or was interrupted: `interrupted` is the KeyboardInterrupt):
    wait for quiescence, shut down, return the exit status."""
    global _current
    ex = root.exec
    assert ex is not None, "the root processor runs on the main thread"
    root.unclaim()
    rt.leave_running(ex)
    try:
        if not interrupted:
            rt.wait_quiet()
    except KeyboardInterrupt as e:
        interrupted = e
    status = status_of(interrupted) if interrupted else 0
    if isinstance(interrupted, Stopped):
        rt.stderr.write(f"scoopc: stopped by {interrupted.signal_name}\n")
    if interrupted:
        for line in interrupted_lines(rt):
            rt.stderr.write(line + "\n")
    rt.stop()
    assert rt.monitor is not None, "set by `start`"
    rt.monitor.stop()
    _run_hooks(rt)
    alive = rt.join_workers()
    rt.clock.join(1.0)
    rt.out.flush()
    for message, _exc in rt.failures:
        rt.stderr.write(f"scoopc: run-time failure: {message}\n")
    if alive:
        shown = ", ".join(alive[:5]) + (f" and {len(alive) - 5} more" if len(alive) > 5 else "")
        rt.stderr.write(f"scoopc: still busy at exit, ended with the process: {shown}\n")
    _current = None
    if rt.failures and status == 0:
        status = Exit.RUNTIME
    return status


def run_main(
    root_cls: type[Separate],
    creator: Routine | None,
    args: Args = (),
    describe: Callable[[BaseException, Processor], str] | None = None,
    on_start: Callable[[Runtime], object] | None = None,
    **options: Unpack[Options],
) -> int:
    """Run a program: `creator(root_object, *args)` on the root processor. Exit status.
    `describe(exception, processor)`: the text reporting an uncaught exception (default: the
    exception and the processor's innermost frame). `on_start(rt)`: called on the root's thread
    once the runtime exists, before the root object is created (to attach a simulator, say)."""
    rt, root = start(**options)
    rt.describe = describe
    restore = _install_dump_signal(rt)
    interrupted: KeyboardInterrupt | None = None
    try:
        if on_start is not None:
            on_start(rt)
        obj = root.new(root_cls)
        root.name = root_cls.__name__
        if creator is not None:
            creator(obj, *args)
    except Shutdown:
        pass
    except KeyboardInterrupt as e:
        interrupted = e
    except BaseException as e:
        rt.fail((describe or _uncaught)(e, root), e)
    try:
        return finish(rt, root, interrupted)
    finally:
        restore()


def _uncaught(e: BaseException, proc: Processor) -> str:
    where = f" in {fmt_where(proc.frames[-1])}" if proc.frames else ""
    text = "".join(traceback.format_exception_only(type(e), e)).strip()
    return f"uncaught exception on {proc!r}{where}: {text}"


def _run_hooks(rt: Runtime) -> None:
    with rt.glock:
        hooks = list(reversed(rt.shutdown_hooks))
    for fn in hooks:
        try:
            fn()
        except Exception as e:  # a failing hook must not stop the others
            rt.stderr.write(f"scoopc: shutdown hook {fn!r} failed: {e!r}\n")


def _install_dump_signal(rt: Runtime) -> Callable[[], object]:
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "SIGUSR1"):
        return lambda: None
    old = signal.signal(signal.SIGUSR1, lambda *_: rt.stderr.write(dump(rt)))
    return lambda: signal.signal(signal.SIGUSR1, old)
