"""Input collection: command-line paths (.e files, cluster directories, .ecf files) -> a Project.

A Project lists the user's source files, the root named by an .ecf, the settings we honour and
notes for what we ignore. The standard library is added by later stages, not here.
"""

from __future__ import annotations

import os
import re
import sys
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from . import diagnostics
from .diagnostics import Diagnostic
from .exits import UsageError
from .source import Span

# The .ecf libraries our stdlib provides, by the name EiffelStudio gives each (its `name`, or the
# folder under $ISE_LIBRARY/library/ of its `location`), and the stdlib cluster that is each one:
# EiffelBase (FreeELKS is its kernel, `base-safe`/`base-scoop-safe` are its older .ecf files),
# EiffelThread, EiffelTime, EiffelStudio's testing library and Roboscoop.
STDLIB_LIBRARIES = {
    "base": "base",
    "free_elks": "base",
    "elks": "base",
    "thread": "thread",
    "time": "time",
    "testing": "testing",
    "roboscoop": "roboscoop",
}
# Libraries of EiffelStudio that we are going to provide, named in a note rather than an error.
PLANNED_LIBRARIES: dict[str, str] = {}
# Variables naming EiffelStudio's installation in library locations.
_ISE_VARIABLES = ("ISE_LIBRARY", "ISE_EIFFEL")


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
    syntax: str | None = None  # "obsolete" | "transitional" | "standard" | "provisional"; None: standard


@dataclass
class ExternalSettings:
    """What an .ecf names for the program's externals (docs/LANGUAGE.md, Externals): C headers'
    folders, objects, sources and libraries to build and link with, compiler and linker flags,
    and folders of Python modules (`<variable name="python_path">`)."""

    include_dirs: list[Path] = field(default_factory=list)
    objects: list[Path] = field(default_factory=list)  # .o/.a/.so files, and .c/.cpp sources to compile
    libraries: list[str] = field(default_factory=list)  # -lNAME
    cflags: list[str] = field(default_factory=list)
    linker_flags: list[str] = field(default_factory=list)
    python_paths: list[Path] = field(default_factory=list)


@dataclass
class Project:
    files: list[Path] = field(default_factory=list)
    root: Root | None = None
    settings: Settings = field(default_factory=Settings)
    notes: list[Diagnostic] = field(default_factory=list)
    errors: list[Diagnostic] = field(default_factory=list)
    libraries: list[str] = field(default_factory=list)  # the stdlib clusters the .ecf names
    ecf_files: list[Path] = field(default_factory=list)  # every .ecf read (libraries' included)
    externals: ExternalSettings = field(default_factory=ExternalSettings)
    # (library name, its concurrency support, where it is named): checked against the system's
    library_concurrency: list[tuple[str, str, Span]] = field(default_factory=list)
    # the syntax level of the files of each .ecf's clusters (a library's own, else the application's)
    file_syntax: dict[Path, str] = field(default_factory=dict)
    # Visibility, as EiffelStudio groups classes: each file's .ecf, and what each .ecf names
    # directly (stdlib clusters by name, user libraries by their .ecf); empty without an .ecf.
    file_group: dict[Path, Path] = field(default_factory=dict)
    group_names: dict[Path, set] = field(default_factory=dict)

    def visibility(self) -> Visibility | None:
        """Which classes each class sees; None when every class sees every other (no .ecf: the
        command line's files and the whole standard library)."""
        if not self.group_names:
            return None
        return Visibility(dict(self.file_group), {g: frozenset(n) for g, n in self.group_names.items()})

    def syntax_level(self, path: Path) -> str:
        return self.file_syntax.get(Path(path).resolve(), self.settings.syntax or "standard")

    @property
    def concurrency(self) -> str:
        """The system's concurrency: the .ecf's, else SCOOP (EiffelStudio's default since ECF 1.16)."""
        return self.settings.concurrency or "scoop"

    def add_file(self, path: Path) -> None:
        resolved = path.resolve()
        if all(f.resolve() != resolved for f in self.files):
            self.files.append(path)


