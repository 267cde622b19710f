"""Driver, `scoopc test`: the test classes of a checked program (descendants of EQA_TEST_SET) and
their tests (the procedures without arguments they export to every client, as EiffelStudio's
AutoTest finds them), each run in a runtime of its own (fresh processors and once values) within
a time limit; a descendant of ROBOT_TEST_SET runs in a simulated world on simulated time.

A test's run: an object of the test class made by `default_create` (which calls `on_prepare`),
the test procedure, then `clean` (`on_clean`), on the root processor. It fails with the run's
report (what failed, where, the Eiffel trace) when the run fails: a failed `assert`, a contract
violation, an uncaught exception, a deadlock, a lost exception of an asynchronous call (the
runtime is strict), or the time limit.
"""

from __future__ import annotations

import fnmatch
import importlib
import io
import signal
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import FrameType
from typing import Any

from .. import syntax
from ..codegen.names import Naming, class_name, module_name
from ..exits import Exit, SourceErrors, UsageError
from ..kernel import launcher
from ..results import TestOutcome, TestResult
from ..robots.simulated_test import run_in_world
from ..runtime.monitor import dump
from ..runtime.sched import Runtime
from ..runtime.stop_signals import stop_on_signals
from ..semantics.features import Feature
from ..semantics.universe import ClassInfo, Universe
from .compilation import Compilation, CompiledProgram
from .junit import write_junit, write_source_errors
from .packages import DamagedCache, ensure_on_path
from .running import load_root, recompiled

TEST_SET = "EQA_TEST_SET"
ROBOT_TEST_SET = "ROBOT_TEST_SET"
DEFAULT_TIMEOUT = 30.0  # seconds of wall time per test
GRACE = 1.0  # seconds a stopped runtime has to end the test before its body is interrupted
_FAILURE_PREFIX = "scoopc: run-time failure: "


@dataclass(frozen=True)
class TestCase:
    """A test found in the program: a procedure of a test class."""

    class_key: str  # the test class
    routine: str  # the procedure's Eiffel name, lower case
    python_name: str  # its name in the generated class
    file: str
    line: int
    prepare: str = "default_create"  # the Python names of EQA_TEST_SET's `default_create` and `clean`
    clean: str = "clean"
    robot: bool = False  # a ROBOT_TEST_SET: run in a simulated world
    world: str | None = None  # the `world` note of the routine or class (a file, relative to the class's)

    @property
    def name(self) -> str:
        return f"{self.class_key}.{self.routine}"


@dataclass
class TestOptions:
    """How `scoopc test` runs (its options)."""

    pattern: str | None = None  # -k: run the tests whose CLASS.routine matches
    timeout: float = DEFAULT_TIMEOUT  # seconds per test
    junit: str | Path | None = None  # where to write JUnit XML
    debug: bool = False  # Python tracebacks in the reports too
    on_outcome: Callable[[TestOutcome], None] | None = None  # told of each test as it ends
    on_checked: Callable[[], None] | None = None  # called once the program is checked, before any test

    def __post_init__(self) -> None:
        if not (self.timeout > 0):
            raise UsageError(f"timeout must be a positive number of seconds, not {self.timeout!r}")


# ---- finding the tests -----------------------------------------------------------------------


def find_tests(compilation: Compilation) -> list[TestCase]:
    """Every test of the program's test classes, class by class (by name), in source order."""
    universe = compilation.semantics.universe
    naming = Naming(universe)  # type: ignore[no-untyped-call]  # codegen is not annotated
    found: list[TestCase] = []
    for key in sorted(universe.classes):
        info = universe.classes[key]
        if info.from_library or info.is_deferred or info.formals or TEST_SET not in info.ancestors:
            continue
        if info.creators is not None and "default_create" not in info.creators:
            raise UsageError(
                f"test class {key} must be creatable with `default_create` (each test gets an object made so)"
            )
        robot = ROBOT_TEST_SET in info.ancestors
        for feature in info.features.values():
            if _is_test(universe, info, feature):
                decl = feature.decl
                world = _note(decl.notes, "world") or _note(info.decl.notes, "world") or _world_beside(info)
                found.append(
                    TestCase(
                        key,
                        feature.name,
                        naming.name_in(key, feature),
                        feature.fname.span.file,
                        feature.fname.span.line,
                        naming.name_in(key, info.features["default_create"]),
                        naming.name_in(key, info.features["clean"]),
                        robot,
                        _beside(world, info) if world else None,
                    )
                )
    found.sort(key=lambda t: (t.class_key, t.line))
    return found


def _is_test(universe: Universe, info: ClassInfo, feature: Feature) -> bool:
    """AutoTest's rule: a procedure without arguments, exported to every client, that the test
    class has from itself or a test class of the program (not from the testing library)."""
    decl = feature.decl
    if not isinstance(decl, syntax.Routine) or decl.type is not None or decl.arguments or feature.deferred:
        return False
    if feature.exports is not None and "ANY" not in feature.exports:
        return False
    owner = universe.get(feature.written_in)
    return owner is not None and not owner.from_library


