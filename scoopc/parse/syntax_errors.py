"""Parser stage, syntax errors: lark's exceptions to diagnostics in Eiffel terms.

Input: the UnexpectedInput raised by the LALR parser, the SourceFile and the parser's
terminals. Output: one Diagnostic (SYNTAX, SYNTAX-END, SYNTAX-RESERVED, SYNTAX-LEXICAL or
SYNTAX-OBSOLETE).
Diagnosis tries repairs on copies of the parser: if inserting `end` lets the parse go on, an
`end` is missing; if reading the keyword as a name does, a reserved word was used as a name.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from lark import Token
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

from .. import diagnostics, syntax
from ..diagnostics import Diagnostic
from ..source import SourceFile, Span
from .syntax_terms import EXPRESSION_STARTS, INSTRUCTION_KEYWORDS, KEYWORDS, OPENERS, OPERATORS, describe_token, display

# After a keyword used as a name, one of these usually follows (or a `.` precedes it).
_NAME_FOLLOWERS = {"COLON", "COMMA", "ASSIGNMENT", "DOT", "RPAR", "SEMICOLON", "LPAR"}
_MAX_MISSING_ENDS = 6


def describe(error: UnexpectedInput, source: SourceFile, lark_parser: Any) -> Diagnostic:
    """The diagnostic for the first syntax error of a file."""
    if isinstance(error, UnexpectedCharacters):
        return _lexical(error, source)
    if isinstance(error, UnexpectedToken):
        return _unexpected(error, source, lark_parser)
    return diagnostics.make(
        "SYNTAX", Span.point(source.path, error.line, error.column), found="this text", expected="Eiffel text"
    )


# ---- lexical errors ---------------------------------------------------------------------
def _lexical(error: UnexpectedCharacters, source: SourceFile) -> Diagnostic:
    text, pos = source.text, error.pos_in_stream
    char = text[pos] if pos < len(text) else ""
    span = Span.point(source.path, error.line, error.column)
    return diagnostics.make("SYNTAX-LEXICAL", span, reason=_lexical_reason(char, text, pos))


def _lexical_reason(char: str, text: str, pos: int) -> str:
    if char == '"':
        if text[pos + 1 : pos + 2] in ("[", "{") and text[pos + 2 :].lstrip(" \t")[:1] == "\n":
            closer = "]" if text[pos + 1] == "[" else "}"
            return f'unterminated verbatim string: no line `{closer}"` closes it'
        return (
            'unterminated string: a manifest string ends with `"` on the same line '
            "(end a line with `%` and start the next with `%` to continue it)"
        )
    if char == "'":
        return "bad character constant: write one character between single quotes, such as `'a'` or `'%N'`"
    if char == "\\":
        return "`\\` is not an Eiffel escape character; special characters are written `%N`, `%T`, `%%`"
    if char.isprintable() and not char.isspace():
        return f"`{char}` (U+{ord(char):04X}) is not part of any Eiffel token"
    return f"the character U+{ord(char):04X} is not allowed in Eiffel text" if char else "unexpected end of the file"


# ---- unexpected tokens ------------------------------------------------------------------
def _unexpected(error: UnexpectedToken, source: SourceFile, lark_parser: Any) -> Diagnostic:
    token = error.token
    span = _token_span(token, source)
    try:
        parser, following = _replay(lark_parser, source.text, token)
        expected = parser.accepts()
    except UnexpectedInput:  # cannot happen: the prefix parsed once already
        parser, following, expected = None, None, set(error.expected)
    if parser is not None:
        if _is_reserved_name(parser, token, expected, following):
            return diagnostics.make("SYNTAX-RESERVED", span, word=token.value)
    obsolete = _obsolete(token, expected, parser.parser_state.value_stack if parser is not None else [])
    if obsolete is not None:
        return diagnostics.make("SYNTAX-OBSOLETE", span, **obsolete)
    if parser is not None:
        missing = _dedent_missing_end(lark_parser, source.text, token) or _missing_end(parser, token, expected)
        if missing is not None:
            return _syntax_end(missing, source, span)
    patterns = {t.name: t.pattern.value for t in lark_parser.terminals}
    stack = parser.parser_state.value_stack if parser is not None else []
    return diagnostics.make(
        "SYNTAX",
        span,
        found=describe_token(token),
        expected=expected_phrase(expected, patterns),
        hint=_hint(token, expected, stack),
    )


def _hint(token: Token, expected: set, stack: list) -> str:
    """Advice for the mistakes students make most, recognised by the token and what the parser
    wanted; '' when none applies."""
    previous = getattr(stack[-1], "type", None) if stack else None
    kind = token.type
    if kind == "EQUAL" and previous == "EQUAL":
        return "Eiffel compares with a single `=` (and `/=` for not equal)"
    if kind == "ASSIGNMENT" and expected and expected <= {"COMMA", "COLON"}:
        return "instructions come after `do`: is the `do` of this routine missing?"
    if kind == "ASSIGNMENT" and expected & OPERATORS:
        return "`:=` assigns a value; to compare two values write `=`"
    if kind == "EQUAL" and "ASSIGNMENT" in expected:
        return "`=` compares two values; to assign a value write `:=`"
    if kind == "SEMICOLON" and "THEN" in expected:
        return "a condition ends with `then`"
    if kind == "IDENTIFIER" and "THEN" in expected:
        return "a condition ends with `then` before the instructions it guards"
    if kind == "IDENTIFIER" and "LOOP" in expected:
        return "the exit condition after `until` ends with `loop` before the loop body"
    return ""


# Pre-ECMA spellings still found in old course material and old example programs.
_OBSOLETE = {
    ("IDENTIFIER", "creation"): ("`creation` is the obsolete spelling of `create`", "write `create` instead"),
    ("IS", "is"): (
        "`is` before a routine body or a constant's value is obsolete syntax",
        "delete `is` before a routine's body; write a constant as `Name: TYPE = value`",
    ),
    ("IDENTIFIER", "infix"): (
        '`infix "op"` feature names are obsolete syntax',
        'name the feature and give it an alias: `plus alias "+" (other: like Current)`',
    ),
    ("IDENTIFIER", "prefix"): (
        '`prefix "op"` feature names are obsolete syntax',
        'name the feature and give it an alias: `negated alias "-"`',
    ),
}


def _obsolete(token: Token, expected: set, stack: list) -> dict | None:
    """Arguments of a SYNTAX-OBSOLETE diagnostic when `token` starts or shows an obsolete form."""
    entry = _OBSOLETE.get((token.type, str(token.value).lower()))
    previous = stack[-1] if stack else None
    if entry is None and token.type == "STRING" and getattr(previous, "type", None) == "IDENTIFIER":
        entry = _OBSOLETE.get(("IDENTIFIER", str(previous.value).lower()))
    if entry is None and token.type == "QUESTION" and "DETACHABLE" in expected:
        entry = ("`?T` is the obsolete spelling of `detachable T`", "write `detachable T`")
    if (
        entry is None
        and token.type == "COLON"
        and len(stack) >= 2
        and getattr(stack[-2], "type", None) == "LBRACE"
        and getattr(stack[-1], "type", None) == "IDENTIFIER"
    ):
        entry = ("`{x: T} e` is the obsolete form of an object test", "write `attached {T} e as x`")
    if entry is None:
        return None
    return {"what": entry[0], "instead": entry[1] + "; scoopc accepts ECMA-367's form only"}


def _replay(lark_parser: Any, text: str, stop: Token) -> tuple[Any, Token | None]:
    """A parser fed with every token before `stop` (so with no reduction that `stop` caused:
    LALR may reduce on a token it then rejects), and the token after `stop`."""
    parser = lark_parser.parse_interactive(text)
    tokens = parser.lexer_thread.lex(parser.parser_state)
    at_end = stop.type == "$END"
    for token in tokens:
        if not at_end and token.start_pos >= stop.start_pos:
            return parser, _next(tokens)
        parser.feed_token(token)
    return parser, None


def _next(tokens: Iterator[Token]) -> Token | None:
    try:
        return next(tokens, None)
    except UnexpectedInput:
        return None


def _token_span(token: Token, source: SourceFile) -> Span:
    if token.type == "$END":  # the start of the last line with text: where `end` was due
        line, _ = source.position(max(0, len(source.text.rstrip()) - 1))
        return Span.point(source.path, line, 1)
    return Span(source.path, token.line, token.column, token.end_line, token.end_column)


def _feeds(parser: Any, tokens: list) -> bool:
    """Whether `tokens` are accepted one after the other by a copy of `parser` (a copy without
    the AST callbacks, so trying has no side effect)."""
    trial = parser.copy(deepcopy_values=False)
    conf = copy.copy(trial.parser_state.parse_conf)
    conf.callbacks = {}
    trial.parser_state.parse_conf = conf
    try:
        for token in tokens:
            trial.feed_token(token)
    except UnexpectedInput:
        return False
    return True


def _borrow(type_: str, value: str, token: Token) -> Token:
    return Token(type_, value, token.start_pos, token.line, token.column, token.line, token.column, token.start_pos)


def _is_reserved_name(parser: Any, token: Token, expected: set, following: Token | None) -> bool:
    if token.type not in KEYWORDS or token.type in expected or "IDENTIFIER" not in expected:
        return False
    stack = parser.parser_state.value_stack
    after_dot = bool(stack) and getattr(stack[-1], "type", None) == "DOT"
    if following is None or (following.type not in _NAME_FOLLOWERS and not after_dot):
        return False
    return _feeds(parser, [_borrow("IDENTIFIER", token.value, token), following])


@dataclass(frozen=True)
class _Open:
    """A construct left open: its keyword, where the keyword is, and the routine it belongs to."""

    construct: str
    line: int
    column: int
    routine: str = ""


def _syntax_end(missing: tuple[_Open, Token | None], source: SourceFile, at: Span) -> Diagnostic:
    """SYNTAX-END located at the construct that lacks its `end`, with a note where it was due."""
    opened, due = missing
    due_span = _token_span(due, source) if due is not None else at
    span = Span(source.path, opened.line, opened.column, opened.line, opened.column + len(opened.construct))
    owner = f" of `{opened.routine}`" if opened.routine else ""
    where = "the end of the file" if due is None or due.type == "$END" else f"line {due_span.line}"
    found = diagnostics.make(
        "SYNTAX-END",
        span,
        notes=[diagnostics.Note(f"the `end` was due before {where}", due_span)],
        construct=opened.construct,
        opened=f"{opened.line}:{opened.column}",
        owner=owner,
        due=where,
    )
    lines = source.text.split("\n")[opened.line - 1 : due_span.line]
    if opened.construct == "if" and any(_ELSE_IF.match(line) for line in lines):
        return dataclasses.replace(found, hint=_ELSE_IF_HINT)
    return found


_ELSE_IF = re.compile(r"\s*else\s+if\b", re.IGNORECASE)
_ELSE_IF_HINT = "`else if` opens a second `if`, which needs its own `end`: write `elseif` to add a branch"


# Words that may start a line at the same column as the keyword of the construct they belong to.
_SAME_COLUMN = frozenset(
    """