@dataclass(frozen=True)
class Visibility:
    """EiffelStudio's visibility of classes between groups: a class sees the classes of its own
    .ecf's clusters, of the libraries that .ecf names directly (a library's libraries are its
    own), and EiffelBase (every system has it; scoopc does not ask for it to be named)."""

    file_group: dict  # file -> the .ecf whose cluster holds it
    group_names: dict  # .ecf -> the stdlib clusters and the libraries' .ecf files it names

    def __call__(self, from_file: str, to_file: str, to_cluster: str | None) -> bool:
        """Does a class of `from_file` see the class of `to_file` (of stdlib cluster `to_cluster`,
        None for a class of the program)?"""
        group = self.file_group.get(Path(from_file).resolve())
        if group is None:
            return True  # a file given on the command line beside the .ecf
        if to_cluster is not None:
            return to_cluster == "base" or to_cluster in self.group_names[group]
        target = self.file_group.get(Path(to_file).resolve())
        return target is None or target == group or target in self.group_names[group]

    def library_of(self, file: str) -> str:
        group = self.file_group.get(Path(file).resolve())
        return group.stem if group is not None else Path(file).parent.name


def collect(paths: list[str], target: str | None = None) -> Project:
    """Gather the source files named by `paths` (files, directories, .ecf files)."""
    project = Project()
    for raw in paths:
        path = Path(raw)
        if not path.exists():
            raise UsageError(f"no such file or directory: {raw}")
        if path.is_dir():
            _add_cluster(project, path, recursive=True)
            for ecf in sorted(path.glob("*.ecf")):
                if not any(Path(other).resolve() == ecf.resolve() for other in paths):
                    _note(
                        project,
                        ecf,
                        f"{raw} is read as a cluster: its {ecf.name} (libraries, externals, settings) is not read; "
                        f"give {ecf} to use it",
                    )
        elif path.suffix.lower() == ".e":
            project.add_file(path)
        elif path.suffix.lower() == ".ecf":
            _read_ecf(project, path, target)
        else:
            raise UsageError(f"{raw}: expected a .e file, a directory or an .ecf file")
    if not project.files and not project.errors:
        raise UsageError("no Eiffel source files (.e) found in " + ", ".join(paths))
    _check_library_concurrency(project)
    return project


# EiffelStudio's order of the concurrency capability (Gobo's ET_ECF_CAPABILITY_NAMES: thread <
# none < scoop): a target supporting one value supports the values before it too.
CONCURRENCY_ORDER = ("thread", "none", "scoop")
# EiffelStudio's syntax levels (EIFFEL_PARSER's obsolete_syntax, transitional_syntax, ecma_syntax
# for `standard`, provisional_syntax); scoopc reads `provisional` as `standard`.
SYNTAX_LEVELS = ("obsolete", "transitional", "standard", "provisional")
# The syntax level of an .ecf with no `syntax` option, by its schema: the defaults of the
# EiffelStudio release that wrote the schema (CONF_LOAD_PARSE_CALLBACKS.set_default_options,
# Src/framework/configuration/parser/load/, and CONF_OPTION.make_6_3 / make_6_4 / make_7_0):
# schemas 1-0-0 to 1-4-0 take EiffelStudio 6.3's, obsolete syntax; 1-5-0 to 1-8-0 take 6.4's,
# transitional syntax; 1-9-0 and later standard syntax.
_SCHEMA_SYNTAX = {
    **dict.fromkeys(("1-0-0", "1-2-0", "1-3-0", "1-4-0"), "obsolete"),
    **dict.fromkeys(("1-5-0", "1-6-0", "1-7-0", "1-8-0"), "transitional"),
}
# Void safety likewise (CONF_OPTION.make_6_3 to make_14_05): none up to schema 1-10-0
# (EiffelStudio 7.0), transitional for 1-11-0 and 1-12-0 (7.3), complete from 1-13-0 (14.05).
_SCHEMA_VOID_SAFETY = {
    **dict.fromkeys(
        ("1-0-0", "1-2-0", "1-3-0", "1-4-0", "1-5-0", "1-6-0", "1-7-0", "1-8-0", "1-9-0", "1-10-0"), "none"
    ),
    **dict.fromkeys(("1-11-0", "1-12-0"), "transitional"),
}
_SCHEMA_VERSION = re.compile(r"^http://www\.eiffel\.com/developers/xml/configuration-(\d+-\d+-\d+)$")


