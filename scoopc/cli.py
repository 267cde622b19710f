"""The `scoopc` command: argument parsing, running the pipeline, rendering diagnostics, exit codes.

Exit codes (DESIGN section 8): 0 success, 1 source errors, 2 bad usage, 3 run-time failure,
4 internal error of scoopc (a bug: reported with its Python traceback).
"""
from __future__ import annotations

import argparse
import re
import sys
import traceback
from typing import Optional, Sequence

from . import __version__, diagnostics, messages
from .project import UsageError, collect
from .runtime.stop_signals import status_of

EXIT_OK, EXIT_SOURCE, EXIT_USAGE, EXIT_RUNTIME, EXIT_INTERNAL = 0, 1, 2, 3, 4

PATHS_HELP = "a .e file, a directory (a cluster: every .e file below it) or an .ecf project file"


class _Parser(argparse.ArgumentParser):
    """argparse that exits with code 2 and a one-line hint, as the CLI contract says."""

    def error(self, message: str) -> None:  # type: ignore[override]
        self.print_usage(sys.stderr)
        self.exit(EXIT_USAGE, f"scoopc: error: {message}\n(run `{self.prog} --help` for help)\n")


def _add_source_options(command: argparse.ArgumentParser) -> None:
    command.add_argument("paths", nargs="*", metavar="PATH", help=PATHS_HELP)
    command.add_argument("--target", help="the .ecf target to use (default: the last concrete one)")
    command.add_argument("--format", choices=("auto", "short", "pretty"), default="auto",
                         help="diagnostics: one line each (short), with source excerpts and hints "
                              "(pretty); auto: pretty on a terminal")


def build_parser() -> argparse.ArgumentParser:
    top = _Parser(prog="scoopc", description="Compile Eiffel programs with SCOOP concurrency to Python.",
                  epilog="Run `scoopc COMMAND --help` for the options of a command.")
    top.add_argument("--version", action="version", version=f"scoopc {__version__}")
    commands = top.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    commands.required = True

    parse = commands.add_parser("parse", help="check the syntax only",
                                description="Parse the given Eiffel sources and report syntax errors.")
    _add_source_options(parse)
    parse.add_argument("--dump", action="store_true", help="print the syntax tree of each class")
    parse.set_defaults(handler=_command_parse)

    check = commands.add_parser("check", help="report all errors of a program, compile nothing",
                                description="Check Eiffel sources and report every error found: syntax, Eiffel validity (types, inheritance, calls, creation, contracts, void safety) and SCOOP separateness rules, each with its EiffelStudio code.")
    check.add_argument("--explain", metavar="CODE", help="explain a diagnostic code and exit")
    _add_source_options(check)
    check.set_defaults(handler=_command_check)
    _add_compile_and_run(commands)
    return top


def _add_compile_and_run(commands) -> None:
    from . import commands as run_commands

    compile_ = commands.add_parser("compile", help="compile a program to a Python package",
                                   description="Check the program, then write it as readable Python: one "
                                               "module per class, in a package runnable with `python -m`, "
                                               "beside the compiled standard library (eiffel_base).")
    _add_source_options(compile_)
    compile_.add_argument("-o", "--output", default="build", metavar="DIR",
                          help="the folder to write the packages into (default: build)")
    run_commands.add_compile_options(compile_)
    compile_.set_defaults(handler=run_commands.command_compile)

    run = commands.add_parser("run", help="compile (cached by content) and run a program",
                              description="Compile the program (reusing an earlier compilation of the same "
                                          "sources) and run it. Arguments after `--` go to the program. Exit "
                                          "status: the program's, 1 on source errors, 3 on a run-time failure "
                                          "(contract violation, uncaught exception, deadlock).")
    _add_source_options(run)
    run_commands.add_compile_options(run)
    run_commands.add_run_options(run)
    run.set_defaults(handler=run_commands.command_run)

    msg = commands.add_parser("msg", help="generate Eiffel classes for a ROS 2 message type",
                              description="Write one Eiffel class per message type: the given ROS 2 type "
                                          "(pkg/msg/Name, from the ROS 2 Humble type store or --file) and, "
                                          "recursively, the message types its fields use.")
    msg.add_argument("typename", nargs="?", metavar="TYPE", help="e.g. geometry_msgs/msg/Twist")
    msg.add_argument("--file", metavar="MSG", help="a .msg definition of the type (needs --type)")
    msg.add_argument("--type", metavar="TYPE", help="the type name the --file defines (pkg/msg/Name)")
    msg.add_argument("-o", "--output", default=".", metavar="DIR", help="where to write the .e files (default: .)")
    msg.add_argument("--all", action="store_true",
                     help="also write the classes the Roboscoop library already has (std_msgs/Header, ...)")
    msg.set_defaults(handler=lambda args: __import__("scoopc.robots.eiffel_messages",
                                                     fromlist=["command_msg"]).command_msg(args))

    sim = commands.add_parser("sim", help="run the simulator as a ROS 2 (DDS) node",
                              description="Run a simulator world as a separate ROS 2 node over DDS: it subscribes "
                                          "each robot's cmd_vel and publishes its sensors and /clock, paced to the "
                                          "wall clock, so that `scoopc run app.e --robot ros2` drives it over the "
                                          "real transport (docs/ROBOTS.md).")
    from .robots import simnode

    simnode.add_arguments(sim)
    sim.set_defaults(handler=simnode.command)


