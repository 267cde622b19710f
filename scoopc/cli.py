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
from .exits import Exit, SourceErrors, UsageError
from .runtime import COMPILED
from .runtime.stop_signals import status_of
from .version import __version__

PATHS_HELP = "a .e file, a directory (a cluster: every .e file below it) or an .ecf project file"


class _Parser(argparse.ArgumentParser):
    """argparse that exits with code 2 and a one-line hint, as the CLI contract says."""

    def error(self, message: str) -> None:  # type: ignore[override]
        self.print_usage(sys.stderr)
        self.exit(Exit.USAGE, f"scoopc: error: {message}\n(run `{self.prog} --help` for help)\n")


# ---- arguments -----------------------------------------------------------------------------------


def _runtime_kind() -> str:
    return "compiled to C" if COMPILED else "pure Python"


def build_parser() -> argparse.ArgumentParser:
    top = _Parser(
        prog="scoopc",
        description="Compile Eiffel programs with SCOOP concurrency to Python.",
        epilog="Run `scoopc COMMAND --help` for the options of a command.",
    )
    top.add_argument("--version", action="version", version=f"scoopc {__version__} (runtime: {_runtime_kind()})")
    commands = top.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    commands.required = True

    parse = commands.add_parser(
        "parse", help="check the syntax only", description="Parse the given Eiffel sources and report syntax errors."
    )
    _add_source_options(parse)
    parse.add_argument("--dump", action="store_true", help="print the syntax tree of each class")
    parse.set_defaults(handler=_command_parse)

    check = commands.add_parser(
        "check",
        help="report all errors of a program, compile nothing",
        description="Check Eiffel sources and report every error found: syntax, Eiffel "
        "validity (types, inheritance, calls, creation, contracts, void "
        "safety) and SCOOP separateness rules, each with its EiffelStudio "
        "code.",
    )
    check.add_argument(
        "--explain",
        metavar="CODE",
        nargs="?",
        const="",
        help="explain a diagnostic code (VUTA3, vuta-3, 'VUTA(3)', Gobo's VUTA-4G) and exit; alone: list the codes",
    )
    _add_source_options(check)
    check.set_defaults(handler=_command_check)

    compile_ = commands.add_parser(
        "compile",
        help="compile a program to a Python package",
        description="Check the program, then write it as readable Python: one "
        "module per class, in a package runnable with `python -m`, "
        "beside the compiled standard library (eiffel_base). A folder "
        "scoopc did not write is never replaced.",
    )
    _add_source_options(compile_)
    compile_.add_argument(
        "-o", "--output", default="build", metavar="DIR", help="the folder to write the packages into (default: build)"
    )
    _add_compile_options(compile_)
    compile_.set_defaults(handler=_command_compile)

    run = commands.add_parser(
        "run",
        help="compile (cached by content) and run a program",
        description="Compile the program (reusing an earlier compilation of the same "
        "sources) and run it. Arguments after `--` go to the program. Exit "
        "status: the program's, 1 on source errors, 3 on a run-time failure "
        "(contract violation, uncaught exception, deadlock), 128 + N when "
        "signal N stopped it (130: Ctrl-C).",
    )
    _add_source_options(run)
    _add_compile_options(run)
    _add_run_options(run)
    run.set_defaults(handler=_command_run)

    _add_test_command(commands)
    _add_robot_commands(commands)
    return top


def _add_test_command(commands) -> None:
    test = commands.add_parser(
        "test",
        help="run the tests of a program (EQA_TEST_SET descendants)",
        description="Check the program, then run its tests as EiffelStudio's AutoTest finds them: "
        "every procedure without arguments that a descendant of EQA_TEST_SET exports to all "
        "clients, each in a runtime of its own (its own processors and once values); a "
        "ROBOT_TEST_SET runs in a simulated world. A failed assertion, a contract violation, "
        "an exception, a deadlock, a lost exception or the time limit fails a test, with its "
        "report. Exit status: 0 when every test passed, 1 when one failed or the program has "
        "errors, 2 for bad usage (no test found, say).",
    )
    _add_source_options(test)
    _add_assertions_option(test)
    test.add_argument(
        "-k",
        dest="pattern",
        metavar="PATTERN",
        help="run the tests whose CLASS.routine contains PATTERN (or matches it as a glob: *, ?, [])",
    )
    test.add_argument(
        "--timeout",
        type=_positive,
        default=30.0,
        metavar="SECONDS",
        help="wall-clock seconds a test may take before it fails (default 30)",
    )
    test.add_argument("--junit", metavar="FILE", help="also write the outcomes as JUnit XML (for graders and CI)")
    test.add_argument("--debug", action="store_true", help="also show Python tracebacks of failures")
    test.set_defaults(handler=_command_test)


