"""The program entry point for generated code: run the root creation procedure as the root
processor on the main thread, wait for termination, and shut down (Ctrl-C, deadlock,
failure) with every thread joined and every failure reported."""
import signal
import threading
import traceback

from ..exits import Exit
from .errors import Shutdown, fmt_where
from .monitor import Monitor, dump
from .processor import RUNNING, Processor
from .sched import Exec, Runtime
from .stop_signals import Stopped, status_of

_current = None        # the runtime of the running program (one at a time)


def current():
    if _current is None:
        raise RuntimeError("no SCOOP runtime is running (use rt.run_main or rt.start)")
    return _current


def start(**options):
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


def finish(rt, root, interrupted=None):
    """The root routine returned (or was interrupted: `interrupted` is the KeyboardInterrupt):
    wait for quiescence, shut down, return the exit status."""
    global _current
    ex = root.exec
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
    rt.stop()
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


def run_main(root_cls, creator, args=(), describe=None, on_start=None, **options):
    """Run a program: `creator(root_object, *args)` on the root processor. Exit status.
    `describe(exception, processor)`: the text reporting an uncaught exception (default: the
    exception and the processor's innermost frame). `on_start(rt)`: called on the root's thread
    once the runtime exists, before the root object is created (to attach a simulator, say)."""
    rt, root = start(**options)
    rt.describe = describe
    restore = _install_dump_signal(rt)
    interrupted = None
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


def _uncaught(e, proc):
    where = f" in {fmt_where(proc.frames[-1])}" if proc.frames else ""
    text = "".join(traceback.format_exception_only(type(e), e)).strip()
    return f"uncaught exception on {proc!r}{where}: {text}"


def _run_hooks(rt):
    with rt.glock:
        hooks = list(reversed(rt.shutdown_hooks))
    for fn in hooks:
        try:
            fn()
        except Exception as e:     # a failing hook must not stop the others
            rt.stderr.write(f"scoopc: shutdown hook {fn!r} failed: {e!r}\n")


def _install_dump_signal(rt):
    if threading.current_thread() is not threading.main_thread() or \
            not hasattr(signal, "SIGUSR1"):
        return lambda: None
    old = signal.signal(signal.SIGUSR1, lambda *_: rt.stderr.write(dump(rt)))
    return lambda: signal.signal(signal.SIGUSR1, old)
