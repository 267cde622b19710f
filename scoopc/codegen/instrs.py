"""Codegen, instructions: one `s_<Node>` method per instruction kind, each returning a list of
Python statements."""

from __future__ import annotations

import ast

from .. import syntax
from ..semantics.types import BASIC
from . import pyast as P
from .context import fail
from .exprs import INTEGER_BITS, WIDE_STRINGS, manifest_text
from .scoop_calls import NAMES, USES, interval_across, mark_names

_VALUE_COPIES = frozenset({"copy", "standard_copy", "deep_copy"})


class Instructions:
    def block(self, instructions) -> list:
        out = []
        for instruction in instructions:
            method = getattr(self, "s_" + type(instruction).__name__, None)
            if method is None:
                fail(f"no code for {type(instruction).__name__}", instruction.span)
            for stmt in method(instruction):
                out.append(P.at(stmt, instruction.span))
        return out

    # --- assignment --------------------------------------------------------------------------------
    def s_Assignment(self, node):
        target_ty = self.tables.types.get(node.target) or self.entity_type(node.target)
        if target_ty is not None and target_ty.name in INTEGER_BITS and not target_ty.is_formal:
            checked = self.ring_assignment(self.target(node.target), node.source)
            if checked is not None:
                return checked
        value = self.copied(node.source, self.x(node.source))
        value = self.reattached(node.source, value, self.tables.types.get(node.target) or self.entity_type(node.target))
        return [P.assign(self.target(node.target), value)]

    def copied(self, node, value):
        """A value of a user-defined expanded type is copied when attached to another entity."""
        ty = self.tables.types.get(node)
        if ty is None or ty.is_formal or ty.name in BASIC:
            return value
        info = self.universe.get(ty.name)
        if info is not None and info.is_expanded:
            return P.call("_S.copy_expanded", [value])
        return value

    def s_AssignmentAttempt(self, node):
        ty = self.tables.types.get(node.target) or self.entity_type(node.target)
        value = P.call("_S.attempt", [self.x(node.source), self.type_desc(ty)])
        return [P.assign(self.target(node.target), value)]

    def entity_type(self, target):
        entity = self.tables.entities.get(target)
        if entity is not None:
            return entity.ty
        if isinstance(target, syntax.Result):
            return self.result_type
        feature = self.tables.features.get(target)
        return feature.signature.result if feature is not None else None

    def target(self, node):
        if isinstance(node, syntax.Result):
            return self.result_ref()
        entity = self.tables.entities.get(node)
        if entity is not None and entity.kind != "attribute":
            return P.name(self.local_name(entity.name))
        feature = self.tables.features.get(node)
        if feature is None:
            fail("unresolved assignment target", node.span)
        return P.attr(P.name("self"), self.py_name(feature))

    def s_AssignerCall(self, node):
        assigner = self.tables.features.get(node)
        target = node.target
        if assigner is None:
            if isinstance(target, syntax.QualifiedCall) and self.tuple_label(target) is not None:
                index = self.tuple_label(target)
                holder = self.x(target.target)
                return [P.expr_stmt(P.call("_S.tuple_put", [holder, P.const(index), self.x(node.source)]))]
            fail("assigner call without an assigner", node.span)
        if isinstance(target, syntax.BracketExpression):
            owner, arguments = target.target, target.arguments
        elif isinstance(target, syntax.QualifiedCall):
            owner, arguments = target.target, target.arguments
        else:
            owner, arguments = None, target.arguments
        receiver = self.x(owner) if owner is not None else P.name("self")
        args = [self.x(node.source)] + [self.argument(a) for a in arguments]
        if target in self.tables.separate_calls:
            return [
                P.expr_stmt(
                    P.call(
                        "_S.scall",
                        [P.name("here"), receiver, P.const(self.py_name(assigner)), P.tup(args), P.const(True)],
                    )
                )
            ]
        return [P.expr_stmt(P.call(P.attr(receiver, self.py_name(assigner)), args))]

    # --- calls and creation ----------------------------------------------------------------------------
    def s_CallInstruction(self, node):
        call = node.call
        if (
            isinstance(call, syntax.QualifiedCall)
            and call.name.key in _VALUE_COPIES
            and len(call.arguments) == 1
            and self.is_basic(self.tables.types.get(call.target))
            and self.is_variable(call.target)
        ):
            # `i.copy (j)` on an entity of a basic (expanded) type copies into the entity
            # itself (a call on an entity of an expanded type works on the entity's value)
            return [P.assign(self.target(call.target), self.x(call.arguments[0]))]
        return [P.expr_stmt(self.x(call))]

    def is_variable(self, node) -> bool:
        """A local, Result or attribute of Current: an entity `copy` may write."""
        if isinstance(node, syntax.Result):
            return True
        entity = self.tables.entities.get(node)
        if entity is not None:
            return entity.kind in ("local", "argument", "result", "attribute")
        feature = self.tables.features.get(node)
        return (
            isinstance(node, syntax.UnqualifiedCall)
            and not node.arguments
            and feature is not None
            and feature.kind == "attribute"
        )

    def s_CreationInstruction(self, node):
        ty = self.tables.types.get(node)
        if ty is None:
            fail("creation without a type", node.span)
        feature = self.tables.features.get(node)
        target = self.target(node.target)
        if isinstance(target, ast.Name) and not ty.is_formal and not ty.separate and node.processor is None:
            return self.local_creation(target, ty, feature, node.arguments)
        value = self.creation_value(node, ty, feature, node.arguments, node.processor is not None)
        return [P.assign(target, value)]

    def local_creation(self, target, ty, feature, arguments):
        """`create x.make (a)` into a local or Result, spelled out: `x = here.new(C)`, then
        `x.make(a)` (the common case, and the cheapest: no helper call)."""
        info = self.universe.get(ty.name)
        if self.is_tuple_class(info):
            return [P.assign(target, self.new_tuple_object(ty))]
        args = [self.argument(a) for a in arguments]
        out = [P.assign(target, P.call("here.new", [self.class_ref(info.name)]))]
        if info.formals:
            out.append(P.assign(P.attr(P.name(target.id), "_gen_"), self.generics_desc(ty)))
        creator = self.py_name(feature) if feature is not None else None
        if creator is not None:
            out.append(P.expr_stmt(P.call(P.attr(P.name(target.id), creator), args)))
        if self.assertions == "all" and self.program_has_invariant(info):
            out.append(P.expr_stmt(P.call("_S.check_invariant", [P.name(target.id)])))
        return out

    # --- control -------------------------------------------------------------------------------------
    def s_Conditional(self, node):
        orelse = self.block(node.else_part) if node.else_part else []
        for part in reversed(node.elseif_parts):
            orelse = [P.at(P.if_(self.x(part.condition), self.block(part.then_part), orelse), part.span)]
        return [P.if_(self.x(node.condition), self.block(node.then_part), orelse)]

    def s_MultiBranch(self, node):
        subject = self.temp("inspect")
        value, text = self.inspect_subject(node)
        out = [P.assign(P.name(subject), value)]
        if node.else_part is not None:
            orelse = self.block(node.else_part)
        else:
            orelse = [P.expr_stmt(P.call("_S.bad_inspect", [P.name(subject), self.where(node)]))]
        for part in reversed(node.when_parts):
            tests = [self.choice(P.name(subject), c, text) for c in part.choices]
            orelse = [P.at(P.if_(P.boolop(ast.Or(), tests), self.block(part.then_part), orelse), part.span)]
        return out + orelse

    def inspect_subject(self, node) -> tuple[ast.expr, str]:
        """The value an inspect compares, and for a string its kind ("8" or "32"; "" for other
        types): strings are inspected by value (their characters), as EiffelStudio does, never by
        identity."""
        value = self.x(node.expression)
        ty = self.tables.types.get(node.expression)
        if ty is not None and not ty.is_formal and "STRING" in ty.name:
            return P.call("_S.inspect_text", [value, self.where(node)]), ("32" if ty.name in WIDE_STRINGS else "8")
        return value, ""

    def choice(self, subject, choice, text: str = ""):
        lower = self.choice_value(choice.lower, text)
        if choice.upper is None:
            return P.compare(subject, ast.Eq(), lower)
        return ast.Compare(lower, [ast.LtE(), ast.LtE()], [subject, self.choice_value(choice.upper, text)])

    def choice_value(self, node, text: str):
        """A `when` value; for a string subject (`text` is "8" or "32", its kind), the characters
        of the string it denotes, as the subject holds them."""
        if not text:
            return self.x(node)
        if isinstance(node, syntax.ManifestString):
            return P.const(manifest_text(node.value, text == "32"))
        return P.attr(self.x(node), "_s")

    def s_Loop(self, node):
        out = self.block(node.initialization)
        body = self.block(node.body)
        checks, variant = self.loop_checks(node)
        out += variant[0]
        loop = ast.While(P.not_(self.x(node.until)), checks + body + variant[1] or [ast.Pass()], [])
        return out + checks + [loop] + checks

    def loop_checks(self, node):
        if self.assertions != "all":
            return [], ([], [])
        checks = [self.assertion(c, "loop_invariant") for c in node.invariant if c.expression is not None]
        if node.variant is None:
            return checks, ([], [])
        name = self.temp("variant")
        variant = node.variant
        tag = [P.const(variant.tag.text)] if variant.tag is not None else []
        first = [
            P.assign(P.name(name), P.call("_S.variant_start", [self.x(variant.expression), self.where(variant)] + tag))
        ]
        step = [
            P.assign(
                P.name(name),
                P.call("_S.variant_step", [P.name(name), self.x(variant.expression), self.where(variant)] + tag),
            )
        ]
        return checks, (first, step)

    def s_Across(self, node):

        fast = interval_across(self, node)  # `across a |..| b`: a Python range
        if fast is not None:
            return fast
        iteration = node.iteration
        var = self.local_name(iteration.name.key)
        out = self.block(node.initialization)
        body = self.block(node.body)
        if node.until is not None:
            body = [P.if_(self.x(node.until), [ast.Break()])] + body
        checks, _ = self.loop_checks(node)
        body = checks + body
        source = self.iteration_source(iteration)
        if not iteration.cursor_mode:
            # `across s is x` (and `⟳ x: s ¦ ... ⟲`) is `across s as c` with each `x` read as
            # `c.item` at the point of use, as the unfolded `new_cursor` loop reads it
            source = P.call("_S.cursors", [self.x(iteration.expression)])
            body = [_ItemReads(var).visit(stmt) for stmt in body]
        loop = ast.For(P.name(var, store=True), source, body or [ast.Pass()], [], None)
        return out + [mark_names(loop)]

    def s_Check(self, node):
        out = []
        if self.assertions == "all" or node.then_part is not None:
            for clause in node.assertions:
                if clause.expression is not None:
                    out.append(self.assertion(clause, "check"))
        if node.then_part is not None:
            out += self.block(node.then_part)
        return out

    def s_Debug(self, node):
        return []

    def s_Retry(self, node):
        return [ast.Continue()]

    def s_SeparateInstruction(self, node):
        out, names = [], []
        for argument in node.arguments:
            local = self.local_name(argument.name.key)
            out.append(P.assign(P.name(local), self.x(argument.expression)))
            names.append(P.name(local))
        body = self.block(node.body)
        return out + self.reserved(names, None, body, self.where(node))

    # --- assertions ----------------------------------------------------------------------------------
    def assertion(self, clause, kind: str):
        tag = clause.tag.text if clause.tag is not None else None
        failure = P.call("_S.assertion_failed", [P.const(kind), P.const(tag), self.where(clause)])
        return P.at(P.if_(P.not_(self.x(clause.expression)), [P.expr_stmt(failure)]), clause.span)


class _ItemReads(ast.NodeTransformer):
    """Every read of the cursor variable `var` becomes `var.item`."""

    def __init__(self, var: str):
        self.var = var

    def visit_For(self, node):
        names = getattr(node, NAMES, None)
        if names is not None and self.var not in names:
            return node  # an `across` loop without `var` (2,000 of them in one another are not each looked through)
        if hasattr(node, USES):  # what it says of `var` changes here
            delattr(node, USES)
        return self.generic_visit(node)

    def visit_Name(self, node):
        if node.id == self.var and isinstance(node.ctx, ast.Load):
            return ast.copy_location(P.attr(P.name(self.var), "item"), node)
        return node