def _add_source_options(command: argparse.ArgumentParser) -> None:
    command.add_argument("paths", nargs="*", metavar="PATH", help=PATHS_HELP)
    command.add_argument("--target", help="the .ecf target to use (default: the last concrete one)")
    command.add_argument(
        "--format",
        choices=("auto", "short", "pretty"),
        default="auto",
        help="diagnostics: one line each (short), with source excerpts and hints (pretty); auto: pretty on a terminal",
    )


def _add_compile_options(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--root",
        metavar="CLASS[.creation]",
        help="the root class and its creation procedure (default: the .ecf's root, else "
        "the class named like the single file or directory, else the one class with "
        "a `make` no other class uses)",
    )
    _add_assertions_option(command)


def _add_assertions_option(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--assertions",
        choices=("all", "require", "none"),
        default=None,
        help="which contracts are checked at run time (default: the .ecf's setting, else "
        "all); wait conditions are always evaluated",
    )


def _add_run_options(command: argparse.ArgumentParser, compiled: bool = False) -> None:
    """`scoopc run`'s options; `compiled`: those a compiled program takes (no cache to skip)."""
    command.add_argument(
        "--trace-processors",
        action="store_true",
        help="prefix every output line with the processor that wrote it ([P3] ...)",
    )
    command.add_argument(
        "--strict", action="store_true", help="an exception lost in an asynchronous call fails the run (exit 3)"
    )
    command.add_argument("--debug", action="store_true", help="also show Python tracebacks of failures")
    command.add_argument(
        "--virtual-clock",
        action="store_true",
        help="run `sleep` and timers on a virtual clock that jumps ahead when every "
        "processor waits (fast runs of programs that sleep)",
    )
    if not compiled:
        command.add_argument(
            "--no-cache", action="store_true", help="compile the program and the standard library again, even if cached"
        )
    command.add_argument(
        "--status",
        nargs="?",
        const=0.0,
        type=_status_period,
        metavar="N",
        help="print the processors and the wait conditions waited on (on stderr) when the process gets "
        "SIGUSR1, or every N seconds with N",
    )
    command.add_argument(
        "--live",
        type=_port,
        metavar="PORT",
        help="serve the running program to Foxglove on ws://localhost:PORT: processors, waits, events, the "
        'robot and its topics (needs the live extra: pip install "scoopc[live]"; implies --realtime; '
        "docs/LIVE.md)",
    )
    robot = command.add_argument_group(
        "robots",
        "A program that uses Roboscoop (stdlib/roboscoop) runs on the in-process simulator unless "
        "`--robot ros2` is given (docs/ROBOTS.md).",
    )
    robot.add_argument(
        "--robot",
        choices=("sim", "ros2", "none"),
        default=None,
        help="sim: the built-in simulator (default for Roboscoop programs); ros2: a ROS 2 robot "
        "(rclpy when installed, else DDS with cyclonedds; SCOOPC_ROS2_BACKEND forces one); "
        "none: no robot transport",
    )
    robot.add_argument(
        "--world",
        metavar="WORLD.yaml",
        help="the simulator's world (default: world.yaml beside the program, else a built-in "
        "5 x 5 m arena with one Thymio)",
    )
    robot.add_argument(
        "--namespace",
        metavar="NS",
        help="the robot's namespace: which robot of the world is the program's (default: the "
        "first), or the prefix of a ROS 2 robot's topics (default: none)",
    )
    robot.add_argument(
        "--realtime",
        action="store_true",
        help="pace the simulator to the wall clock (default: simulated time as fast as possible)",
    )
    robot.add_argument(
        "--duration",
        type=_non_negative,
        metavar="SECONDS",
        help="simulated seconds to run (default: the world's duration)",
    )
    robot.add_argument("--goal", type=_point, metavar="X,Y", help="the goal the program is told (default: the world's)")
    robot.add_argument("--png", metavar="FILE", help="where to draw the trajectory (default: <program>.png)")
    robot.add_argument("--no-png", action="store_true", help="draw no trajectory")
    robot.add_argument("--gif", metavar="FILE", help="also write an animation of the run")
    robot.add_argument(
        "--record",
        metavar="FILE.mcap",
        help="record every topic of the run in an MCAP file (ROS 2 schemas; opens in Foxglove)",
    )
    _add_distro_option(robot)
    robot.add_argument(
        "--use-sim-time",
        action="store_true",
        help="ROS 2: stamp commands with the latest /clock (use_sim_time) instead of the system clock",
    )
    robot.add_argument(
        "--wait-robot",
        type=_non_negative,
        default=3.0,
        metavar="S",
        help="ROS 2: seconds before the topics still silent are reported (default 3)",
    )
    robot.add_argument(
        "--require-robot",
        action="store_true",
        help="ROS 2: fail (exit 3) when a subscribed topic is still silent after --wait-robot seconds",
    )
    robot.add_argument(
        "--node-name",
        metavar="NAME",
        help="ROS 2: the program's node name in the ROS graph (default: the root class in lower case)",
    )
    robot.add_argument(
        "--profile",
        metavar="FILE",
        help="the robot profile of DIFF_DRIVE_ROBOT.make_from_profile: topic names, command type, QoS, limits "
        "(default: robot.yaml beside the program, if any)",
    )