def schema_syntax(system: ElementTree.Element) -> str:
    """The syntax level of the .ecf whose root element is `system` when it sets none: the default
    of the EiffelStudio release that wrote its schema (its `xmlns`)."""
    return _SCHEMA_SYNTAX.get(_schema_version(system), "standard")


def schema_void_safety(system: ElementTree.Element) -> str | None:
    """The void-safety level of the application's .ecf `system` when its options set none (None:
    today's default, complete)."""
    return _SCHEMA_VOID_SAFETY.get(_schema_version(system))


def _schema_version(system: ElementTree.Element) -> str:
    """The version of the ECF schema `system` names in its `xmlns` ("1-5-0"), else ""."""
    found = _SCHEMA_VERSION.match((system.get("xmlns") or "").strip())
    return found.group(1) if found else ""


def _check_library_concurrency(project: Project) -> None:
    """The application's concurrency governs every class; a library whose .ecf says it does not
    support that concurrency is named in a warning (its classes are still compiled)."""
    wanted = project.concurrency
    if wanted not in CONCURRENCY_ORDER:
        return
    for name, support, span in project.library_concurrency:
        if support in CONCURRENCY_ORDER and CONCURRENCY_ORDER.index(support) < CONCURRENCY_ORDER.index(wanted):
            project.notes.append(
                diagnostics.make(
                    "ECF-CAPABILITY",
                    span,
                    severity=diagnostics.WARNING,
                    name=name,
                    capability="concurrency",
                    support=support,
                    wanted=wanted,
                )
            )


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


def _ecf_span(path: Path, element: ElementTree.Element | None = None, positions=None) -> Span:
    """Where `element` starts in the .ecf file (its first line when unknown)."""
    line, column = (positions or {}).get(element, (1, 1)) if element is not None else (1, 1)
    width = len(_local(element.tag)) + 1 if element is not None else 1
    return Span(str(path), line, column, line, column + width)


class _Refused(Exception):
    """A construct an .ecf file may not use (entity declarations)."""


def _parse_xml(path: Path):
    """(root element, {element: (line, column)}) of an .ecf file, with expat directly so that
    every element keeps its position. Entity declarations (and so entity expansion, internal or
    external) are refused: an .ecf file never needs them."""
    builder = ElementTree.TreeBuilder()
    positions: dict = {}
    parser = expat.ParserCreate()
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)

    def start(tag, attributes):
        element = builder.start(tag, attributes)
        positions[element] = (parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)

    def refuse(*_):
        raise _Refused("entity declarations are not accepted in an .ecf file")

    parser.StartElementHandler = start
    parser.EndElementHandler = builder.end
    parser.CharacterDataHandler = builder.data
    parser.EntityDeclHandler = refuse
    parser.UnparsedEntityDeclHandler = refuse
    parser.ExternalEntityRefHandler = refuse
    with open(path, "rb") as handle:
        parser.ParseFile(handle)
    return builder.close(), positions


