"""`scoopc compile` and `scoopc run`: root selection, compilation into packages (cached by
content for `run`), and running a program in this process (DESIGN section 8)."""
from __future__ import annotations

import argparse
import importlib
import json
import os
import shutil
import sys
from pathlib import Path
from typing import Optional

from . import outdir
from .project import UsageError, collect
from .runtime.stop_signals import stop_on_signals

EXIT_OK, EXIT_SOURCE, EXIT_USAGE, EXIT_RUNTIME = 0, 1, 2, 3


def add_compile_options(command: argparse.ArgumentParser) -> None:
    command.add_argument("--root", metavar="CLASS[.creation]",
                         help="the root class and its creation procedure (default: the .ecf's root, else "
                              "the class named like the single file or directory, else the one class with "
                              "a `make` no other class uses)")
    command.add_argument("--assertions", choices=("all", "require", "none"), default=None,
                         help="which contracts are checked at run time (default: the .ecf's setting, else "
                              "all); wait conditions are always evaluated")


def add_run_options(command: argparse.ArgumentParser) -> None:
    command.add_argument("--trace-processors", action="store_true",
                         help="prefix every output line with the processor that wrote it ([P3] ...)")
    command.add_argument("--strict", action="store_true",
                         help="an exception lost in an asynchronous call fails the run (exit 3)")
    command.add_argument("--debug", action="store_true", help="also show Python tracebacks of failures")
    command.add_argument("--virtual-clock", action="store_true",
                         help="run `sleep` and timers on a virtual clock that jumps ahead when every "
                              "processor waits (fast runs of programs that sleep)")
    command.add_argument("--no-cache", action="store_true", help="compile again even if cached")
    robot = command.add_argument_group(
        "robots", "A program that uses Roboscoop (stdlib/roboscoop) runs on the in-process simulator unless "
                  "`--robot ros2` is given (docs/ROBOTS.md).")
    robot.add_argument("--robot", choices=("sim", "ros2", "none"), default=None,
                       help="sim: the built-in simulator (default for Roboscoop programs); ros2: a ROS 2 robot "
                            "(rclpy when installed, else DDS with cyclonedds; SCOOPC_ROS2_BACKEND forces one); "
                            "none: no robot transport")
    robot.add_argument("--world", metavar="WORLD.yaml",
                       help="the simulator's world (default: world.yaml beside the program, else a built-in "
                            "5 x 5 m arena with one Thymio)")
    robot.add_argument("--namespace", metavar="NS",
                       help="the robot's namespace: which robot of the world is the program's (default: the "
                            "first), or the prefix of a ROS 2 robot's topics (default: none)")
    robot.add_argument("--realtime", action="store_true",
                       help="pace the simulator to the wall clock (default: simulated time as fast as possible)")
    robot.add_argument("--duration", type=_non_negative, metavar="SECONDS",
                       help="simulated seconds to run (default: the world's duration)")
    robot.add_argument("--goal", type=_point, metavar="X,Y", help="the goal the program is told (default: the world's)")
    robot.add_argument("--png", metavar="FILE", help="where to draw the trajectory (default: <program>.png)")
    robot.add_argument("--no-png", action="store_true", help="draw no trajectory")
    robot.add_argument("--gif", metavar="FILE", help="also write an animation of the run")
    robot.add_argument("--record", metavar="FILE.mcap",
                       help="record every topic of the run in an MCAP file (ROS 2 schemas; opens in Foxglove)")


def _non_negative(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if value < 0 or value != value:
        raise argparse.ArgumentTypeError(f"a duration must not be negative: {text!r}")
    return value


def _point(text: str) -> tuple:
    try:
        x, y = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"a point is X,Y (metres), not {text!r}") from None
    return (x, y)


class Root:
    def __init__(self, key: str, creator: str):
        self.key, self.creator = key, creator


def _root_option(text: Optional[str]):
    if not text:
        return None
    name, _, creator = text.partition(".")
    return name.upper(), (creator or "make").lower()


