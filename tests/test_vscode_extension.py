"""The VS Code extension (editors/vscode): `npm ci` from its lockfile, its grammar tests (annotated
excerpts of the samples, and every class of samples/ and stdlib/ tokenized with no invalid token
and no runaway string) and the .vsix build. Skipped only where node and npm are absent; .ci/run sets
SCOOPC_REQUIRE_NPM=1 so that CI fails instead of skipping."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

EXTENSION = Path(__file__).resolve().parent.parent / "editors" / "vscode"
NPM = shutil.which("npm")

pytestmark = pytest.mark.slow

if NPM is None and os.environ.get("SCOOPC_REQUIRE_NPM") != "1":
    pytestmark = [
        pytest.mark.slow,
        pytest.mark.skip(reason="npm (Node.js) is not installed: the VS Code extension cannot be built"),
    ]


def _npm(*arguments: str) -> subprocess.CompletedProcess:
    assert NPM is not None, "SCOOPC_REQUIRE_NPM=1 but npm is not on PATH"
    done = subprocess.run([NPM, *arguments], cwd=EXTENSION, capture_output=True, text=True, timeout=900, check=False)
    assert done.returncode == 0, f"npm {' '.join(arguments)} failed:\n{done.stdout}\n{done.stderr}"
    return done


def test_the_extension_installs_passes_its_grammar_tests_and_packages(tmp_path):
    _npm("ci", "--prefer-offline", "--no-audit", "--no-fund")
    _npm("run", "test:client")  # the client's JavaScript parses
    grammar = _npm("run", "test:grammar")
    assert grammar.stdout.count("run successfuly") == len(list((EXTENSION / "test").glob("*.e")))
    samples = _npm("run", "test:samples")
    tokenized = int(samples.stdout.strip().split("\n")[-1].split()[0])
    assert tokenized == len(list((EXTENSION.parent.parent / "samples").rglob("*.e"))) + len(
        list((EXTENSION.parent.parent / "stdlib").rglob("*.e"))
    )
    vsix = tmp_path / "scoopc-eiffel.vsix"
    _npm("exec", "--", "vsce", "package", "--skip-license", "--allow-missing-repository", "--out", str(vsix))
    with zipfile.ZipFile(vsix) as archive:
        names = set(archive.namelist())
        manifest = json.loads(archive.read("extension/package.json"))
    for inside in (
        "extension.js",
        "language-configuration.json",
        "syntaxes/eiffel.tmLanguage.json",
        "snippets/eiffel.json",
    ):
        assert f"extension/{inside}" in names
    assert "extension/node_modules/vscode-languageclient/package.json" in names  # the client ships with it
    assert not any(name.startswith("extension/test/") for name in names)
    assert manifest["contributes"]["languages"][0]["extensions"] == [".e"]
