"""Checker speed: parse and check the whole stdlib plus a generated program of about 5,000 lines,
cold (no cache: the stdlib is parsed and all of it checked) and cached (the stdlib's syntax trees
come from the cache and its bodies, known clean, are not checked again).

The baseline measured in the same run is parsing alone of the same files, so `ratio` says what
checking costs on top of parsing. Targets on a 2-core machine: cold < 2 s, cached < 0.5 s.

Then the whole compiler as a user meets it, each run a fresh `python -m scoopc` process: the full
cold compile of a sample (`scoopc compile`: parse, check and codegen of the stdlib and the sample,
no caches; target < 3 s), and a cached `scoopc run` of the sample (stdlib and program compiled
before: start-up up to the program's first output line; target < 0.5 s) and of a trivial program
(the whole run).
Usage: python benchmarks/compile.py [--lines N] [--repeat K] [--sample DIR] [--no-full]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from scoopc import pipeline  # noqa: E402
from scoopc.project import collect  # noqa: E402
from scoopc.semantics.universe import stdlib_files  # noqa: E402

WORKER = """class WORKER_{n}
create
	make
feature
	make (a_id: INTEGER)
		do
			id := a_id
			create log.make_empty
			create values.make (10)
		end
	id: INTEGER
	total: INTEGER
	log: STRING
	values: ARRAYED_LIST [INTEGER]
	run (a_counter: separate COUNTER_{n}; a_rounds: INTEGER)
		require
			positive: a_rounds > 0
			open: not a_counter.is_closed
		local
			i: INTEGER
			l_text: STRING
		do
			from
				i := 1
			until
				i > a_rounds
			loop
				a_counter.increment (i)
				total := total + a_counter.value \\\\ 7
				values.extend (i * 2)
				i := i + 1
			variant
				a_rounds - i + 1
			end
			across values as v loop
				total := total + v.item
			end
			l_text := "worker " + id.out
			log.append (l_text)
			if attached {STRING} log as l_log and then not l_log.is_empty then
				print (l_log.count.out + "%N")
			end
		ensure
			counted: total >= old total
		end
	summary: STRING
		do
			Result := "worker " + id.out + ": " + total.out
			inspect id \\\\ 3
			when 0 then Result.append (" zero")
			when 1 then Result.append (" one")
			else Result.append (" two")
			end
		end
end
"""

COUNTER = """class COUNTER_{n}
create
	make
feature
	make do create history.make (4) end
	value: INTEGER
	is_closed: BOOLEAN
	history: ARRAYED_LIST [INTEGER]
	increment (a_by: INTEGER)
		require
			positive: a_by > 0
		do
			value := value + a_by
			history.extend (value)
		ensure
			grown: value = old value + a_by
		end
	close do is_closed := True end
invariant
	non_negative: value >= 0
end
"""

ROOT_CLASS = """class BENCH_ROOT
create
	make
feature
	make
		local
{locals}
		do
{body}
		end
	start (a_worker: separate ANY)
		do
		end
