"""Every class of the standard library checks cleanly, bodies included (no cache)."""

from pathlib import Path

import pytest

from scoopc import diagnostics, pipeline
from scoopc.project import Project
from scoopc.semantics.universe import stdlib_files


def test_every_stdlib_class_checks_without_diagnostics():
    checked = pipeline.check_project(Project(), use_cache=False, library_bodies=True)
    assert not checked.diagnostics, "\n".join(diagnostics.short(d) for d in checked.diagnostics)


def test_stdlib_holds_the_kernel_classes_programs_name():
    names = {p.stem.upper() for p in stdlib_files()}
    wanted = {
        "ANY",
        "INTEGER_32",
        "REAL_64",
        "BOOLEAN",
        "CHARACTER_8",
        "STRING_8",
        "STRING_32",
        "ARRAY",
        "SPECIAL",
        "TUPLE",
        "CELL",
        "ARRAYED_LIST",
        "LINKED_LIST",
        "ARRAYED_QUEUE",
        "HASH_TABLE",
        "PROCEDURE",
        "FUNCTION",
        "PREDICATE",
        "EXECUTION_ENVIRONMENT",
        "ARGUMENTS",
        "RANDOM",
        "DOUBLE_MATH",
        "STD_FILES",
        "IMMUTABLE_STRING_8",
        "TYPE",
        "EXCEPTIONS",
        "PLAIN_TEXT_FILE",
    }
    assert wanted <= names, sorted(wanted - names)


@pytest.mark.slow  # 5 to 12 s: outside the quick selection
def test_cached_check_reports_what_a_cold_check_reports(tmp_path, monkeypatch):
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")  # the cache file, not the one a wheel ships
    sample = Path(__file__).resolve().parents[2] / "samples" / "producer_consumer"
    from scoopc.project import collect

    cold = pipeline.check_project(collect([str(sample)]), use_cache=False, library_bodies=False)
    pipeline.check_project(collect([str(sample)]), use_cache=True)
    warm = pipeline.check_project(collect([str(sample)]), use_cache=True)
    assert [diagnostics.short(d) for d in warm.diagnostics] == [diagnostics.short(d) for d in cold.diagnostics]
    assert any(tmp_path.iterdir()), "the cache was not written"


@pytest.mark.slow  # 5 to 12 s: outside the quick selection
def test_a_damaged_cache_is_ignored_and_rewritten(tmp_path, monkeypatch):
    monkeypatch.setenv("SCOOPC_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv("SCOOPC_NO_PREBUILT", "1")  # the cache file, not the one a wheel ships
    sample = Path(__file__).resolve().parents[2] / "samples" / "producer_consumer"
    from scoopc.project import collect

    pipeline.check_project(collect([str(sample)]))
    (cache,) = tmp_path.glob("stdlib-*.pickle")
    cache.write_bytes(b"\x80\x04not a pickle at all")
    checked = pipeline.check_project(collect([str(sample)]))
    assert not checked.diagnostics
    assert cache.read_bytes()[:20] != b"\x80\x04not a pickle at all"[:20]