END ELSE ELSEIF WHEN THEN UNTIL LOOP INVARIANT VARIANT ENSURE RESCUE REQUIRE LOCAL DO ONCE ALL SOME
FROM FEATURE CREATE INHERIT CONVERT NOTE ATTRIBUTE EXTERNAL
""".split()
)
_LOOKAHEAD = 40  # tokens after the error a repair must also accept


def _dedent_missing_end(lark_parser: Any, text: str, stop: Token) -> tuple[_Open, Token] | None:
    """The construct whose `end` is missing, found by indentation: the first line, up to the
    error, that starts left of an open construct's keyword (or at its column with a word that
    does not continue it), where adding that many `end`s lets the parse go on past the error.
    Eiffel code is laid out so; this finds a routine's missing `end` even when the next
    routine's header parsed for a while as a call (`print (n)` then `other (x`)."""
    parser = lark_parser.parse_interactive(text)
    tokens = _tokens_through(parser, stop)
    indents = [len(line) - len(line.lstrip(" \t")) + 1 for line in text.split("\n")]
    line = 0
    for index, token in enumerate(tokens):
        if token.type == "$END" or token.start_pos > stop.start_pos:
            break
        if token.line > line:
            found = _close_before(parser, tokens[index:], indents)
            if found is not None:
                return found, token
        try:
            parser.feed_token(token)
        except UnexpectedInput:
            return None
        line = token.end_line or token.line
    return None


