"""Codegen, calls: feature calls (built-ins of basic types inlined, dynamic dispatch on values
that may be basic, separate calls lowered onto the runtime), Precursor, static calls, creation,
conversions and agents."""

from __future__ import annotations

import ast

from .. import syntax
from ..semantics.features import member_signature
from ..semantics.types import BASIC, Ty
from . import pyast as P
from .context import fail
from .names import class_name
from .scoop_calls import separate_call

AGENT_CLASSES = ("ROUTINE", "PROCEDURE", "FUNCTION", "PREDICATE")
# Queries whose answer depends on the basic class of a value (asked of a formal-typed target).
KIND_QUERIES = frozenset({"out", "generator", "generating_type", "tagged_out"})
# Basic classes whose values are boxed when reattached to a reference type.
BOXED = frozenset(
    {
        "REAL_32",
        "CHARACTER_32",
        "INTEGER_8",
        "INTEGER_16",
        "INTEGER_64",
        "NATURAL_8",
        "NATURAL_16",
        "NATURAL_32",
        "NATURAL_64",
    }
)


def is_external(feature, language: str) -> bool:
    body = feature.body
    inner = getattr(body, "body", None)
    return isinstance(inner, syntax.ExternalBody) and inner.language.lower() == language.lower()


def declared_name(feature) -> str:
    """The feature's name as written in the class that declares this version."""
    for fname in feature.decl.names:
        if fname is feature.fname:
            return fname.name.key
    return feature.decl.names[0].name.key


