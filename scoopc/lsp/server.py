"""Language server over stdio (`scoopc lsp`), on pygls: diagnostics of the real checker on open,
change and save; hover, definition, references, completion, outline, folding and quick fixes.
Each change re-checks the file's program with the editor's buffers and the standard library held
in memory (analysis.Programs)."""

from __future__ import annotations

import asyncio
import os
import threading
from pathlib import Path
from typing import BinaryIO

from lsprotocol import types as lsp
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from ..diagnostics import Diagnostic
from ..explain import canonical_code, explain
from ..parse import parser
from ..semantics.library import cache_dir
from ..source import SourceFile
from ..version import __version__
from . import completion, fixes, hover, lookup, navigation, outline
from .analysis import SERVER_PROCESS, Analysis, Programs, in_library, program_paths, warm_up
from .nodes import from_position, library_file, to_location, to_range

QUICK_FIX = lsp.CodeActionKind.QuickFix
DEBOUNCE = 0.02  # seconds a check waits for more changes of the same burst of typing


class ScoopServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__("scoopc", __version__)
        self.programs = Programs()
        self.pending: set[tuple[str, ...]] = set()
        self.published: dict[tuple[str, ...], set[str]] = {}
        self.warming = threading.Thread(target=warm_up, name="scoopc-lsp-warm-up", daemon=True)

    # ---- checking ------------------------------------------------------------------------------
    def buffer_changed(self, uri: str) -> str:
        path = _path(uri)
        self.programs.texts.buffers[path] = self.workspace.get_text_document(uri).source.replace("\r\n", "\n")
        return path

    def check_now(self, path: str) -> Analysis | None:
        if in_library(path):
            return None
        analysis = self.programs.check(path)
        self.publish(analysis)
        return analysis

    async def check_soon(self, path: str) -> None:
        key = program_paths(path)
        if key in self.pending:
            return
        self.pending.add(key)
        await asyncio.sleep(DEBOUNCE)
        self.pending.discard(key)
        self.check_now(path)

    def publish(self, analysis: Analysis) -> None:
        found = analysis.diagnostics_by_file()
        stale = self.published.get(analysis.paths, set()) - set(found)
        for path in stale:
            found[path] = []
        for path, diagnostics in found.items():
            uri = Path(path).as_uri()
            document = self.workspace.text_documents.get(uri)
            self.text_document_publish_diagnostics(
                lsp.PublishDiagnosticsParams(
                    uri, [to_lsp(d) for d in diagnostics], version=document.version if document else None
                )
            )
        self.published[analysis.paths] = {p for p, ds in found.items() if ds}


def _path(uri: str) -> str:
    return os.path.abspath(to_fs_path(uri) or uri)


def to_lsp(d: Diagnostic) -> lsp.Diagnostic:
    related = [
        lsp.DiagnosticRelatedInformation(to_location(note.span), note.message)
        for note in d.notes
        if note.span is not None
    ]
    if d.hint and d.span is not None:
        related.append(lsp.DiagnosticRelatedInformation(to_location(d.span), f"hint: {d.hint}"))
    message = d.message + "".join(f"\nnote: {n.message}" for n in d.notes if n.span is None)
    severity = {"error": lsp.DiagnosticSeverity.Error, "warning": lsp.DiagnosticSeverity.Warning}
    return lsp.Diagnostic(
        to_range(d.span) if d.span is not None else lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1)),
        message,
        severity=severity.get(d.severity, lsp.DiagnosticSeverity.Information),
        code=d.code,
        code_description=explanation_link(d.code),
        source="scoopc",
        related_information=related or None,
    )


def explanation_link(code: str) -> lsp.CodeDescription | None:
    """`scoopc check --explain CODE` as a Markdown file the editor opens from the code's link."""
    text = explain(code)
    if text is None:
        return None
    name = canonical_code(code).replace("(", "-").replace(")", "")
    target = cache_dir() / "explain" / __version__ / f"{name}.md"
    try:
        if not target.exists():
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(f"# {canonical_code(code)}\n\n```\n{text}\n```\n", encoding="utf-8")
    except OSError:
        return None
    return lsp.CodeDescription(target.as_uri())


def on_initialized(ls: ScoopServer, params: lsp.InitializedParams) -> None:
    ls.warming.start()  # the library loads while the editor opens its first file


def on_shutdown(ls: ScoopServer, params: None) -> None:
    if ls.warming.is_alive():
        ls.warming.join()


def did_open(ls: ScoopServer, params: lsp.DidOpenTextDocumentParams) -> None:
    ls.check_now(ls.buffer_changed(params.text_document.uri))


async def did_change(ls: ScoopServer, params: lsp.DidChangeTextDocumentParams) -> None:
    await ls.check_soon(ls.buffer_changed(params.text_document.uri))


def did_save(ls: ScoopServer, params: lsp.DidSaveTextDocumentParams) -> None:
    ls.check_now(ls.buffer_changed(params.text_document.uri))


def did_close(ls: ScoopServer, params: lsp.DidCloseTextDocumentParams) -> None:
    path = _path(params.text_document.uri)
    ls.programs.texts.buffers.pop(path, None)
    if not in_library(path) and os.path.exists(path):
        ls.check_now(path)  # the file on disk counts again


