"""`scoopc compile` and `scoopc run`: root selection, compilation into packages (cached by
content for `run`), and running a program in this process (DESIGN section 8)."""
from __future__ import annotations

import argparse
import importlib
import json
import shutil
import sys
from pathlib import Path
from typing import Optional

from .project import UsageError, collect

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
    compiled = build.compile_program(checked, out, package, root.key, root.creator, _assertions(args, project),
                                     progress=_progress())
    target = out / build.BASE_PACKAGE
    if target.exists():
        shutil.rmtree(target)
    shutil.copytree(compiled.base_path / build.BASE_PACKAGE, target)
    print(f"scoopc: wrote {out / package} and {target}; run it with: cd {out} && python -m {package}",
          file=sys.stderr)
    return EXIT_OK


def command_run(args, program_args: list[str]) -> int:
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
        staging = folder.with_name(key + ".tmp")
        if staging.exists():
            shutil.rmtree(staging)
        compiled = build.compile_program(checked, staging, "program", root.key, root.creator,
                                         _assertions(args, project), progress=_progress())
        meta = {"root": root.key, "creator": root.creator, "base": str(compiled.base_path),
                "shadowed": checked.semantics.universe.shadowed}
        (staging / "program.json").write_text(json.dumps(meta))
        if folder.exists():
            shutil.rmtree(folder)
        staging.rename(folder)
    return run_compiled(folder, meta, program_args, args)


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
    return meta if Path(meta["base"]).exists() else None


def run_compiled(folder: Path, meta: dict, program_args: list[str], args) -> int:
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
    status = launcher.main(root_cls, meta["creator"], argv, shadowed=meta.get("shadowed"),
                           trace_processors=args.trace_processors, strict=args.strict,
                           virtual_clock=args.virtual_clock, debug=args.debug)
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
