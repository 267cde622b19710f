"""Checker, calls: feature calls of every form (unqualified, qualified, bracket, static,
Precursor, operators) with the rules VEEN, VUEX(2), VUAR(1), VUAR(2), VKCN(1), VKCN(2), VUTA(2),
VDPR(1), VDPR(2), and the SCOOP rules through scoop.py. Records the feature of every call.
"""

from __future__ import annotations

from .. import syntax
from . import scoop, suggest, walk
from .conformance import base_type
from .features import member_signature
from .types import NONE, Ty
from .values import UNCONTROLLED, Value


class CallChecks:
    def unqualified_call(self, node, as_instruction: bool = False) -> Value | None:
        name = node.name.key
        entity = self.scopes.lookup(name)
        if entity is not None:
            self.tables.entities[node] = entity
            if node.arguments:
                value = self.entity_value(node, entity)
                return None if value is None else self.agent_call(node, value, as_instruction)
            if as_instruction:
                self.report("VKCN(1)", node.span, name=node.name.text)
            return self.entity_value(node, entity)
        feature = self.info.features.get(name)
        if feature is not None and self.in_precondition:
            self.precondition_export(feature, node.name.span)
        if feature is not None and node.arguments and not feature.arguments and feature.is_query:
            value = self.call_feature(node, None, Value(self.current), feature, (), node.name.span)
            return None if value is None else self.agent_call(node, value, as_instruction)
        if feature is None:
            hint = suggest.unknown_identifier(self, node.name.text)
            self.report("VEEN", node.name.span, name=node.name.text, where=f"in class {self.info.name}", hint=hint)
            self.evaluate(node.arguments)
            return None
        value = self.call_feature(
            node, None, Value(self.current), feature, node.arguments, node.name.span, as_instruction
        )
        if value is not None and feature.kind == "attribute" and name in self.facts.attached:
            value = Value(value.ty.with_marks(attached=True), value.handler)
        return value

    def agent_call(self, node, agent: Value, as_instruction: bool) -> Value | None:
        """`f (a, b)` where f is an agent: its "()" feature applied to the tuple [a, b]; where f is
        of another class, its "()" alias called with a and b (EiffelStudio's
        `look_for_parenthesis_alias`)."""
        base = base_type(self.universe, agent.ty, self.info)
        info = self.universe.get(base.name)
        if info is not None and not _is_agent_class(info):
            inner = syntax.UnqualifiedCall(node.name, (), node.name.span)
            for table in (self.tables.features, self.tables.entities):
                if node in table:
                    table[inner] = table.pop(node)
            self.tables.types[inner] = agent.ty
            return self.parenthesis_call(node, inner, agent, node.arguments, as_instruction)
        feature = next(iter(info.aliases.get("()", ())), None) if info is not None else None
        if feature is None:
            self.report("VWOE", node.span, operator="()", type=str(agent.ty))
            self.evaluate(node.arguments)
            return None
        if agent.ty.separate and not scoop.check_target(self, node, agent):
            self.evaluate(node.arguments)
            return None
        self.tables.agent_calls.add(node)
        self.tables.features[node] = feature
        operands = member_signature(self.universe, base.with_marks(attached=True), feature).arguments
        tuple_type = operands[0] if operands and operands[0] is not None else None
        formals = tuple(g for g in tuple_type.generics) if tuple_type is not None else ()
        self.actuals(node, node.arguments, formals, agent if agent.ty.separate else None)
        if feature.is_query:
            if as_instruction:
                self.report("VKCN(1)", node.span, name=feature.text)
            result = member_signature(self.universe, base, feature).result
            return None if result is None else Value(result)
        if not as_instruction:
            self.report("VKCN(2)", node.span, name=node.name.text)
            return None
        return Value(NONE)

    def parenthesis_call(self, node, inner, target: Value, arguments, as_instruction: bool) -> Value | None:
        """`x (a)` as `x.f (a)` where `f` has the alias "()" in the class of `x`: checked as that
        call, which the code generator compiles in place of `node`."""
        base = base_type(self.universe, target.ty, self.info)
        info = self.universe.get(base.name)
        feature = next(iter(info.aliases.get("()", ())), None) if info is not None else None
        if feature is None:
            self.report("VUAR(1)", node.span, expected=0, given=len(arguments))
            self.evaluate(arguments)
            return None
        name = syntax.Identifier(feature.text, feature.name, node.span)
        outer = syntax.QualifiedCall(inner, name, arguments, node.span)
        self.tables.rewrites[node] = outer
        value = self.call_on(outer, inner, target, name, arguments, as_instruction)
        if value is not None:
            self.tables.types[outer] = value.ty
        return value

    def entity_value(self, node, entity) -> Value | None:
        if entity.ty is None:
            return None
        self.use_entity(node, entity.name)
        attached = entity.ty.attached or entity.name in self.facts.attached
        return Value(entity.ty.with_marks(attached=attached), entity.handler)

    def qualified_call(self, node, as_instruction: bool = False) -> Value | None:
        target = self.expr(node.target)
        if target is None:
            self.evaluate(node.arguments)
            return None
        return self.call_on(node, node.target, target, node.name, node.arguments, as_instruction)

    def call_on(self, node, target_node, target: Value, name, arguments, as_instruction=False) -> Value | None:
        ty = target.ty
        scoop.foreign_use(self, target, "is the target of a non-separate call here")
        if ty.is_none or (not ty.attached and self.void_level >= 3 and not scoop.is_expanded(self.universe, ty)):
            self.report("VUTA(2)", target_node.span, target=walk.describe(target_node), type=str(ty))
            if ty.is_none:
                self.evaluate(arguments)
                return None
        base, feature = self._find_feature(ty, name)
        if feature is None and (owner := self.universe.get(base.name)) is not None and owner.failed:
            self.evaluate(arguments)
            return None  # the class's own errors are reported there
        if base.name == "TUPLE" and name is not None and name.key in base.labels and not arguments:
            item = base.generics[base.labels.index(name.key)]
            if ty.separate:
                return scoop.adapt_result(self, node, item, target)
            return Value(item, UNCONTROLLED if item.separate or scoop.separate_by_constraint(self, item) else None)
        if feature is None:
            hint = suggest.unknown_feature(self, name.text, self.universe.get(base.name))
            self.report("VEEN", name.span, name=name.text, where=f"among the features of {base.name}", hint=hint)
            self.evaluate(arguments)
            return None
        if ty.separate and not scoop.check_target(self, target_node, target):
            self.evaluate(arguments)
            return None  # reported: the enclosing expression stays silent
        if target.handler == UNCONTROLLED and scoop.separate_by_constraint(self, ty):
            target = walk.describe(target_node)
            self.report("VUTA(3)", target_node.span, target=target, type=str(ty), fresh=scoop.fresh(target_node))
            self.evaluate(arguments)
            return None
        current = ty.with_marks(attached=True) if ty.is_formal else None  # `like Current` is G, not its constraint
        if arguments and feature.is_query and not feature.arguments and not _returns_agent(self, base, feature):
            inner = syntax.QualifiedCall(target_node, name, (), name.span)
            value = self.call_feature(inner, target_node, Value(base, target.handler), feature, (), name.span)
            if value is None:
                self.evaluate(arguments)
                return None
            self.tables.types[inner] = value.ty
            return self.parenthesis_call(node, inner, value, arguments, as_instruction)
        return self.call_feature(
            node,
            target_node,
            Value(base, target.handler),
            feature,
            arguments,
            name.span,
            as_instruction,
            current=current,
        )

    def _find_feature(self, ty: Ty, name):
        """The feature `name` of the class of `ty` (of one of the constraints for a formal)."""
        from .conformance import (
            constraint_types,  # deferred: a cycle (scoopc.semantics.conformance imports this module)
        )

        bounds = constraint_types(self.universe, ty, self.info)
        renamed = self.info.constraint_renames
        renamed = renamed[ty.formal] if ty.is_formal and ty.formal < len(renamed) else {}
        for bound in bounds:
            info = self.universe.get(bound.name)
            key = name.key if name is not None else None
            renames = renamed.get(bound.name)
            if renames and key is not None:
                key = renames.get(key, None if key in renames.values() else key)
            feature = info.features.get(key) if info is not None and key is not None else None
            if feature is not None:
                return bound.with_marks(attached=True), feature
        return bounds[0].with_marks(attached=True), None

    def call_feature(
        self,
        node,
        target_node,
        target: Value,
        feature,
        arguments,
        name_span,
        as_instruction: bool = False,
        known=None,
        current=None,
    ) -> Value | None:
        """Arguments, exports and result of a call of `feature` on `target` (target_node None:
        the call is on Current, unqualified)."""
        self.tables.features[node] = feature
        if self.in_precondition and target_node is not None:
            self.precondition_export(feature, name_span)
        signature = member_signature(self.universe, target.ty, feature, current)
        separate = target.ty.separate and target_node is not None
        if separate:
            self.tables.separate_calls.add(node)
        if target_node is not None and not self.available(feature):
            self.report("VUEX(2)", name_span, name=feature.text, cls=target.ty.name, client=self.info.name)
        values = self.actuals(node, arguments, signature.arguments, target if separate else None, known)
        if separate:
            scoop.lock_passing(self, node, values, signature.arguments)
        if feature.is_query:
            if as_instruction:
                self.report("VKCN(1)", node.span, name=feature.text)
            result = signature.result
            if result is None:
                return None
            if separate:
                return scoop.adapt_result(self, node, result, target)
            return Value(
                result, UNCONTROLLED if result.separate or scoop.separate_by_constraint(self, result) else None
            )
        if not as_instruction:
            self.report("VKCN(2)", node.span, name=feature.text)
            return None
        return Value(NONE)

    def actuals(self, node, arguments, formals, separate_target: Value | None, known=None) -> list:
        if (
            not arguments
            and len(formals) == 1
            and _no_operands(formals[0])
            and self.tables.features.get(node) is not None
            and self.tables.features[node].written_in in AGENT_CLASSES
        ):
            self.tables.agent_calls.add(node)  # `p.call` for `p.call ([])`, as EiffelStudio accepts
            return []
        if len(arguments) != len(formals):
            self.report("VUAR(1)", node.span, expected=len(formals), given=len(arguments))
            self.evaluate(arguments)
            return []
        values = []
        for actual, formal in zip(arguments, formals):
            value = known[actual] if known and actual in known else self.expr(actual, formal)
            values.append(value)
            if value is None or formal is None:
                continue
            if separate_target is not None:
                if not scoop.check_actual(self, actual, value, formal):
                    continue
                formal = formal.with_marks(separate=True)
            self.expect(actual, value, formal, "VUAR(2)")
        return values

    def arguments_fit(self, feature, target_ty: Ty, arguments, mode: str = "convert") -> bool:
        """Whether already-typed (node, Value) arguments meet the formals, without reporting.
        mode "strict": by conformance alone; "manifest": conformance or a manifest constant typed
        by the formal; "convert": also by a conversion."""
        from .conformance import (  # deferred: a cycle (scoopc.semantics.conformance imports this module)
            manifest_fits,
            why_not,
        )
        from .values import manifest_kind  # deferred: a cycle (scoopc.semantics.values imports this module)

        formals = member_signature(self.universe, target_ty, feature).arguments
        if len(formals) != len(arguments):
            return False
        for (node, value), formal in zip(arguments, formals):
            if value is None or formal is None:
                return False
            if mode == "convert":
                fits = self.meets(node, value, formal) is None
            else:
                kind = manifest_kind(node) if mode == "manifest" else None
                fits = why_not(self.universe, value.ty, formal, self.info) is None or (
                    kind is not None and manifest_fits(kind[0], kind[1], formal)
                )
            if not fits:
                return False
        return True

    def expect(self, node, value: Value, target: Ty, code: str, written=None) -> bool:
        """Whether `value` fits `target`, reporting `code` if not; `written` is the entity an
        assignment writes (its kind shapes the hint)."""
        reason = self.meets(node, value, target)
        if reason is None:
            if value.foreign is not None and not target.separate and not scoop.is_expanded(self.universe, target):
                scoop.foreign_use(self, value, f"is attached to an entity of non-separate type {target}")
            return True
        if reason == "separate":
            scoop.separate_mismatch(self, code, node, value.ty, target, written)
        else:
            detail = {
                "detachable": "it may be Void (detachable) and the target is attached",
                "separate-generic": "an actual generic parameter of it is separate where the "
                + ("formal's" if code == "VUAR(2)" else "target's")
                + " is not",
            }.get(reason, "it does not conform and no conversion applies")
            self.report(
                code,
                node.span,
                source=str(value.ty),
                target=str(target),
                actual=str(value.ty),
                formal=str(target),
                reason=detail,
                hint=_hint(reason),
            )
        return False

    def precondition_export(self, feature, span) -> None:
        """VAPE (ECMA-367's Precondition Export rule): a feature called unqualified in the
        precondition of the routine being checked is available to every class the routine is
        available to (a client must be able to test the precondition it has to meet)."""
        routine = self.feature
        if routine is None or self.in_agent:
            return
        client = export_gap(self.universe, routine, feature)
        if client is not None:
            listed = ", ".join(sorted(feature.exports)) or "NONE"
            self.report("VAPE", span, name=feature.text, routine=routine.text, client=client, exports=listed)

    def available(self, feature) -> bool:
        if feature.exports is None:
            return True
        return any(name in self.info.ancestors for name in feature.exports)

    def bracket_call(self, node, as_instruction: bool = False) -> Value | None:
        target = self.expr(node.target)
        if target is None:
            self.evaluate(node.arguments)
            return None
        base = base_type(self.universe, target.ty, self.info)
        info = self.universe.get(base.name)
        feature = (info.aliases.get("[]") or [None])[0] if info is not None else None
        if feature is None:
            self.report("VWOE", node.span, operator="[]", type=str(target.ty))
            self.evaluate(node.arguments)
            return None
        if target.ty.separate and not scoop.check_target(self, node.target, target):
            self.evaluate(node.arguments)
            return None
        return self.call_feature(
            node,
            node.target,
            Value(base.with_marks(attached=True), target.handler),
            feature,
            node.arguments,
            node.span,
            as_instruction,
        )

    def static_call(self, node, as_instruction: bool = False) -> Value | None:
        ty = self.resolve_type(node.type)
        if ty is None:
            self.evaluate(node.arguments)
            return None
        info = self.universe.get(ty.name)
        feature = info.features.get(node.name.key) if info is not None else None
        if feature is None:
            hint = suggest.unknown_feature(self, node.name.text, info)
            self.report(
                "VEEN", node.name.span, name=node.name.text, where=f"among the features of {ty.name}", hint=hint
            )
            self.evaluate(node.arguments)
            return None
        return self.call_feature(node, None, Value(ty), feature, node.arguments, node.name.span, as_instruction)

    def precursor_call(self, node, as_instruction: bool = False) -> Value | None:
        precursors = self.feature.precursors if self.feature is not None else ()
        if node.parent is not None:
            wanted = self.universe.canonical(node.parent.text)
            if not any(ty.name == wanted for _, ty, _ in self.info.parents):
                self.report("VDPR(2)", node.span, parent=node.parent.text, cls=self.info.name)
                self.evaluate(node.arguments)
                return None
            precursors = tuple(p for p in precursors if p[0] == wanted)
        effective = [p for p in precursors if not p[1].deferred]
        if not effective:
            self.report("VDPR(1)", node.span, name=self.feature.text if self.feature else "?")
            self.evaluate(node.arguments)
            return None
        return self.call_feature(
            node, None, Value(self.current), effective[0][1], node.arguments, node.span, as_instruction
        )

    def evaluate(self, nodes) -> None:
        for n in nodes:
            self.expr(n)


