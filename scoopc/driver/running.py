"""Driver, the run: a compiled program's package imported into this process and started on the
SCOOP runtime by the launcher, with a robot (the simulator or ROS 2) when it uses Roboscoop.
SIGINT, SIGTERM and SIGHUP end a run the same way (runtime.stop_signals)."""

from __future__ import annotations

import gc
import importlib
import os
import sys
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from ..codegen.names import class_name, module_name
from ..exits import UsageError
from ..kernel import launcher, link
from ..results import RunResult
from ..robots import runner
from ..robots.runner import RobotOptions
from ..runtime.sched import Runtime
from ..runtime.stop_signals import stop_on_signals
from .compilation import Compilation, CompiledProgram
from .packages import BASE_PACKAGE, DamagedCache, ensure_on_path, remove_cached
from .status import ClauseSource, StatusPrinter

if TYPE_CHECKING:
    from .live import Sampler


@dataclass
class RunOptions:
    """How the runtime runs the program (the run options of `scoopc run`)."""

    trace_processors: bool = False  # tag each output line with its processor ([P3] ...)
    strict: bool = False  # an exception lost in an asynchronous call fails the run
    virtual_clock: bool = False  # sleeps and timers on a clock that jumps when all wait
    debug: bool = False  # Python tracebacks too
    stdout: TextIO | None = None  # where the program's output goes (default: sys.stdout)
    stderr: TextIO | None = None  # where failures and scoopc's reports go (default: sys.stderr)
    status: float | None = None  # --status: the processors and waits on stderr on SIGUSR1 (0) or every N s
    live: int | None = None  # --live PORT: serve the Foxglove WebSocket protocol (docs/LIVE.md)


def run_compilation(
    compilation: Compilation, args: Sequence[str], options: RunOptions, robot: RobotOptions, use_cache: bool = True
) -> RunResult:
    """Compile (cached by content) and run. A cached package that does not load (a module deleted,
    truncated or garbled, bad bytecode) is compiled again, with a note on stderr: the program's
    first (cheap), then the standard library's too."""
    program = compilation.cached_program(use_cache=use_cache)
    for rebuild_library in (False, True):
        try:
            return run_program(program, args, options, robot, compilation.paths)
        except DamagedCache:
            if not rebuild_library:
                (options.stderr or sys.stderr).write(
                    "scoopc: note: the compiled program in scoopc's cache was "
                    "damaged (a module did not load): compiling it again\n"
                )
        program = recompiled(compilation, program, rebuild_library)
    return run_program(program, args, options, robot, compilation.paths)  # a third failure is a bug


def recompiled(compilation: Compilation, damaged: CompiledProgram, rebuild_library: bool) -> CompiledProgram:
    remove_cached(damaged.folder)
    again = Compilation(
        compilation.paths,
        target=compilation.target,
        root=compilation.root_option,
        assertions=compilation.assertions_option,
        progress=compilation.progress,
    )
    again.rebuild_library = rebuild_library
    return again.cached_program()


def run_program(
    program: CompiledProgram,
    args: Sequence[str],
    options: RunOptions,
    robot: RobotOptions,
    program_paths: Sequence[str] = (),
) -> RunResult:
    """Run `program` with the command-line arguments `args`; `program_paths` are its sources
    (where the simulator looks for world.yaml)."""
    with _collector_spared():
        return _run_program(program, args, options, robot, program_paths)


@contextmanager
def _collector_spared() -> Iterator[None]:
    """The program runs with the cyclic collector on, and what exists before it starts (the
    compiler's objects: a checked standard library is millions) stays out of the collector's
    passes while it runs (a pass over them costs half a second). They go back into them
    afterwards, unless the collector was off (the `scoopc` command's own process, cli.main,
    which then ends: the final collection at exit spares them too). Objects frozen already
    stay so (the language server's)."""
    enabled = gc.isenabled()
    freeze = not gc.get_freeze_count()
    if freeze:
        gc.freeze()
    gc.enable()
    try:
        yield
    finally:
        if not enabled:
            gc.disable()
        elif freeze:
            gc.unfreeze()


