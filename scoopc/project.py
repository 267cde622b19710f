"""Input collection: command-line paths (.e files, cluster directories, .ecf files) -> a Project.

A Project lists the user's source files, the root named by an .ecf, the settings we honour and
notes for what we ignore. The standard library is added by later stages, not here.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path

from . import diagnostics
from .diagnostics import Diagnostic
from .exits import UsageError
from .source import Span

# Libraries whose classes our stdlib provides (EiffelBase/FreeELKS and the SCOOP support around it).
BASE_LIBRARIES = {"base", "base_extension", "free_elks", "elks", "thread", "time", "api_wrapper"}
# Libraries that are our own stdlib's clusters.
OWN_LIBRARIES = {"roboscoop"}


@dataclass
class Root:
    class_name: str
    creation: str = "make"


@dataclass
class Settings:
    """What an .ecf (or the command line) asks of the compiler."""

    assertions: str | None = None  # "all" | "require" | "none"; None: the tool's default
    void_safety: str | None = None  # "none" | "conformance" | "initialization" | "transitional" | "all"
    concurrency: str | None = None  # "scoop" | "thread" | "none"


@dataclass
class Project:
    files: list[Path] = field(default_factory=list)
    root: Root | None = None
    settings: Settings = field(default_factory=Settings)
    notes: list[Diagnostic] = field(default_factory=list)
    errors: list[Diagnostic] = field(default_factory=list)

    def add_file(self, path: Path) -> None:
        resolved = path.resolve()
        if all(f.resolve() != resolved for f in self.files):
            self.files.append(path)


def collect(paths: list[str], target: str | None = None) -> Project:
    """Gather the source files named by `paths` (files, directories, .ecf files)."""
    project = Project()
    for raw in paths:
        path = Path(raw)
        if not path.exists():
            raise UsageError(f"no such file or directory: {raw}")
        if path.is_dir():
            _add_cluster(project, path, recursive=True)
        elif path.suffix.lower() == ".e":
            project.add_file(path)
        elif path.suffix.lower() == ".ecf":
            _read_ecf(project, path, target)
        else:
            raise UsageError(f"{raw}: expected a .e file, a directory or an .ecf file")
    if not project.files and not project.errors:
        raise UsageError("no Eiffel source files (.e) found in " + ", ".join(paths))
    return project


def _add_cluster(
    project: Project,
    directory: Path,
    recursive: bool,
    excludes: tuple[re.Pattern, ...] = (),
    includes: tuple[re.Pattern, ...] = (),
) -> None:
    pattern = "**/*.e" if recursive else "*.e"
    for file in sorted(directory.glob(pattern)):
        parts = file.relative_to(directory).parts
        hidden = any(part.startswith(".") or part == "EIFGENs" for part in parts)
        if file.is_file() and not hidden and not _excluded(parts, excludes, includes):
            project.add_file(file)


def _excluded(parts: tuple[str, ...], excludes: tuple[re.Pattern, ...], includes: tuple[re.Pattern, ...]) -> bool:
    """An .ecf file rule excludes a file when a pattern matches its path or a folder above it
    (`/skipped$` excludes everything in `skipped/`), unless an include pattern matches."""
    prefixes = ["/" + "/".join(parts[:i]) for i in range(1, len(parts) + 1)]
    excluded = any(p.search(prefix) for p in excludes for prefix in prefixes)
    return excluded and not any(p.search(prefix) for p in includes for prefix in prefixes)


# --- .ecf ----------------------------------------------------------------------------------


def _local(tag: str) -> str:
    """An element's tag without its XML namespace."""
    return tag.rsplit("}", 1)[-1]


def _children(element: ElementTree.Element, name: str) -> list[ElementTree.Element]:
    return [child for child in element if _local(child.tag) == name]


def _ecf_span(path: Path) -> Span:
    return Span(str(path), 1, 1, 1, 2)


def _read_ecf(project: Project, path: Path, target_name: str | None) -> None:
    try:
        system = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as problem:
        line, column = problem.position
        span = Span(str(path), line, column + 1, line, column + 2)
        project.errors.append(diagnostics.make("ECF", span, reason=f"{path} is not well-formed XML: {problem}"))
        return
    except OSError as problem:
        project.errors.append(diagnostics.make("ECF", _ecf_span(path), reason=f"cannot read {path}: {problem}"))
        return
    targets = {t.get("name", ""): t for t in _children(system, "target")}
    if not targets:
        project.errors.append(diagnostics.make("ECF", _ecf_span(path), reason=f"{path} defines no target"))
        return
    chosen = _choose_target(project, path, targets, target_name)
    if chosen is None:
        return
    for element in _target_chain(chosen, targets):
        _read_target(project, path, element)