def _tokens_through(parser: Any, stop: Token) -> list[Token]:
    """The tokens of the file up to `stop` and a few beyond (fewer if the lexer fails); with
    `stop` itself last when it is the end of the file."""
    stream = parser.lexer_thread.lex(parser.parser_state)
    if stop.type == "$END":
        return list(iter(lambda: _next(stream), None)) + [stop]
    tokens: list[Token] = []
    after = 0
    while after < _LOOKAHEAD:
        token = _next(stream)
        if token is None:
            break
        tokens.append(token)
        after += token.start_pos > stop.start_pos
    return tokens


def _close_before(parser: Any, rest: list[Token], indents: list[int]) -> _Open | None:
    """The innermost open construct that `rest[0]` (a line's first token) leaves, if closing the
    constructs it leaves with `end`s lets the parser accept `rest`. A construct's indentation
    is that of the line its keyword is on (`separate a as b do` is as indented as `separate`)."""
    first = rest[0]
    left = []
    for opened in _open_constructs(parser.parser_state.value_stack):
        indent = indents[opened.line - 1]
        if first.column < indent or (first.column == indent and first.type not in _SAME_COLUMN):
            left.append(opened)
        else:
            break
    if not left or "END" not in parser.accepts():
        return None
    ends = [_borrow("END", "end", first) for _ in left]
    return left[0] if _feeds(parser, ends + rest) else None


