"""Parser stage, instructions: reductions of compounds and every instruction to AST nodes.

Input: the children of one instruction rule. Output: Instruction nodes (tuples for compounds).
"""

from __future__ import annotations

from typing import Any

from ... import syntax as s
from .base import BuilderBase, Keyworded

_CALLS = (s.UnqualifiedCall, s.QualifiedCall, s.StaticCall, s.Precursor, s.BracketExpression)
_ASSIGNER_TARGETS = (s.UnqualifiedCall, s.QualifiedCall, s.BracketExpression)


def _last(compound: tuple, default: Any) -> Any:
    return compound[-1] if compound else default


def _is_variable(target: Any) -> bool:
    if isinstance(target, s.Result):
        return True
    return (
        isinstance(target, s.UnqualifiedCall)
        and not target.arguments
        and target.span.end_column == target.name.span.end_column
        and target.span.end_line == target.name.span.end_line
    )


class InstructionBuilder(BuilderBase):
    def compound(self, c: list) -> tuple:
        return tuple(c)

    def call_instruction(self, c: list) -> s.CallInstruction:
        call = c[0]
        if not isinstance(call, _CALLS):
            self.report("SYNTAX", call, found=f"`{_describe(call)}`", expected="an instruction")
        return s.CallInstruction(call, call.span)

    def assignment(self, c: list) -> Any:
        target, source = c
        span = self.span(target, source)
        if _is_variable(target):
            return s.Assignment(target, source, span)
        if not isinstance(target, _ASSIGNER_TARGETS):
            self.report(
                "SYNTAX", target, found=f"`{_describe(target)}`", expected="a variable or a query call before `:=`"
            )
        return s.AssignerCall(target, source, span)

    def assignment_attempt(self, c: list) -> s.AssignmentAttempt:
        target, source = c
        if not _is_variable(target):
            self.report("SYNTAX", target, found=f"`{_describe(target)}`", expected="a variable before `?=`")
        return s.AssignmentAttempt(target, source, self.span(target, source))

    # ---- creation --------------------------------------------------------------------
    def creation_instruction(self, c: list) -> s.CreationInstruction:
        keyword, processor, type_, target, call = c
        name, arguments, last = call if call is not None else (None, (), target)
        return s.CreationInstruction(processor, type_, target, name, arguments, self.span(keyword, last))

    def processor_tag(self, c: list) -> s.Identifier:
        """`<NONE>` (a passive region) is the one processor tag there is, as in EiffelStudio,
        whose parser rejects any other name between `<` and `>`."""
        tag = self.ident(c[0])
        if tag.key != "none":
            self.report(
                "SYNTAX",
                tag.span,
                found=f"`{tag.text}`",
                expected="`NONE` in `create <NONE>`",
                hint="write `create <NONE> x.make` for a passive region, or `create x.make` for a new processor",
            )
        return tag

    def explicit_creation_type(self, c: list) -> s.Type:
        return c[0]

    def unqualified_target(self, c: list) -> s.UnqualifiedCall:
        return s.UnqualifiedCall(self.ident(c[0]), (), self.tspan(c[0]))

    def creation_call(self, c: list) -> tuple:
        name, actuals = c
        if actuals is None:
            return self.ident(name), (), name
        return self.ident(name), actuals[0], actuals[1]

    # ---- control structures ----------------------------------------------------------
    def conditional(self, c: list) -> s.Conditional:
        return s.Conditional(c[1], c[3], tuple(c[4:-2]), c[-2], self.span(c[0], c[-1]))

    def elseif_part(self, c: list) -> s.ElseifPart:
        keyword, condition, then, compound = c
        return s.ElseifPart(condition, compound, self.span(keyword, _last(compound, then)))

    def else_part(self, c: list) -> tuple:
        return c[0]

    def multi_branch(self, c: list) -> s.MultiBranch:
        return s.MultiBranch(c[1], tuple(c[2:-2]), c[-2], self.span(c[0], c[-1]))

    def when_part(self, c: list) -> s.WhenPart:
        then, compound = c[-2], c[-1]
        return s.WhenPart(tuple(c[1:-2]), compound, self.span(c[0], _last(compound, then)))

    def choice(self, c: list) -> s.Choice:
        lower, upper = c
        return s.Choice(lower, upper, self.span(lower, upper or lower))

    def loop(self, c: list) -> s.Loop:
        keyword, initialization, invariant, variant, _, until, _, body, late_variant, end = c
        return s.Loop(initialization, invariant or (), until, body, variant or late_variant, self.span(keyword, end))

    def loop_invariant(self, c: list) -> tuple:
        return c[1]

    def across(self, c: list) -> s.Across:
        keyword, iteration, initialization, invariant, until, _, body, variant, end = c
        return s.Across(iteration, initialization or (), invariant or (), until, body, variant, self.span(keyword, end))

    def symbolic_loop(self, c: list) -> s.Across:
        """`⟳ x: s ¦ compound ⟲` is `across s is x loop compound end`."""
        opener, iteration, _, body, closer = c
        return s.Across(iteration, (), (), None, body, None, self.span(opener, closer))

    def symbolic_iteration(self, c: list) -> s.Iteration:
        name, expression = c
        return s.Iteration(expression, self.ident(name), False, self.span(name, expression))

    def from_part(self, c: list) -> tuple:
        return c[0]

    def exit_condition(self, c: list) -> Any:
        return c[1]

    def iteration(self, c: list) -> s.Iteration:
        expression, mode, name = c
        return s.Iteration(expression, self.ident(name), mode.type == "AS", self.span(expression, name))

    def check(self, c: list) -> s.Check:
        keyword, assertions, then_part, end = c
        return s.Check(assertions, then_part, self.span(keyword, end))

    def check_then(self, c: list) -> tuple:
        return c[0]

    def debug(self, c: list) -> s.Debug:
        keyword, keys, body, end = c
        return s.Debug(keys or (), body, self.span(keyword, end))

    def debug_keys(self, c: list) -> tuple:
        return tuple(self.manifest_string([k]).value for k in c[1:-1] if k is not None)

    def separate_instruction(self, c: list) -> s.SeparateInstruction:
        header, body, end = c
        return s.SeparateInstruction(tuple(header), body, self.span(header.keyword, end))

    def separate_header(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], c[1:])

    def separate_argument(self, c: list) -> s.SeparateArgument:
        expression, name = c
        return s.SeparateArgument(expression, self.ident(name), self.span(expression, name))

    def retry(self, c: list) -> s.Retry:
        return s.Retry(self.tspan(c[0]))


def _describe(node: Any) -> str:
    """A short name for a node that is misplaced, for messages."""
    names = {s.Current: "Current", s.Result: "Result", s.Void: "Void"}
    if type(node) in names:
        return names[type(node)]
    if isinstance(node, s.Parenthesized):
        return "( ... )"
    return type(node).__name__
