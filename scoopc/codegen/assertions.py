"""Codegen, assertions of redeclared routines (ECMA-367 8.10, "assertion redeclaration"): the
precondition of a redeclaration is its `require else' clauses `or else' the precondition of each
version it redeclares; its postcondition is its `ensure then' clauses `and then' theirs. An
inherited clause is compiled in the context of the class that wrote it (its arguments renamed
to ours). Versions written in the library are not compiled with the program (their bodies are
not checked then): their assertions are left out of a program class's redeclarations.
"""

from __future__ import annotations

import ast
from contextlib import contextmanager

from .. import syntax
from . import pyast as P

TRUE = None  # a precondition group list standing for `True` (some version has none)


class InheritedAssertions:
    renames: dict = {}

    def local_name(self, name: str) -> str:
        from .routines import local_identifier  # deferred: a cycle (scoopc.codegen.routines imports this module)

        return local_identifier(self.renames.get(name, name))

    @contextmanager
    def written_in(self, info, renames: dict):
        """Compile expressions as the class `info` wrote them (an inherited assertion)."""
        saved = self.info, self.renames
        self.info, self.renames = info, renames
        try:
            yield
        finally:
            self.info, self.renames = saved

    # --- the versions ----------------------------------------------------------------------------
    def _version(self, version):
        """(class info, routine body, renames) of a redeclared version, None if not compilable."""
        info = self.universe.get(version.written_in)
        body = getattr(version.decl, "body", None)
        if (
            info is None
            or (info.from_library and not getattr(self, "library_versions", False))
            or not isinstance(body, syntax.RoutineBody)
        ):
            return None
        own = [a.name.key for a in self.feature.decl.arguments]
        theirs = [a.name.key for a in getattr(version.decl, "arguments", ())]
        return info, body, dict(zip(theirs, own))

    def _precursors(self, feature):
        seen = set()
        for _, version in feature.precursors:
            if id(version.decl) not in seen and version.decl is not self.feature.decl:
                seen.add(id(version.decl))
                yield version

    def precondition_groups(self, feature, own_clauses, context):
        """The precondition as `or else` of `and then` groups [(context, clauses)], TRUE when
        some version has no precondition."""
        groups = [(context, own_clauses)] if own_clauses else []
        precursors = list(self._precursors(feature))
        if not precursors:
            return groups or TRUE
        for version in precursors:
            found = self._version(version)
            if found is None:
                continue
            info, body, renames = found
            clauses = (
                [c for c in body.precondition.clauses if c.expression is not None]
                if body.precondition is not None
                else []
            )
            inner = self.precondition_groups(version, clauses, (info, renames))
            if inner is TRUE:
                return TRUE
            groups += inner
        return groups or TRUE

    def inherited_postconditions(self) -> list:
        """[(context, clauses)] of every version this feature redeclares, transitively."""
        if self.feature is None or self.assertions != "all":
            return []
        found, seen, todo = [], {id(self.feature.decl)}, list(self._precursors(self.feature))
        while todo:
            version = todo.pop(0)
            if id(version.decl) in seen:
                continue
            seen.add(id(version.decl))
            todo += [v for _, v in version.precursors]
            compiled = self._version(version)
            if compiled is None or compiled[1].postcondition is None:
                continue
            info, body, renames = compiled
            clauses = [c for c in body.postcondition.clauses if c.expression is not None]
            if clauses:
                found.append(((info, renames), clauses))
        return found

    # --- code ----------------------------------------------------------------------------------------
    def full_precondition(self, clauses) -> list:
        """The checks of a routine's precondition, inherited versions included."""
        own = [c for c in clauses if c.expression is not None]
        if self.feature is None or not self.feature.precursors:
            return [self.assertion(c, "precondition") for c in own]
        groups = self.precondition_groups(self.feature, own, None)
        if groups is TRUE:
            return []
        if len(groups) == 1:
            context, group = groups[0]
            return self.in_context(context, lambda: [self.assertion(c, "precondition") for c in group])
        tests = [
            self.in_context(
                context,
                lambda g=group: (
                    P.boolop(ast.And(), [self.x(c.expression) for c in g]) if len(g) > 1 else self.x(g[0].expression)
                ),
            )
            for context, group in groups
        ]
        context, group = groups[0]
        report = self.in_context(context, lambda: [self.assertion(c, "precondition") for c in group])
        tag = group[0].tag.text if group[0].tag is not None else None
        report.append(
            P.expr_stmt(
                P.call(
                    "_S.assertion_failed",
                    [P.const("precondition"), P.const(tag), self.in_context(context, lambda: self.where(group[0]))],
                )
            )
        )
        return [P.if_(P.not_(P.boolop(ast.Or(), tests)), report)]

    def in_context(self, context, make):
        if context is None:
            return make()
        with self.written_in(*context):
            return make()