def _add_distro_option(group) -> None:
    group.add_argument(
        "--ros-distro",
        type=str.lower,
        choices=("humble", "jazzy", "lyrical"),
        metavar="DISTRO",
        help="the ROS 2 distribution whose message definitions and type hashes are used: "
        "humble, jazzy or lyrical (default: ROS_DISTRO, else jazzy)",
    )


def _add_robot_commands(commands) -> None:
    msg = commands.add_parser(
        "msg",
        help="generate Eiffel classes for a ROS 2 message type",
        description="Write one Eiffel class per message type: the given ROS 2 type "
        "(pkg/msg/Name, from the type store of the ROS 2 distribution, or "
        "--file) and, recursively, the message types its fields use.",
    )
    msg.add_argument("typename", nargs="?", metavar="TYPE", help="e.g. geometry_msgs/msg/Twist")
    msg.add_argument("--file", metavar="MSG", help="a .msg definition of the type (needs --type)")
    msg.add_argument("--type", metavar="TYPE", help="the type name the --file defines (pkg/msg/Name)")
    msg.add_argument("-o", "--output", default=".", metavar="DIR", help="where to write the .e files (default: .)")
    _add_distro_option(msg)
    msg.add_argument(
        "--all",
        action="store_true",
        help="also write the classes the Roboscoop library already has (std_msgs/Header, ...)",
    )
    msg.set_defaults(handler=_command_msg)

    lsp = commands.add_parser(
        "lsp",
        help="run the language server for editors (LSP over stdio)",
        description="Run the language server on stdin and stdout for an editor: the checker's "
        "diagnostics as you type, hover, go to definition, references, completion, outline, folding "
        "and quick fixes (docs/EDITOR.md).",
    )
    lsp.add_argument("--stdio", action="store_true", help="talk over stdin and stdout (the default and only way)")
    lsp.set_defaults(handler=_command_lsp)

    cache_ = commands.add_parser(
        "cache",
        help="show or clean scoopc's cache of compiled libraries and programs",
        description="scoopc keeps the compiled standard library and compiled programs in its cache "
        "folder ($SCOOPC_CACHE_DIR, else ~/.cache/scoopc). `info` shows what it holds; `clean` removes "
        "the entries of other scoopc versions, leftovers of interrupted runs and, past the size limit "
        "($SCOOPC_CACHE_MAX, default 500M), the least recently used programs (`--all`: everything).",
    )
    cache_.add_argument("action", choices=("info", "clean"), help="info or clean")
    cache_.add_argument("--all", action="store_true", help="with clean: remove everything scoopc cached")
    cache_.set_defaults(handler=_command_cache)

    sim = commands.add_parser(
        "sim",
        help="run the simulator as a ROS 2 (DDS) node",
        description="Run a simulator world as a separate ROS 2 node over DDS: it subscribes "
        "each robot's cmd_vel and publishes its sensors and /clock, paced to the "
        "wall clock, so that `scoopc run app.e --robot ros2` drives it over the "
        "real transport (docs/ROBOTS.md).",
    )
    from .robots import simnode  # deferred: only its argument list is needed here (start-up)

    simnode.add_arguments(sim)
    sim.set_defaults(handler=simnode.command)


def _non_negative(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if value < 0 or value != value:
        raise argparse.ArgumentTypeError(f"a duration must not be negative: {text!r}")
    return value


def _status_period(text: str) -> float:
    try:
        return _positive(text)
    except argparse.ArgumentTypeError:
        raise argparse.ArgumentTypeError(
            f"not a number of seconds: {text!r} (without N, put --status after the program's paths)"
        ) from None


def _port(text: str) -> int:
    if not text.isdigit() or not 1 <= int(text) <= 65535:
        raise argparse.ArgumentTypeError(f"not a port (1 to 65535): {text!r}")
    return int(text)


def _positive(text: str) -> float:
    value = _non_negative(text)
    if value == 0:
        raise argparse.ArgumentTypeError(f"a time limit must be more than 0 seconds: {text!r}")
    return value


def _point(text: str) -> tuple:
    try:
        x, y = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"a point is X,Y (metres), not {text!r}") from None
    return (x, y)


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
    if args.command == "run":
        return _reported(lambda: args.handler(args, program_args))
    return _reported(lambda: args.handler(args))


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