def _read_ecf(
    project: Project, path: Path, target_name: str | None, chain: tuple = (), named_at: Span | None = None
) -> None:
    """Read the .ecf file `path`: the application's (chain empty) or a library's, named at
    `named_at` by the last of `chain` (the .ecf files naming each other down to this one)."""
    try:
        system, positions = _parse_xml(path)
    except expat.ExpatError as problem:
        line, column = problem.lineno, problem.offset
        span = Span(str(path), line, column + 1, line, column + 2)
        reason = expat.ErrorString(problem.code)
        project.errors.append(
            diagnostics.make(
                "ECF", span, reason=f"{path} is not well-formed XML: {reason}: line {line}, column {column}"
            )
        )
        return
    except _Refused as problem:
        project.errors.append(diagnostics.make("ECF", _ecf_span(path), reason=f"{path}: {problem}"))
        return
    except OSError as problem:
        reason = problem.strerror or "unreadable"
        span = named_at or _ecf_span(path)
        project.errors.append(diagnostics.make("ECF", span, reason=f"cannot read {path}: {reason}"))
        return
    project.ecf_files.append(path.resolve())
    targets = {t.get("name", ""): t for t in _children(system, "target")}
    if not targets:
        project.errors.append(diagnostics.make("ECF", _ecf_span(path), reason=f"{path} defines no target"))
        return
    if chain and target_name is None:
        target_name = system.get("library_target") or None  # a library's own target, if it names one
        if target_name not in targets:
            target_name = None
    chosen = _choose_target(project, path, targets, target_name)
    if chosen is None:
        return
    reader = _EcfReader(project, path, positions, chain + (path.resolve(),), library=bool(chain))
    reader.syntax = schema_syntax(system)
    if not chain:  # the application's schema gives the void-safety default its options may change
        project.settings.void_safety = schema_void_safety(system)
    for element in _target_chain(chosen, targets):
        reader.read_target(element)


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
# What a library's .ecf holds that applies to the library alone (its root, its options): the
# application's settings govern every class (docs/LANGUAGE.md, Libraries).
_LIBRARY_ONLY = {
    "root",
    "option",
    "capability",
    "setting",
    "external_include",
    "external_object",
    "external_library",
    "external_cflag",
    "external_linker_flag",
    "variable",
    "mapping",
    "pre_compile_action",
    "post_compile_action",
    "debug",
    "assertions",
    "warning",
}


