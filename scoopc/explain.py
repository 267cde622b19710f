"""`scoopc check --explain CODE`: a diagnostic code (ours, EiffelStudio's spelling, or a Gobo alias)
-> its explanation (explanations.py) and its message and hint templates (messages.py)."""

from __future__ import annotations

import difflib
import re
import textwrap

from . import messages
from .explanations import ALIASES, EXPLANATIONS


def _squeezed(code: str) -> str:
    """A code with case, spaces and punctuation ignored: `vuta-3`, `VUTA(3)` and `VUTA3` agree."""
    return re.sub(r"[^A-Z0-9]", "", code.upper())


def _spellings() -> dict[str, str]:
    """Every known code and alias, squeezed, to the code we print."""
    table = {_squeezed(code): code for code in list(messages.MESSAGES) + list(EXPLANATIONS)}
    table.update({_squeezed(alias): code for alias, code in ALIASES.items()})
    return table


def canonical_code(code: str) -> str:
    """`vuta-3`, `VUTA3` or `VUTA(3)` -> `VUTA(3)`: test folders and shells write parentheses as
    a dash, and a shell needs quotes around `VUTA(3)`. Gobo's finer SCOOP codes resolve to ours
    (`vuta-4g`, `VUTA4G` or `VUTA(4G)` -> `VUTA(3)`)."""
    spelled = re.sub(r"\((\w+)\)$", r"-\1", code.strip().upper())
    if spelled in ALIASES:
        return ALIASES[spelled]
    known = _spellings().get(_squeezed(code))
    if known is not None:
        return known
    match = re.fullmatch(r"(V[A-Z0-9]+)-(\d+)", spelled)
    return f"{match.group(1)}({match.group(2)})" if match else spelled


def suggestions(code: str) -> list[str]:
    """Known codes spelled like `code`, closest first (for an unknown code)."""
    table = _spellings()
    close = difflib.get_close_matches(_squeezed(code), list(table), n=3, cutoff=0.6)
    return list(dict.fromkeys(table[name] for name in close))


def summary(code: str) -> str:
    """One line: the code and the first sentence of its rule."""
    entry = EXPLANATIONS.get(code)
    text = entry.rule if entry is not None else messages.MESSAGES[code].text
    sentences = re.split(r"(?<=[.:;])\s", text)
    first = sentences[0] if len(sentences[0]) >= 30 or len(sentences) == 1 else " ".join(sentences[:2])
    first = first.rstrip(".:;")
    if len(first) > 96:
        first = first[:93].rsplit(" ", 1)[0] + " ..."
    return f"{code:<18} {first}"


def listing() -> str:
    """Every code we print, one line each, for `scoopc check --explain` with no code."""
    codes = sorted(set(EXPLANATIONS) | set(messages.MESSAGES))
    aliases = ", ".join(f"{alias} = {code}" for alias, code in ALIASES.items() if "-G" not in alias)
    return "\n".join(
        [summary(code) for code in codes]
        + ["", f"Gobo's spellings are accepted too: {aliases}.", "Details: scoopc check --explain CODE"]
    )


def explain(code: str) -> str | None:
    """The explanation of a diagnostic code (ours or a Gobo alias), or None when the code is unknown:
    the rule, a wrong example and its fix, then the message and hint templates."""
    canonical = canonical_code(code)
    entry, message = EXPLANATIONS.get(canonical), messages.MESSAGES.get(canonical)
    if entry is None and message is None:
        return None
    spelled = re.sub(r"\((\w+)\)$", r"-\1", code.strip().upper())
    heading = f"{canonical} (Gobo: {spelled})" if spelled in ALIASES else canonical
    if entry is None:
        lines = [f"{heading}: {message.text}"] + ([f"hint: {message.hint}"] if message.hint else [])
        return "\n".join(lines)

    def fill(text: str) -> str:
        return textwrap.fill(text, 100, break_on_hyphens=False, break_long_words=False)

    example, _, sentence = entry.fix.rpartition("\n\n")
    lines = [
        fill(f"{heading}: {entry.rule}"),
        "",
        "Wrong:",
        textwrap.indent(entry.wrong, "    "),
        "Fix:",
        textwrap.indent(example, "    "),
        fill(sentence),
    ]
    if message is not None:
        lines += ["", f"Message: {message.text}"] + ([f"Hint: {message.hint}"] if message.hint else [])
    return "\n".join(lines)
