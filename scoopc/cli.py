"""The `scoopc` command: arguments -> driver calls; diagnostics and failures -> stderr and an exit
code (scoopc.exits: 0 success, 1 source errors, 2 bad usage, 3 run-time failure, 4 internal
error of scoopc, reported with its Python traceback). No other module imports this one.
"""

from __future__ import annotations

import argparse
import gc
import sys
import traceback
from collections.abc import Callable, Sequence
from pathlib import Path

from . import diagnostics
from .cli_args import PATHS_HELP, _add_run_options, _Parser, build_parser
from .exits import Exit, SourceErrors, UsageError
from .runtime.stop_signals import status_of
from .version import __version__

# ---- commands ------------------------------------------------------------------------------------


def _compilation(args: argparse.Namespace, **options):
    from .driver import Compilation  # deferred: `scoopc --help` and `parse` need no code generator

    if not args.paths:
        raise UsageError(f"`scoopc {args.command}` needs at least one PATH ({PATHS_HELP})")
    return Compilation(args.paths, target=args.target, progress=_progress(), **options)


def _command_parse(args: argparse.Namespace) -> int:
    parsed = _compilation(args).parsed
    _render(parsed.diagnostics, parsed.line_text, args.format)
    if args.dump:
        from . import syntax  # deferred: only --dump prints trees

        for unit in parsed.units:
            if unit.tree is not None:
                sys.stdout.write(syntax.dump(unit.tree).rstrip("\n") + "\n")
    return Exit.SOURCE if parsed.has_errors else Exit.OK


def _command_check(args: argparse.Namespace) -> int:
    if args.explain is not None:
        return _explain(args.explain)
    checked = _compilation(args).checked
    _render(checked.diagnostics, checked.line_text, args.format, checked=len(checked.units))
    return Exit.SOURCE if checked.has_errors else Exit.OK


def _explain(code: str) -> int:
    from . import explain  # deferred: the explanation table is large (start-up)

    if not code.strip():
        print(explain.listing())
        return Exit.OK
    text = explain.explain(code)
    if text is None:
        close = explain.suggestions(code)
        advice = f"; did you mean {' or '.join(f'`{c}`' for c in close)}?" if close else ""
        raise UsageError(f"unknown diagnostic code `{code}`{advice} (`scoopc check --explain` lists them all)")
    print(text)
    return Exit.OK


def _command_compile(args: argparse.Namespace) -> int:
    compilation = _compilation(args, root=args.root, assertions=args.assertions)
    try:
        compilation.require_clean()
    finally:
        _render(compilation.checked.diagnostics, compilation.checked.line_text, args.format)
    program = compilation.compile_to(args.output)
    robot = f" (on the simulator; `python -m {program.package} --help` for the robot options)"
    print(
        f"scoopc: wrote {program.folder / program.package} and {program.folder / 'eiffel_base'}; run it with: "
        f"cd {program.folder} && python -m {program.package}{robot if program.roboscoop else ''}",
        file=sys.stderr,
    )
    return Exit.OK


def _command_run(args: argparse.Namespace, program_args: Sequence[str]) -> int:
    from .driver import run_compilation  # deferred: the code generator (start-up)

    compilation = _compilation(args, root=args.root, assertions=args.assertions)
    options, robot = _run_options(args)
    try:
        compilation.cached_program(use_cache=not args.no_cache)
    finally:
        if compilation.was_checked:  # checked now, not taken from the cache
            _render(compilation.checked.diagnostics, compilation.checked.line_text, args.format)
    return run_compilation(compilation, program_args, options, robot).status


def _run_options(args: argparse.Namespace):
    """The run options and the robot options `_add_run_options` parsed: (RunOptions, RobotOptions)."""
    from .driver import RunOptions  # deferred: the code generator (start-up)
    from .robots.runner import RobotOptions  # deferred: the robot side (start-up)

    options = RunOptions(
        args.trace_processors, args.strict, args.virtual_clock, args.debug, status=args.status, live=args.live
    )
    robot = RobotOptions(
        args.robot,
        args.world,
        args.namespace,
        args.realtime or args.live is not None,
        args.duration,
        args.goal,
        None if args.no_png else (args.png or True),
        args.gif,
        args.record,
        ros_distro=args.ros_distro,
        use_sim_time=args.use_sim_time,
        wait_robot=args.wait_robot,
        require_robot=args.require_robot,
        profile=args.profile,
        node_name=args.node_name,
    )
    return options, robot


def _command_lsp(args: argparse.Namespace) -> int:
    from .lsp import server  # deferred: pygls and the checker load only for the server (start-up)

    return server.main()