def _note(notes: Sequence[syntax.Note], tag: str) -> str | None:
    for note in notes:
        if note.tag.key.lower() == tag and note.values and isinstance(note.values[0], syntax.ManifestString):
            return note.values[0].value
    return None


def _world_beside(info: ClassInfo) -> str | None:
    """world.yaml in the test class's folder, if there is one."""
    return "world.yaml" if (Path(info.decl.span.file).parent / "world.yaml").is_file() else None


def _beside(world: str, info: ClassInfo) -> str:
    path = Path(world)
    return str(path if path.is_absolute() else Path(info.decl.span.file).parent / path)


def select(tests: list[TestCase], pattern: str | None) -> list[TestCase]:
    """The tests whose CLASS.routine matches `pattern` (-k): a glob when it has *, ? or [, else a
    part of the name; case does not matter."""
    if not pattern:
        return tests
    wanted = pattern.lower()
    if any(c in wanted for c in "*?["):
        return [t for t in tests if fnmatch.fnmatchcase(t.name.lower(), wanted)]
    return [t for t in tests if wanted in t.name.lower()]


# ---- running them ----------------------------------------------------------------------------


def run_tests(compilation: Compilation, options: TestOptions) -> TestResult:
    """Check the program, find its tests, run those selected, write the JUnit file. SourceErrors
    when the program has errors (the JUnit file then has one test, `check`, in error);
    UsageError when there is no test to run."""
    if options.junit and not Path(options.junit).resolve().parent.is_dir():
        raise UsageError(f"cannot write the JUnit file {options.junit}: its folder does not exist")
    try:
        compilation.require_clean()
    except SourceErrors as errors:
        if options.junit:
            write_source_errors(errors.diagnostics, options.junit)
        raise
    finally:
        if options.on_checked is not None:
            options.on_checked()
    found = find_tests(compilation)
    if not found:
        raise UsageError(f"no tests in {', '.join(compilation.paths)}: a test class inherits {TEST_SET}")
    chosen = select(found, options.pattern)
    if not chosen:
        raise UsageError(f"no test matches -k {options.pattern!r} (there are {len(found)} tests)")
    compilation.root_option = f"{chosen[0].class_key}.default_create"  # any class will do: tests have no root
    program = compilation.cached_program()
    try:
        classes = _load_classes(program, chosen)
    except DamagedCache:  # a module of the cached program does not load: compile it again
        program = recompiled(compilation, program, rebuild_library=False)
        classes = _load_classes(program, chosen)
    outcomes = []
    with stop_on_signals():  # Ctrl-C, SIGTERM and SIGHUP end the test under way, then the run
        for case in chosen:
            outcome = run_test(program, classes[case.class_key], case, options)
            outcomes.append(outcome)
            if options.on_outcome is not None:
                options.on_outcome(outcome)
    result = TestResult(Exit.OK if all(o.passed for o in outcomes) else Exit.SOURCE, tests=outcomes)
    if options.junit:
        result.junit = write_junit(outcomes, options.junit)
    return result


def run_test(program: CompiledProgram, test_class: type, case: TestCase, options: TestOptions) -> TestOutcome:
    """Run one test (of `test_class`, loaded from `program`) in a runtime of its own;
    KeyboardInterrupt when a signal stopped it."""
    out, err = io.StringIO(), io.StringIO()
    watchdog = _Watchdog(options.timeout)

    def launch(on_start: Callable[[Any], None] | None = None, virtual_clock: bool = False) -> int:
        def start(rt: Runtime) -> None:
            if on_start is not None:
                on_start(rt)
            watchdog.start(rt)

        return launcher.main(
            test_class,
            lambda obj: _body(obj, case, watchdog),
            [case.class_key.lower()],
            shadowed=program.shadowed,
            strict=True,
            virtual_clock=virtual_clock,
            debug=options.debug,
            on_start=start,
            stdout=out,
            stderr=err,
        )

    began = time.monotonic()
    with watchdog.interrupting():
        try:
            if case.robot:
                status = _in_world(case, lambda on_start: launch(on_start, True), err)
            else:
                status = launch()
        finally:
            watchdog.finish()
    seconds = time.monotonic() - began
    if status > 128 and not watchdog.expired:
        raise KeyboardInterrupt(f"stopped during {case.name}")
    return _outcome(case, status, watchdog, err.getvalue(), out.getvalue(), seconds)


def _in_world(case: TestCase, launch: Callable[[Callable[[Any], None]], int], err: io.StringIO) -> int:
    try:
        return run_in_world(launch, case.world, stderr=err).status
    except UsageError as problem:  # the world cannot be read: the test suite's mistake
        raise UsageError(f"{case.name} ({case.file}:{case.line}): {problem}") from None


