"""Parser stage: Eiffel source text to an AST, with syntax diagnostics.

Input: a SourceFile. Output: ParseResult (the ClassDeclaration or None, and diagnostics).
lark's LALR(1) parser with the basic lexer (so keywords are reserved) builds AST nodes in its
reduction callbacks (scoopc/parse_tree); there is no intermediate parse tree.
"""

from __future__ import annotations

import hashlib
import os
import re
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path

import lark
from lark import Lark
from lark.exceptions import UnexpectedInput

from .. import diagnostics, syntax, version
from ..diagnostics import Diagnostic, InternalError
from ..source import SourceFile, Span
from . import syntax_errors
from .builders import AstBuilder
from .nesting import too_deep

GRAMMAR_PATH = Path(__file__).parents[1] / "grammar.lark"  # where users and docs look for it

_lock = threading.Lock()
_instance: tuple[Lark, AstBuilder] | None = None
_pure: Lark | None = None


@dataclass
class ParseResult:
    tree: syntax.ClassDeclaration | None
    diagnostics: list[Diagnostic] = field(default_factory=list)


def _accelerator() -> dict:
    """lark-cython's plugins when installed and not disabled (SCOOPC_PURE_PARSER=1)."""
    if os.environ.get("SCOOPC_PURE_PARSER"):
        return {}
    try:
        import lark_cython  # type: ignore[import-not-found]  # optional: the `fast` extra
    except ImportError:
        return {}
    return {"_plugins": lark_cython.plugins}


def make_parser(builder: object, accelerate: bool = True) -> Lark:
    """A lark LALR parser for the grammar that calls `builder`'s methods on each reduction. Its
    tables are the ones a wheel ships, made for this grammar, lark and Python, when they load
    (building them takes about a second); else they are built, with lark's cache in the
    temporary folder."""
    options = _accelerator() if accelerate else {}
    grammar = GRAMMAR_PATH.read_text(encoding="utf-8")
    shipped = version.prebuilt(parser_file(grammar))
    if shipped is not None:
        try:
            with open(shipped, "rb") as handle:
                # Lark.load with the callbacks: the form lark's own cache uses (Lark.load takes none)
                return Lark.__new__(Lark)._load(handle, transformer=builder, **options)
        except Exception:  # not loadable by this lark after all: build the tables
            pass
    return Lark(grammar, transformer=builder, cache=True, **PARSER_OPTIONS, **options)


PARSER_OPTIONS = {"parser": "lalr", "lexer": "basic", "maybe_placeholders": True, "propagate_positions": False}


def parser_file(grammar: str) -> str:
    """The name of the serialized parser for `grammar` under this lark and Python."""
    key = f"{grammar}{PARSER_OPTIONS}{lark.__version__}{sys.version_info[:2]}"
    return f"parser-{hashlib.sha256(key.encode()).hexdigest()[:24]}.lark"


def save_parser(folder: Path) -> Path:
    """Serialize the parser's tables into `folder` (a wheel's build): what make_parser loads."""
    grammar = GRAMMAR_PATH.read_text(encoding="utf-8")
    path = folder / parser_file(grammar)
    with open(path, "wb") as handle:
        Lark(grammar, **PARSER_OPTIONS).save(handle)
    return path


def _parser() -> tuple[Lark, AstBuilder]:
    global _instance
    if _instance is None:
        builder = AstBuilder()
        _instance = (make_parser(builder), builder)
    return _instance


def _diagnosis_parser(fast: Lark, builder: AstBuilder) -> Lark:
    """The pure-Python parser, which syntax_errors replays to explain an error (lark-cython's
    interactive parser lacks what it needs); the same as `fast` when there is no accelerator."""
    global _pure
    if not _accelerator():
        return fast
    if _pure is None:
        _pure = make_parser(builder, accelerate=False)
    return _pure


