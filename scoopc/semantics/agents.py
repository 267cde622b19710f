"""Checker, agents: `agent f (?, x)`, `agent t.f`, `agent {T}.f` and inline agents; their types
are PROCEDURE / FUNCTION / PREDICATE [TUPLE [open operand types]].
"""

from __future__ import annotations

from .. import syntax
from . import suggest
from .features import member_signature
from .resolve import declare_routine_entities
from .types import Ty
from .values import UNCONTROLLED, Value


class AgentChecks:
    def agent(self, node: syntax.Agent, expected: Ty | None = None) -> Value | None:
        open_types: list[Ty] = []
        handler = None
        if node.target is None:
            base = self.current
        elif isinstance(node.target, syntax.ManifestType):
            base = self.resolve_type(node.target.type)
            if base is None:
                return None
            open_types.append(base)
        else:
            target = self.expr(node.target)
            if target is None:
                return None
            base, handler = target.ty, target.handler
        from .conformance import base_type  # deferred: a cycle (scoopc.semantics.conformance imports this module)

        base_class = base_type(self.universe, base, self.info)
        if base_class.name == "TUPLE" and node.name.key in base_class.labels and not node.arguments:
            index = base_class.labels.index(node.name.key)
            self.tables.agent_labels[node] = index
            return Value(routine_type(True, base_class.generics[index], tuple(open_types)))
        info = self.universe.get(base_class.name)
        if info is not None and info.failed:
            return None  # the class's own errors are reported there
        feature = info.features.get(node.name.key) if info is not None else None
        if feature is None:
            where = f"among the features of {base_class.name}"
            hint = suggest.unknown_feature(self, node.name.text, info)
            self.report("VEEN", node.name.span, name=node.name.text, where=where, hint=hint)
            return None
        self.tables.features[node] = feature
        signature = member_signature(self.universe, base_class.with_marks(attached=True), feature)
        if node.arguments is None:
            open_types.extend(a for a in signature.arguments if a is not None)
        elif len(node.arguments) != len(signature.arguments):
            self.report("VUAR(1)", node.span, expected=len(signature.arguments), given=len(node.arguments))
            return None
        else:
            for operand, formal in zip(node.arguments, signature.arguments):
                if isinstance(operand, syntax.OpenOperand):
                    own = self.resolve_type(operand.type) if operand.type is not None else None
                    open_types.append(own or formal)
                    continue
                value = self.expr(operand, formal)
                if value is not None and formal is not None:
                    self.expect(operand, value, formal, "VUAR(2)")
        open_types = self._from_context(tuple(t for t in open_types if t is not None), expected)
        agent = routine_type(feature.is_query, signature.result, open_types)
        if base.separate:
            return Value(agent.with_marks(separate=True), handler or UNCONTROLLED)
        return Value(agent)

    def _from_context(self, open_types: tuple, expected: Ty | None) -> tuple:
        """Open operand types taken from the expected agent type when each of them conforms to
        the routine's own (an agent accepting READABLE_STRING_8 serves as a PROCEDURE [STRING])."""
        from .conformance import conforms  # deferred: a cycle (scoopc.semantics.conformance imports this module)

        if (
            expected is None
            or expected.name not in ("ROUTINE", "PROCEDURE", "FUNCTION", "PREDICATE")
            or not expected.generics
            or expected.generics[0].name != "TUPLE"
        ):
            return open_types
        wanted = expected.generics[0].generics
        if len(wanted) == len(open_types) and all(
            conforms(self.universe, w, t, self.info) for w, t in zip(wanted, open_types)
        ):
            return tuple(wanted)
        return open_types

    def inline_agent(self, node: syntax.InlineAgent) -> Value | None:
        arguments = tuple(self.resolve_type(a.type) for a in node.arguments)
        result = self.resolve_type(node.type) if node.type is not None else None
        saved = self.enter_nested()
        try:
            declare_routine_entities(self, node.arguments, node.body.locals, arguments, self.resolve_type)
            self.result_type = result
            self.result_context = "an inline agent without a result type"
            self.check_routine_body(node.body, result)
        finally:
            self.leave_nested(saved)
        if node.actuals is not None:
            if len(node.actuals) != len(arguments):
                self.report("VUAR(1)", node.span, expected=len(arguments), given=len(node.actuals))
            else:
                open_args = []
                for actual, formal in zip(node.actuals, arguments):
                    if isinstance(actual, syntax.OpenOperand):
                        open_args.append(formal)
                        continue
                    value = self.expr(actual, formal)
                    if value is not None and formal is not None:
                        self.expect(actual, value, formal, "VUAR(2)")
                arguments = tuple(open_args)
        if any(a is None for a in arguments):
            return None
        return Value(routine_type(node.type is not None, result, arguments))


def routine_type(is_query: bool, result: Ty | None, open_types: tuple) -> Ty:
    operands = Ty("TUPLE", open_types)
    if not is_query or result is None:
        return Ty("PROCEDURE", (operands,))
    if result.name == "BOOLEAN":
        return Ty("PREDICATE", (operands,))
    return Ty("FUNCTION", (operands, result))
