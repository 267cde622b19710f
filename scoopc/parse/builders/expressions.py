"""Parser stage, expressions: reductions of calls, operators, literals and agents to AST nodes.

Input: the children of one grammar rule (tokens and built nodes). Output: an Expression node.
"""

from __future__ import annotations

from typing import Any

from lark import Token

from ... import syntax as s
from .base import BuilderBase
from .literals import (
    LARGEST_INTEGER,
    SMALLEST_INTEGER_NEGATED,
    character_value,
    integer_value,
    real_value,
    string_value,
    too_large,
    too_small,
)


def _arguments(actuals: tuple | None) -> tuple:
    return actuals[0] if actuals is not None else ()


class ExpressionBuilder(BuilderBase):
    # ---- calls -----------------------------------------------------------------------
    def unqualified_call(self, c: list) -> s.UnqualifiedCall:
        name, actuals = c
        last = actuals[1] if actuals is not None else name
        return s.UnqualifiedCall(self.ident(name), _arguments(actuals), self.span(name, last))

    def qualified_call(self, c: list) -> s.QualifiedCall:
        target, name, actuals = c
        last = actuals[1] if actuals is not None else name
        return s.QualifiedCall(target, self.ident(name), _arguments(actuals), self.span(target, last))

    def static_call(self, c: list) -> s.StaticCall:
        brace, type_, _, name, actuals = c
        last = actuals[1] if actuals is not None else name
        return s.StaticCall(type_, self.ident(name), _arguments(actuals), self.span(brace, last))

    def precursor(self, c: list) -> s.Precursor:
        keyword, _, parent, closing, actuals = c
        last = actuals[1] if actuals is not None else (closing or keyword)
        parent_name = self.ident(parent) if parent is not None else None
        return s.Precursor(parent_name, _arguments(actuals), self.span(keyword, last))

    def bracket(self, c: list) -> s.BracketExpression:
        target, _, arguments, closing = c
        return s.BracketExpression(target, arguments, self.span(target, closing))

    def actuals(self, c: list) -> tuple:
        return (c[1] if c[1] is not None else ()), c[2]

    def expression_list(self, c: list) -> tuple:
        return tuple(c)

    def current(self, c: list) -> s.Current:
        return s.Current(self.tspan(c[0]))

    def result(self, c: list) -> s.Result:
        return s.Result(self.tspan(c[0]))

    def void(self, c: list) -> s.Void:
        return s.Void(self.tspan(c[0]))

    def parenthesized(self, c: list) -> s.Parenthesized:
        return s.Parenthesized(c[1], self.span(c[0], c[2]))

    # ---- operators -------------------------------------------------------------------
    def binary(self, c: list) -> s.BinaryExpression:
        left, operator, right = c
        return s.BinaryExpression(operator.value.lower(), left, right, self.tspan(operator), self.span(left, right))

    def or_operator(self, c: list) -> Token:
        return self._operator_words(c)

    def and_operator(self, c: list) -> Token:
        return self._operator_words(c)

    def _operator_words(self, c: list) -> Token:
        """`and then`, `or else`: one operator token spanning both words."""
        if len(c) == 1:
            return c[0]
        first, last = c
        text = f"{first.value.lower()} {last.value.lower()}"
        return Token(
            "OPERATOR", text, first.start_pos, first.line, first.column, last.end_line, last.end_column, last.end_pos
        )

    def unary(self, c: list) -> s.UnaryExpression:
        operator, operand = c
        literal = isinstance(operand, s.ManifestInteger)
        if operator.value == "-" and literal and operand.value > SMALLEST_INTEGER_NEGATED:
            # a negative literal below INTEGER_64's minimum fits no integer type either
            same_line = operand.span.end_line == operator.line
            width = operand.span.end_column - operator.column if same_line else 1
            self.report_at_offset(operator, 0, width, too_small(operand.text))
            operand = s.ManifestInteger(0, operand.text, operand.span)
        return s.UnaryExpression(operator.value.lower(), operand, self.span(operator, operand))

    def old(self, c: list) -> s.Old:
        return s.Old(c[1], self.span(c[0], c[1]))

    # ---- manifest constants ----------------------------------------------------------
    def manifest_integer(self, c: list) -> s.ManifestInteger:
        token = c[0]
        value = integer_value(token.value)
        if value is None:
            self.report_at_offset(token, 0, len(token.value), f"`{token.value}` is not a valid integer")
            value = 0
        elif value > LARGEST_INTEGER:
            # EiffelStudio's parser: a literal beyond NATURAL_64 fits no integer type (a syntax error)
            self.report_at_offset(token, 0, len(token.value), too_large(token.value))
            value = 0
        return s.ManifestInteger(value, token.value, self.tspan(token))

    def manifest_real(self, c: list) -> s.ManifestReal:
        token = c[0]
        return s.ManifestReal(real_value(token.value), token.value, self.tspan(token))

    def manifest_string(self, c: list) -> s.ManifestString:
        return self._string(c[0], 0, False)

    def once_string(self, c: list) -> s.ManifestString:
        token = c[0]
        return self._string(token, token.value.index('"'), True)

    def _string(self, token: Token, start: int, once: bool) -> s.ManifestString:
        value, verbatim, problems = string_value(token.value[start:])
        for offset, length, reason in problems:
            self.report_at_offset(token, start + offset, length, reason)
        return s.ManifestString(value, verbatim, once, self.tspan(token))

    def manifest_character(self, c: list) -> s.ManifestCharacter:
        token = c[0]
        value, problems = character_value(token.value)
        for offset, length, reason in problems:
            self.report_at_offset(token, offset, length, reason)
        return s.ManifestCharacter(value, self.tspan(token))

    def manifest_true(self, c: list) -> s.ManifestBoolean:
        return s.ManifestBoolean(True, self.tspan(c[0]))

    def manifest_false(self, c: list) -> s.ManifestBoolean:
        return s.ManifestBoolean(False, self.tspan(c[0]))

    def sign(self, c: list) -> Token:
        return c[0]

    def signed_number(self, c: list) -> Any:
        sign, number = c
        if sign.value == "+":
            return type(number)(number.value, "+" + number.text, self.span(sign, number))
        return type(number)(-number.value, "-" + number.text, self.span(sign, number))

    def typed_constant(self, c: list) -> s.TypedConstant:
        constant = c[2] if len(c) == 3 else self.signed_number(c[2:])
        return s.TypedConstant(c[1], constant, self.span(c[0], constant))

    def unique(self, c: list) -> s.Unique:
        return s.Unique(self.tspan(c[0]))

    def manifest_type(self, c: list) -> s.ManifestType:
        return s.ManifestType(c[1], self.span(c[0], c[2]))

    def manifest_tuple(self, c: list) -> s.TupleExpression:
        return s.TupleExpression(c[1] or (), self.span(c[0], c[2]))

    def manifest_array(self, c: list) -> s.ManifestArray:
        return s.ManifestArray(c[1] or (), self.span(c[0], c[2]))

    def address(self, c: list) -> s.Address:
        return s.Address(self.ident(c[1]), self.span(c[0], c[1]))

    # ---- other primaries -------------------------------------------------------------
    def object_test(self, c: list) -> s.ObjectTest:
        keyword, _, type_, expression, local = c
        return s.ObjectTest(type_, expression, local, self.span(keyword, local or expression))

    def obsolete_object_test(self, c: list) -> s.ObjectTest:
        """`{x: T} e`, the object test before ECMA-367: `attached {T} e as x`."""
        opening, name, colon, type_, expression = c
        self.obsolete_form(colon, "`{x: T} e` is the obsolete form of an object test", "write `attached {T} e as x`")
        return s.ObjectTest(type_, expression, self.ident(name), self.span(opening, expression))

    def object_test_local(self, c: list) -> s.Identifier:
        return self.ident(c[0])

    def creation_expression(self, c: list) -> s.CreationExpression:
        keyword, processor, type_, closing, call = c
        name, arguments, last = call if call is not None else (None, (), closing)
        return s.CreationExpression(processor, type_, name, arguments, self.span(keyword, last))

    def conditional_expression(self, c: list) -> s.ConditionalExpression:
        return s.ConditionalExpression(c[1], c[3], tuple(c[4:-2]), c[-2], self.span(c[0], c[-1]))

    def elseif_expression(self, c: list) -> s.ElseifExpression:
        return s.ElseifExpression(c[1], c[3], self.span(c[0], c[3]))

    def inspect_expression(self, c: list) -> s.InspectExpression:
        keyword, subject, *parts, else_part, end = c
        return s.InspectExpression(subject, tuple(parts), else_part, self.span(keyword, end))

    def when_expression(self, c: list) -> s.WhenExpression:
        return s.WhenExpression(tuple(c[1:-2]), c[-1], self.span(c[0], c[-1]))

    def else_expression(self, c: list) -> s.Expression:
        return c[0]

    def quantifier(self, c: list) -> s.AcrossExpression:
        """`∀ x: s ¦ e` is `across s is x all e end`; `∃` is `some`."""
        symbol, iteration, _, body = c
        quantifier = "all" if symbol.type == "FOR_ALL" else "some"
        return s.AcrossExpression(iteration, (), None, quantifier, body, None, self.span(symbol, body))

    def across_expression(self, c: list) -> s.AcrossExpression:
        keyword, iteration, invariant, until, quantifier, body, variant, end = c
        return s.AcrossExpression(
            iteration, invariant or (), until, quantifier.value.lower(), body, variant, self.span(keyword, end)
        )
