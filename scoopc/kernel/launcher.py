"""Running a compiled program: arguments, the runtime's options, and the Eiffel-level report of a
run-time failure (the violated assertion, then class, routine and file:line of each frame).

Generated modules are mapped back to Eiffel lines through `_lines.json`, written beside them by
the compiler: {module: [eiffel file, {python line: eiffel line}]}.
"""

from __future__ import annotations

import gc
import json
import keyword
import sys
import traceback
from pathlib import Path

from .. import runtime as rt
from ..exits import Exit
from ..runtime import DeadlockError, DirtyRegionError, PreconditionViolation
from . import CLASSES, link
from .errors import EiffelFailure
from .support import GUARDS, ContractViolation, EiffelRuntimeError

_LINE_MAPS: dict = {}
_PYTHON_NAMES = frozenset({"self", "here", "print", "type", "super", "object"})  # taken, as keywords are
PROGRAM = [sys.argv[0] if sys.argv and sys.argv[0] else "program"]  # the command line ARGUMENTS reads


def set_arguments(args) -> None:
    """Make `args` (command name first, then the arguments: strings) the program's command line."""
    args = [str(a) for a in args]
    if not args:
        raise ValueError("set_arguments: the command name (index 0) is required")
    PROGRAM[:] = args


def main(
    root_cls,
    creator,  # the creation procedure's name, or a routine (obj) -> None
    argv,
    shadowed=None,
    trace_processors=False,
    strict=False,
    virtual_clock=False,
    debug=False,
    stdout=None,
    stderr=None,
    on_start=None,
) -> int:

    link.register_again("eiffel_base")  # the registry may have been reset
    link.register_again(root_cls.__module__.rpartition(".")[0])
    for name, key in (shadowed or {}).items():
        CLASSES.setdefault(key, CLASSES.get(name))
    set_arguments(list(argv))
    stderr = stderr or sys.stderr

    def describe(error, proc):
        return report(error, debug)

    if callable(creator):  # a routine of the caller's (`scoopc test` runs a test so)
        routine = creator
    else:
        routine = getattr(root_cls, creator, None) if creator else None
    if creator and routine is None:
        stderr.write(f"scoopc: the root class has no creation procedure `{creator}`\n")
        return Exit.USAGE
    restore = _tune_collector()
    try:
        return rt.run_main(
            root_cls,
            routine,
            (),
            describe=describe,
            trace_processors=trace_processors,
            strict=strict,
            virtual_clock=virtual_clock,
            stdout=stdout or sys.stdout,
            stderr=stderr,
            on_start=on_start,
        )
    finally:
        restore()


def _tune_collector():
    """The loaded classes live as long as the program: keep them out of the cyclic collector's
    way, and let it run less often (programs allocate many small objects, such as the links of
    a LINKED_QUEUE, that plain reference counting frees)."""

    before = gc.get_threshold()
    gc.freeze()
    gc.set_threshold(20_000, 20, 20)

    def restore():
        gc.set_threshold(*before)
        gc.unfreeze()

    return restore


def report(error, debug: bool = False) -> str:
    """The text of an uncaught exception: what failed, then the Eiffel call stack; one line when
    it follows from an exception lost earlier on the same region (reported then)."""
    consequence = _consequence(error)
    if consequence is not None and not debug:
        return consequence
    lines = [describe_error(error)]
    frames = eiffel_frames(error)
    cause = error.__cause__ if isinstance(error, DirtyRegionError) else None
    supplier = eiffel_frames(cause) if cause is not None and cause.__traceback__ is not None else []
    supplier = [f for f in supplier if f not in frames]
    if getattr(error, "asynchronous", False) and supplier:
        # The failed command ran on the supplier after its client had gone on: the supplier's
        # frames, then where the client learnt of it (its next synchronous call there).
        lines.extend(trace_lines(supplier))
        lines.extend(trace_lines(frames, first="failure noticed in"))
    else:
        lines.extend(trace_lines(supplier + frames))
    if debug:
        lines.append("Python traceback (--debug):")
        lines.append("".join(traceback.format_exception(type(error), error, error.__traceback__)).rstrip())
    return "\n".join(lines)


def _consequence(error) -> str | None:
    """One line for a failure on a region whose earlier asynchronous call failed unseen (a Void
    attribute its creation procedure never set, say), or None."""
    proc = getattr(error, "proc", None) if isinstance(error, DirtyRegionError) else None
    try:
        runtime = rt.current()
    except RuntimeError:
        return None
    with runtime.glock:
        if proc is None or proc not in runtime.lost:
            return None
    cause = error.__cause__ if error.__cause__ is not None else error
    where = eiffel_frames(cause)[:1] + eiffel_frames(error)[:1]
    places = " noticed in ".join(f"{cls}.{routine} ({place})" for cls, routine, place in where)
    return f"a consequence of the exception lost on {proc!r} (reported above): {describe_error(cause)}" + (
        f" in {places}" if places else ""
    )


def trace_lines(frames: list, first: str = "in") -> list[str]:
    """The lines of an Eiffel trace: `first` ("in") the innermost frame, `called by` each other."""
    return [
        f"  {first if index == 0 else 'called by'} {cls}.{routine} ({place})"
        for index, (cls, routine, place) in enumerate(frames)
    ]


