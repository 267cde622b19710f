"""Checker, instructions: assignment (VJAW, VJAR), assigner calls (VBAC), call instructions,
creation instructions, conditionals, inspect (VOMB), loops, across (VOIT), check, debug,
separate blocks (scoop.py's V1SE rules) and retry (VXRT), with the flow facts of void safety.
"""

from __future__ import annotations

from contextlib import contextmanager

from .. import syntax
from . import scoop, suggest, walk
from .flow import UNREACHABLE, join
from .tables import Entity
from .types import INTEGERS, NATURALS, STRINGS
from .values import UNCONTROLLED, Value


class InstructionChecks:
    def instructions(self, body) -> None:
        for instruction in body:
            if self.facts is UNREACHABLE:
                return
            getattr(self, "i_" + type(instruction).__name__)(instruction)

    def branch(self, body, facts):
        saved = self.facts
        self.facts = facts
        self.instructions(body)
        result, self.facts = self.facts, saved
        return result

    # --- assignment ------------------------------------------------------------------------
    def i_Assignment(self, node) -> None:
        target = self.writable(node.target)
        value = self.expr(node.source, target.ty if target is not None else None)
        if target is None or target.ty is None:
            return
        if value is None:  # already reported: the target counts as set
            if self.facts is not UNREACHABLE:
                self.facts = self.facts.set(target.name, target.ty.attached)
            return
        self.tables.types[node.target] = target.ty
        fits = self.expect(node.source, value, target.ty, "VJAR", target)
        if self.facts is not UNREACHABLE:  # after a VJAR the target counts as set: no VEVI cascade
            attached = value.ty.attached or scoop.is_expanded(self.universe, value.ty)
            self.facts = self.facts.set(target.name, attached if fits else target.ty.attached)

    def writable(self, target):
        """The entity an assignment or creation writes, or None after reporting VJAW / V1SE(3)."""
        if isinstance(target, syntax.Result):
            if self.result_type is None:
                self.report("VEEN(2)", target.span, where=self.result_context)
                return None
            return Entity("result", "result", self.result_type)
        name = target.name.key
        entity = self.scopes.lookup(name)
        if entity is not None:
            self.tables.entities[target] = entity
            if entity.kind == "local":
                return entity
            if entity.kind == "separate":
                scoop.assign_to_separate_local(self, target, target.name.text)
            else:
                self.report("VJAW", target.span, name=target.name.text, what=_KINDS.get(entity.kind, entity.kind))
            return None
        feature = self.info.features.get(name)
        if feature is None:
            hint = suggest.unknown_identifier(self, target.name.text, assigned=True)
            self.report("VEEN", target.name.span, name=target.name.text, where=f"in class {self.info.name}", hint=hint)
            return None
        if feature.kind != "attribute":
            self.report("VJAW", target.span, name=target.name.text, what=f"a {feature.kind}, not a variable")
            return None
        self.tables.features[target] = feature
        from .features import member_signature  # deferred: a cycle (scoopc.semantics.features imports this module)

        return Entity(name, "attribute", member_signature(self.universe, self.current, feature).result)

    def i_AssignmentAttempt(self, node) -> None:
        self.writable(node.target)
        self.expr(node.source)

    def i_AssignerCall(self, node) -> None:
        call = node.target
        target_value = None
        if isinstance(call, syntax.QualifiedCall):
            target_value = self.expr(call.target)
            if target_value is None:
                self.expr(node.source)
                return
            base = target_value.ty
            if base.name == "TUPLE" and call.name.key in base.labels and not call.arguments:
                item = base.generics[base.labels.index(call.name.key)]
                self.expect(node.source, self.expr(node.source, item) or Value(item), item, "VBAC(1)")
                return
            query = self.call_on(call, call.target, target_value, call.name, call.arguments)
        elif isinstance(call, syntax.BracketExpression):
            query = self.bracket_call(call)
        else:
            query = self.expr(call)
        feature = self.tables.features.get(call)
        value = self.expr(node.source, query.ty if query is not None else None)
        if feature is None or query is None:
            return
        if feature.assigner is None:
            self.report("VBAC(2)", call.span, name=feature.text)
            return
        owner = self.universe.get(self.tables.types.get(getattr(call, "target", None), self.current).name) or self.info
        assigner = owner.features.get(feature.assigner)
        if assigner is not None:
            self.tables.features[node] = assigner
        if value is not None:
            self.expect(node.source, value, query.ty, "VBAC(1)")

    # --- calls and creation -----------------------------------------------------------------
    def i_CallInstruction(self, node) -> None:
        call = node.call
        kind = type(call).__name__
        if kind == "UnqualifiedCall":
            self.unqualified_call(call, as_instruction=True)
        elif kind == "QualifiedCall":
            target = self.expr(call.target)
            if target is None:
                self.evaluate(call.arguments)
            else:
                self.call_on(call, call.target, target, call.name, call.arguments, as_instruction=True)
        elif kind == "Precursor":
            self.precursor_call(call, as_instruction=True)
        elif kind == "StaticCall":
            self.static_call(call, as_instruction=True)
        elif kind == "BracketExpression":
            self.bracket_call(call, as_instruction=True)
        else:
            self.expr(call)
            self.report("VKCN(1)", call.span, name="this expression")

    def i_CreationInstruction(self, node) -> None:
        target = self.writable(node.target)
        if target is None or target.ty is None:
            self.evaluate(node.arguments)
            return
        ty = target.ty
        if node.type is not None:
            explicit = self.resolve_type(node.type)
            if explicit is None:
                return
            explicit = explicit.with_marks(separate=explicit.separate or ty.separate)
            if self.meets(node.type, Value(explicit.with_marks(attached=True)), ty) is not None:
                self.report("VGCC(3)", node.type.span, type=str(explicit), target=str(ty))
                return
            ty = explicit
        self.tables.types[node] = ty.with_marks(attached=True)
        self.creation(node, ty.with_marks(attached=True), node.procedure, node.arguments)
        self.facts = self.facts.set(target.name, True)

    # --- control structures ----------------------------------------------------------------
    def i_Conditional(self, node) -> None:
        self.boolean(node.condition)
        when_true, when_false = self.branches(node.condition)
        after = self.guarded(node.then_part, when_true)
        for part in node.elseif_parts:
            with self.assuming(when_false):
                self.boolean(part.condition)
                t, f = self.branches(part.condition)
                after = join(after, self.guarded(part.then_part, t))
            when_false = (when_false[0] + f[0], when_false[1] | f[1])
        after = join(after, self.guarded(node.else_part or (), when_false))
        self.facts = after

    def guarded(self, body, branch):
        entities, attached = branch
        self.scopes.push(entities)
        try:
            return self.branch(body, self.facts.with_attached(attached))
        finally:
            self.scopes.pop()

    def i_MultiBranch(self, node) -> None:
        value = self.expr(node.expression)
        if value is not None and not _inspectable(value.ty):
            self.report("VOMB(1)", node.expression.span, type=str(value.ty))
            value = None
        seen = {}
        after = UNREACHABLE
        for part in node.when_parts:
            for choice in part.choices:
                self._choice(choice, value, seen)
            after = join(after, self.branch(part.then_part, self.facts))
        if node.else_part is None:  # no branch matches: an exception, not a path
            self.facts = after if after is not UNREACHABLE else self.facts
        else:
            self.facts = join(after, self.branch(node.else_part, self.facts))

    def _choice(self, choice, value, seen) -> None:
        for bound in (choice.lower, choice.upper):
            if bound is None:
                continue
            bound_value = self.expr(bound, value.ty if value is not None else None)
            if value is None or bound_value is None:
                continue
            constant = _constant(bound)
            if self.meets(bound, bound_value, value.ty) is not None or (
                constant is None and not self._is_constant(bound)
            ):
                self.report("VOMB(2)", bound.span, type=str(value.ty))
                return
        low, high = (
            _constant(choice.lower),
            _constant(choice.upper) if choice.upper is not None else _constant(choice.lower),
        )
        if low is None or high is None:
            return
        if any(not (high < a or low > b) for a, b in seen.values()):
            self.report("VOMB(3)", choice.span)
        seen[choice] = (low, high)

    def _is_constant(self, node) -> bool:
        feature = self.tables.features.get(node)
        return feature is not None and feature.kind == "constant"

    def i_Loop(self, node) -> None:
        self.instructions(node.initialization)
        self.loop_parts(node.invariant, node.until, node.body, node.variant)

    def loop_parts(self, invariant, until, body, variant) -> None:
        for clause in invariant:
            if clause.expression is not None:
                self.boolean(clause.expression)
        if self.facts is UNREACHABLE:
            return
        entry = self.facts
        assigned = _assigned(body, self.assigned_in)
        start = entry.__class__(entry.attached - assigned, entry.unset)
        self.facts = start
        when_true, when_false = ((), frozenset()), ((), frozenset())
        if until is not None:
            self.boolean(until)
            when_true, when_false = self.branches(until)
        end = self.guarded(body, when_false)
        if variant is not None:
            self.variant(variant)
        after = join(start, end)
        self.facts = after.with_attached(when_true[1]) if after is not UNREACHABLE else entry

    def variant(self, variant) -> None:
        """VAVE: a loop variant is an INTEGER expression (it must decrease and stay non-negative)."""
        value = self.expr(variant.expression)
        if value is not None and value.ty.name not in INTEGERS + NATURALS:
            self.report("VAVE", variant.expression.span, type=str(value.ty))

    def i_Across(self, node) -> None:
        with self.iteration(node.iteration):
            self.instructions(node.initialization)
            self.loop_parts(node.invariant, node.until, node.body, node.variant)

    @contextmanager
    def iteration(self, iteration):
        from .conformance import (  # deferred: a cycle (scoopc.semantics.conformance imports this module)
            ancestor,
            base_type,
        )
        from .features import member_signature  # deferred: a cycle (scoopc.semantics.features imports this module)

        value = self.expr(iteration.expression)
        entity = Entity(iteration.name.key, "across", None, iteration.name.span)
        if value is not None:
            base = base_type(self.universe, value.ty, self.info)
            iterable = ancestor(self.universe, base, "ITERABLE")
            broken = (owner := self.universe.get(base.name)) is not None and owner.failed
            if iterable is None:
                if not broken:
                    self.report("VOIT(1)", iteration.expression.span, type=str(value.ty))
            else:
                item = iterable.generics[0] if iterable.generics else None
                if iteration.cursor_mode:
                    info = self.universe.get(base.name)
                    cursor = info.features.get("new_cursor") if info is not None else None
                    item = member_signature(self.universe, base, cursor).result if cursor is not None else item
                if item is not None and value.ty.separate:
                    handler = value.handler if value.controlled else UNCONTROLLED
                    item = (
                        item
                        if item.separate or scoop.is_expanded(self.universe, item)
                        else item.with_marks(separate=True)
                    )
                    entity.handler = handler if item.separate else None
                entity.ty = item.with_marks(attached=True) if item is not None else None
        if self.clashes(iteration.name.key):
            self.report("VOIT(2)", iteration.name.span, name=iteration.name.text)
        self.tables.entities[iteration] = entity
        self.scopes.push((entity,))
        try:
            yield entity
        finally:
            self.scopes.pop()

    def i_Check(self, node) -> None:
        from .contracts import assertions  # deferred: a cycle (scoopc.semantics.contracts imports this module)

        found = assertions(self, node.assertions)
        if any(isinstance(c.expression, syntax.ManifestBoolean) and not c.expression.value for c in node.assertions):
            self.facts = UNREACHABLE  # `check False then end`: this point is never reached
            return
        if node.then_part is not None:
            self.facts = self.guarded(node.then_part, found)
        elif self.facts is not UNREACHABLE:
            self.facts = self.facts.with_attached(found[1])

    def i_Debug(self, node) -> None:
        self.facts = join(self.facts, self.branch(node.body, self.facts))

    def i_SeparateInstruction(self, node) -> None:
        entities = []
        for argument in node.arguments:
            value = self.expr(argument.expression)
            clash = self.clashes(argument.name.key) or any(e.name == argument.name.key for e in entities)
            if not scoop.check_separate_argument(self, argument, value, clash) or value is None:
                entities.append(Entity(argument.name.key, "separate", None, argument.name.span))
                continue
            entity = Entity(
                argument.name.key,
                "separate",
                value.ty.with_marks(attached=True),
                argument.name.span,
                argument.name.key if value.ty.separate else None,
            )
            self.tables.entities[argument] = entity
            entities.append(entity)
        self.facts = self.guarded(node.body, (tuple(entities), frozenset()))

    def i_Retry(self, node) -> None:
        if not self.in_rescue:
            self.report("VXRT", node.span)
        self.facts = UNREACHABLE