def _load_classes(program: CompiledProgram, cases: list[TestCase]) -> dict[str, type]:
    """The test classes, from the program's package imported fresh (its root, one of them,
    first); DamagedCache when a module does not load."""
    found = {program.root.key: load_root(program)}
    ensure_on_path(program.library, program.folder)
    for key in dict.fromkeys(c.class_key for c in cases):
        if key not in found:
            module = importlib.import_module(f"{program.package}.{module_name(key)}")
            found[key] = getattr(module, class_name(key))
    return found


def _body(obj: Any, case: TestCase, watchdog: _Watchdog) -> None:
    """The test, on the root processor: prepare, run, clean (also after a failure, as AutoTest
    does); the first failure is the test's. A robot test stops its world when it is over."""
    watchdog.in_body = True
    try:
        getattr(obj, case.prepare)()
        failure: BaseException | None = None
        try:
            getattr(obj, case.python_name)()
        except Exception as error:  # the test's failure: reported once `clean` has run
            failure = error
        getattr(obj, case.clean)(failure is not None)
        if failure is not None:
            raise failure
    finally:
        watchdog.in_body = False
    if case.robot and watchdog.rt is not None:
        watchdog.rt.stop()  # the controllers it started run forever: the test is what counts


def _outcome(case: TestCase, status: int, watchdog: _Watchdog, err: str, out: str, seconds: float) -> TestOutcome:
    outcome = TestOutcome(case.class_key, case.routine, "passed", seconds, output=out, file=case.file, line=case.line)
    report = _failures(err)
    if watchdog.expired:
        outcome.status = "timeout"
        outcome.message = f"timed out after {watchdog.seconds:g} s"
        interrupted = ["the test body was interrupted", *watchdog.where] if watchdog.where else []
        outcome.report = "\n".join(filter(None, [outcome.message, *interrupted, watchdog.dump.rstrip(), report]))
    elif status != Exit.OK:
        outcome.status = "failed"
        outcome.report = report or f"the test's run ended with status {status}"
        outcome.message = outcome.report.splitlines()[0]
    return outcome


def _failures(err: str) -> str:
    """The run-time failures the run reported on `err`, each with its trace; everything it
    reported when there is none (a note on a lost exception precedes its failure: it goes)."""
    blocks: list[list[str]] = []
    for line in err.splitlines():
        if line.startswith("scoopc: ") or not blocks:
            blocks.append([])
        blocks[-1].append(line)
    failures = [b for b in blocks if b[0].startswith(_FAILURE_PREFIX)]
    if not failures:
        return err.strip()
    return "\n".join(line for b in failures for line in [b[0][len(_FAILURE_PREFIX) :], *b[1:]]).strip()


class _TimedOut(KeyboardInterrupt):
    """Raised in a test body that computes past its time without a call into the runtime."""

    status = Exit.RUNTIME


class _Watchdog:
    """Ends a test that runs out of time: the runtime is stopped (each processor at its next call
    into the runtime, each blocked thread woken); a body that still runs after GRACE seconds,
    computing without such calls, is interrupted on the main thread (SIGALRM)."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.rt: Any = None
        self.in_body = False  # set and read on the main thread (the signal handler runs there)
        self.expired = False
        self.dump = ""  # the processors and what each waited for, when time ran out
        self.where: list[str] = []  # the Eiffel trace of the test body, when it was interrupted
        self._done = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self, rt: Runtime) -> None:
        self.rt = rt
        self._thread = threading.Thread(target=self._watch, name="scoopc-test-watchdog", daemon=True)
        self._thread.start()

    def _watch(self) -> None:
        if self._done.wait(self.seconds):
            return
        self.dump = dump(self.rt)
        self.expired = True
        self.rt.stop()
        if self._done.wait(GRACE) or not self.in_body:
            return
        if _can_interrupt():
            signal.pthread_kill(threading.main_thread().ident or 0, signal.SIGALRM)

    def finish(self) -> None:
        self._done.set()
        if self._thread is not None:
            self._thread.join()

    def interrupting(self) -> _AlarmHandler:
        """Within the block, SIGALRM interrupts the test body (when this is the main thread)."""
        return _AlarmHandler(self)


def _can_interrupt() -> bool:
    return hasattr(signal, "SIGALRM") and hasattr(signal, "pthread_kill")


class _AlarmHandler:
    def __init__(self, watchdog: _Watchdog):
        self.watchdog = watchdog
        self.previous: Any = None

    def __enter__(self) -> None:
        if _can_interrupt() and threading.current_thread() is threading.main_thread():
            self.previous = signal.signal(signal.SIGALRM, self._handle)

    def _handle(self, _number: int, frame: FrameType | None) -> None:
        if self.watchdog.in_body:
            self.watchdog.where = launcher.trace_lines(launcher.stack_frames(frame))
            raise _TimedOut("the test ran out of time")

    def __exit__(self, *_exc: object) -> None:
        if self.previous is not None:
            signal.signal(signal.SIGALRM, self.previous)