class Calls:
    # --- unqualified and qualified calls ---------------------------------------------------------
    def x_UnqualifiedCall(self, node):
        if node in self.tables.rewrites:
            return self.x(self.tables.rewrites[node])  # `x (a)`: x's "()" alias
        entity = self.tables.entities.get(node)
        if entity is not None and entity.kind != "attribute":
            value = P.name(self.local_name(entity.name))
            if node.arguments:
                return self.agent_application(node, value, node)
            return value
        feature = self.tables.features.get(node)
        if feature is None:
            fail(f"unresolved call {node.name.text}", node.span)
        if node in self.tables.agent_calls:
            target = self.plain_call(P.name("self"), feature, [])
            return self.agent_application(node, target, node)
        return self.call_feature(node, None, P.name("self"), feature, node.arguments)

    def x_QualifiedCall(self, node):
        if node in self.tables.rewrites:
            return self.x(self.tables.rewrites[node])  # `t.x (a)`: x's "()" alias
        target = self.x(node.target)
        feature = self.tables.features.get(node)
        if feature is None:
            label = self.tuple_label(node)
            if label is not None:
                return self.tuple_item(node, target, label)
            fail(f"unresolved call {node.name.text}", node.span)
        return self.call_feature(node, node.target, target, feature, node.arguments)

    def x_BracketExpression(self, node):
        feature = self.tables.features.get(node)
        if feature is None:
            fail("unresolved bracket", node.span)
        return self.call_feature(node, node.target, self.x(node.target), feature, node.arguments)

    def x_StaticCall(self, node):
        feature = self.tables.features.get(node)
        ty = self.type_of(node.type)
        if feature.kind == "constant":
            return P.attr(self.class_ref(ty.name), self.py_name(feature))
        holder = P.call("_S.static_target", [P.name("here"), self.class_ref(ty.name)])
        return self.call_feature(node, None, holder, feature, node.arguments, static_type=ty)

    def x_Precursor(self, node):
        feature = self.tables.features.get(node)
        if feature is None:
            fail("unresolved Precursor", node.span)
        owner = self.class_ref(feature.written_in)
        args = [self.argument(a) for a in node.arguments]
        if self.is_property(feature):
            return P.call(P.attr(P.attr(owner, self.py_name(feature)), "fget"), [P.name("self")])
        if feature.kind in ("attribute", "constant"):
            return P.attr(P.name("self"), self.py_name(feature))
        return P.call(P.attr(owner, self.py_name(feature)), [P.name("self")] + args)

    def tuple_label(self, node):
        ty = self.tables.types.get(node.target)
        if ty is not None and ty.name == "TUPLE" and node.name.key in ty.labels:
            return ty.labels.index(node.name.key)
        return None

    def tuple_item(self, node, target, index: int):
        if node in self.tables.separate_calls or (self.tables.types.get(node.target) or Ty("X")).separate:
            return P.call("here.query", [target, P.dotted("_S.tuple_item"), P.tup([P.const(index)])])
        return ast.Subscript(P.attr(target, "_items"), P.const(index), ast.Load())

    # --- the call itself ---------------------------------------------------------------------------
    def call_feature(self, node, target_node, target, feature, arguments, conversion=None, static_type=None):
        if feature.name in _OWN_ARGUMENT:
            args = [self.x(a) for a in arguments]  # `other` itself: see _OWN_ARGUMENT
        else:
            args = [self.argument(a) for a in arguments]
        if not args and feature.arguments and node in self.tables.agent_calls:
            args = [P.const(None)]  # `p.call` for `p.call ([])`: no open operands
        if conversion is not None:
            target = self.convert(target_node, target, conversion)
            target_ty = conversion[1]
        else:
            target_ty = static_type or (self.tables.types.get(target_node) if target_node is not None else None)
        args = self.boxed_arguments(arguments, args, feature, target_ty)
        if node in self.tables.separate_calls:
            return self.separate_call(node, target, feature, args)
        owner = (
            self.info.name
            if target_node is None
            else (target_ty.name if target_ty is not None and not target_ty.is_formal else None)
        )
        if self.is_builtin_basic(feature):
            from ..kernel import basic  # deferred: start-up (loaded on first use only)

            return basic.inline(feature.written_in, declared_name(feature), target, args)
        if target_node is not None and self.is_basic(target_ty) and feature.written_in not in BASIC:
            # ANY's features on a basic value (`i.twin`, `i.is_equal (j)`): the basic class's
            # own versions, by its static class (kernel/basic_dispatch.py)
            if self.is_property(feature) or feature.kind in ("attribute", "constant"):
                return P.call(
                    "_B.query_as", [P.const(target_ty.name), target, P.const(self.py_name(feature)), P.name("here")]
                )
            return P.call(
                "_B.call_as",
                [P.const(target_ty.name), target, P.const(self.py_name(feature)), P.tup(args), P.name("here")],
            )
        if (
            target_node is not None
            and target_ty is not None
            and self.may_hold_basic(target_ty)
            and not self.is_basic(target_ty)
        ):
            if self.is_property(feature) or feature.kind in ("attribute", "constant"):
                if target_ty.is_formal and feature.name in KIND_QUERIES:
                    return P.call(
                        "_S.formal_query",
                        [target, P.const(self.py_name(feature)), P.name("here"), self.type_desc(target_ty)],
                    )
                return P.call("_B.query", [target, P.const(self.py_name(feature)), P.name("here")])
            return P.call("_B.call", [target, P.const(self.py_name(feature)), P.tup(args), P.name("here")])
        if (
            target_node is not None
            and self.assertions == "all"
            and target_ty is not None
            and target_ty.name in self.program.invariant_classes
            and feature.kind not in ("attribute", "constant")
        ):
            return P.call("_S.call_checked", [target, P.const(self.py_name(feature, owner)), P.tup(args)])
        return self.plain_call(target, feature, args, owner)

    def plain_call(self, target, feature, args, owner=None):
        name = self.py_name(feature, owner)
        if self.is_property(feature) or (feature.kind in ("attribute", "constant") and not args):
            return P.attr(target, name)
        return P.call(P.attr(target, name), args)

    def is_property(self, feature) -> bool:
        return feature.is_query and not feature.arguments

    def is_builtin_basic(self, feature) -> bool:
        return feature.written_in in BASIC and is_external(feature, "built_in")

    def argument(self, node):
        return self.copied(node, self.x(node))

    # --- basic values reattached to reference types (scoopc/kernel/boxes.py) -----------------------
    def value_type(self, node):
        conversion = self.tables.conversions.get(node)
        return conversion[1] if conversion is not None else self.tables.types.get(node)

    def reattached(self, node, value, target_ty):
        """`value` (the code of `node`) attached to an entity of type `target_ty`: a basic value
        of a class other than INTEGER_32, REAL_64, BOOLEAN, CHARACTER_8 going to a reference
        type is boxed, so it keeps its class (`print (r)` with r: REAL_32 prints as a REAL_32)."""
        source = self.value_type(node)
        if source is None or target_ty is None or target_ty.is_formal or target_ty.name in BASIC:
            return value
        if not (source.name in BOXED or (source.is_formal and self.formal_may_be_basic(source))):
            return value
        info = self.universe.get(target_ty.name)
        if info is None or info.is_expanded:
            return value
        if source.is_formal:  # the actual generic says (at run time)
            return P.call("_S.box_formal", [value, self.type_desc(source)])
        return P.call("_S.box", [P.const(source.name), value])

    def boxed_arguments(self, arguments, args, feature, target_ty):
        if feature is None or not any(
            (t := self.value_type(a)) is not None and (t.name in BOXED or t.is_formal) for a in arguments
        ):
            return args
        signature = feature.signature
        if target_ty is not None and not target_ty.is_formal and self.universe.get(target_ty.name) is not None:
            signature = member_signature(self.universe, target_ty, feature)
        formals = signature.arguments if signature is not None else ()
        return [
            self.reattached(node, value, formals[i] if i < len(formals) else None)
            for i, (node, value) in enumerate(zip(arguments, args))
        ]

    # --- separate calls ---------------------------------------------------------------------------
    def separate_call(self, node, target, feature, args):
        """A call on a controlled separate target: the runtime entry point its static facts
        allow (scoop_calls.separate_call)."""

        return separate_call(self, node, target, feature, args)

    # --- conversions ----------------------------------------------------------------------------------
    def convert(self, node, value, conversion):
        converter, target_ty = conversion
        source_ty = self.tables.types.get(node)
        source = self.universe.get(source_ty.name) if source_ty is not None else None
        feature = source.features.get(converter) if source is not None else None
        if feature is not None and feature.is_query:
            if self.is_builtin_basic(feature):
                from ..kernel import basic  # deferred: start-up (loaded on first use only)

                return basic.inline(feature.written_in, declared_name(feature), value, [])
            return self.plain_call(value, feature, [])
        target_info = self.universe.get(target_ty.name)
        creator = target_info.features.get(converter) if target_info is not None else None
        if creator is None:
            fail(f"conversion {converter} not found", getattr(node, "span", None))
        return self.new_object(target_ty, creator, [value], separate=False, passive=False)

    # --- creation -------------------------------------------------------------------------------------
    def creation_value(self, node, ty: Ty, feature, arguments, passive: bool):
        args = self.boxed_arguments(arguments, [self.argument(a) for a in arguments], feature, ty)
        if ty.is_formal:
            if feature is None and getattr(node, "procedure", None) is not None:
                feature = self.constraint_creator(ty, node.procedure.key)
            name = self.py_name(feature) if feature is not None else "default_create"
            return P.call("_S.create_formal", [P.name("here"), self.type_desc(ty), P.const(name), P.tup(args)])
        return self.new_object(ty, feature, args, separate=ty.separate, passive=passive)

    def constraint_creator(self, ty: Ty, name: str):
        """`create x.make` on a formal generic: `make` of the constraint (its seed names it)."""
        constraints = self.info.constraints[ty.formal] if ty.formal < len(self.info.constraints) else ()
        for constraint in constraints:
            owner = self.universe.get(constraint.name)
            found = owner.features.get(name) if owner is not None else None
            if found is not None:
                return found
        return None

    def new_object(self, ty: Ty, feature, args, separate: bool, passive: bool):
        info = self.universe.get(ty.name)
        if self.is_tuple_class(info) and not (separate or passive):
            return self.new_tuple_object(ty)
        cls = self.class_ref(info.name)
        gen = self.generics_desc(ty) if info.formals else None
        creator = self.py_name(feature) if feature is not None else None
        if separate or passive:
            maker = "here.new_passive" if passive else "here.new_separate"
            routine = P.attr(cls, creator) if creator else P.const(None)
            extra = [gen] if gen is not None else []
            return P.call(maker, [cls, routine, P.tup(args)] + extra)
        invariant = self.assertions == "all" and self.program_has_invariant(info)
        return P.call(
            "_S.create",
            [P.name("here"), cls, gen if gen is not None else P.const(None), P.const(creator), P.tup(args)]
            + ([P.const(True)] if invariant else []),
        )

    def is_tuple_class(self, info) -> bool:
        return info is not None and info.name.split("@")[0] == "TUPLE" and info.from_library

    def new_tuple_object(self, ty: Ty):
        """`create t` of a TUPLE type: its items are the defaults of its item types."""
        return P.call("_S.new_default_tuple", [P.name("here"), self.generics_desc(ty)])

    def program_has_invariant(self, info) -> bool:
        """Is there an invariant to check after creating an `info` object? (The library runs
        with preconditions only: its invariants are not compiled.)"""
        return bool(getattr(info, "_has_invariant", False)) and not info.from_library

    # --- agents ------------------------------------------------------------------------------------
    def agent_application(self, node, agent, call_node):
        """`f (a, b)` on an agent: `f.call ([a, b])` / `f.item ([a, b])`."""
        feature = self.tables.features.get(call_node)
        items = [self.argument(a) for a in call_node.arguments]
        operands = P.call("_S.new_tuple", [P.name("here"), P.lst(items), P.tup([])])
        name = self.py_name(feature)
        if (self.agent_type_of(node) or Ty("X")).separate:
            helper = "_S.squery" if feature.is_query else "_S.scall"
            extra = [self.where(call_node)] if feature.is_query else []
            return P.call(helper, [P.name("here"), agent, P.const(name), P.tup([operands]), P.const(True)] + extra)
        return P.call(P.attr(agent, name), [operands])

    def agent_type_of(self, node):
        entity = self.tables.entities.get(node)
        return entity.ty if entity is not None else None

    def x_Agent(self, node):
        ty = self.type_of(node)
        feature = self.tables.features.get(node)
        if node.target is None:
            target, open_target = P.name("self"), False
        elif isinstance(node.target, syntax.ManifestType):
            target, open_target = P.const(None), True
        else:
            target, open_target = self.x(node.target), False
        slots, opened = [target], [0] if open_target else []
        if feature is None:  # a TUPLE label: the agent reads that item, its index a closed operand
            index = self.tables.agent_labels.get(node)
            if index is None:
                fail("agent on an unresolved feature", node.span)
            fn, slots = P.dotted("_S.tuple_item"), [target, P.const(index)]
        else:
            fn = P.call("_S.dispatcher", [P.const(self.py_name(feature)), P.const(self.is_property(feature))])
            slots.extend(self.agent_operands(node, feature, opened))
        return P.call(
            "_S.new_agent",
            [
                P.name("here"),
                self.class_ref(ty.name),
                self.generics_desc(ty),
                fn,
                P.lst(slots),
                P.tup([P.const(i) for i in opened]),
            ],
        )

    def agent_operands(self, node, feature, opened: list) -> list:
        """The slots of an agent's operands after its target; the open ones' places go into `opened`."""
        slots = []
        count = len(feature.arguments)
        operands = node.arguments if node.arguments is not None else [None] * count
        for index, operand in enumerate(operands, start=1):
            if operand is None or isinstance(operand, syntax.OpenOperand):
                slots.append(P.const(None))
                opened.append(index)
            else:
                slots.append(self.argument(operand))
        return slots

    def x_InlineAgent(self, node):
        ty = self.type_of(node)
        fn_name = self.inline_agent_function(node)
        count = len(node.arguments)
        slots = [P.name("self")]
        opened = []
        if node.actuals is None:
            slots += [P.const(None)] * count
            opened = list(range(1, count + 1))
        else:
            for index, operand in enumerate(node.actuals, start=1):
                if isinstance(operand, syntax.OpenOperand):
                    slots.append(P.const(None))
                    opened.append(index)
                else:
                    slots.append(self.argument(operand))
        return P.call(
            "_S.new_agent",
            [
                P.name("here"),
                self.class_ref(ty.name),
                self.generics_desc(ty),
                P.name(fn_name),
                P.lst(slots),
                P.tup([P.const(i) for i in opened]),
            ],
        )

    # --- run-time types ------------------------------------------------------------------------------
    def type_desc(self, ty: Ty, formals=None) -> ast.expr:
        """The run-time type: `formals(i)` gives the expression of formal generic i (default: the
        actual generic of Current seen from the class this code is written in)."""
        if ty.is_formal:
            if formals is not None:
                return formals(ty.formal)
            return P.call("_T.formal", [P.name("self"), P.const(self.info.name), P.const(ty.formal)])
        if ty.name == "<Current>":
            return P.call("_T.of", [P.name("self")])
        constant = ("type", str(ty), ty.attached)
        known = self.module.known_constant(constant) if formals is None else None
        if known is not None:  # made before: not looked through again (a TUPLE in a TUPLE, 2,000 deep)
            return known
        key = self.universe.canonical(ty.name) if self.universe.get(ty.name) is None else ty.name
        generics = [self.type_desc(g, formals) for g in ty.generics]
        call = P.call("_T.t", [P.const(key), P.tup(generics), P.const(bool(ty.attached))])
        if formals is not None or any(not _constant_desc(g) for g in generics):
            return call
        return self.module.constant("T", call, key=constant)

    def generics_desc(self, ty: Ty) -> ast.expr:
        formals = self.info.formals
        own = all(g.is_formal and g.formal == i for i, g in enumerate(ty.generics))
        if formals and len(ty.generics) == len(formals) and own:
            # Current's own actual generics, in order (LINKABLE [G] in LINKED_QUEUE [G]): shared,
            # not rebuilt per object; an heir's object has them computed (kernel.types)
            exact = P.compare(P.call("type", [P.name("self")]), ast.Is(), self.class_ref(self.info.name))
            own = P.call("_T.own_generics", [P.name("self"), P.const(self.info.name)])
            return ast.IfExp(exact, P.attr(P.name("self"), "_gen_"), own)
        return P.tup([self.type_desc(g) for g in ty.generics])

    def class_ref(self, key: str):
        return self.module.class_ref(key)


# ANY's duplication and comparison features work on `other` itself: an expanded actual argument
# is not copied to be passed (a redefined `copy` would otherwise run to pass the argument of
# `copy`, and `standard_copy`, `standard_is_equal` would see the fields a redefined copy made).
_OWN_ARGUMENT = frozenset({"copy", "standard_copy", "deep_copy", "is_equal", "standard_is_equal", "is_deep_equal"})


def _constant_desc(node) -> bool:
    return isinstance(node, ast.Name)


__all__ = ["Calls", "class_name", "is_external", "declared_name"]
