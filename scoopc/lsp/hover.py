"""Language server, hover: a feature's signature, header comment, contracts and class; an
entity's type; and, on a separate target, whether this routine controls it."""

from __future__ import annotations

import re

from .. import syntax
from ..semantics.features import Feature
from ..semantics.tables import Entity
from ..semantics.universe import ClassInfo
from ..source import Span
from .lookup import Found
from .nodes import Texts

_BODY_START = re.compile(r"(require|local|do|once|deferred|external|attribute|obsolete|note|ensure|end)\b")


def header(feature: Feature, texts: Texts) -> tuple[str, str]:
    """(signature, header comment) of a feature, as its declaration writes them."""
    span = feature.fname.span
    source = texts.source(span.file)
    if source is None:
        return feature.text, ""
    signature: list[str] = []
    comment: list[str] = []
    for number in range(span.line, min(span.line + 30, source.line_count + 1)):
        text = source.line_text(number).strip()
        if number == span.line:
            text = source.line_text(number)[span.column - 1 :].strip()
        if text.startswith("--") and (signature or comment):
            comment.append(text[2:].strip())
        elif comment or not text or _BODY_START.match(text):
            break
        else:
            signature.append(text)
    return " ".join(signature), "\n".join(comment)


def contracts(feature: Feature, texts: Texts) -> list[str]:
    """`require` and `ensure` clauses of the feature's own declaration, as written."""
    body = getattr(feature.decl, "body", None)
    lines: list[str] = []
    for part, keyword in (("precondition", "require"), ("postcondition", "ensure")):
        assertion = getattr(body, part, None) if body is not None else None
        if assertion is None or not assertion.clauses:
            continue
        lines.append(keyword)
        lines.extend("    " + " ".join(texts.text(clause.span).split()) for clause in assertion.clauses)
    return lines


def feature_text(feature: Feature, written_in: ClassInfo | None, texts: Texts) -> str:
    signature, comment = header(feature, texts)
    kind = "deferred " if feature.deferred else ""
    where = written_in.decl.name.text if written_in is not None else feature.written_in
    parts = [f"```eiffel\n{signature}\n```", f"*{kind}feature of class* `{where}`{_exports(feature)}"]
    if comment:
        parts.append(comment)
    found = contracts(feature, texts)
    if found:
        parts.append("```eiffel\n" + "\n".join(found) + "\n```")
    return "\n\n".join(parts)


def _exports(feature: Feature) -> str:
    if feature.exports is None:
        return ""
    names = ", ".join(sorted(feature.exports)) or "NONE"
    return f", *exported to* `{{{names}}}`"


def entity_text(entity: Entity) -> str:
    kind = {"object_test": "object-test local", "separate": "separate-block local", "across": "iteration cursor"}
    ty = f": {entity.ty}" if entity.ty is not None else ""
    return f"```eiffel\n{entity.name}{ty}\n```\n\n*{kind.get(entity.kind, entity.kind)}*"


def class_text(info: ClassInfo, texts: Texts) -> str:
    decl = info.decl
    formals = f" [{', '.join(info.formals)}]" if info.formals else ""
    marks = " ".join(m for m in decl.marks if m in ("deferred", "expanded", "frozen"))
    head = f"{marks} class {decl.name.text}{formals}".strip()
    parts = [f"```eiffel\n{head}\n```"]
    description = _description(decl, texts)
    if description:
        parts.append(description)
    parts.append(f"*{'library' if info.from_library else 'program'} class*")
    return "\n\n".join(parts)


def _description(decl, texts: Texts) -> str:
    for note in decl.notes:
        if note.tag.key == "description" and note.values:
            value = note.values[0]
            return getattr(value, "value", None) or texts.text(value.span)
    return ""


def separateness(found: Found, tables, texts: Texts) -> str:
    """On a call or an entity of separate type: is it separate, and controlled here?"""
    node = found.node
    target = getattr(node, "target", None) if isinstance(node, syntax.QualifiedCall) else None
    ty = tables.types.get(target) if target is not None else None
    if ty is not None and ty.separate:
        return _control_line(texts.text(target.span), ty, target in tables.controlled)
    if found.entity is not None and found.entity.ty is not None and found.entity.ty.separate:
        controlled = node in tables.controlled or found.entity.handler not in (None, "?")
        return _control_line(found.entity.name, found.entity.ty, controlled)
    ty = tables.types.get(node)
    if ty is not None and ty.separate and isinstance(node, syntax.UnqualifiedCall):
        return _control_line(node.name.text, ty, node in tables.controlled)
    return ""


def _control_line(target: str, ty, controlled: bool) -> str:
    if controlled:
        return (
            f"**separate**: `{target}` ({ty}) is controlled here: calls on it are requests to its "
            "processor, reserved by this routine"
        )
    return (
        f"**separate**: `{target}` ({ty}) is **not controlled** here: pass it as an argument of a "
        "routine or use a `separate ... as ... do ... end` block to call it (VUTA(3))"
    )


def hover_text(found: Found, declaring: ClassInfo | None, sem, texts: Texts) -> tuple[str, Span | None]:
    """Markdown for what `found` names, and the span it covers ('' when nothing is known)."""
    if found.feature is not None:
        text = feature_text(found.feature, declaring, texts)
    elif found.entity is not None:
        text = entity_text(found.entity)
    elif found.class_info is not None:
        text = class_text(found.class_info, texts)
    else:
        return "", None
    extra = separateness(found, sem.tables, texts)
    span = getattr(found.chain[-1], "span", None) if found.chain else None
    return (text + ("\n\n" + extra if extra else "")), span
