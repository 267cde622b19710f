"""Every user-facing diagnostic message, by code: the one table of wording.

Codes of the Eiffel validity rules are spelled as EiffelStudio prints them (VEEN, VUTA(3), ...).
Codes of our own, for conditions ECMA-367 gives no code, are listed here with their meaning:

- SYNTAX: a token the grammar does not allow at that place.
- SYNTAX-END: a construct is not closed by its `end`.
- SYNTAX-RESERVED: a reserved word used where a name is expected.
- SYNTAX-LEXICAL: a character or literal that is not part of any Eiffel token.
- SYNTAX-CLASS: the file does not hold exactly one class.
- SYNTAX-OBSOLETE: pre-ECMA syntax (`indexing`, `is` before a routine body, `creation`,
  `infix`/`prefix` names) that EiffelStudio accepts only in its obsolete-syntax mode.
- SYNTAX-FEATURE: an `attribute` body on a feature without a type, or an attribute or
  constant declared with arguments.
- SOURCE: a file that cannot be read (missing, not UTF-8).
- ECF: a problem in an .ecf project file; ECF-NOTE: an .ecf setting we ignore.

Each entry has a `text` template (str.format fields) and a `hint` template a student can act on.
"""
from __future__ import annotations

from typing import NamedTuple


class Message(NamedTuple):
    text: str
    hint: str = ""


MESSAGES: dict[str, Message] = {
    # --- input files --------------------------------------------------------------------
    "SOURCE": Message("cannot read {path}: {reason}"),
    "ECF": Message("{reason}"),
    "ECF-NOTE": Message("{reason}"),
    # --- syntax ---------------------------------------------------------------------------
    "SYNTAX": Message("{found} is not allowed here; expected {expected}", "{hint}"),
    "SYNTAX-END": Message(
        "missing `end` of the `{construct}` opened at {opened}",
        "every `{construct}` needs its own `end`; check the lines between {opened} and here",
    ),
    "SYNTAX-RESERVED": Message(
        "`{word}` is a reserved word and cannot be used as a name",
        "choose another name, for example `{word}_value`",
    ),
    "SYNTAX-LEXICAL": Message("{reason}"),
    "SYNTAX-OBSOLETE": Message("{what}", "{instead}; scoopc accepts the ECMA-367 syntax of EiffelStudio 7 and later"),
    "SYNTAX-CLASS": Message("{reason}", "Eiffel puts one class in each .e file"),
    "SYNTAX-FEATURE": Message(
        "the feature `{name}` mixes an attribute and a routine: an attribute has a type and no arguments",
        "write `{name}: TYPE` (with `attribute ... end` if needed) for an attribute, or `do ... end` for a routine",
    ),
}