def _open_constructs(stack: list) -> list[_Open]:
    """The constructs open on the parser's stack (no `end` shifted for them), innermost first."""
    ends = 0
    found: list[_Open] = []
    for index in range(len(stack) - 1, -1, -1):
        value = stack[index]
        if getattr(value, "type", None) == "END":
            ends += 1
            continue
        opener = _opener(value)
        if opener is None or _separate_do(stack, index):
            continue
        if ends:
            ends -= 1
            continue
        found.append(_Open(opener[0], opener[1], opener[2], _routine_name(stack, index, opener[0])))
    return found


def _separate_do(stack: list, index: int) -> bool:
    """Whether `stack[index]` is the `do` of a separate instruction's header."""
    if getattr(stack[index], "type", None) != "DO":
        return False
    for value in reversed(stack[:index]):
        kind = getattr(value, "type", None)
        if kind == "SEPARATE":
            return True
        if kind != "COMMA" and not isinstance(value, syntax.SeparateArgument):
            return False
    return False


def _routine_name(stack: list, index: int, construct: str) -> str:
    """The name of the routine whose body `stack[index]` opens ('' for other constructs)."""
    if construct not in _BODIES.values() and construct != "once":
        return ""
    for value in reversed(stack[:index]):
        if getattr(value, "data", None) == "_feature_names":
            names = [getattr(getattr(n, "name", None), "text", "") for n in value.children]
            return ", ".join(n for n in names if n)
    return ""


def _missing_end(parser: Any, token: Token, expected: set) -> tuple[_Open, Token] | None:
    """The innermost construct whose `end` is missing, if adding `end`s lets the parser accept
    `token`, and `token` (where the `end` was due)."""
    if "END" not in expected:
        return None
    ends: list[Token] = []
    for _ in range(_MAX_MISSING_ENDS):
        ends.append(_borrow("END", "end", token))
        if _feeds(parser, ends + [token]):
            opened = _innermost_opener(parser.parser_state.value_stack)
            return (opened, token) if opened is not None else None
        if not _feeds(parser, ends):
            return None
    return None


