"""The Python API: `scoopc.check`, `scoopc.compile`, `scoopc.run` and `scoopc.test` do what the commands of the
same names do, with options as keyword arguments and results as records (scoopc.results), never
printing diagnostics (docs/API.md). A usage mistake raises scoopc.UsageError; source errors come
back as the result's diagnostics with status 1."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, TextIO

from .driver import Compilation, RunOptions, TestOptions, run_compilation, run_tests
from .exits import Exit, SourceErrors, UsageError
from .results import CheckResult, CompileResult, RunResult, TestOutcome, TestResult
from .robots.runner import RobotOptions

PathLike = str | Path
Progress = Callable[[str], None] | None

__all__ = [
    "CheckResult",
    "CompileResult",
    "RunResult",
    "TestOutcome",
    "TestResult",
    "UsageError",
    "check",
    "compile",
    "run",
    "test",
]


def check(paths: Sequence[PathLike], *, target: str | None = None) -> CheckResult:
    """Check a program (its .e files, cluster folders or .ecf project): every syntax, validity and
    SCOOP error, as `scoopc check` reports them."""
    compilation = Compilation(paths, target=target)
    found = compilation.checked.diagnostics
    return CheckResult(Exit.SOURCE if compilation.checked.has_errors else Exit.OK, found)


def compile(
    paths: Sequence[PathLike],
    output: PathLike = "build",
    *,
    target: str | None = None,  # noqa: A001
    root: str | None = None,
    assertions: str | None = None,
    progress: Progress = None,
) -> CompileResult:
    """Check, then write readable Python: `output/<root>` (the program, runnable with `python -m`)
    beside `output/eiffel_base` (the compiled standard library), as `scoopc compile -o` does."""
    compilation = Compilation(paths, target=target, root=root, assertions=assertions, progress=progress)
    try:
        program = compilation.compile_to(output)
    except SourceErrors as errors:
        return CompileResult(Exit.SOURCE, errors.diagnostics)
    return CompileResult(
        Exit.OK, compilation.checked.diagnostics, program.folder / program.package, program.folder / "eiffel_base"
    )


def run(
    paths: Sequence[PathLike],
    args: Sequence[str] = (),
    *,
    target: str | None = None,
    root: str | None = None,
    assertions: str | None = None,
    cache: bool = True,
    progress: Progress = None,
    trace_processors: bool = False,
    strict: bool = False,
    virtual_clock: bool = False,
    debug: bool = False,
    stdout: TextIO | None = None,
    stderr: TextIO | None = None,
    robot: str | None = None,
    world: Any = None,
    namespace: str | None = None,
    realtime: bool = False,
    duration: float | None = None,
    goal: tuple | None = None,
    png: PathLike | bool | None = None,
    gif: PathLike | None = None,
    record: PathLike | None = None,
    ros_distro: str | None = None,
    use_sim_time: bool = False,
    wait_robot: float = 3.0,
    require_robot: bool = False,
    profile: PathLike | None = None,
    node_name: str | None = None,
    status: float | None = None,
    live: int | None = None,
) -> RunResult:
    """Compile (cached by content unless `cache` is false) and run a program in this process, as
    `scoopc run` does; `args` are the program's arguments. A Roboscoop program runs on the
    simulator unless `robot` says "ros2" or "none"; `png=True` draws the trajectory in
    runs/<root>/<n>/<root>.png. The result's `status` is the program's exit status."""
    compilation = Compilation(paths, target=target, root=root, assertions=assertions, progress=progress)
    options = RunOptions(trace_processors, strict, virtual_clock, debug, stdout, stderr, status=status, live=live)
    robot_options = RobotOptions(
        robot,
        world,
        namespace,
        realtime or live is not None,
        duration,
        goal,
        png,
        gif,
        record,
        ros_distro=ros_distro,
        use_sim_time=use_sim_time,
        wait_robot=wait_robot,
        require_robot=require_robot,
        profile=profile,
        node_name=node_name,
    )
    try:
        result = run_compilation(compilation, args, options, robot_options, use_cache=cache)
    except SourceErrors as errors:
        return RunResult(Exit.SOURCE, errors.diagnostics)
    if compilation.was_checked:  # compiled now, not taken from the cache
        result.diagnostics = compilation.checked.diagnostics
    return result


def test(
    paths: Sequence[PathLike],
    *,
    target: str | None = None,
    assertions: str | None = None,
    pattern: str | None = None,
    timeout: float = 30.0,
    junit: PathLike | None = None,
    debug: bool = False,
    progress: Progress = None,
    on_outcome: Callable[[TestOutcome], None] | None = None,
) -> TestResult:
    """Run the program's tests (the procedures of its descendants of EQA_TEST_SET), each in a
    runtime of its own within `timeout` seconds, as `scoopc test` does; `pattern` selects (-k),
    `junit` names a JUnit XML file to write, `on_outcome` is told of each test as it ends. The
    result's `status` is 0 when every test passed, 1 when one failed or the program has errors."""
    compilation = Compilation(paths, target=target, assertions=assertions, progress=progress)
    options = TestOptions(pattern, timeout, junit, debug, on_outcome)
    try:
        result = run_tests(compilation, options)
    except SourceErrors as errors:
        return TestResult(Exit.SOURCE, errors.diagnostics)
    result.diagnostics = compilation.checked.diagnostics
    return result