class _EcfReader:
    """One .ecf file's target: its clusters, libraries, root and settings."""

    def __init__(self, project: Project, ecf: Path, positions: dict, chain: tuple, library: bool):
        self.project, self.ecf, self.positions, self.chain, self.library = project, ecf, positions, chain, library
        self.syntax = "standard"  # this .ecf's own syntax level, for the files of its clusters
        self.group = ecf.resolve()
        project.group_names.setdefault(self.group, set())

    def span(self, element) -> Span:
        return _ecf_span(self.ecf, element, self.positions)

    def read_target(self, target: ElementTree.Element) -> None:
        project, ecf = self.project, self.ecf
        for element in target:
            kind = _local(element.tag)
            if self.library and kind == "capability":
                self.read_library_capability(element)
            if self.library and kind == "option":
                self.syntax = _syntax(element, self.syntax)  # its own level (its other options are ignored)
            if self.library and kind in _LIBRARY_ONLY:
                continue
            if kind == "root":
                _read_root(project, element)
            elif kind in ("cluster", "override"):  # an override cluster's classes replace library ones
                self.read_cluster(element, ecf.parent)
            elif kind in ("library", "precompile"):
                self.read_library(element)
            elif kind == "option":
                _read_option(project, element)
                if _syntax(element, None) is not None:
                    self.syntax = project.settings.syntax = _syntax(element, self.syntax)
            elif kind == "capability":
                _read_capability(project, element)
            elif kind in _EXTERNAL_ELEMENTS or (kind == "variable" and element.get("name") == "python_path"):
                _read_external(project, element, kind, ecf.parent)
            elif kind == "setting":
                self.read_setting(element)
            elif kind not in _IGNORED_QUIETLY:
                _note(project, ecf, f"<{kind}> is not supported and is ignored", self.span(element))

    def read_setting(self, element: ElementTree.Element) -> None:
        """The settings we honour: the application's `concurrency` (ECF 1.7 to 1.15; `multithreaded`
        before it; the capability of ECF 1.16 superseded both); any other is named in a note."""
        name, value = (element.get("name") or "").lower(), (element.get("value") or "").lower()
        if name == "concurrency" and value in CONCURRENCY_ORDER:
            self.project.settings.concurrency = value
        elif name == "multithreaded" and value in ("true", "false"):
            self.project.settings.concurrency = "thread" if value == "true" else "none"
        else:
            _note(self.project, self.ecf, f"setting `{element.get('name')}` is ignored", self.span(element))

    def read_library_capability(self, element: ElementTree.Element) -> None:
        for child in element:
            support = (child.get("support") or "").lower()
            if _local(child.tag) == "concurrency" and support:
                self.project.library_concurrency.append((self.ecf.stem, support, self.span(child)))

    def read_cluster(self, element: ElementTree.Element, base: Path) -> None:
        location = _expand_location(element.get("location", "."), base)
        if not location.is_dir():
            self.project.errors.append(
                diagnostics.make(
                    "ECF", self.span(element), reason=f"cluster `{element.get('name')}`: no directory {location}"
                )
            )
            return
        recursive = element.get("recursive", "false").lower() == "true"
        known = len(self.project.files)
        _add_cluster(self.project, location, recursive, _patterns(element, "exclude"), _patterns(element, "include"))
        level = self.syntax  # a cluster's own option overrides its target's
        for option in _children(element, "option"):
            level = _syntax(option, level)
        for path in self.project.files[known:]:
            self.project.file_syntax[path.resolve()] = level
            self.project.file_group[path.resolve()] = self.group
        for sub in _children(element, "cluster"):
            self.read_cluster(sub, location)

    def read_library(self, element: ElementTree.Element) -> None:
        """A library: one of the stdlib's (by name or by an $ISE_LIBRARY location), or a user's
        library read from its own .ecf, recursively."""
        project = self.project
        name = element.get("name") or ""
        raw = (element.get("location") or "").strip()
        ours = _stdlib_library(name, raw)
        if ours is not None:
            if ours not in project.libraries:
                project.libraries.append(ours)
            project.group_names[self.group].add(ours)
            return
        planned = _planned_library(name, raw)
        if planned is not None:
            _note(project, self.ecf, f"library `{name}` ({raw}): {planned}", self.span(element))
            return
        if not raw or _ise_folder(raw) is not None:
            known = ", ".join(sorted(set(STDLIB_LIBRARIES) - {"free_elks", "elks"}))
            where = f" ({raw})" if raw else ""
            project.errors.append(
                diagnostics.make(
                    "ECF-LIBRARY",
                    self.span(element),
                    name=name,
                    location=where,
                    reason="scoopc does not have this library",
                    hint=f"the libraries scoopc has are: {known}",
                )
            )
            return
        path = Path(os.path.normpath(_expand_location(raw, self.ecf.parent)))
        if path.is_dir():
            path = path / f"{name}.ecf"
        if not path.is_file():
            project.errors.append(
                diagnostics.make(
                    "ECF-LIBRARY",
                    self.span(element),
                    name=name,
                    location=f" ({raw})",
                    reason=f"no .ecf file {path}",
                    hint="a library's location names its .ecf file, relative to the .ecf file naming it",
                )
            )
            return
        resolved = path.resolve()
        project.group_names[self.group].add(resolved)  # its classes are visible to this .ecf's
        if resolved in self.chain:
            cycle = self.chain[self.chain.index(resolved) :] + (resolved,)
            project.notes.append(
                diagnostics.make(
                    "ECF-CYCLE",
                    self.span(element),
                    severity=diagnostics.WARNING,
                    name=name,
                    cycle=" -> ".join(p.name for p in cycle),
                )
            )
            return
        if resolved in project.ecf_files:
            return  # named by two libraries: read once
        _read_ecf(project, path, None, self.chain, self.span(element))


_EXTERNAL_ELEMENTS = {
    "external_include",
    "external_object",
    "external_library",
    "external_cflag",
    "external_linker_flag",
}