def parse(source: SourceFile) -> ParseResult:
    """Parse one file, which must hold exactly one class. Never raises for bad input.

    After a syntax error, parsing resumes at the next feature clause (see `_recover`), so that
    independent mistakes in different clauses are all reported, one diagnostic each."""
    with _lock:
        classes, problems, error = _parse_once(source)
        if error is None:
            return _one_class(classes, source, problems)
        return ParseResult(None, _sorted(problems + [error] + _recover(source, error)))


def _parse_once(source: SourceFile) -> tuple[list, list[Diagnostic], Diagnostic | None]:
    """(classes, problems, the syntax error or None) of one run of the parser over `source`."""
    lark_parser, builder = _parser()
    builder.reset(source.path)
    try:
        classes = lark_parser.parse(source.text)
    except UnexpectedInput as error:
        found = syntax_errors.describe(error, source, _diagnosis_parser(lark_parser, builder))
        return [], list(builder.problems), found
    except Exception as error:  # a bug in scoopc, not the user's mistake
        raise InternalError(f"the parser failed on {source.path}: {error!r}") from error
    return classes, builder.problems + _stray_open_operands(builder), None


# A clause keyword at the start of a line: where parsing can resume after an error.
_CLAUSE_START = re.compile(r"^(?:feature|invariant|end)\b", re.IGNORECASE | re.MULTILINE)
_FEATURE_START = re.compile(r"^feature\b", re.IGNORECASE | re.MULTILINE)
_MAX_ERRORS = 20


def _recover(source: SourceFile, error: Diagnostic) -> list[Diagnostic]:
    """Further syntax errors after `error`: the feature clause holding an error is blanked
    (spaces, newlines kept, so positions stay true) and the file parsed again, as long as each
    new error lies after the blanked text. Relies on `feature` starting its line, as Eiffel
    code is laid out; without that, only the first error is reported."""
    found: list[Diagnostic] = []
    text = source.text
    while error is not None and len(found) < _MAX_ERRORS - 1:
        at = source.offset(error.span.line, error.span.column)
        clause = _last_match_before(_FEATURE_START, text, at + 1)
        resume = _CLAUSE_START.search(text, at + 1 if clause is not None and clause == at else at)
        if clause is None or resume is None:
            break
        text = text[:clause] + re.sub(r"[^\n]", " ", text[clause : resume.start()]) + text[resume.start() :]
        _, problems, error = _parse_once(SourceFile(source.path, text))
        later = [p for p in problems + ([error] if error else []) if _offset(source, p) >= resume.start()]
        if error is not None and _offset(source, error) < resume.start():
            break
        found.extend(later)
    return found


def _last_match_before(pattern: re.Pattern, text: str, end: int) -> int | None:
    start = None
    for match in pattern.finditer(text, 0, end):
        start = match.start()
    return start


def _offset(source: SourceFile, d: Diagnostic) -> int:
    return source.offset(d.span.line, d.span.column) if d.span else 0


def _stray_open_operands(builder: AstBuilder) -> list[Diagnostic]:
    return [
        diagnostics.make(
            "SYNTAX",
            operand.span,
            found="`?`",
            expected="an expression (`?` is an open operand, only allowed among the arguments of an agent)",
        )
        for operand in builder.unopened_operands()
    ]


def _one_class(classes: list, source: SourceFile, problems: list[Diagnostic]) -> ParseResult:
    if not classes:
        end = source.position(len(source.text))
        problems.append(
            diagnostics.make("SYNTAX-CLASS", Span.point(source.path, *end), reason="the file holds no class")
        )
        return ParseResult(None, _sorted(problems))
    for extra in classes[1:]:
        problems.append(
            diagnostics.make(
                "SYNTAX-CLASS",
                Span.point(source.path, extra.span.line, extra.span.column),
                reason=f"class `{extra.name.text}` is a second class in this file (after `{classes[0].name.text}`)",
            )
        )
    deep = too_deep(classes[0])
    if deep is not None:
        return ParseResult(None, _sorted(problems + [deep]))
    return ParseResult(classes[0], _sorted(problems))


def _sorted(problems: list[Diagnostic]) -> list[Diagnostic]:
    return sorted(problems, key=diagnostics.sort_key)
