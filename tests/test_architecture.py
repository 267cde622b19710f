"""docs/ARCHITECTURE.md stays true: every repository path it names exists."""

import re

from harness import ROOT

PATH_LIKE = re.compile(r"`([A-Za-z_][\w./-]*(?:/|\.(?:py|lark|toml|md|e)))`")


def named_paths():
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    return sorted(set(PATH_LIKE.findall(text)))


def test_architecture_names_paths():
    assert len(named_paths()) >= 10


def test_every_path_named_in_architecture_exists():
    missing = [p for p in named_paths() if not (ROOT / p).exists()]
    assert not missing, f"docs/ARCHITECTURE.md names paths that do not exist: {missing}"
