"""Language server, the document's outline (the class, its feature clauses and their features)
and its folding ranges (the class, clauses, features, compound instructions, comment blocks),
from the syntax tree alone."""

from __future__ import annotations

from lsprotocol import types as lsp

from .. import syntax
from ..source import SourceFile, Span
from .nodes import is_instruction, to_range, walk

_KINDS = {syntax.Routine: lsp.SymbolKind.Method, syntax.Attribute: lsp.SymbolKind.Field}


def symbols(tree, source: SourceFile) -> list[lsp.DocumentSymbol]:
    clauses = [_clause(clause, source) for clause in tree.feature_clauses]
    whole = lsp.DocumentSymbol(
        tree.name.text,
        lsp.SymbolKind.Class,
        to_range(tree.span),
        to_range(tree.name.span),
        children=clauses,
    )
    return [whole]


def _clause(clause, source: SourceFile) -> lsp.DocumentSymbol:
    title = source.line_text(clause.span.line).strip() or "feature"
    features = [item for feature in clause.features for item in _feature(feature, source)]
    return lsp.DocumentSymbol(
        title, lsp.SymbolKind.Namespace, to_range(clause.span), to_range(_first_line(clause.span)), children=features
    )


def _first_line(span: Span) -> Span:
    return Span(span.file, span.line, span.column, span.line, span.column + len("feature"))


def _feature(decl, source: SourceFile) -> list[lsp.DocumentSymbol]:
    kind = _KINDS.get(type(decl), lsp.SymbolKind.Constant)
    detail = source.line_text(decl.span.line).strip()  # the signature as written
    return [
        lsp.DocumentSymbol(name.name.text, kind, to_range(decl.span), to_range(name.name.span), detail=detail)
        for name in decl.names
    ]


def folding(tree, source: SourceFile) -> list[lsp.FoldingRange]:
    ranges = []
    for node in walk(tree):
        if isinstance(node, (syntax.ClassDeclaration, syntax.FeatureClause, syntax.Routine, syntax.Attribute)) or (
            is_instruction(node)
        ):
            span = node.span
            if span.end_line > span.line:
                ranges.append(lsp.FoldingRange(span.line - 1, _last_line(span) - 1))
    ranges += _comment_blocks(source)
    unique = {(r.start_line, r.end_line, r.kind): r for r in ranges if r.end_line > r.start_line}
    return sorted(unique.values(), key=lambda r: (r.start_line, r.end_line))


def _last_line(span) -> int:
    return span.end_line - 1 if span.end_column == 1 else span.end_line


def _comment_blocks(source: SourceFile) -> list[lsp.FoldingRange]:
    blocks, start = [], None
    for number in range(1, source.line_count + 2):
        is_comment = source.line_text(number).lstrip().startswith("--")
        if is_comment and start is None:
            start = number
        elif not is_comment and start is not None:
            if number - 1 > start:
                blocks.append(lsp.FoldingRange(start - 1, number - 2, kind=lsp.FoldingRangeKind.Comment))
            start = None
    return blocks
