"""The `scoopc` command's arguments: the parser of every subcommand, their options, and the checks
of option values (`scoopc.cli` turns the parsed arguments into driver calls). Also the options of a
compiled program's own `python -m PACKAGE` (`cli.run_compiled`).
"""

from __future__ import annotations

import argparse
import sys

from .exits import Exit
from .runtime import COMPILED
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

    lsp = commands.add_parser(
        "lsp",
        help="run the language server for editors (LSP over stdio)",
        description="Run the language server on stdin and stdout for an editor: the checker's "
        "diagnostics as you type, hover, go to definition, references, completion, outline, folding "
        "and quick fixes (docs/EDITOR.md).",
    )
    lsp.add_argument("--stdio", action="store_true", help="talk over stdin and stdout (the default and only way)")

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