def describe_error(error) -> str:
    if isinstance(error, DirtyRegionError):
        # EiffelStudio's client raises its dirty processor exception (private_queue.c); the
        # supplier's own failure follows, which EiffelStudio does not show but a user needs.
        text = str(error)
        if error.__cause__ is not None:
            text += ": " + describe_error(error.__cause__)
        return text
    cause = error
    if isinstance(cause, ContractViolation):
        text = f"{cause.kind.replace('_', ' ')} violated: `{cause.tag or '(untagged)'}`"
        return text + _at(cause.where)
    if isinstance(cause, PreconditionViolation):
        return f"precondition violated: `{cause.tag or '(untagged)'}`" + _at(cause.where)
    if isinstance(cause, DeadlockError):
        return str(cause)
    if isinstance(cause, EiffelRuntimeError):
        return f"{cause.kind.replace('_', ' ')}: {cause}" + _at(cause.where)
    if isinstance(cause, EiffelFailure):
        return "exception raised: " + _exception_text(cause.exception)
    if isinstance(cause, AttributeError) and "'NoneType'" in str(cause):
        return "feature call on a Void target"
    if isinstance(cause, ZeroDivisionError):
        return "integer division by zero"
    if isinstance(cause, RecursionError):
        return "stack overflow (recursion too deep)"
    return f"{type(cause).__name__}: {cause}"


def _exception_text(exception) -> str:
    try:
        from .strings import shown  # deferred: optional (its absence is handled below)

        message = exception.message
        tag = shown(message) if message is not None else ""
        return f"{type(exception)._key_}" + (f": {tag}" if tag else "")
    except Exception:  # noqa: BLE001 - a report must not fail
        return type(exception).__name__


def _at(where) -> str:
    if not where:
        return ""
    cls, routine, path, line = where
    return f" (in {cls}.{routine}, {Path(path).name}:{line})"


def eiffel_frames(error) -> list:
    """(class, routine, file:line) for each frame of generated code, innermost first. Python's
    own helpers never show: a precondition clause (a module-level function of the generated
    code) is named after its routine, at the clause's line; any other helper function (an `old`
    or a loop's exit condition) is left out, as its routine's frame shows the line."""
    frames = _frames(traceback.walk_tb(error.__traceback__))[::-1]
    noticed = getattr(error, "noticed", None)
    if noticed is not None and frames:
        # A direct block (runtime direct.py) raises where the general path would not: at a
        # failed command, what the general path raises at the block's next query (`noticed`
        # a where tuple); at the block's end, a failed query's failure (`noticed` the generated
        # file and line of the query). The client's frame shows the general path's line.
        cls, routine, _ = frames[0]
        if len(noticed) == 4:
            frames[0] = (cls, routine, f"{Path(noticed[2]).name}:{noticed[3]}")
        else:
            frames[0] = (cls, routine, eiffel_place(*noticed) or frames[0][2])
    return frames


def stack_frames(frame) -> list:
    """(class, routine, file:line) for each frame of generated code on the stack that ends in
    `frame` (a running thread's), innermost first."""
    return _frames(traceback.walk_stack(frame))


def _frames(walk) -> list:
    frames = []
    for frame, lineno in walk:
        place = eiffel_place(frame.f_code.co_filename, lineno)
        if place is None or frame.f_code in GUARDS:
            continue
        if frame.f_code.co_name == "<lambda>":
            clause = _clause_of(frame)
            if clause is not None:
                frames.append(clause)
            continue
        module = frame.f_globals.get("__name__", "")
        cls = module.rsplit(".", 1)[-1].upper()
        routine = frame.f_code.co_name
        for suffix in ("_once_", "_init_"):
            routine = routine[: -len(suffix)] if routine.endswith(suffix) else routine
        if routine.startswith("_") and routine.endswith("_refused_"):
            routine = routine[1 : -len("_refused_")]  # a host-bound routine's precondition (STANDING_FOR_EIFFEL)
        if routine == "_invariant_":
            routine = "invariant"
        elif routine.endswith("_") and (keyword.iskeyword(routine[:-1]) or routine[:-1] in _PYTHON_NAMES):
            routine = routine[:-1]  # `assert` is `assert_` in Python (codegen.names.py_identifier)
        frames.append((cls, "inline agent" if routine.startswith("_agent_") else routine, place))
    return frames


_CLAUSES: dict = {}  # code object of a precondition clause -> its frame, filled per module


def _clause_of(frame) -> tuple | None:
    """(class, "routine, wait condition" or "routine, precondition", file:line) when `frame` runs
    a precondition clause of a routine with separate arguments: generated modules keep those in
    `_PRE_n` tables of (clause, separate arguments it queries, tag, (class, routine, file, line))."""
    module = frame.f_globals
    key = module.get("__name__", "")
    if key not in _CLAUSES:
        table = {}
        for name, value in list(module.items()):
            if name.startswith("_PRE_") and isinstance(value, tuple):
                for clause in value:
                    predicate, queried, _tag, (cls, routine, path, line) = clause
                    what = "wait condition" if queried else "precondition"
                    table[predicate.__code__] = (cls, f"{routine}, {what}", f"{Path(path).name}:{line}")
        _CLAUSES[key] = table
    return _CLAUSES[key].get(frame.f_code)


def eiffel_place(filename: str, lineno: int):
    path = Path(filename)
    table = _line_map(path.parent)
    entry = table.get(path.stem)
    if entry is None:
        return None
    source, lines = entry
    line = lines.get(str(lineno))
    if line is None:
        candidates = [int(k) for k in lines if int(k) <= lineno]
        line = lines[str(max(candidates))] if candidates else "?"
    return f"{Path(source).name}:{line}"


def _line_map(folder: Path) -> dict:
    found = _LINE_MAPS.get(folder)
    if found is None:
        try:
            found = json.loads((folder / "_lines.json").read_text())
        except (OSError, ValueError):
            found = {}
        _LINE_MAPS[folder] = found
    return found