AGENT_CLASSES = ("ROUTINE", "PROCEDURE", "FUNCTION", "PREDICATE")


def export_gap(universe, routine, feature) -> str | None:
    """A client `routine` is available to and `feature` is not (ECMA-367's Precondition Export
    rule, EiffelStudio's `export_status.is_subset`), or None."""
    if feature.exports is None:
        return None
    clients = routine.exports if routine.exports is not None else frozenset({"ANY"})
    for client in sorted(clients):
        info = universe.get(client)
        if client == "NONE" or info is None:
            continue
        if not any(name == client or name in info.ancestors for name in feature.exports):
            return client
    return None


def _is_agent_class(info) -> bool:
    return info.name in AGENT_CLASSES or any(name in info.ancestors for name in AGENT_CLASSES)


def _returns_agent(ctx, base, feature) -> bool:
    """Is the result of `feature` (a query without arguments) an agent? `x.f (a)` is then left to
    the agent rules."""
    result = member_signature(ctx.universe, base, feature).result
    if result is None:
        return True
    info = ctx.universe.get(base_type(ctx.universe, result, ctx.info).name)
    return info is None or _is_agent_class(info)


def _no_operands(formal) -> bool:
    return formal is not None and formal.name == "TUPLE" and not formal.generics


def _hint(reason: str) -> str:
    if reason == "detachable":
        return "test it first: `if attached x as l_x then ... end`, or declare the target `detachable`"
    if reason == "separate-generic":
        return "declare that actual generic parameter `separate` in the target's type too"
    return ""
