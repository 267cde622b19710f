"""Checker, expressions: typing every expression (recorded in tables.types) with the rules on
operators (VWOE, VWBE), manifest constants (VWMQ), `old` (VAOL(1)), `Result` (VEEN(2)),
object tests (VUOT(1)) and agents. Calls are in calls.py.

A method returns a Value, or None after an error has been reported (callers stay silent then).
"""

from __future__ import annotations

from .. import syntax
from . import scoop, walk
from .conformance import conforms, manifest_fits
from .tables import Entity
from .types import BOOLEAN, CHARACTER, INTEGER, NONE, POINTER, RANGES, REAL_64, STRING, Ty
from .values import UNCONTROLLED, Value

BOOLEAN_OPERATORS = ("and then", "or else", "implies")
EQUALITY = ("=", "/=", "~", "/~")


class ExpressionChecks:
    def expr(self, node, expected: Ty | None = None) -> Value | None:
        value = (
            getattr(self, "e_" + type(node).__name__)(node, expected)
            if expected is not None
            else getattr(self, "e_" + type(node).__name__)(node)
        )
        if value is not None:
            self.tables.types.setdefault(node, value.ty)
            if value.ty.separate and value.controlled:
                self.tables.controlled.add(node)
        return value

    def boolean(self, node) -> None:
        value = self.expr(node)
        if value is not None and value.ty.name != "BOOLEAN":
            self.report("VWBE", node.span, type=str(value.ty))

    # --- constants -----------------------------------------------------------------------
    def e_ManifestInteger(self, node, expected=None):
        # EiffelStudio types a literal INTEGER_32 when it fits, else INTEGER_64, else NATURAL_64
        for name in ("INTEGER_32", "INTEGER_64", "NATURAL_64"):
            if node.value <= RANGES[name][1]:
                return Value(INTEGER if name == "INTEGER_32" else Ty(name))
        return Value(INTEGER)  # beyond every type: the parser reported it

    def e_ManifestReal(self, node, expected=None):
        return Value(REAL_64)

    def e_ManifestString(self, node, expected=None):
        return Value(STRING)

    def e_ManifestCharacter(self, node, expected=None):
        return Value(Ty("CHARACTER_32") if len(node.value) == 1 and ord(node.value) > 255 else CHARACTER)

    def e_ManifestBoolean(self, node, expected=None):
        return Value(BOOLEAN)

    def e_Unique(self, node, expected=None):
        return Value(INTEGER)

    def e_ClassAssertion(self, node, expected=None):
        return Value(BOOLEAN)

    def e_Address(self, node, expected=None):
        return Value(POINTER)

    def e_TypedConstant(self, node, expected=None):
        ty = self.resolve_type(node.type)
        if ty is None:
            return None
        if isinstance(node.constant, (syntax.ManifestArray, syntax.TupleExpression)):
            value = self.expr(node.constant, ty)
            if value is not None:
                self.expect(node.constant, value, ty, "VJAR")
            return Value(ty)
        self.expr(node.constant)
        from .values import manifest_kind  # deferred: a cycle (scoopc.semantics.values imports this module)

        kind = manifest_kind(node.constant)
        if kind is None or not manifest_fits(kind[0], kind[1], ty):
            self.report("VWMQ", node.span, constant=walk.describe(node.constant), type=str(ty))
            return None
        self.tables.types[node.constant] = ty
        return Value(ty)

    def e_ManifestType(self, node, expected=None):
        ty = self.resolve_type(node.type)
        return None if ty is None else Value(Ty("TYPE", (ty,)))

    def e_TupleExpression(self, node, expected=None):
        wanted = expected.generics if expected is not None and expected.name == "TUPLE" else ()
        items = []
        for index, item in enumerate(node.items):
            value = self.expr(item, wanted[index] if index < len(wanted) else None)
            if value is None:
                return None
            items.append(self._manifest_typed(item, value, wanted[index] if index < len(wanted) else None))
        return Value(Ty("TUPLE", tuple(items)))

    def _manifest_typed(self, node, value: Value, wanted: Ty | None) -> Ty:
        if wanted is not None and self.meets(node, value, wanted) is None:
            return wanted
        return value.ty

    def e_ManifestArray(self, node, expected=None):
        wanted = (
            expected.generics[0] if expected is not None and expected.name == "ARRAY" and expected.generics else None
        )
        values = [self.expr(item, wanted) for item in node.items]
        if any(v is None for v in values):
            return None
        if wanted is not None and all(self.meets(i, v, wanted) is None for i, v in zip(node.items, values)):
            return Value(Ty("ARRAY", (wanted,)))
        element = self._common(values)
        return Value(Ty("ARRAY", (element,)))

    def _common(self, values) -> Ty:
        if not values:
            return Ty("ANY")
        first = values[0].ty
        if all(conforms(self.universe, v.ty, first, self.info) for v in values):
            return first
        for v in values:
            if all(conforms(self.universe, w.ty, v.ty, self.info) for w in values):
                return v.ty
        return Ty("ANY", separate=any(v.ty.separate for v in values))

    # --- entities ------------------------------------------------------------------------
    def e_Current(self, node, expected=None):
        return Value(self.current)

    def e_Void(self, node, expected=None):
        return Value(NONE)

    def e_Result(self, node, expected=None):
        if self.result_type is None:
            self.report("VEEN(2)", node.span, where=self.result_context)
            return None
        self.use_entity(node, "result")
        ty = self.result_type
        attached = ty.attached or "result" in self.facts.attached
        return Value(ty.with_marks(attached=attached), UNCONTROLLED if ty.separate else None)

    def e_Parenthesized(self, node, expected=None):
        return self.expr(node.expression, expected)

    def e_Old(self, node, expected=None):
        if not self.in_postcondition:
            self.report("VAOL(1)", node.span)
            return None
        return self.expr(node.expression, expected)

    # --- operators -----------------------------------------------------------------------
    def e_BinaryExpression(self, node, expected=None):
        op = node.operator
        if op in BOOLEAN_OPERATORS:
            self.boolean(node.left)
            return self._boolean_right(node)
        left = self.expr(node.left)
        if op in ("and", "or", "xor") and left is not None and left.ty.name == "BOOLEAN":
            return self._boolean_right(node)
        right = self.expr(node.right)
        if op in EQUALITY:
            if left is None or right is None:
                return None
            self._comparable(node, left, right)
            return Value(BOOLEAN)
        if left is None or right is None:
            return None
        return self.operator_call(node, node.left, left, op, [(node.right, right)], node.operator_span)

    def _comparable(self, node, left: Value, right: Value) -> None:
        """VWEQ: `=` and `~` need operands one of which conforms or converts to the other; checked
        where a value of a basic type is involved (`count = "0"`). A warning, as in EiffelStudio."""
        if not (scoop.is_expanded(self.universe, left.ty) or scoop.is_expanded(self.universe, right.ty)):
            return
        if left.ty.is_formal or right.ty.is_formal:
            return
        if self.meets(node.right, right, left.ty.with_marks(attached=False, separate=True)) in (
            None,
            "detachable",
        ) or self.meets(node.left, left, right.ty.with_marks(attached=False, separate=True)) in (None, "detachable"):
            return
        self.warn("VWEQ", node.operator_span, left=str(left.ty), right=str(right.ty), operator=node.operator)

    def _boolean_right(self, node):
        when_true, when_false = self.branches(node.left)
        branch = when_false if node.operator in ("or else", "or") else when_true
        if node.operator == "xor":
            branch = ((), frozenset())
        with self.assuming(branch):
            self.boolean(node.right)
        return Value(BOOLEAN)

    def e_UnaryExpression(self, node, expected=None):
        if node.operator == "not":
            self.boolean(node.operand)
            return Value(BOOLEAN)
        operand = self.expr(node.operand)
        if operand is None:
            return None
        if node.operator == "-" and isinstance(node.operand, syntax.ManifestInteger) and node.operand.value == 2**63:
            operand = Value(Ty("INTEGER_64"))  # -9223372036854775808: INTEGER_64's minimum, not a NATURAL_64 negated
        return self.operator_call(node, node.operand, operand, node.operator, [], node.span)

    def operator_call(self, node, target_node, target: Value, op: str, arguments, where) -> Value | None:
        """`a op b` or `op a`: the feature of a's class with that alias, or of the type that a
        converts to when only that one accepts b (target conversion, as for `1 + x` with x: REAL_64)."""
        candidates = self._operator_candidates(target.ty, op, len(arguments))
        if not candidates:
            self.report("VWOE", where, operator=op, type=str(target.ty))
            return None
        own = [c for c in candidates if c[1] is None]
        converted = [c for c in candidates if c[1] is not None]
        chosen = (
            next((c for c in own if self.arguments_fit(c[2], c[0], arguments, mode="manifest")), None)
            or next((c for c in converted if self.arguments_fit(c[2], c[0], arguments, mode="strict")), None)
            or next((c for c in candidates if self.arguments_fit(c[2], c[0], arguments)), candidates[0])
        )
        ty, converter, feature = chosen
        if converter is not None:
            self.tables.conversions[target_node] = (converter, ty)
        where = node.operator_span if isinstance(node, syntax.BinaryExpression) else node.span
        return self.call_feature(
            node,
            target_node,
            Value(ty, target.handler),
            feature,
            [n for n, _ in arguments],
            where,
            known=dict(arguments),
        )

    def _operator_candidates(self, ty: Ty, op: str, arity: int) -> list:
        """(type, converter or None, feature) for each type that may serve `op` on a `ty` operand
        (memoised per universe: the answer depends only on the classes)."""
        memo = self.universe.operator_memo
        key = (ty, op, arity, self.info.name if ty.is_formal else None)
        found = memo.get(key)
        if found is None:
            targets = self._operator_targets(ty, converted=arity > 0)
            found = [(t, c, f) for t, c in targets if (f := self._alias(t, op, arity)) is not None]
            memo[key] = found
        return found

    def _operator_targets(self, ty: Ty, converted: bool = True):
        from .conformance import (
            constraint_types,  # deferred: a cycle (scoopc.semantics.conformance imports this module)
        )

        bounds = constraint_types(self.universe, ty, self.info)
        for bound in bounds[1:]:
            yield bound, None
        base = bounds[0]
        yield base, None
        if not converted:
            return
        info = self.universe.get(base.name)
        for converter in info.decl.converters if info is not None else ():
            if not converter.creation_mode:
                for written in converter.types:
                    target = self.resolve_quiet(written, info)
                    if target is not None:
                        yield target, converter.name.key

    def _alias(self, ty: Ty, op: str, arity: int):
        info = self.universe.get(ty.name)
        for feature in info.aliases.get(op, ()) if info is not None else ():
            if len(feature.arguments) == arity:
                return feature
        return None

    # --- object tests, conditionals, agents ----------------------------------------------
    def e_ObjectTest(self, node, expected=None):
        value = self.expr(node.expression)
        ty = self.resolve_type(node.type) if node.type is not None else None
        if node.local is not None:
            if self.clashes(node.local.key):
                self.report("VUOT(1)", node.local.span, name=node.local.text)
            bound = ty or (value.ty if value is not None else None)
            handler = None
            if bound is not None and bound.separate:
                handler = (
                    value.handler if value is not None and value.ty.separate and value.controlled else UNCONTROLLED
                )
            self.object_tests[node] = Entity(
                node.local.key,
                "object_test",
                bound.with_marks(attached=True) if bound is not None else None,
                node.local.span,
                handler,
            )
        return Value(BOOLEAN)

    def e_ConditionalExpression(self, node, expected=None):
        values = []
        self.boolean(node.condition)
        when_true, when_false = self.branches(node.condition)
        with self.assuming(when_true):
            values.append(self.expr(node.then_part, expected))
        for part in node.elseif_parts:
            with self.assuming(when_false):
                self.boolean(part.condition)
                t, f = self.branches(part.condition)
                with self.assuming(t):
                    values.append(self.expr(part.then_part, expected))
            when_false = f
        with self.assuming(when_false):
            values.append(self.expr(node.else_part, expected))
        if any(v is None for v in values):
            return None
        return Value(self._common(values), values[0].handler)

    def e_InspectExpression(self, node, expected=None):
        """The expression form of `inspect` (EiffelStudio 22.05+): the rules of the instruction
        (VOMB(1)..(3)) for the subject and choices; its type is the branches' common type."""
        from .instructions import _inspectable  # deferred: a cycle (scoopc.semantics.instructions imports this module)

        subject = self.expr(node.expression)
        if subject is not None and not _inspectable(subject.ty):
            self.report("VOMB(1)", node.expression.span, type=str(subject.ty))
            subject = None
        seen = {}
        values = []
        for part in node.when_parts:
            for choice in part.choices:
                self._choice(choice, subject, seen)
            values.append(self.expr(part.then_part, expected))
        if node.else_part is not None:
            values.append(self.expr(node.else_part, expected))
        if not values or any(v is None for v in values):
            return None
        return Value(self._common(values), values[0].handler)

    def e_AcrossExpression(self, node, expected=None):
        with self.iteration(node.iteration):
            for clause in node.invariant:
                if clause.expression is not None:
                    self.boolean(clause.expression)
            if node.until is not None:
                self.boolean(node.until)
            self.boolean(node.body)
            if node.variant is not None:
                self.variant(node.variant)
        return Value(BOOLEAN)

    def e_OpenOperand(self, node, expected=None):
        return None

    def e_InlineAgent(self, node, expected=None):
        return self.inline_agent(node)

    def e_Agent(self, node, expected=None):
        return self.agent(node, expected)

    def e_CreationExpression(self, node, expected=None):
        ty = self.resolve_type(node.type)
        if ty is None:
            return None
        self.creation(node, ty, node.procedure, node.arguments)
        return Value(ty.with_marks(attached=True), UNCONTROLLED if ty.separate else None)

    # --- calls (calls.py does the work) ----------------------------------------------------
    def e_UnqualifiedCall(self, node, expected=None):
        return self.unqualified_call(node)

    def e_QualifiedCall(self, node, expected=None):
        return self.qualified_call(node)

    def e_BracketExpression(self, node, expected=None):
        return self.bracket_call(node)

    def e_StaticCall(self, node, expected=None):
        return self.static_call(node)

    def e_Precursor(self, node, expected=None):
        return self.precursor_call(node)