def _render(found: list[diagnostics.Diagnostic], line_text, style: str) -> None:
    pretty = style == "pretty" or (style == "auto" and sys.stderr.isatty())
    color = pretty and sys.stderr.isatty()
    for d in found:
        text = diagnostics.pretty(d, line_text, color) if pretty else diagnostics.short(d)
        print(text, file=sys.stderr)
    errors = sum(1 for d in found if d.is_error)
    if errors and pretty:
        print(f"{errors} error{'s' if errors != 1 else ''}", file=sys.stderr)


def _front_end(args: argparse.Namespace, stage: str = "parse"):
    from . import pipeline

    if not args.paths:
        raise UsageError(f"`scoopc {args.command}` needs at least one PATH ({PATHS_HELP})")
    project = collect(args.paths, args.target)
    parsed = pipeline.parse_project(project) if stage == "parse" else pipeline.check_project(project)
    _render(parsed.diagnostics, parsed.line_text, args.format)
    return parsed


def _command_parse(args: argparse.Namespace) -> int:
    parsed = _front_end(args)
    if args.dump:
        from . import syntax

        for unit in parsed.units:
            if unit.tree is not None:
                sys.stdout.write(syntax.dump(unit.tree).rstrip("\n") + "\n")
    return EXIT_SOURCE if parsed.has_errors else EXIT_OK


def _command_check(args: argparse.Namespace) -> int:
    if args.explain is not None:
        text = explain(args.explain)
        if text is None:
            raise UsageError(f"unknown diagnostic code `{args.explain}`")
        print(text)
        return EXIT_OK
    parsed = _front_end(args, "check")
    return EXIT_SOURCE if parsed.has_errors else EXIT_OK


def _canonical(code: str) -> str:
    """`vuta-3` -> `VUTA(3)`: test folders and shells write parentheses as a dash. Gobo's finer
    SCOOP codes resolve to ours (`vuta-4g` or `VUTA(4G)` -> `VUTA(3)`)."""
    from .explanations import ALIASES

    spelled = re.sub(r"\((\w+)\)$", r"-\1", code.strip().upper())
    if spelled in ALIASES:
        return ALIASES[spelled]
    match = re.fullmatch(r"(V[A-Z0-9]+)-(\d+)", spelled)
    return f"{match.group(1)}({match.group(2)})" if match else spelled


def explain(code: str) -> Optional[str]:
    """The explanation of a diagnostic code (ours or a Gobo alias), or None when the code is unknown:
    the rule, a wrong example and its fix, then the message and hint templates."""
    import textwrap

    from .explanations import ALIASES, EXPLANATIONS

    canonical = _canonical(code)
    entry, message = EXPLANATIONS.get(canonical), messages.MESSAGES.get(canonical)
    if entry is None and message is None:
        return None
    spelled = re.sub(r"\((\w+)\)$", r"-\1", code.strip().upper())
    heading = f"{canonical} (Gobo: {spelled})" if spelled in ALIASES else canonical
    if entry is None:
        lines = [f"{heading}: {message.text}"] + ([f"hint: {message.hint}"] if message.hint else [])
        return "\n".join(lines)

    def fill(text: str) -> str:
        return textwrap.fill(text, 100, break_on_hyphens=False, break_long_words=False)

    example, _, sentence = entry.fix.rpartition("\n\n")
    lines = [fill(f"{heading}: {entry.rule}"), "", "Wrong:", textwrap.indent(entry.wrong, "    "),
             "Fix:", textwrap.indent(example, "    "), fill(sentence)]
    if message is not None:
        lines += ["", f"Message: {message.text}"] + ([f"Hint: {message.hint}"] if message.hint else [])
    return "\n".join(lines)


def main(argv: Optional[Sequence[str]] = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    program_args: list[str] = []
    if "--" in argv:
        split = argv.index("--")
        argv, program_args = argv[:split], argv[split + 1:]
    args = build_parser().parse_args(argv)
    if program_args and args.command != "run":
        build_parser().error("arguments after `--` are for `scoopc run` only")
    try:
        if args.command == "run":
            return args.handler(args, program_args)
        return args.handler(args)
    except UsageError as problem:
        print(f"scoopc: error: {problem}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt as interrupt:
        name = getattr(interrupt, "signal_name", "SIGINT")
        print("scoopc: interrupted" if name == "SIGINT" else f"scoopc: stopped by {name}", file=sys.stderr)
        return status_of(interrupt)
    except BrokenPipeError:
        return EXIT_OK
    except Exception:  # a bug in scoopc, never the user's fault
        print("scoopc: internal error (a bug in scoopc; please report it with the input):", file=sys.stderr)
        traceback.print_exc()
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