def _choose_target(project: Project, path: Path, targets: dict, wanted: str | None):
    if wanted is not None:
        if wanted not in targets:
            project.errors.append(
                diagnostics.make(
                    "ECF",
                    _ecf_span(path),
                    reason=f"{path} has no target `{wanted}`; its targets are: {', '.join(targets)}",
                )
            )
            return None
        return targets[wanted]
    concrete = [t for t in targets.values() if t.get("abstract", "false").lower() != "true"]
    # EiffelStudio picks the last concrete target when none is named.
    return (concrete or list(targets.values()))[-1]


def _target_chain(target: ElementTree.Element, targets: dict) -> list[ElementTree.Element]:
    """The target and the targets it extends, most general first."""
    chain = [target]
    while chain[0].get("extends") in targets and targets[chain[0].get("extends")] not in chain:
        chain.insert(0, targets[chain[0].get("extends")])
    return chain


def _expand_location(location: str, base: Path) -> Path:
    text = location.replace("\\", "/")
    text = re.sub(r"\$\(?(\w+)\)?", lambda m: os.environ.get(m.group(1), m.group(0)), text)
    candidate = Path(text)
    return candidate if candidate.is_absolute() else (base / candidate)


_IGNORED_QUIETLY = {"note", "description", "file_rule", "version", "uuid"}


def _read_target(project: Project, ecf: Path, target: ElementTree.Element) -> None:
    base = ecf.parent
    for element in target:
        kind = _local(element.tag)
        if kind == "root":
            _read_root(project, element)
        elif kind in ("cluster", "override"):  # an override cluster's classes replace library ones
            _read_cluster(project, ecf, element, base)
        elif kind in ("library", "precompile"):
            _read_library(project, ecf, element)
        elif kind == "option":
            _read_option(project, element)
        elif kind == "capability":
            _read_capability(project, element)
        elif kind == "setting":
            _note(project, ecf, f"setting `{element.get('name')}` is ignored")
        elif kind not in _IGNORED_QUIETLY:
            _note(project, ecf, f"<{kind}> is not supported and is ignored")


def _note(project: Project, ecf: Path, reason: str) -> None:
    project.notes.append(diagnostics.make("ECF-NOTE", _ecf_span(ecf), severity=diagnostics.NOTE, reason=reason))


def _read_root(project: Project, element: ElementTree.Element) -> None:
    if element.get("all_classes", "false").lower() == "true" or not element.get("class"):
        return
    project.root = Root(element.get("class").upper(), (element.get("feature") or "make").lower())


def _patterns(element: ElementTree.Element, kind: str) -> tuple[re.Pattern, ...]:
    found = []
    for rule in _children(element, "file_rule"):
        for item in _children(rule, kind):
            try:
                found.append(re.compile(item.text or ""))
            except re.error:
                continue
    return tuple(found)


def _read_cluster(project: Project, ecf: Path, element: ElementTree.Element, base: Path) -> None:
    location = _expand_location(element.get("location", "."), base)
    if not location.is_dir():
        project.errors.append(
            diagnostics.make("ECF", _ecf_span(ecf), reason=f"cluster `{element.get('name')}`: no directory {location}")
        )
        return
    recursive = element.get("recursive", "false").lower() == "true"
    _add_cluster(project, location, recursive, _patterns(element, "exclude"), _patterns(element, "include"))
    for sub in _children(element, "cluster"):
        _read_cluster(project, ecf, sub, location)


def _read_library(project: Project, ecf: Path, element: ElementTree.Element) -> None:
    name = (element.get("name") or "").lower()
    location = (element.get("location") or "").replace("\\", "/").lower()
    stem = Path(location).stem
    if name in BASE_LIBRARIES or stem in BASE_LIBRARIES or stem.startswith("base"):
        return  # the standard library is always available
    if name in OWN_LIBRARIES or stem in OWN_LIBRARIES:
        return
    _note(
        project,
        ecf,
        f"library `{element.get('name')}` ({element.get('location')}) is not available; "
        "only EiffelBase (our stdlib) and Roboscoop are",
    )


def _read_option(project: Project, element: ElementTree.Element) -> None:
    void_safety = element.get("void_safety")
    if void_safety:
        project.settings.void_safety = void_safety.lower()
    for assertions in _children(element, "assertions"):
        checked = {k for k, v in assertions.attrib.items() if v.lower() == "true"}
        if checked - {"precondition"}:
            project.settings.assertions = "all"
        elif "precondition" in checked:
            project.settings.assertions = "require"
        else:
            project.settings.assertions = "none"


def _read_capability(project: Project, element: ElementTree.Element) -> None:
    for child in element:
        kind, support = _local(child.tag), (child.get("use") or child.get("support") or "").lower()
        if kind == "concurrency" and support:
            project.settings.concurrency = support
        elif kind == "void_safety" and support:
            project.settings.void_safety = support