def _innermost_opener(stack: list) -> _Open | None:
    """The innermost opener on the parser's stack that lacks its `end`. An `end` less indented
    than the opener it was matched with belonged to an outer construct (Eiffel code aligns
    `end` with its opener), so that opener, or a construct nested in it that took its `end`,
    is the one left open."""
    ends: list[Any] = []
    inner: list[Any] = []
    for index in range(len(stack) - 1, -1, -1):
        value = stack[index]
        if getattr(value, "type", None) == "END":
            ends.append(value)
            continue
        opener = _opener(value)
        if opener is None:
            inner.append(value)
            continue
        if not ends or ends.pop().column < opener[2]:
            nested = _misaligned_within(inner + [value])
            return nested or _Open(opener[0], opener[1], opener[2], _routine_name(stack, index, opener[0]))
        inner.append(value)
    return None


_CONSTRUCTS = {
    syntax.Conditional: "if",
    syntax.MultiBranch: "inspect",
    syntax.Loop: "from",
    syntax.Across: "across",
    syntax.Check: "check",
    syntax.Debug: "debug",
    syntax.SeparateInstruction: "separate",
}


def _misaligned_within(values: list) -> _Open | None:
    """The deepest construct, along the last instructions of `values`, whose `end` is less
    indented than its opening keyword (it took the `end` of the construct around it)."""
    found = None
    node: Any = _last_instruction(values)
    while node is not None:
        span = node.span
        if type(node) in _CONSTRUCTS and span.end_column - 3 < span.column:
            found = _Open(_CONSTRUCTS[type(node)], span.line, span.column)
        node = _last_instruction(_inner_compound(node))
    return found


def _last_instruction(values: Any) -> Any:
    for value in reversed(values or ()):
        if isinstance(value, tuple):
            value = _last_instruction(value)
        if value is not None and hasattr(value, "span"):
            return value
    return None


def _inner_compound(node: Any) -> Any:
    if isinstance(node, syntax.Conditional):
        return node.else_part or (node.elseif_parts[-1].then_part if node.elseif_parts else node.then_part)
    if isinstance(node, syntax.MultiBranch):
        return node.else_part or (node.when_parts[-1].then_part if node.when_parts else ())
    if isinstance(node, syntax.Check):
        return node.then_part
    if isinstance(node, (syntax.InternalBody, syntax.AttributeBody)):
        return node.instructions
    return getattr(node, "body", None) if type(node) in _CONSTRUCTS else None


def _opener(value: Any) -> tuple[str, int, int] | None:
    """(keyword, line, column) if `value` on the parser's stack opens a construct."""
    if isinstance(getattr(value, "type", None), str):
        token = value
    else:
        token = getattr(value, "keyword", None)
    if token is not None:
        if token.type not in OPENERS:
            return None
        return token.value.lower(), token.line, token.column
    body = _BODIES.get(type(value))
    if body is None:
        return None
    word = "once" if getattr(value, "once", False) else body
    return word, value.span.line, value.span.column


_BODIES = {
    syntax.InternalBody: "do",
    syntax.DeferredBody: "deferred",
    syntax.ExternalBody: "external",
    syntax.AttributeBody: "attribute",
}


def expected_phrase(expected: set, patterns: dict[str, str]) -> str:
    """A short human list of what the grammar allowed, in Eiffel terms."""
    remaining = set(expected)
    categories: list[str] = []
    if len(remaining & OPERATORS) >= 4:
        remaining -= OPERATORS | {"DOT", "LPAR", "LSQB", "ASSIGNMENT", "ASSIGNMENT_ATTEMPT", "INTERVAL"}
        categories.append("an operator")
    if len(remaining & (INSTRUCTION_KEYWORDS - EXPRESSION_STARTS)) >= 3:
        remaining -= INSTRUCTION_KEYWORDS | EXPRESSION_STARTS
        categories.append("an instruction")
    elif len(remaining & EXPRESSION_STARTS) >= 6:
        remaining -= EXPRESSION_STARTS
        categories.append("an expression")
    words = sorted({display(name, patterns) for name in remaining} - {""})
    items = words[:6] + (["..."] if len(words) > 6 else []) + categories
    if not items:
        return "something else"
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]
