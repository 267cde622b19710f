"""The checker never fails on a program that parses: mutants of the valid programs (lines
deleted, swapped or with a name replaced) give diagnostics, never an exception."""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from scoopc import api, exits, pipeline
from scoopc.project import collect

TESTS = Path(__file__).resolve().parents[1]
PROGRAMS = sorted(p for p in (TESTS / "semantics" / "valid").iterdir() if p.is_dir()) + sorted(
    (TESTS / "syntax" / "valid").glob("*.e")
)
WORDS = [
    "Current",
    "Result",
    "Void",
    "item",
    "count",
    "separate",
    "attached",
    "detachable",
    "STRING",
    "INTEGER",
    "ANY",
    "NONE",
    "like Current",
    "42",
    '"s"',
    "old item",
    "agent make",
    "create {STRING}.make_empty",
    "[1, 2]",
    "<<1>>",
    "(1 |..| 3)",
    "x.y.z",
    "not",
    "+",
]

edits = st.lists(
    st.tuples(
        st.sampled_from(["delete", "replace", "swap"]),
        st.integers(0, 10**6),
        st.integers(0, 10**6),
        st.sampled_from(WORDS),
    ),
    min_size=1,
    max_size=3,
)


def mutate(lines: list, edit) -> None:
    kind, i, j, word = edit
    if not lines:
        return
    i, j = i % len(lines), j % len(lines)
    if kind == "delete":
        del lines[i]
    elif kind == "swap":
        lines[i], lines[j] = lines[j], lines[i]
    else:
        names = re.findall(r"[A-Za-z_][A-Za-z_0-9]*", lines[i])
        if names:
            lines[i] = lines[i].replace(names[j % len(names)], word, 1)


# Each example checks a whole program: 40 keep the default run short; the thorough profile runs 1,000.
EXAMPLES = 1000 if os.environ.get("SCOOPC_HYPOTHESIS_PROFILE") == "thorough" else 40


@pytest.mark.slow
@settings(max_examples=EXAMPLES)
@given(program=st.sampled_from(PROGRAMS), which=st.integers(0, 100), changes=edits)
def test_a_mutated_program_gets_diagnostics_not_a_crash(tmp_path_factory, program, which, changes):
    folder = tmp_path_factory.mktemp("mutant")
    sources = sorted(program.glob("*.e")) if program.is_dir() else [program]
    for source in sources:
        (folder / source.name).write_text(source.read_text(encoding="utf-8"), encoding="utf-8")
    target = folder / sources[which % len(sources)].name
    lines = target.read_text(encoding="utf-8").splitlines()
    for change in changes:
        mutate(lines, change)
    target.write_text("\n".join(lines) + "\n", encoding="utf-8")
    checked = pipeline.check_project(collect([str(folder)]))
    assert all(d.span is not None and d.code for d in checked.diagnostics)


GOLDEN = sorted(p for p in (TESTS / "golden").iterdir() if p.is_dir() and any(p.glob("*.e")))


@pytest.mark.slow
@settings(max_examples=EXAMPLES // 4, deadline=None)
@given(program=st.sampled_from(GOLDEN), which=st.integers(0, 100), changes=edits)
def test_a_mutant_that_checks_clean_compiles_and_runs_or_fails_with_exit_3(tmp_path_factory, program, which, changes):
    """The code generator never meets what the checker let through as a surprise (tools/fuzz_long.py
    runs this at length)."""
    folder = tmp_path_factory.mktemp("mutant") / program.name
    folder.mkdir()
    sources = sorted(program.glob("*.e"))
    for source in sources:
        (folder / source.name).write_text(source.read_text(encoding="utf-8"), encoding="utf-8")
    target = folder / sources[which % len(sources)].name
    lines = target.read_text(encoding="utf-8").splitlines()
    for change in changes:
        mutate(lines, change)
    target.write_text("\n".join(lines) + "\n", encoding="utf-8")
    if pipeline.check_project(collect([str(folder)])).has_errors:
        return
    try:
        result = api.compile([str(folder)], folder.parent / "out")
    except exits.UsageError:
        return  # the mutant lost its root class
    assert result.status == 0
    try:
        done = subprocess.run(
            [sys.executable, "-m", result.package.name],
            cwd=result.package.parent,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=10,
        )
    except subprocess.TimeoutExpired:
        return  # a mutant may loop forever
    assert done.returncode in (0, 3), done.stderr[-2000:]
