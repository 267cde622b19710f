"""Language server, completion: after a dot, the features of the target's class that the current
class may call (export status respected); elsewhere the keywords, the class names, and the
features and entities in scope. The target's type comes from checking the text with the member
being typed replaced by ANY's `do_nothing` (`x.fo|` is checked as `x.do_nothing`, a call every
class has), so it is the checker's own answer."""

from __future__ import annotations

import os
import re

from lsprotocol import types as lsp

from .. import syntax
from ..driver import Compilation
from ..exits import UsageError
from ..semantics.universe import ClassInfo
from .analysis import Programs, program_paths
from .hover import header
from .nodes import path_to, walk

KEYWORDS = (
    "across agent alias all and as assign attached attribute check class convert create Current debug deferred "
    "detachable do else elseif end ensure expanded export external False feature from frozen if implies inherit "
    "inspect invariant like local loop not note obsolete old once or Precursor redefine rename require rescue "
    "Result retry select separate some then True TUPLE undefine until variant Void when xor"
).split()

_MEMBER = re.compile(r"\.\s*([A-Za-z_][A-Za-z0-9_]*)?$")


def complete(programs: Programs, path: str, line: int, column: int) -> list[lsp.CompletionItem]:
    text = programs.texts.buffers.get(path)
    if text is None:
        return []
    lines = text.split("\n")
    before = lines[line - 1][: column - 1] if line <= len(lines) else ""
    if "--" in before.split('"')[-1] and before.count('"') % 2 == 0:
        return []  # in a comment
    member = _MEMBER.search(before)
    if member is not None and not before[: member.start()].rstrip().endswith("."):
        return _members(programs, path, lines, line, member.start() + 1, column)
    return _everything(programs, path, line)


def _members(programs: Programs, path: str, lines: list[str], line: int, dot: int, column: int):
    """Features callable on the expression that ends just before the dot at `dot` (1-based)."""
    edited = lines[:]
    edited[line - 1] = edited[line - 1][: dot - 1] + ".do_nothing" + edited[line - 1][column - 1 :]
    overlay = dict(programs.texts.buffers)
    overlay[path] = "\n".join(edited)
    try:
        checked = Compilation(list(program_paths(path)), overlay=overlay, stdlib=programs.stdlib).checked
    except UsageError:
        return []
    sem = checked.semantics
    tree = next((u.tree for u in checked.units if os.path.abspath(u.source.path) == path), None)
    if sem is None or tree is None:
        return []
    target = _target_type(tree, sem.tables, line, dot)
    current = sem.universe.get(tree.name.key)
    info = sem.universe.get(target.name) if target is not None else None
    if info is None or current is None:
        return []
    return [_feature_item(f, programs) for f in info.features.values() if _exported(f, current)]


def _target_type(tree, tables, line: int, dot: int):
    """The type of the expression ending at (line, dot): the latest-starting one (`x + a.b` -> `a.b`)."""
    best = None
    for node in walk(tree):
        span = getattr(node, "span", None)
        if span is None or (span.end_line, span.end_column) != (line, dot) or node not in tables.types:
            continue
        if best is None or (span.line, span.column) > (best.span.line, best.span.column):
            best = node
    return tables.types.get(best) if best is not None else None


def _exported(feature, current: ClassInfo) -> bool:
    if feature.exports is None:
        return True
    clients = {current.name, *current.ancestors}
    return any(name.upper() in clients for name in feature.exports)


def _feature_item(feature, programs: Programs) -> lsp.CompletionItem:
    signature, comment = header(feature, programs.texts)
    kind = {
        syntax.Attribute: lsp.CompletionItemKind.Field,
        syntax.Constant: lsp.CompletionItemKind.Constant,
    }.get(type(feature.decl), lsp.CompletionItemKind.Method)
    return lsp.CompletionItem(
        feature.text,
        kind=kind,
        detail=signature,
        documentation=lsp.MarkupContent(lsp.MarkupKind.Markdown, comment) if comment else None,
    )


def _everything(programs: Programs, path: str, line: int) -> list[lsp.CompletionItem]:
    items = [lsp.CompletionItem(word, kind=lsp.CompletionItemKind.Keyword) for word in KEYWORDS]
    analysis = programs.analysis(path)
    if analysis is None or analysis.semantics is None:
        return items
    universe = analysis.semantics.universe
    items += [
        lsp.CompletionItem(info.decl.name.text, kind=lsp.CompletionItemKind.Class, detail=_class_detail(info))
        for key, info in universe.classes.items()
        if "@" not in key
    ]
    current = analysis.class_info(path)
    if current is not None:
        items += [_feature_item(f, programs) for f in current.features.values()]
        items += _entities(analysis.trees[path], line)
    return items


def _class_detail(info: ClassInfo) -> str:
    return "library class" if info.from_library else "class of the program"


def _entities(tree, line: int) -> list[lsp.CompletionItem]:
    """Arguments and locals of the routine around `line` (as the last good check saw it)."""
    chain = path_to(tree, line, 1, inclusive=True) or [tree]
    routine = next((n for n in reversed(chain) if isinstance(n, syntax.Routine)), None)
    if routine is None:
        for node in walk(tree):
            if isinstance(node, syntax.Routine) and node.span.line <= line <= node.span.end_line:
                routine = node
    if routine is None:
        return []
    declared = list(routine.arguments) + list(routine.body.locals)
    return [lsp.CompletionItem(d.name.text, kind=lsp.CompletionItemKind.Variable) for d in declared]