def on_watched_files(ls: ScoopServer, params: lsp.DidChangeWatchedFilesParams) -> None:
    """Files changed on disk (a `git checkout`, another editor): their programs are checked again."""
    changed = {program_paths(_path(change.uri)): _path(change.uri) for change in params.changes}
    for key, path in changed.items():
        if key in ls.programs.latest and key not in ls.pending:
            ls.publish(ls.programs.check_program(key, path))


def on_hover(ls: ScoopServer, params: lsp.HoverParams) -> lsp.Hover | None:
    path, analysis, found = _lookup(ls, params)
    if found is None:
        return None
    declaring = lookup.class_of(found, analysis.semantics.universe)
    text, span = hover.hover_text(found, declaring, analysis.semantics, ls.programs.texts)
    if not text:
        return None
    return lsp.Hover(lsp.MarkupContent(lsp.MarkupKind.Markdown, text), to_range(span) if span else None)


def on_definition(ls: ScoopServer, params: lsp.DefinitionParams) -> lsp.Location | None:
    path, analysis, found = _lookup(ls, params)
    span = navigation.definition(found, analysis) if found is not None else None
    return to_location(span) if span is not None else None


def on_references(ls: ScoopServer, params: lsp.ReferenceParams) -> list[lsp.Location]:
    path, analysis, found = _lookup(ls, params)
    if found is None:
        return []
    spans = navigation.references(found, analysis, params.context.include_declaration)
    return [to_location(s) for s in spans]


def _lookup(ls: ScoopServer, params):
    path = _path(params.text_document.uri)
    analysis = ls.programs.analysis(path)
    if analysis is None:
        return path, None, None
    line, column = from_position(params.position)
    found = lookup.at(analysis, path, line, column)
    return path, analysis, (None if found.empty else found)


def on_completion(ls: ScoopServer, params: lsp.CompletionParams) -> lsp.CompletionList:
    path = _path(params.text_document.uri)
    line, column = from_position(params.position)
    items = completion.complete(ls.programs, path, line, column)
    return lsp.CompletionList(is_incomplete=False, items=items)


def _tree(ls: ScoopServer, uri: str):
    """The document's syntax tree: parsed from the buffer, else the last one that parsed."""
    path = _path(uri)
    source = ls.programs.texts.source(path)
    if source is None:
        return None, None
    tree = parser.parse(SourceFile(library_file(path), source.text)).tree
    if tree is None:
        analysis = ls.programs.good.get(path)
        tree = analysis.trees.get(path) if analysis is not None else None
    return tree, source


def on_symbols(ls: ScoopServer, params: lsp.DocumentSymbolParams) -> list[lsp.DocumentSymbol]:
    tree, source = _tree(ls, params.text_document.uri)
    return outline.symbols(tree, source) if tree is not None else []


def on_folding(ls: ScoopServer, params: lsp.FoldingRangeParams) -> list[lsp.FoldingRange]:
    tree, source = _tree(ls, params.text_document.uri)
    return outline.folding(tree, source) if tree is not None else []


def on_code_action(ls: ScoopServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
    path = _path(params.text_document.uri)
    analysis = ls.programs.latest.get(program_paths(path))
    if analysis is None:
        return []
    found = []
    for diagnostic in params.context.diagnostics:
        if diagnostic.code == fixes.UNCONTROLLED:
            found += fixes.actions(analysis, path, params.text_document.uri, diagnostic, ls.programs.texts)
    return found


_FEATURES = [
    ((lsp.INITIALIZED,), on_initialized),
    ((lsp.SHUTDOWN,), on_shutdown),
    ((lsp.TEXT_DOCUMENT_DID_OPEN,), did_open),
    ((lsp.TEXT_DOCUMENT_DID_CHANGE,), did_change),
    ((lsp.TEXT_DOCUMENT_DID_SAVE,), did_save),
    ((lsp.TEXT_DOCUMENT_DID_CLOSE,), did_close),
    ((lsp.WORKSPACE_DID_CHANGE_WATCHED_FILES,), on_watched_files),
    ((lsp.TEXT_DOCUMENT_HOVER,), on_hover),
    ((lsp.TEXT_DOCUMENT_DEFINITION,), on_definition),
    ((lsp.TEXT_DOCUMENT_REFERENCES,), on_references),
    ((lsp.TEXT_DOCUMENT_COMPLETION, lsp.CompletionOptions(trigger_characters=["."])), on_completion),
    ((lsp.TEXT_DOCUMENT_DOCUMENT_SYMBOL,), on_symbols),
    ((lsp.TEXT_DOCUMENT_FOLDING_RANGE,), on_folding),
    (
        (
            lsp.TEXT_DOCUMENT_CODE_ACTION,
            lsp.CodeActionOptions(code_action_kinds=[lsp.CodeActionKind.QuickFix]),
        ),
        on_code_action,
    ),
]


def build() -> ScoopServer:
    """A server with every feature registered (one per client: the tests start several)."""
    server = ScoopServer()
    for arguments, handler in _FEATURES:
        server.feature(*arguments)(handler)
    return server


def serve(stdin: BinaryIO | None = None, stdout: BinaryIO | None = None) -> int:
    """Run a server on stdin and stdout (or the given binary streams) until the client exits."""
    build().start_io(stdin, stdout)
    return 0


def main() -> int:
    """`scoopc lsp`: this process is the server's."""
    SERVER_PROCESS["freeze"] = True
    return serve()
