"""Language server, quick fixes for the commonest SCOOP error, a call on a separate target that
is not controlled (VUTA(3)): wrap the instruction in a separate block, or move the call into a
new routine that takes the target as a separate argument (which reserves it)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from lsprotocol import types as lsp

from .. import syntax
from ..source import Span
from .analysis import Analysis
from .nodes import Texts, is_instruction, path_to, to_range, walk

UNCONTROLLED = "VUTA(3)"


@dataclass
class _Site:
    """Where an uncontrolled separate call is: its target, the instruction and the routine."""

    target: object
    instruction: object
    routine: object
    text: str  # the target as written
    indent: str  # of the instruction's line
    unit: str  # one level of indentation in this file


def actions(analysis: Analysis, path: str, uri: str, diagnostic: lsp.Diagnostic, texts: Texts) -> list[lsp.CodeAction]:
    site = _site(analysis, path, diagnostic, texts)
    if site is None:
        return []
    found = [_action(f"Wrap in `separate {site.text} as ... do ... end`", uri, diagnostic, _wrap(site, texts))]
    moved = _move(site, analysis, texts, path)
    if moved is not None:
        name, edits = moved
        found.append(
            _action(f"Move the call into a new routine `{name}` with `{site.text}` as argument", uri, diagnostic, edits)
        )
    return found


def _action(title: str, uri: str, diagnostic: lsp.Diagnostic, edits: list[lsp.TextEdit]) -> lsp.CodeAction:
    return lsp.CodeAction(
        title,
        kind=lsp.CodeActionKind.QuickFix,
        diagnostics=[diagnostic],
        edit=lsp.WorkspaceEdit(changes={uri: edits}),
    )


def _site(analysis: Analysis, path: str, diagnostic: lsp.Diagnostic, texts: Texts) -> _Site | None:
    tree = analysis.trees.get(path)
    start, end = diagnostic.range.start, diagnostic.range.end
    if tree is None or analysis.semantics is None:
        return None
    chain = path_to(tree, start.line + 1, start.character + 1)
    wanted = (start.line + 1, start.character + 1, end.line + 1, end.character + 1)
    target = next(
        (n for n in reversed(chain) if _corners(n.span) == wanted and n in analysis.semantics.tables.types), None
    )
    instruction = next((n for n in reversed(chain) if is_instruction(n)), None)
    routine = next((n for n in reversed(chain) if isinstance(n, syntax.Routine)), None)
    if target is None or instruction is None or routine is None:
        return None
    source = texts.source(path)
    line = source.line_text(instruction.span.line) if source is not None else ""
    indent = line[: len(line) - len(line.lstrip())]
    return _Site(
        target, instruction, routine, texts.text(target.span), indent, "\t" if "\t" in indent or not indent else "    "
    )


def _corners(span: Span) -> tuple[int, int, int, int]:
    return (span.line, span.column, span.end_line, span.end_column)


def _local_name(site: _Site, taken: set[str]) -> str:
    base = re.sub(r"\W+", "_", site.text.split(".")[-1]).strip("_").lower() or "target"
    name = f"l_{base}"
    number = 2
    while name in taken:
        name, number = f"l_{base}_{number}", number + 1
    return name


def _names(node) -> set[str]:
    return {n.key for n in walk(node) if isinstance(n, syntax.Identifier)}


def _wrap(site: _Site, texts: Texts) -> list[lsp.TextEdit]:
    local = _local_name(site, _names(site.routine))
    body = re.sub(re.escape(site.text) + r"(?=\s*\.)", local, texts.text(site.instruction.span))
    first, *rest = body.split("\n")
    lines = [f"separate {site.text} as {local} do", f"{site.indent}{site.unit}{first}"]
    lines += [site.unit + line if line.strip() else line for line in rest]
    lines.append(f"{site.indent}end")
    return [lsp.TextEdit(to_range(site.instruction.span), "\n".join(lines))]


def _move(site: _Site, analysis: Analysis, texts: Texts, path: str) -> tuple[str, list[lsp.TextEdit]] | None:
    """A new routine `NAME (a_x: separate T) do a_x.call end` after the current one, called in place
    of the instruction; offered when the call's arguments use no local or argument of the routine."""
    call = getattr(site.instruction, "call", None)
    tables = analysis.semantics.tables
    if not isinstance(call, syntax.QualifiedCall) or call.target is not site.target or _uses_locals(call, tables):
        return None
    ty = tables.types.get(site.target)
    info = analysis.class_info(path)
    taken = set(info.features) if info is not None else set()
    base = re.sub(r"\W+", "_", site.text.split(".")[-1]).strip("_").lower()
    name, number = f"{call.name.key}_on_{base}", 2
    while name in taken:
        name, number = f"{call.name.key}_on_{base}_{number}", number + 1
    argument = f"a_{base}"
    rest = texts.text(
        Span(
            call.span.file,
            site.target.span.end_line,
            site.target.span.end_column,
            call.span.end_line,
            call.span.end_column,
        )
    )
    routine_line = texts.source(site.routine.span.file).line_text(site.routine.span.line)
    outer = routine_line[: len(routine_line) - len(routine_line.lstrip())]
    unit = site.unit
    new = [
        "",
        "",
        f"{outer}{name} ({argument}: {_argument_type(ty)})",
        f"{outer}{unit}{unit}-- Call `{call.name.text}' on `{argument}', reserved by this routine.",
        f"{outer}{unit}do",
        f"{outer}{unit}{unit}{argument}{rest}",
        f"{outer}{unit}end",
    ]
    end = site.routine.span
    insert = lsp.Range(
        lsp.Position(end.end_line - 1, end.end_column - 1), lsp.Position(end.end_line - 1, end.end_column - 1)
    )
    edits = [
        lsp.TextEdit(to_range(site.instruction.span), f"{name} ({site.text})"),
        lsp.TextEdit(insert, "\n".join(new)),
    ]
    return name, edits


def _uses_locals(call, tables) -> bool:
    for argument in call.arguments:
        for node in walk(argument):
            entity = tables.entities.get(node)
            if entity is not None and entity.kind != "attribute":
                return True
    return False


def _argument_type(ty) -> str:
    text = str(ty)
    for mark in ("detachable ", "attached "):
        text = text.replace(mark, "")
    return text if text.startswith("separate ") else f"separate {text}"