def _command_test(args: argparse.Namespace) -> int:
    from .driver import TestOptions, run_tests  # deferred: the code generator (start-up)

    compilation = _compilation(args, assertions=args.assertions)
    options = TestOptions(
        args.pattern,
        args.timeout,
        args.junit,
        args.debug,
        _show_outcome,
        lambda: _render(compilation.checked.diagnostics, compilation.checked.line_text, args.format),
    )
    result = run_tests(compilation, options)
    for outcome in result.failed:
        _show_failure(outcome)
    print(result.summary(), flush=True)
    if result.junit:
        print(f"scoopc: JUnit XML written to {result.junit}", file=sys.stderr)
    return result.status


def _show_outcome(outcome) -> None:
    verdict = {"passed": "ok", "failed": "FAILED", "timeout": "TIMED OUT"}[outcome.status]
    print(f"{outcome.name} ... {verdict} ({outcome.seconds:.2f} s)", flush=True)


def _show_failure(outcome) -> None:
    print(f"\n==== {outcome.name} ({outcome.file}:{outcome.line}) ====")
    print(outcome.report)
    if outcome.output:
        print("---- its output ----")
        print(outcome.output.rstrip("\n"))
    print()


def _command_cache(args: argparse.Namespace) -> int:
    from .driver import cache  # deferred: only this command needs it (start-up)
    from .semantics.library import cache_dir  # deferred: as above

    if args.all and args.action != "clean":
        raise UsageError("--all goes with `scoopc cache clean`")
    limit = cache.cache_limit()
    if args.action == "clean":
        removed = cache.clean(everything=args.all)
        freed = sum(entry.size for entry in removed)
        print(
            f"scoopc: removed {len(removed)} cache entr{'y' if len(removed) == 1 else 'ies'} ({cache.size_text(freed)})"
        )
    print(cache.describe(cache.entries(), cache_dir(), limit))
    return Exit.OK


def _command_msg(args: argparse.Namespace) -> int:
    from .robots.eiffel_messages import command_msg  # deferred: loads the ROS 2 type store

    return command_msg(args)


# ---- rendering -----------------------------------------------------------------------------------


def _render(found: list, line_text: Callable[[str, int], str], style: str, checked: int | None = None) -> None:
    """The diagnostics on stderr; in the pretty form, then the count of errors, or with `checked`
    (`scoopc check`) one closing line even when all is well: "12 classes checked, no errors"."""
    pretty = style == "pretty" or (style == "auto" and sys.stderr.isatty())
    color = pretty and sys.stderr.isatty()
    for d in found:
        text = diagnostics.pretty(d, line_text, color) if pretty else diagnostics.short(d)
        print(text, file=sys.stderr)
    errors = sum(1 for d in found if d.is_error)
    warnings = sum(1 for d in found if d.severity == diagnostics.WARNING)
    counted = f"{errors} error{'s' if errors != 1 else ''}" if errors else "no errors"
    if warnings:
        counted += f", {warnings} warning{'s' if warnings != 1 else ''}"
    if pretty and checked is not None:
        print(f"{checked} class{'es' if checked != 1 else ''} checked, {counted}", file=sys.stderr)
    elif errors and pretty:
        print(counted, file=sys.stderr)


def _progress() -> Callable[[str], None] | None:
    """Progress of long steps on stderr, on a terminal only (stderr stays clean otherwise)."""
    return ProgressBar(sys.stderr) if sys.stderr.isatty() else None


class ProgressBar:
    """One line of stderr, rewritten in place: a step's title, its stage (2/4 generating Python)
    and a bar of how far the stage has gone (progress.Steps draws through `bar`)."""

    WIDTH = 24

    def __init__(self, stream) -> None:
        self.stream = stream
        self.shown = ""

    def __call__(self, message: str) -> None:
        self._show(message)

    def bar(self, title: str, index: int, stages: int, stage: str, done: int, total: int) -> None:
        filled = self.WIDTH * min(done, total) // total if total else 0
        count = f" {done}/{total}" if total else ""
        self._show(f"{title} [{'#' * filled}{'.' * (self.WIDTH - filled)}] {index + 1}/{stages} {stage}{count}")

    def end(self) -> None:
        if self.shown:
            self.stream.write("\n")
            self.stream.flush()
            self.shown = ""

    def _show(self, text: str) -> None:
        if text != self.shown:
            self.stream.write(f"\r\033[Kscoopc: {text}")
            self.stream.flush()
            self.shown = text


ONE_SHOT = ("check", "compile", "run")  # commands that compile, then end (or run the program)