def choose_root(project, checked, option: Optional[str], paths: list[str]) -> Root:
    universe = checked.semantics.universe
    user = {i.name: i for i in universe.classes.values() if not i.from_library}
    wanted = _root_option(option)
    if wanted is None and project.root is not None:
        wanted = (project.root.class_name.upper(), project.root.creation.lower())
    if wanted is None and len(paths) == 1:
        stem = Path(paths[0].rstrip("/")).stem.upper()
        if stem in user:
            wanted = (stem, "make")
    if wanted is None:
        candidates = [n for n, i in user.items() if "make" in i.features and (i.creators is None or "make" in i.creators)]
        used = {ty.name for i in user.values() for _, ty, _ in i.parents}
        unused = [n for n in candidates if n not in used and not _mentioned_elsewhere(n, user)]
        if len(unused) == 1:
            wanted = (unused[0], "make")
        else:
            listed = ", ".join(sorted(candidates)) or "none"
            raise UsageError(f"cannot tell which class is the root: use --root CLASS (candidates: {listed})")
    name, creator = wanted
    info = user.get(name)
    if info is None:
        raise UsageError(f"root class {name} is not among the given classes")
    creators = info.creators
    allowed = (creators is None and creator == "default_create") or (creators is not None and creator in creators)
    if not allowed:
        listed = ", ".join(sorted(creators)) if creators is not None else "default_create"
        raise UsageError(f"`{creator}` is not a creation procedure of {name} (it has: {listed})")
    feature = info.features.get(creator)
    if feature is not None and feature.arguments:
        raise UsageError(f"the root creation procedure {name}.{creator} must take no arguments")
    return Root(name, creator)


def _mentioned_elsewhere(name: str, user: dict) -> bool:
    import re

    pattern = re.compile(r"\b" + name + r"\b", re.IGNORECASE)
    for other in user.values():
        if other.name != name and pattern.search(Path(other.decl.span.file).read_text(errors="replace")):
            return True
    return False


def _check(args):
    from . import pipeline
    from .cli import _render

    if not args.paths:
        raise UsageError(f"`scoopc {args.command}` needs at least one PATH")
    project = collect(args.paths, args.target)
    checked = pipeline.check_project(project)
    _render(checked.diagnostics, checked.line_text, args.format)
    return project, checked


def _assertions(args, project) -> str:
    return args.assertions or (project.settings.assertions if project is not None else None) or "all"


def command_compile(args) -> int:
    from . import build

    project, checked = _check(args)
    if checked.has_errors:
        return EXIT_SOURCE
    root = choose_root(project, checked, args.root, args.paths)
    out = Path(args.output)
    package = root.key.lower()
    target = out / build.BASE_PACKAGE
    outdir.prepare(out)
    for folder in (out / package, target):      # both checked before either is touched
        outdir.check(folder)
    for folder in (out / package, target):
        outdir.clear(folder)
    compiled = build.compile_program(checked, out, package, root.key, root.creator, _assertions(args, project),
                                     progress=_progress())
    shutil.copytree(compiled.base_path / build.BASE_PACKAGE, target,
                    ignore=shutil.ignore_patterns("__pycache__", outdir.MARKER, "scoopc-complete"))
    outdir.mark(target)
    print(f"scoopc: wrote {out / package} and {target}; run it with: cd {out} && python -m {package}",
          file=sys.stderr)
    return EXIT_OK


def command_run(args, program_args: list[str]) -> int:
    compiled = compiled_program(args)
    if isinstance(compiled, int):
        return compiled
    folder, meta = compiled
    outcome = run_compiled(folder, meta, program_args, args)
    return outcome if isinstance(outcome, int) else outcome.status


def compiled_program(args):
    """(folder, meta) of the program's compilation (cached by content), or an exit status."""
    from . import build

    if not args.paths:
        raise UsageError("`scoopc run` needs at least one PATH")
    project = collect(args.paths, args.target)
    extra = json.dumps([args.root, args.assertions, project.settings.assertions,
                        project.root.class_name if project.root else None])
    key = build.program_key([Path(p) for p in project.files], extra)
    folder = build.cache_dir() / "programs" / key
    meta_path = folder / "program.json"
    meta = None if args.no_cache else _read_meta(meta_path)
    if meta is None:
        _, checked = _check(args)
        if checked.has_errors:
            return EXIT_SOURCE
        root = choose_root(project, checked, args.root, args.paths)
        staging = folder.with_name(f"{key}.{os.getpid()}.tmp")      # per process: runs may race
        if staging.exists():
            shutil.rmtree(staging)
        compiled = build.compile_program(checked, staging, "program", root.key, root.creator,
                                         _assertions(args, project), progress=_progress())
        meta = {"root": root.key, "creator": root.creator, "base": str(compiled.base_path),
                "shadowed": checked.semantics.universe.shadowed,
                "roboscoop": uses_roboscoop(project.files)}
        (staging / "program.json").write_text(json.dumps(meta))
        build.write_bytecode(staging / "program")
        if folder.exists():                  # --no-cache, or another process compiled it meanwhile
            old = folder.with_name(f"{key}.{os.getpid()}.old")
            try:
                folder.rename(old)
                shutil.rmtree(old, ignore_errors=True)
            except OSError:
                pass
        try:
            staging.rename(folder)
        except OSError:                      # another process put its copy in place first: use it
            shutil.rmtree(staging, ignore_errors=True)
    build.ensure_bytecode(Path(meta["base"]))
    return folder, meta