_KINDS = {
    "argument": "a formal argument (arguments are read-only)",
    "object_test": "an object-test local",
    "across": "an iteration cursor",
    "result": "Result",
}


def _inspectable(ty) -> bool:
    """VOMB(1): `inspect` works on integers, naturals, characters (and strings, as EiffelStudio 19)."""
    return not ty.is_formal and (
        ty.name in INTEGERS + NATURALS or ty.name in ("CHARACTER_8", "CHARACTER_32") or ty.name in STRINGS
    )


def _constant(node):
    from .values import manifest_kind  # deferred: a cycle (scoopc.semantics.values imports this module)

    kind = manifest_kind(node)
    if kind is not None and kind[0] in ("integer", "character", "string"):
        return kind[1]
    return None


def _assigned(body, known: dict) -> frozenset:
    """Names assigned (or created) anywhere in a list of instructions. `known` ({id(node): (node,
    names)}, one per routine checker) keeps what each compound instruction assigns: loops in
    loops, 2,000 deep, ask again about the instructions inside them."""
    names: set = set()
    for instruction in body:
        names |= _assigned_in(instruction, known)
    return frozenset(names)


def _assigned_in(node, known: dict) -> frozenset:
    found = known.get(id(node))
    if found is not None:
        return found[1]
    names = set()
    if isinstance(node, (syntax.Assignment, syntax.CreationInstruction)):
        target = node.target
        names.add("result" if isinstance(target, syntax.Result) else target.name.key)
    for child in walk.children(node):
        if not isinstance(child, (syntax.InlineAgent,)):
            names |= _assigned_in(child, known)
    result = frozenset(names)
    known[id(node)] = (node, result)  # the node kept alive with its id
    return result