def main(argv: Sequence[str] | None = None) -> int:
    """The command line: `argv`, else (the `scoopc` command's own process) sys.argv."""
    argv_given = argv
    argv, program_args = _program_arguments(list(sys.argv[1:] if argv is None else argv))
    args = build_parser().parse_args(argv)
    if program_args and args.command != "run":
        build_parser().error("arguments after `--` are for `scoopc run` only")
    if argv_given is None and args.command in ONE_SHOT:
        # The command's own process (not a caller's): the compiler's objects (a checked standard
        # library: millions) live to its end and make little garbage, so the collector's passes
        # over them would cost more than the compilation. A run's program gets the collector
        # back, with these objects frozen out of its way to the end (driver.running).
        gc.disable()
    handler = HANDLERS[args.command]
    if args.command == "run":
        return _reported(lambda: handler(args, program_args))
    return _reported(lambda: handler(args))


def _command_sim(args: argparse.Namespace) -> int:
    from .robots import simnode  # deferred: start-up (the simulator node only)

    return simnode.command(args)


# Each command's handler (its arguments: scoopc.cli_args).
HANDLERS: dict[str, Callable[..., int]] = {
    "parse": _command_parse,
    "check": _command_check,
    "compile": _command_compile,
    "run": _command_run,
    "test": _command_test,
    "msg": _command_msg,
    "lsp": _command_lsp,
    "cache": _command_cache,
    "sim": _command_sim,
}


def _program_arguments(argv: list[str]) -> tuple[list[str], list[str]]:
    """(the options, the program's arguments: those after `--`)."""
    if "--" not in argv:
        return argv, []
    split = argv.index("--")
    return argv[:split], argv[split + 1 :]


def _reported(command: Callable[[], int]) -> int:
    """Run a command; a failure becomes its message on stderr and its exit code."""
    try:
        return int(command())
    except SourceErrors:
        return Exit.SOURCE  # the diagnostics are on stderr already
    except UsageError as problem:
        print(f"scoopc: error: {problem}", file=sys.stderr)
        return Exit.USAGE
    except KeyboardInterrupt as interrupt:
        name = getattr(interrupt, "signal_name", "SIGINT")
        print("scoopc: interrupted" if name == "SIGINT" else f"scoopc: stopped by {name}", file=sys.stderr)
        return status_of(interrupt)
    except BrokenPipeError:
        return Exit.OK
    except Exception:  # a bug in scoopc, never the user's fault
        print("scoopc: internal error (a bug in scoopc; please report it with the input):", file=sys.stderr)
        traceback.print_exc()
        return Exit.INTERNAL


# ---- compiled programs ---------------------------------------------------------------------------


def run_compiled(main_file: str, program: dict, argv: Sequence[str] | None = None) -> int:
    """`python -m PACKAGE [OPTIONS] [-- ARGS]`: the run of a Roboscoop program `scoopc compile`
    wrote, from its `__main__.py` (`main_file`, in the package's folder; `program`: its root class,
    creation procedure, classes shadowing the library's, the scoopc version that compiled it). It
    takes `scoopc run`'s run and robot options, its own arguments after `--`, and runs with a robot
    as `scoopc run` runs it: on the simulator unless `--robot ros2`, in the world.yaml (and with the
    robot.yaml) `scoopc compile` put beside the package."""
    folder = Path(main_file).resolve().parent
    parser = _Parser(
        prog=f"python -m {folder.name}",
        description=f"Run {program['root']}, compiled by scoopc, with a robot: the built-in simulator unless "
        "`--robot ros2` (docs/ROBOTS.md). Arguments after `--` go to the program.",
    )
    _add_run_options(parser, compiled=True)
    argv, program_args = _program_arguments(list(sys.argv[1:] if argv is None else argv))
    args = parser.parse_args(argv)
    if program.get("version") != __version__:
        print(
            f"scoopc: note: {folder.name} was compiled by scoopc {program.get('version')} and runs on scoopc "
            f"{__version__}; if it fails, compile it again",
            file=sys.stderr,
        )
    return _reported(lambda: _run_compiled(folder, program, args, program_args))


def _run_compiled(folder: Path, program: dict, args: argparse.Namespace, program_args: list[str]) -> int:
    from .driver import CompiledProgram, Root, run_program  # deferred: start-up (the run only)
    from .driver.packages import DamagedCache  # deferred: as above

    options, robot = _run_options(args)
    root = Root(program["root"], program["creator"])
    compiled = CompiledProgram(folder.parent, folder.name, root, folder.parent, program["shadowed"], True)
    try:
        return run_program(compiled, program_args, options, robot, [str(folder)]).status
    except DamagedCache as damage:
        raise UsageError(f"the compiled program does not load ({damage}): compile it again") from None


if __name__ == "__main__":
    sys.exit(main())