def uses_roboscoop(files) -> bool:
    """Does a user class name a class of stdlib/roboscoop? (Comments do not count.)"""
    import re

    from .semantics.universe import stdlib_root

    library = stdlib_root()
    names = {p.stem.upper() for p in (library / "roboscoop").rglob("*.e")}
    for name in files:
        path = Path(name).resolve()
        if library in path.parents:
            continue
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        code = re.sub(r"--[^\n]*", "", text)
        if names.intersection(re.findall(r"\b[A-Z][A-Z0-9_]*\b", code)):
            return True
    return False


def run_program(paths: list[str], program_args: list[str], **robot_options):
    """`scoopc run PATHS` from Python (tests and tools): the RunResult of a robot run, or the exit
    status. `robot_options` are the robot arguments of `scoopc run` (robot=, world=, duration=, ...),
    plus stdout= and stderr=; `world` may also be a dict or a World."""
    from .cli import build_parser

    args = build_parser().parse_args(["run", *paths])
    streams = {k: robot_options.pop(k, None) for k in ("stdout", "stderr")}
    for name, value in robot_options.items():
        if not hasattr(args, name):
            raise TypeError(f"unknown run option {name!r}")
        if value is not None:
            setattr(args, name, value)
    args.no_png = not robot_options.get("png")
    compiled = compiled_program(args)
    if isinstance(compiled, int):
        return compiled
    folder, meta = compiled
    return run_compiled(folder, meta, program_args, args, **streams)


def _progress():
    """Progress lines on stderr for long steps, on a terminal only (stderr stays clean otherwise)."""
    if not sys.stderr.isatty():
        return None
    return lambda message: print(f"scoopc: {message}", file=sys.stderr, flush=True)


def _read_meta(path: Path):
    try:
        meta = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    return meta if "roboscoop" in meta and Path(meta["base"]).exists() else None


def run_compiled(folder: Path, meta: dict, program_args: list[str], args, stdout=None, stderr=None):
    """Run a compiled program: its exit status, or the RunResult of a run with a robot."""
    from . import build
    from .codegen.names import class_name, module_name
    from .kernel import launcher

    build.ensure_on_path(Path(meta["base"]), folder)
    from .kernel import link

    for name in [m for m in sys.modules if m == "program" or m.startswith("program.")]:
        del sys.modules[name]            # another program ran in this process before
    link.forget("program")
    module = importlib.import_module(f"program.{module_name(meta['root'])}")
    root_cls = getattr(module, class_name(meta["root"]))
    argv = [meta["root"].lower()] + list(program_args)
    sys.stdout.flush()
    robot = getattr(args, "robot", None) or ("sim" if meta.get("roboscoop") else "none")

    def launch(on_start=None, virtual_clock=args.virtual_clock):
        return launcher.main(root_cls, meta["creator"], argv, shadowed=meta.get("shadowed"),
                             trace_processors=args.trace_processors, strict=args.strict,
                             virtual_clock=virtual_clock, debug=args.debug, on_start=on_start,
                             stdout=stdout, stderr=stderr)

    with stop_on_signals():                  # SIGTERM and SIGHUP end a run the way Ctrl-C does
        if robot == "none":
            status = launch()
        else:
            from .robots import runner

            status = runner.run(robot, launch, args, meta, stderr=stderr)
    _quiet_if_reader_gone()
    return status


def _quiet_if_reader_gone() -> None:
    """Output piped into a reader that stopped (`| head`): no complaint at interpreter exit."""
    import os

    try:
        sys.stdout.flush()
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