def _read_external(project: Project, element: ElementTree.Element, kind: str, base: Path) -> None:
    """One of the .ecf's external settings; $(ECF_CONFIG_PATH) is the .ecf's folder, and an
    element whose <condition> names another platform is skipped."""
    if not _for_this_platform(element):
        return
    found = project.externals
    value = (element.get("value") or "").strip()
    if kind == "external_cflag":
        found.cflags += value.split()
        return
    if kind == "external_linker_flag":
        found.linker_flags += value.split()
        return
    raw = (element.get("location") or value).replace("$(ECF_CONFIG_PATH)", str(base.resolve())).strip().strip('"')
    if kind == "variable":
        found.python_paths += [_expand_location(part, base) for part in raw.split(os.pathsep) if part]
    elif kind == "external_include":
        found.include_dirs.append(_expand_location(raw, base))
    elif raw.startswith("-l"):
        found.libraries.append(raw[2:])
    elif raw.startswith("-"):
        found.linker_flags.append(raw)
    else:
        found.objects.append(_expand_location(raw, base))


def _for_this_platform(element: ElementTree.Element) -> bool:
    here = {"win32": "windows", "darwin": "macintosh"}.get(sys.platform, "unix")
    for condition in _children(element, "condition"):
        for platform in _children(condition, "platform"):
            if platform.get("value") and platform.get("value").lower() != here:
                return False
            if platform.get("excluded_value") and platform.get("excluded_value").lower() == here:
                return False
    return True


def _ise_folder(location: str) -> str | None:
    """The library folder of an $ISE_LIBRARY/library/<folder>/... location (also $ISE_EIFFEL,
    $(ISE_LIBRARY)); None for any other location."""
    text = location.replace("\\", "/")
    match = re.match(r"\$\(?(\w+)\)?/(.*)$", text)
    if match is None or match.group(1).upper() not in _ISE_VARIABLES:
        return None
    parts = [p for p in match.group(2).split("/") if p and p != "."]
    if len(parts) >= 2 and parts[0].lower() == "library":
        return parts[1].lower()
    return parts[0].lower() if parts else ""


def _stdlib_library(name: str, location: str) -> str | None:
    """The stdlib cluster an .ecf <library> (or <precompile>) names, or None."""
    precompiled = re.match(r"\$\(?ISE_PRECOMP\)?[/\\](.*)$", location, re.IGNORECASE)
    if precompiled is not None:  # $ISE_PRECOMP/base-scoop-safe.ecf: EiffelBase precompiled
        stem = Path(precompiled.group(1).replace("\\", "/")).stem.lower()
        return STDLIB_LIBRARIES.get(re.split(r"[-_.]", stem)[0])
    folder = _ise_folder(location) if location else None
    if folder is not None:
        return STDLIB_LIBRARIES.get(folder)
    if not location:
        return STDLIB_LIBRARIES.get(name.lower())
    return None


def _planned_library(name: str, location: str) -> str | None:
    folder = _ise_folder(location) if location else name.lower()
    return PLANNED_LIBRARIES.get(folder or "")


def _note(project: Project, ecf: Path, reason: str, span: Span | None = None) -> None:
    project.notes.append(diagnostics.make("ECF-NOTE", span or _ecf_span(ecf), severity=diagnostics.NOTE, reason=reason))


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


def _syntax(option: ElementTree.Element, level):
    """The syntax level an <option> sets (its `syntax` attribute), else `level`."""
    value = (option.get("syntax") or "").lower()
    return value if value in SYNTAX_LEVELS else level


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


def beside_program(program_paths, name: str) -> Path | None:
    """The file `name` in the folder of the first program path that has one (a path is a folder,
    or a file whose folder counts), or None: where a run finds world.yaml and robot.yaml."""
    for p in program_paths or ():
        folder = Path(p) if Path(p).is_dir() else Path(p).parent
        if (folder / name).is_file():
            return folder / name
    return None
