"""Parser stage, lexical values: the text of literal tokens to Python values.

Input: the text of an INTEGER, REAL, STRING or CHARACTER token. Output: the value and a list
of problems (offset in the text, length, reason) for the caller to report.
"""

from __future__ import annotations

import re

# ECMA-367 special character codes (`%N` and so on); letters are accepted in either case.
ESCAPES = {
    "A": "@",
    "B": "\b",
    "C": "^",
    "D": "$",
    "F": "\f",
    "H": "\\",
    "L": "~",
    "N": "\n",
    "Q": "`",
    "R": "\r",
    "S": "#",
    "T": "\t",
    "U": "\0",
    "V": "|",
    "%": "%",
    "'": "'",
    '"': '"',
    "(": "[",
    ")": "]",
    "<": "{",
    ">": "}",
}
_CODE = re.compile(r"/([0-9A-Za-z_]+)/")
_CONTINUATION = re.compile(r"%[ \t]*\n[ \t]*%")
Problem = tuple[int, int, str]


LARGEST_INTEGER = 2**64 - 1  # NATURAL_64's maximum: no integer type holds a larger literal
SMALLEST_INTEGER_NEGATED = 2**63  # -INTEGER_64's minimum


def too_large(text: str) -> str:
    """EiffelStudio's wording (EIFFEL_PARSER_SKELETON.report_integer_too_large_error)."""
    return f"integer value {text} is too large for any integer type"


def too_small(text: str) -> str:
    return f"integer value -{text} is too small for any integer type"


def integer_value(text: str) -> int | None:
    """The value of an integer literal (decimal, 0x hex, 0c octal, 0b binary); None if malformed."""
    digits = text.replace("_", "")
    base = {"x": 16, "c": 8, "b": 2}.get(digits[1:2].lower(), 10) if len(digits) > 1 and digits[0] == "0" else 10
    if base != 10:
        digits = digits[2:]
    try:
        return int(digits, base)
    except ValueError:
        return None


def real_value(text: str) -> float:
    return float(text.replace("_", ""))


def _code_value(code: str) -> int | None:
    value = integer_value(code)
    return value if value is not None and value <= 0x10FFFF else None


def _escape(text: str, i: int, problems: list[Problem]) -> tuple[str, int]:
    """Decode the escape whose `%` is at text[i]; return the character and the next index."""
    letter = text[i + 1 : i + 2]
    if letter == "/":
        match = _CODE.match(text, i + 1)
        value = _code_value(match.group(1)) if match else None
        if match is None or value is None:
            problems.append((i, 2, "bad character code after `%/`: write `%/65/` with a number"))
            return "", i + 2
        return chr(value), match.end()
    char = ESCAPES.get(letter.upper())
    if char is None:
        problems.append((i, 2, f"`%{letter}` is not a special character code (use `%%` for a percent sign)"))
        return "", i + 2
    return char, i + 2


def _decode_escapes(text: str, start: int, end: int, problems: list[Problem]) -> str:
    out: list[str] = []
    i = start
    find = text.find
    while i < end:
        j = find("%", i, end)
        if j < 0:
            out.append(text[i:end])
            break
        out.append(text[i:j])
        continuation = _CONTINUATION.match(text, j)
        if continuation is not None:
            i = continuation.end()
            continue
        char, i = _escape(text, j, problems)
        out.append(char)
    return "".join(out)


def string_value(text: str) -> tuple[str, bool, list[Problem]]:
    """(value, verbatim, problems) of a manifest string token, quotes included."""
    problems: list[Problem] = []
    if text[1:2] in ("[", "{") and "\n" in text:
        return _verbatim(text), True, problems
    if "%" not in text:
        return text[1:-1], False, problems
    return _decode_escapes(text, 1, len(text) - 1, problems), False, problems


def _verbatim(text: str) -> str:
    """The lines between `"[` and `]"`; an aligned (`[`) string loses their common indentation."""
    first = text.index("\n")
    last = text.rindex("\n")
    if last <= first:
        return ""
    lines = text[first + 1 : last].split("\n")
    if text[1] == "{":
        return "\n".join(lines)
    margins = [len(line) - len(line.lstrip(" \t")) for line in lines if line.strip()]
    cut = min(margins) if margins else 0
    prefix = _common_prefix([line[:cut] for line in lines if line.strip()])
    return "\n".join(line[len(prefix) :] if line.startswith(prefix) else line.lstrip(" \t") for line in lines)


def _common_prefix(items: list[str]) -> str:
    if not items:
        return ""
    low, high = min(items), max(items)
    n = 0
    while n < len(low) and low[n] == high[n]:
        n += 1
    return low[:n]


def character_value(text: str) -> tuple[str, list[Problem]]:
    """(value, problems) of a character token, quotes included."""
    problems: list[Problem] = []
    if text[1] != "%":
        return text[1:-1], problems
    value = _decode_escapes(text, 1, len(text) - 1, problems)
    return value, problems
