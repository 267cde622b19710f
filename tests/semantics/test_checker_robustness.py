"""The checker never fails on a program that parses: mutants of the valid programs (lines
deleted, swapped or with a name replaced) give diagnostics, never an exception."""

import os
import re
from pathlib import Path

from hypothesis import given, settings, strategies as st

from scoopc import pipeline
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
