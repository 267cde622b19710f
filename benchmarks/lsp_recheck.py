"""Language server: seconds from an edit to its diagnostics. `scoopc lsp` runs as an editor starts
it (a process on stdio); a 300-line class (with a separate buffer, wait conditions, contracts and
loops) is opened, then edited K times, each edit timed from the didChange notification to the
publishDiagnostics of that version: the program is checked again with the standard library held in
memory. Every other edit puts a mistake in (VEEN) and the next takes it out, and the diagnostics are
checked each time. Target: at most 0.3 s.

The baseline is what a student does without the server: `scoopc check` of the same folder in a fresh
process (the stdlib from scoopc's cache); `ratio` is the re-check over that.
Usage: python benchmarks/lsp_recheck.py [--lines N] [--repeat K] [--unpinned]
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

from scoopc.lsp.client import Client  # noqa: E402

BUFFER = """class
	STORE

create
	make

feature {NONE} -- Initialization

	make
			-- An empty store.
		do
			create items.make (10)
		end

feature -- Access

	items: ARRAYED_LIST [INTEGER]
			-- What the store holds.

	count: INTEGER
			-- How many items.
		do
			Result := items.count
		end

feature -- Element change

	put (a_value: INTEGER)
			-- Add `a_value'.
		do
			items.extend (a_value)
		ensure
			one_more: count = old count + 1
		end

end
"""

HEAD = """note
	description: "A controller with many routines: the class the benchmark edits."

class
	CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_store: separate STORE)
			-- Controller of `a_store'.
		do
			store := a_store
		end

feature -- Access

	store: separate STORE
			-- Where readings go.

	total: INTEGER
			-- Sum of the readings so far.

feature -- Basic operations
"""

ROUTINE = """
	step_{n} (a_store: separate STORE; a_value: INTEGER)
			-- Put `a_value' times {n} into `a_store' once it has fewer than {limit} items.
		require
			room: a_store.count < {limit}
			positive: a_value > 0
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > {n}
			loop
				total := total + a_value * i
				i := i + 1
			end
			a_store.put (a_value * {n})
		ensure
			grown: total >= old total
		end
"""


def generate(folder: Path, lines: int) -> Path:
    (folder / "store.e").write_text(BUFFER)
    parts, n = [HEAD], 1
    while sum(p.count("\n") for p in parts) < lines - 2:
        parts.append(ROUTINE.format(n=n, limit=10 + n))
        n += 1
    parts.append("\nend\n")
    path = folder / "controller.e"
    path.write_text("".join(parts))
    return path


def pin(unpinned: bool, pid: int) -> str:
    if unpinned:
        return "unpinned"
    if not hasattr(os, "sched_setaffinity"):
        return "unpinned (no sched_setaffinity on this platform)"
    cpu = min(os.sched_getaffinity(0))
    os.sched_setaffinity(pid, {cpu})
    return f"pinned to CPU {cpu}"


def cli_check(folder: Path, repeat: int) -> float:
    """Median seconds of `scoopc check FOLDER` in a fresh process (exit 0 expected)."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        done = subprocess.run([sys.executable, "-m", "scoopc", "check", str(folder)], capture_output=True, text=True)
        times.append(time.perf_counter() - start)
        if done.returncode != 0:
            sys.exit(f"benchmarks/lsp_recheck.py: the generated program does not check:\n{done.stderr}")
    return statistics.median(times)


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=300, help="size of the edited class (default 300)")
    options.add_argument("--repeat", type=int, default=20, help="timed edits; the median is reported")
    options.add_argument("--unpinned", action="store_true", help="do not pin the server to one CPU")
    args = options.parse_args()
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work) / "program"
        folder.mkdir()
        path = generate(folder, args.lines)
        text = path.read_text()
        baseline = cli_check(folder, min(3, args.repeat))
        server = subprocess.Popen(
            [sys.executable, "-m", "scoopc", "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, cwd=work
        )
        where = pin(args.unpinned, server.pid)
        print(f"# scoopc lsp re-check: class of {text.count(chr(10))} lines, repeat={args.repeat}, server {where}")
        client = Client(server.stdout, server.stdin)
        try:
            first, times = measure(client, path, text, args.repeat)
            client.shutdown()
        finally:
            server.stdin.close()
            server.wait(timeout=30)
    recheck = statistics.median(times)
    print(f"first check after open (stdlib loaded): {first:.3f} s")
    print(f"baseline `scoopc check` in a fresh process: {baseline:.3f} s")
    print(
        f"re-check after an edit: median {recheck:.3f} s, min {min(times):.3f} s, max {max(times):.3f} s  "
        f"ratio={recheck / baseline:.2f}  target <= 0.3 s: {'met' if recheck <= 0.3 else 'MISSED'}"
    )


def measure(client: Client, path: Path, text: str, repeat: int) -> tuple[float, list[float]]:
    client.initialize(path.parent)
    start = time.perf_counter()
    uri = client.open(path, text)
    found = client.diagnostics(uri)
    first = time.perf_counter() - start
    if found:
        sys.exit(f"benchmarks/lsp_recheck.py: unexpected diagnostics {found}")
    times = []
    for version in range(2, repeat + 2):
        wrong = version % 2 == 0
        edited = text.replace("a_store.put (a_value * 1)", "a_store.putt (a_value * 1)") if wrong else text
        start = time.perf_counter()
        client.change(uri, edited, version)
        found = client.diagnostics(uri, version)
        times.append(time.perf_counter() - start)
        codes = [d["code"] for d in found]
        if codes != (["VEEN"] if wrong else []):
            sys.exit(f"benchmarks/lsp_recheck.py: edit {version}: diagnostics {codes}")
    return first, times


if __name__ == "__main__":
    main()