end
"""


def generate(directory: Path, lines: int) -> int:
    """Write about `lines` lines of classes into `directory`; return the exact count."""
    written, n = 0, 0
    locals_, body = [], []
    while written < lines:
        n += 1
        for template, name in ((WORKER, f"worker_{n}.e"), (COUNTER, f"counter_{n}.e")):
            text = template.replace("{n}", str(n))
            (directory / name).write_text(text, encoding="utf-8")
            written += text.count("\n")
        locals_.append(f"\t\t\tw{n}: separate WORKER_{n}\n\t\t\tc{n}: separate COUNTER_{n}")
        body.append(f"\t\t\tcreate w{n}.make ({n})\n\t\t\tcreate c{n}.make\n\t\t\tstart (w{n})")
    root = ROOT_CLASS.format(locals="\n".join(locals_), body="\n".join(body))
    (directory / "bench_root.e").write_text(root, encoding="utf-8")
    return written + root.count("\n")


def timed(action) -> tuple[float, object]:
    start = time.perf_counter()
    result = action()
    return time.perf_counter() - start, result


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=5000, help="size of the generated program (default 5,000)")
    options.add_argument("--repeat", type=int, default=3, help="timed runs of each kind; the median is reported")
    options.add_argument(
        "--sample",
        default=str(ROOT / "samples" / "producer_consumer"),
        help="the program of the full compile and start-up measures (default: %(default)s)",
    )
    options.add_argument("--no-full", action="store_true", help="skip the full compile and start-up measures")
    args = options.parse_args()
    library_lines = sum(p.read_text(encoding="utf-8").count("\n") for p in stdlib_files())
    with tempfile.TemporaryDirectory() as work:
        program = Path(work) / "program"
        program.mkdir()
        os.environ["SCOOPC_CACHE_DIR"] = str(Path(work) / "cache")
        lines = generate(program, args.lines)
        project = collect([str(program)])
        from scoopc.parse import parser

        kind = "lark-cython" if parser._accelerator() else "pure-Python lark"
        print(
            f"# scoopc compile benchmark: stdlib {library_lines} lines, program {lines} lines, "
            f"repeat={args.repeat}, parser {kind}",
            flush=True,
        )
        first, checked = timed(lambda: pipeline.check_project(project, use_cache=False, library_bodies=True))
        errors = [d for d in checked.diagnostics if d.is_error]
        if errors:
            sys.exit(f"benchmarks/compile.py: the generated program does not check: {errors[0]}")
        parse = statistics.median(timed(lambda: _parse_all(project))[0] for _ in range(args.repeat))
        cold = statistics.median(
            timed(lambda: pipeline.check_project(project, use_cache=False, library_bodies=True))[0]
            for _ in range(args.repeat)
        )
        pipeline.check_project(project, use_cache=True)  # fills the cache
        cached = statistics.median(
            timed(lambda: pipeline.check_project(project, use_cache=True))[0] for _ in range(args.repeat)
        )
    total = library_lines + lines
    print(f"first run (grammar load included): {first:.3f} s")
    print(f"parse only (baseline): {parse:.3f} s  ({total / parse:.0f} lines/s)")
    print(f"cold parse+check: {cold:.3f} s  ratio={cold / parse:.2f}  target < 2 s: {'met' if cold < 2 else 'MISSED'}")
    print(
        f"cached parse+check: {cached:.3f} s  ratio={cached / parse:.2f}  target < 0.5 s: "
        f"{'met' if cached < 0.5 else 'MISSED'}"
    )
    if not args.no_full:
        full_compile(Path(args.sample), args.repeat)


# --- the whole compiler, as `scoopc compile` and `scoopc run` in fresh processes ---------------------
TRIVIAL = """class HELLO
create
	make
feature
	make
		do
			print ("hello%N")
		end
end
"""


def scoopc(arguments: list, cache: Path, first_line: bool = False) -> float:
    """Seconds a fresh `python -m scoopc ARGUMENTS` takes: until it exits, or until its first
    line of output (then it is let finish); fails loudly when the command fails."""
    env = dict(os.environ, SCOOPC_CACHE_DIR=str(cache))
    command = [sys.executable, "-m", "scoopc"] + arguments
    start = time.perf_counter()
    with subprocess.Popen(
        command, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    ) as child:
        if first_line:
            child.stdout.readline()
            seconds = time.perf_counter() - start
        out, err = child.communicate(timeout=300)
        if not first_line:
            seconds = time.perf_counter() - start
    if child.returncode != 0:
        sys.exit(f"benchmarks/compile.py: scoopc {' '.join(arguments)} failed ({child.returncode}): {err.strip()}")
    return seconds


def full_compile(sample: Path, repeat: int) -> None:
    """Cold `scoopc compile` of the sample (an empty cache each time), then cached `scoopc run`s."""
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        colds = []
        for index in range(repeat):
            colds.append(scoopc(["compile", str(sample), "-o", str(work / f"out{index}")], work / f"cold{index}"))
        cache = work / "warm"
        trivial = work / "hello"
        trivial.mkdir()
        (trivial / "hello.e").write_text(TRIVIAL)
        scoopc(["run", str(sample)], cache)  # compiles stdlib and sample once
        scoopc(["run", str(trivial)], cache)
        starts = [scoopc(["run", str(sample)], cache, first_line=True) for _ in range(repeat)]
        runs = [scoopc(["run", str(trivial)], cache) for _ in range(repeat)]
    cold, start, run = statistics.median(colds), statistics.median(starts), statistics.median(runs)
    name = sample.name
    print(
        f"full cold compile of the stdlib and {name} (scoopc compile, no caches): {cold:.3f} s  "
        f"target < 3 s: {'met' if cold < 3 else 'MISSED'}"
    )
    print(
        f"cached scoopc run {name}: start-up to the first output line {start:.3f} s  "
        f"target < 0.5 s: {'met' if start < 0.5 else 'MISSED'}"
    )
    print(
        f"cached scoopc run of a trivial program (whole run): {run:.3f} s  "
        f"target < 0.5 s: {'met' if run < 0.5 else 'MISSED'}"
    )


def _parse_all(project) -> None:
    from scoopc.parse import parser
    from scoopc.source import SourceFile

    for path in list(project.files) + stdlib_files():
        parser.parse(SourceFile.read(str(path)))


if __name__ == "__main__":
    main()
