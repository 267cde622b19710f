"""Codegen, routines: one Eiffel routine (or inline agent) -> Python function(s): locals and
Result, contracts with `old`, rescue/retry, once, and the reservation of separate arguments with
its wait conditions (a clause table, docs/RUNTIME.md section 2)."""

from __future__ import annotations

import ast

from .. import syntax
from ..kernel.types import _BASIC_DEFAULTS
from ..semantics import scoop as scoop_rules
from ..semantics.conformance import base_type
from . import pyast as P
from .assertions import InheritedAssertions
from .calls import Calls
from .exprs import Expressions
from .instrs import Instructions
from .names import ONCE_CELL, eiffel_class_name, py_identifier
from .scoop_calls import reserved

LOCAL_RESERVED = frozenset(
    {
        "s",
        "b",
        "k",
        "t",
        "ks",
        "rt",
        "here",
        "self",
        "all",
        "any",
        "object",
        "result",
        "len",
        "range",
        "isinstance",
        "type",
    }
)


def local_identifier(name: str) -> str:
    name = py_identifier(name)
    return name + "_" if name in LOCAL_RESERVED else name


class RoutineGen(InheritedAssertions, Expressions, Calls, Instructions):
    def __init__(self, program, module, info, feature, routine_name: str):
        self.program = program
        self.universe = program.universe
        self.tables = program.tables
        self.naming = program.naming
        self.module = module
        self.info = info
        self.feature = feature
        self.routine_name = routine_name
        self.assertions = program.assertions_for(info)
        self.olds: dict = {}
        self.temps = 0
        self.result_type = feature.signature.result if feature is not None and feature.signature else None
        # a once routine's body keeps `Result` in its once cell (the runtime's `Running`, its
        # last parameter `_once_`), so a call during its first execution returns it so far
        self.once_cell = feature is not None and feature.is_once

    def result_ref(self) -> ast.expr:
        """Where `Result` lives: a local, or the once cell's `result`."""
        return P.attr(P.name(ONCE_CELL), "result") if self.once_cell else P.name("Result")

    # --- names ------------------------------------------------------------------------------------
    def py_name(self, feature, owner=None) -> str:
        """The Python name of `feature` called on a target whose static class is `owner`."""
        return self.naming.name_in(owner, feature) if owner is not None else self.naming.primary(feature)

    def local_name(self, name: str) -> str:
        return local_identifier(self.renames.get(name, name))

    def temp(self, prefix: str) -> str:
        self.temps += 1
        return f"_{prefix}{self.temps}"

    def where(self, node) -> ast.expr:
        span = node.span
        value = P.tup(
            [
                P.const(eiffel_class_name(self.info.name)),
                P.const(self.routine_name),
                P.const(self.program.shown_path(span.file)),
                P.const(span.line),
            ]
        )
        return self.module.constant("W", value, key=("where", self.routine_name, span.file, span.line))

    # --- values of types ------------------------------------------------------------------------
    def default_value(self, ty) -> ast.expr:
        if ty is None:
            return P.const(None)
        if ty.is_formal:
            return P.call(P.attr(self.type_desc(ty), "default"), [P.name("here")])

        if ty.name in _BASIC_DEFAULTS:
            return P.const(_BASIC_DEFAULTS[ty.name])
        info = self.universe.get(ty.name)
        if info is not None and info.is_expanded:
            return P.call(P.attr(self.type_desc(ty), "default"), [P.name("here")])
        return P.const(None)

    # --- a routine ----------------------------------------------------------------------------------
    def routine_body(self, body: syntax.RoutineBody, arguments: list, result_type) -> list:
        """The statements of a routine: entry, contracts, reservation, body, exit."""
        out = [P.assign(P.name("here"), P.attr(P.name("self"), "_region_"))]
        for decl in body.locals:
            ty = self.tables.types.get(decl.type)
            out.append(P.at(P.assign(P.name(self.local_name(decl.name.key)), self.default_value(ty)), decl.span))
        if result_type is not None and (self.once_cell or not _sets_result_first(body)):
            out.append(P.assign(self.result_ref(), self.default_value(result_type)))
        separate = self.separate_arguments(arguments)
        pre = body.precondition.clauses if body.precondition is not None else ()
        main = self.olds_at_entry(body) + self.main_body(body)
        main += self.postcondition(body)
        if separate:
            out += self.reserved(
                [P.name(self.local_name(n)) for n, _ in separate],
                pre,
                main,
                self.where(body),
                [n for n, _ in separate],
                arguments,
            )
        else:
            out += self.precondition(pre) + main
        if result_type is not None:
            out.append(ast.Return(self.result_ref()))
        return out

    def separate_arguments(self, arguments) -> list:
        """The arguments the routine reserves: those of a separate type, a formal generic with
        a separate constraint included (`w: G` with `G -> separate T`: the checker takes calls
        on `w` as separate calls, so `w` is reserved as EiffelStudio reserves it)."""
        found = []
        for name, ty in arguments:
            if ty is not None and ty.is_formal:
                ty = base_type(self.universe, ty, self.universe.get(self.info.name))
            if ty is not None and ty.separate and not scoop_rules.is_expanded(self.universe, ty):
                found.append((name, ty))
        return found

    def main_body(self, body) -> list:
        inner = body.body
        instructions = (
            self.block(inner.instructions) if isinstance(inner, (syntax.InternalBody, syntax.AttributeBody)) else []
        )
        if body.rescue is None:
            return instructions
        caught = self.temp("exception")
        rescue = [P.expr_stmt(P.call("_S.caught", [P.name("here"), P.name(caught)]))]
        rescue += self.block(body.rescue) + [ast.Raise(None, None)]
        handler = ast.ExceptHandler(P.dotted("Exception"), caught, rescue)
        attempt = ast.Try(instructions + [ast.Break()], [handler], [], [])
        return [ast.While(P.const(True), [attempt], [])]

    # --- contracts ----------------------------------------------------------------------------------
    def precondition(self, clauses) -> list:
        if self.assertions == "none":
            return []
        return self.full_precondition(clauses)

    def postcondition_groups(self, body) -> list:
        """[(context, clauses)]: inherited postconditions (ensure then), then this routine's."""
        if self.assertions != "all":
            return []
        groups = self.inherited_postconditions()
        if body.postcondition is not None:
            groups.append((None, [c for c in body.postcondition.clauses if c.expression is not None]))
        return groups

    def postcondition(self, body) -> list:
        out = []
        for context, clauses in self.postcondition_groups(body):
            out += self.in_context(context, lambda cs=clauses: [self.assertion(c, "postcondition") for c in cs])
        return out

    def olds_at_entry(self, body) -> list:
        out = []
        for context, clauses in self.postcondition_groups(body):
            out += self.in_context(context, lambda cs=clauses: self.olds_of(cs))
        return out

    def olds_of(self, clauses) -> list:
        out = []
        for clause in clauses:
            for node in _walk(clause.expression):
                if isinstance(node, syntax.Old) and node not in self.olds:
                    name = self.temp("old")
                    self.olds[node] = name
                    out.append(
                        P.at(
                            P.assign(P.name(name), P.call("_S.old", [P.lambda_([], self.x(node.expression))])),
                            node.span,
                        )
                    )
        return out

    # --- reservations --------------------------------------------------------------------------------
    def reserved(self, objs, clauses, body, where, formal_names=None, arguments=None) -> list:
        """`with here.reserve(...)` around body, the precondition as a clause table."""

        table, pre_args = self.clause_table(clauses or (), formal_names or [], arguments or [])
        return reserved(self, objs, table, pre_args, body, where, formal_names)

    def clause_table(self, clauses, formal_names, arguments):
        kept = []
        for clause in clauses:
            if clause.expression is None:
                continue
            waits = self.tables.wait_args.get(clause, ())
            if self.assertions == "none" and not waits:
                continue
            kept.append((clause, tuple(formal_names.index(w) for w in waits if w in formal_names)))
        if not kept:
            return None, None
        params = ["here", "self"] + [self.local_name(n) for n, _ in arguments]
        entries = []
        for clause, targets in kept:
            tag = clause.tag.text if clause.tag is not None else None
            pred = P.lambda_(params, self.x(clause.expression))
            entries.append(P.tup([pred, P.tup([P.const(i) for i in targets]), P.const(tag), self.where(clause)]))
        table = self.module.constant("PRE", P.tup(entries))
        return table, P.tup([P.name(p) for p in params])

    # --- inline agents --------------------------------------------------------------------------------
    def inline_agent_function(self, node) -> str:
        self.module.counter += 1
        fname = f"_agent_{self.module.counter}"
        sub = RoutineGen(self.program, self.module, self.info, None, self.routine_name)
        sub.result_type = self.tables.types.get(node.type) if node.type is not None else None
        arguments = [(a.name.key, self.tables.types.get(a.type)) for a in node.arguments]
        body = sub.routine_body(node.body, arguments, sub.result_type)
        params = ["self"] + [sub.local_name(n) for n, _ in arguments]
        self.module.functions.append(P.at(P.function(fname, params, body), node.span))
        return fname


def _sets_result_first(body) -> bool:
    """Does the body start with `Result := e`, e not using Result (so no default is needed)?
    Also inside a leading `check ... then`, whose failure raises before Result can be seen.
    Not with a rescue clause (a retry may read Result)."""
    inner = body.body
    if body.rescue is not None or not isinstance(inner, syntax.InternalBody):
        return False
    return _starts_with_result(inner.instructions)


def _starts_with_result(instructions) -> bool:
    if not instructions:
        return False
    first = instructions[0]
    if isinstance(first, syntax.Check) and first.then_part is not None:
        return not _uses_result(first.assertions) and _starts_with_result(first.then_part)
    if not isinstance(first, syntax.Assignment) or not isinstance(first.target, syntax.Result):
        return False
    return not _uses_result((first.source,))


def _uses_result(nodes) -> bool:
    return any(isinstance(node, syntax.Result) for top in nodes for node in _walk(top))


def _walk(node):
    if node is None:
        return
    yield node
    from ..semantics import walk  # deferred: start-up (scoopc.semantics.walk loads only when this is used)

    for child in walk.children(node):
        yield from _walk(child)