def _run_program(
    program: CompiledProgram,
    args: Sequence[str],
    options: RunOptions,
    robot: RobotOptions,
    program_paths: Sequence[str],
) -> RunResult:
    root_cls = load_root(program)
    argv = [program.root.key.lower(), *args]
    sys.stdout.flush()
    source = ClauseSource(program_paths)
    kind = robot.robot or ("sim" if program.roboscoop else "none")
    view = _sampler(options, source, robot.record if kind != "none" else None)
    watch = _watchers(options, source, view)

    def launch(
        on_start: Callable[[Runtime], None] | None = None, virtual_clock: bool | None = options.virtual_clock
    ) -> int:
        if watch:
            on_start = _chained(on_start, watch)
        return launcher.main(
            root_cls,
            program.root.creator,
            argv,
            shadowed=program.shadowed,
            trace_processors=options.trace_processors,
            strict=options.strict,
            virtual_clock=options.virtual_clock if virtual_clock is None else virtual_clock,
            debug=options.debug,
            on_start=on_start,
            stdout=options.stdout,
            stderr=options.stderr,
        )

    try:
        with stop_on_signals():  # SIGTERM and SIGHUP end a run the way Ctrl-C does
            if kind == "none":
                result = RunResult(launch())
            else:
                chosen = RobotOptions(**{**vars(robot), "robot": kind})
                result = runner.run(chosen, launch, list(program_paths), program.root.key, stderr=options.stderr)
    finally:
        if view is not None:
            view.close()
    _quiet_if_reader_gone()
    return result


def _sampler(options: RunOptions, source: ClauseSource, record: str | Path | None) -> Sampler | None:
    """`--live PORT`: the server, started before the run (a port in use is a usage error); and with
    `--record run.mcap`, the live channels in run.scoop.mcap beside it."""
    if options.live is None and not record:
        return None
    if options.live is not None and not 1 <= options.live <= 65535:
        raise UsageError(f"--live: not a port (1 to 65535): {options.live}")
    from . import live, live_record  # deferred: start-up (only a live or recorded run samples the runtime)

    sinks: list[live.Sink] = []
    if options.live is not None:
        sinks.append(live.FoxgloveServer(options.live, options.stderr))
    if record:
        sinks.append(live_record.JsonRecording(live_record.beside(record), options.stderr))
    return live.Sampler(source, sinks)


def _watchers(options: RunOptions, source: ClauseSource, view: Sampler | None) -> list[Callable[[Runtime], None]]:
    """What `--status` and `--live` attach to the runtime when the run starts."""
    found: list[Callable[[Runtime], None]] = []
    if view is not None:
        found.append(view.attach)
    if options.status is not None:
        found.append(StatusPrinter(options.status, source).attach)
    return found


Attach = Callable[[Runtime], None]  # a hook run when the runtime starts (`on_start`)


def _chained(first: Attach | None, more: list[Attach]) -> Attach:
    def on_start(rt: Runtime) -> None:  # ours first: the live view's wait for a client comes before the robot's clock
        for attach in more:
            attach(rt)
        if first is not None:
            first(rt)

    return on_start


def load_root(program: CompiledProgram) -> type:
    """The root class, from the program's package imported fresh (another program of the same
    package name may have run in this process before)."""
    ensure_on_path(program.library, program.folder)
    package = program.package
    for name in [m for m in sys.modules if m == package or m.startswith(package + ".")]:
        del sys.modules[name]
    link.forget(package)
    importlib.invalidate_caches()
    try:
        module = importlib.import_module(f"{package}.{module_name(program.root.key)}")
        root_class: type = getattr(module, class_name(program.root.key))
        return root_class
    except Exception as error:  # generated modules only define: a failure is damage
        for name in [m for m in sys.modules if m.split(".")[0] in (package, BASE_PACKAGE)]:
            del sys.modules[name]
        link.forget(package)
        link.forget(BASE_PACKAGE)
        raise DamagedCache(program.folder, error) from error


def _quiet_if_reader_gone() -> None:
    """Output piped into a reader that stopped (`| head`): no complaint at interpreter exit."""
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
