"""Parser stage, features: reductions of feature declarations, routine bodies, contracts and agents.

Input: the children of one rule. Output: Routine, Attribute, Constant, RoutineBody,
assertion and agent nodes.
"""

from __future__ import annotations

from typing import Any

from ... import syntax as s
from .base import BuilderBase, Tag


def _first(*items: Any) -> Any:
    return next(item for item in items if item is not None)


class FeatureBuilder(BuilderBase):
    # ---- declarations ----------------------------------------------------------------
    def query_declaration(self, c: list) -> s.Feature | None:
        names = tuple(c[:-5])
        arguments, (type_, assigner), constant, notes, body = c[-5:]
        notes = tuple(notes or ())
        span = self.span(names[0], body or constant or type_)
        if body is not None and not isinstance(body.body, s.AttributeBody):
            return s.Routine(names, arguments or (), type_, assigner, notes, body, span)
        if arguments:
            self.report("SYNTAX-FEATURE", names[0], name=names[0].name.text)
        if constant is not None:
            return s.Constant(names, type_, constant, notes, span)
        return s.Attribute(names, type_, assigner, notes, body, span)

    def procedure_declaration(self, c: list) -> s.Routine:
        names = tuple(c[:-3])
        arguments, notes, body = c[-3:]
        if isinstance(body.body, s.AttributeBody):
            self.report("SYNTAX-FEATURE", names[0], name=names[0].name.text)
        return s.Routine(names, arguments or (), None, None, tuple(notes or ()), body, self.span(names[0], body))

    def feature_name(self, c: list) -> s.FeatureName:
        frozen, name = c[0], c[1]
        aliases = tuple(c[2:])
        start = frozen or name
        end = aliases[-1] if aliases else name
        return s.FeatureName(self.ident(name), frozen is not None, aliases, self.span(start, end))

    def alias(self, c: list) -> s.Alias:
        keyword, name, convert = c
        text = self.manifest_string([name]).value
        if not is_alias_name(text):
            self.report(
                "SYNTAX",
                name,
                found=f"the alias name `{text}`",
                expected="an operator (`+`, `<`, `and then`, a free operator such as `|>` or `⊕`), `[]` or `()`"
                " (`=`, `/=`, `~` and `/~` cannot be redefined)",
            )
        return s.Alias(text, convert is not None, self.span(keyword, convert or name))

    def query_mark(self, c: list) -> tuple:
        type_, _, assigner = c
        return type_, (self.ident(assigner) if assigner is not None else None)

    def constant_value(self, c: list) -> s.Expression:
        return c[0]

    def obsolete_constant_value(self, c: list) -> s.Expression:
        self._obsolete_is(c[0])
        return c[1]

    def _obsolete_is(self, token) -> None:
        self.obsolete_form(
            token,
            "`is` before a routine body or a constant's value is obsolete syntax",
            "delete `is` before a routine's body; write a constant as `Name: TYPE = value`",
        )

    def formal_arguments(self, c: list) -> tuple:
        return tuple(entity for group in c[1:-1] if group is not None for entity in group)

    def entity_group(self, c: list) -> list:
        type_ = c[-1]
        return [s.EntityDeclaration(self.ident(n), type_, self.span(n, type_)) for n in c[:-1]]

    # ---- routine bodies --------------------------------------------------------------
    def feature_body(self, c: list) -> s.RoutineBody:
        is_, obsolete, precondition, locals_, body, postcondition, rescue, end = c
        if is_ is not None:
            self._obsolete_is(is_)
        start = _first(obsolete, precondition, locals_ and locals_[0], body)
        entities = locals_[1] if locals_ is not None else ()
        message = obsolete.value if obsolete is not None else None
        return s.RoutineBody(message, precondition, entities, body, postcondition, rescue, self.span(start, end))

    def do_body(self, c: list) -> s.InternalBody:
        keyword, compound = c
        return s.InternalBody(False, (), compound, self.span(keyword, compound[-1] if compound else keyword))

    def once_body(self, c: list) -> s.InternalBody:
        keyword, keys, compound = c
        last = compound[-1] if compound else keyword
        return s.InternalBody(True, keys or (), compound, self.span(keyword, last))

    def once_keys(self, c: list) -> tuple:
        return tuple(self.manifest_string([k]).value for k in c[1:-1])

    def deferred_body(self, c: list) -> s.DeferredBody:
        return s.DeferredBody(self.tspan(c[0]))

    def external_body(self, c: list) -> s.ExternalBody:
        keyword, language, _, alias = c
        name = self.manifest_string([alias]).value if alias is not None else None
        return s.ExternalBody(self.manifest_string([language]).value, name, self.span(keyword, alias or language))

    def attribute_body(self, c: list) -> s.AttributeBody:
        keyword, compound = c
        return s.AttributeBody(compound, self.span(keyword, compound[-1] if compound else keyword))

    def locals(self, c: list) -> tuple:
        return c[0], tuple(e for group in c[1:] if group is not None for e in group)

    def rescue(self, c: list) -> tuple:
        return c[1]

    # ---- contracts -------------------------------------------------------------------
    def precondition(self, c: list) -> s.Precondition:
        keyword, else_, clauses = c
        last = clauses[-1] if clauses else (else_ or keyword)
        return s.Precondition(else_ is not None, clauses, self.span(keyword, last))

    def postcondition(self, c: list) -> s.Postcondition:
        keyword, then, clauses = c
        last = clauses[-1] if clauses else (then or keyword)
        return s.Postcondition(then is not None, clauses, self.span(keyword, last))

    def class_invariant(self, c: list) -> tuple:
        return c[1]

    def assertion_tag(self, c: list) -> Tag:
        return Tag(self.ident(c[0]))

    def class_assertion(self, c: list) -> s.ClassAssertion:
        return s.ClassAssertion(self.tspan(c[0]))

    def assertion(self, c: list) -> tuple:
        clauses: list[s.AssertionClause] = []
        tag: s.Identifier | None = None
        for item in c:
            if isinstance(item, Tag):
                if tag is not None:
                    clauses.append(s.AssertionClause(tag, None, tag.span))
                tag = item.name
            elif item is not None:
                clauses.append(s.AssertionClause(tag, item, self.span(tag or item, item)))
                tag = None
        if tag is not None:
            clauses.append(s.AssertionClause(tag, None, tag.span))
        return tuple(clauses)

    def variant(self, c: list) -> s.Variant:
        keyword, tag, expression = c
        name = self.ident(tag) if tag is not None else None
        return s.Variant(name, expression, self.span(keyword, expression))

    # ---- agents ----------------------------------------------------------------------
    def open_operand(self, c: list) -> s.OpenOperand:
        operand = s.OpenOperand(None, self.tspan(c[0]))
        self.open_operands[id(operand)] = operand
        return operand

    def agent(self, c: list) -> Any:
        keyword, call = c
        if isinstance(call, s.UnqualifiedCall):
            target = None
        elif isinstance(call, s.QualifiedCall):
            target = call.target
        elif isinstance(call, s.StaticCall):
            target = s.ManifestType(call.type, self.span(call, call.type))
        else:
            self.report(
                "SYNTAX", call, found="this expression", expected="a feature name or `target.feature` after `agent`"
            )
            return call
        arguments = self._agent_operands(call)
        return s.Agent(target, call.name, arguments, self.span(keyword, call))

    def _agent_operands(self, call: Any) -> tuple | None:
        if call.span.end_line == call.name.span.end_line and call.span.end_column == call.name.span.end_column:
            return None
        return self._open(call.arguments)

    def _open(self, arguments: tuple) -> tuple:
        """Operands of an agent: `?` is allowed here, and `{T}` means an open operand of type T."""
        result = []
        for argument in arguments:
            if isinstance(argument, s.ManifestType):
                argument = s.OpenOperand(argument.type, argument.span)
            self.open_operands.pop(id(argument), None)
            result.append(argument)
        return tuple(result)

    def inline_agent(self, c: list) -> s.InlineAgent:
        keyword, arguments, query, body, actuals = c
        type_ = query[0] if query is not None else None
        operands = self._open(actuals[0]) if actuals is not None else None
        last = actuals[1] if actuals is not None else body
        return s.InlineAgent(arguments or (), type_, body, operands, self.span(keyword, last))

    def unopened_operands(self) -> list:
        return list(self.open_operands.values())


# Operators a feature may take as its alias (EiffelStudio's OPERATOR_SYNTAX_CHECKER, ECMA-367
# 8.32.20): the standard unary and binary operators, brackets, parentheses and free operators;
# never the equality and conformance operators `=`, `/=`, `~`, `/~`.
STANDARD_ALIASES = frozenset("""not + - * / // \\\\ ^ < > <= >= and or xor implies .. |..|""".split()) | {
    "and then",
    "or else",
    "[]",
    "()",
}
_FREE_START = "@#|&"
_FREE_CHARS = ":\\?=~/!#$%&*+-<>@^`|"


def _free_symbol(ch: str) -> bool:
    return ch in _FREE_CHARS or ch in "\u00ac\u00b1\u00d7\u00f7" or "\u2190" <= ch <= "\u2bff"


def is_alias_name(text: str) -> bool:
    if text.lower() in STANDARD_ALIASES:
        return True
    if not text or text in ("=", "/=", "~", "/~"):
        return False
    if text[0] in _FREE_START or not text[0].isascii():
        return all(_free_symbol(ch) for ch in text)
    return False
