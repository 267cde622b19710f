"""Parser stage, vocabulary of syntax errors: grammar terminals named in Eiffel terms.

Input: terminal names of scoopc/grammar.lark and tokens. Output: the words messages use.
"""

from __future__ import annotations

from typing import Any

KEYWORDS = frozenset(
    """
ACROSS AGENT ALIAS ALL AND AS ASSIGN ATTACHED ATTRIBUTE CHECK CLASS CONVERT CREATE CURRENT
DEBUG DEFERRED DETACHABLE DO ELSE ELSEIF END ENSURE EXPANDED EXPORT EXTERNAL FALSE FEATURE
FROM FROZEN IF IMPLIES INDEXING INHERIT INSPECT INVARIANT IS LIKE LOCAL LOOP NOT NOTE OBSOLETE OLD ONCE
OR PRECURSOR REDEFINE REFERENCE RENAME REQUIRE RESCUE RESULT RETRY SELECT SEPARATE SOME THEN TRUE
UNDEFINE UNIQUE UNTIL VARIANT VOID WHEN XOR
""".split()
)

# Keywords that open a construct closed by `end`, innermost first when found on the stack.
OPENERS = frozenset(
    """
CLASS IF INSPECT FROM ACROSS CHECK DEBUG SEPARATE DO ONCE ATTRIBUTE EXTERNAL DEFERRED
RENAME EXPORT UNDEFINE REDEFINE SELECT
""".split()
)

OPERATORS = frozenset(
    """
AND OR XOR IMPLIES EQUAL NOT_EQUAL TILDE NOT_TILDE LESS GREATER LESS_EQUAL GREATER_EQUAL
PLUS MINUS STAR SLASH INTEGER_DIVIDE MODULO CARET FREE_OPERATOR INTERVAL
""".split()
)

INSTRUCTION_KEYWORDS = frozenset("IF INSPECT FROM ACROSS CHECK DEBUG SEPARATE CREATE RETRY LOOP_OPEN".split())

EXPRESSION_STARTS = frozenset(
    """
IDENTIFIER INTEGER REAL STRING CHARACTER TRUE FALSE VOID CURRENT RESULT PRECURSOR LPAR LSQB
LBRACE MANIFEST_ARRAY_OPEN AGENT CREATE ATTACHED IF INSPECT ACROSS QUESTION DOLLAR ONCE_STRING NOT MINUS
PLUS OLD FREE_OPERATOR FOR_ALL THERE_EXISTS
""".split()
)

_CATEGORIES = {
    "IDENTIFIER": "a name",
    "INTEGER": "an integer",
    "REAL": "a real number",
    "STRING": "a string",
    "CHARACTER": "a character",
    "$END": "the end of the file",
    "FREE_OPERATOR": "",
    "ONCE_STRING": "",
}


def display(name: str, patterns: dict[str, str]) -> str:
    """How a terminal is named in a list of expected things."""
    if name in _CATEGORIES:
        return _CATEGORIES[name]
    if name in KEYWORDS:
        return f"`{name.lower()}`"
    pattern = patterns.get(name)
    return f"`{pattern}`" if pattern else ""


def describe_token(token: Any) -> str:
    """How the token found is named in a message."""
    kind, value = token.type, str(token.value)
    if kind == "$END":
        return "the end of the file"
    if kind in KEYWORDS:
        return f"`{value}`"
    if kind == "IDENTIFIER":
        return f"the name `{value}`"
    if kind in ("INTEGER", "REAL"):
        return f"the number `{value}`"
    if kind in ("STRING", "ONCE_STRING"):
        shown = value if len(value) <= 24 else value[:20] + '..."'
        return f"the string {shown}"
    if kind == "CHARACTER":
        return f"the character {value}"
    return f"`{value}`"
