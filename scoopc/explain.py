"""`scoopc check --explain CODE`: a diagnostic code (ours, EiffelStudio's spelling, or a Gobo alias)
-> its explanation (explanations.py) and its message and hint templates (messages.py)."""

from __future__ import annotations

import re
import textwrap

from . import messages
from .explanations import ALIASES, EXPLANATIONS


def canonical_code(code: str) -> str:
    """`vuta-3` -> `VUTA(3)`: test folders and shells write parentheses as a dash. Gobo's finer
    SCOOP codes resolve to ours (`vuta-4g` or `VUTA(4G)` -> `VUTA(3)`)."""
    spelled = re.sub(r"\((\w+)\)$", r"-\1", code.strip().upper())
    if spelled in ALIASES:
        return ALIASES[spelled]
    match = re.fullmatch(r"(V[A-Z0-9]+)-(\d+)", spelled)
    return f"{match.group(1)}({match.group(2)})" if match else spelled


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
