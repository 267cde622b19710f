"""Checker, attribute initialization (VEVI) in creation procedures, by EiffelStudio's rule
(Src/Eiffel/eiffel/AST/visitor/ast_creation_procedure_checker.e).

Input: a checked class. Output: VEVI diagnostics. A creation procedure is walked from its first
instruction with the set of attributes still unset; every routine it calls unqualified is walked
in turn, at the call, with the same set (a read of an unset attribute there is reported in that
routine). `Current` may be used (named, or implicitly by an agent on it) before every attribute
is set, but from then on a qualified call is an error: it could reach the object through that
reference. It is reported at the first use of `Current`, naming the attributes still unset; the
end of the creation procedure counts as a use.
"""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass, replace

from .. import diagnostics, syntax
from ..source import Span
from . import scoop, walk
from .features import member_signature

EQUALITY = ("=", "/=", "~", "/~")


@dataclass(frozen=True)
class State:
    unset: frozenset  # attributes not yet set
    current_at: object = None  # where `Current` was first used while some were unset


class CreationWalk:
    """One creation procedure of `info` walked as EiffelStudio's checker walks it."""

    def __init__(self, universe, info, found: list, complete: bool, probes: dict):
        self.universe, self.info, self.found, self.complete, self.probes = universe, info, found, complete, probes
        self.by_seed = {seed: f for f in info.features.values() for seed in f.seeds()}
        self.state = State(frozenset(required_attributes(universe, info)))
        self.bodies: list = []  # routines being walked (no recursion)
        self.has_qualified_call = False
        self.written = info  # the class the walked code is written in
        self.names: frozenset = frozenset()  # arguments, locals and other local names of that code
        self.routine = None
        self.creator = None

    # --- the rule's events ----------------------------------------------------------------
    def report(self, span, names, where: str) -> None:
        self.found.append(diagnostics.make("VEVI", span, name="`, `".join(sorted(names)), where=where))

    def use_current(self, span) -> None:
        if self.state.current_at is None and self.state.unset:
            self.state = replace(self.state, current_at=span)

    def qualified_call(self) -> None:
        self.has_qualified_call = True
        if self.complete:
            self.check_attributes("where `Current` is used here, and a qualified call follows that could reach it")

    def check_attributes(self, where: str) -> None:
        state = self.state
        if state.current_at is not None and state.unset:
            verb = "is" if len(state.unset) == 1 else "are"
            self.report(state.current_at, state.unset, f"{verb} not set {where}")
            self.state = State(frozenset())

    def set_attribute(self, name: str) -> None:
        unset = self.state.unset - {name}
        self.state = State(unset, self.state.current_at if unset else None)

    def read_attribute(self, feature, span) -> None:
        if feature.decl.body is not None:
            self.self_initializing(feature)
        elif feature.name in self.state.unset:
            where = f"is read before the creation procedure `{self.creator.text}` sets it"
            if self.routine is not None and self.routine is not self.creator:
                where += f" (in `{self.routine.text}`, which it calls)"
            self.report(span, (feature.text,), where)
            self.set_attribute(feature.name)

    def self_initializing(self, feature) -> None:
        key = (feature.written_in, feature.name)
        if key in self.bodies or not isinstance(feature.decl.body.body, syntax.AttributeBody):
            return
        with self.inside(feature):
            saved = self.state
            self.instructions(feature.decl.body.body.instructions)
            self.state = State(saved.unset & self.state.unset, self.state.current_at or saved.current_at)

    # --- routines --------------------------------------------------------------------------
    def run(self, creator, end_span) -> None:
        self.creator = creator
        self.process(creator)
        self.use_current(end_span)
        self.check_attributes(f"by the creation procedure `{creator.text}`")

    def process(self, feature) -> None:
        if self.has_qualified_call and not self.state.unset:
            return  # nothing left to find (EiffelStudio stops here too)
        key = (feature.written_in, feature.name)
        owner = self.universe.get(feature.written_in)
        if key in self.bodies or not feature.is_routine or owner is None:
            return
        if owner.from_library:
            # Our library's text is not EiffelBase's: its routines are trusted to set their own
            # class's attributes and to read none unset, and taken to make qualified calls, as
            # EiffelBase's routines nearly all do (`io.put_string`, `count + 1`).
            self.state = replace(self.state, unset=self.state.unset - self.attributes_of(owner))
            self.qualified_call()
            return
        body = feature.decl.body
        with self.inside(feature):
            self.assertions(feature, "precondition")
            inner = body.body
            if isinstance(inner, syntax.InternalBody):
                start = self.state
                self.instructions(inner.instructions)
                if inner.once and "OBJECT" not in (k.upper() for k in inner.once_keys):
                    # the body runs once: what it sets is set only the first time
                    self.state = State(start.unset, self.state.current_at)
                if body.rescue is not None:
                    after = self.state
                    self.state = start
                    self.instructions(body.rescue)
                    self.state = _join(after, self.state)
            self.assertions(feature, "postcondition")

    def assertions(self, feature, which: str) -> None:
        versions = [feature]
        while versions:
            version = versions.pop()
            versions.extend(p for _, p in version.precursors)
            body = version.body
            part = getattr(body, which, None) if body is not None else None
            owner = self.universe.get(version.written_in)
            if part is None or owner is None or owner.from_library:
                continue
            with self.inside(version):
                for clause in part.clauses:
                    if clause.expression is not None:
                        self.expr(clause.expression)

    @contextmanager
    def inside(self, feature):
        saved = (self.written, self.names, self.routine)
        self.written = self.universe.get(feature.written_in) or self.info
        self.names = _local_names(feature, self.written.features)
        self.routine = feature
        self.bodies.append((feature.written_in, feature.name))
        try:
            yield
        finally:
            self.bodies.pop()
            self.written, self.names, self.routine = saved

    def attributes_of(self, owner) -> frozenset:
        """The attributes of `owner`, by their names in the class checked."""
        mine = (self.by_seed.get(f.seed) for f in owner.features.values() if f.kind == "attribute")
        return frozenset(f.name for f in mine if f is not None)

    def feature_named(self, name: str):
        if name in self.names:
            return None
        found = self.written.features.get(name)
        if found is None or self.written is self.info:
            return found
        return self.by_seed.get(found.seed, found)

    # --- instructions ----------------------------------------------------------------------
    def instructions(self, nodes) -> None:
        for node in nodes or ():
            self.instruction(node)

    def instruction(self, node) -> None:
        if isinstance(node, (syntax.Assignment, syntax.AssignmentAttempt)):
            self.expr(node.source)
            self.attach(node.target)
        elif isinstance(node, syntax.AssignerCall):
            self.expr(node.source)
            self.expr(node.target)
        elif isinstance(node, syntax.CreationInstruction):
            self.creation(node, node.target)
            self.attach(node.target)
        elif isinstance(node, syntax.Conditional):
            self.conditional(node)
        elif isinstance(node, syntax.MultiBranch):
            self.expr(node.expression)
            self.branches([w.then_part for w in node.when_parts], node.else_part, self.instructions)
        elif isinstance(node, (syntax.Loop, syntax.Across)):
            self.loop(node)
        elif isinstance(node, syntax.Debug):
            saved = self.state
            self.instructions(node.body)
            self.state = saved
        elif isinstance(node, syntax.Check):
            self.check(node)
        elif isinstance(node, syntax.SeparateInstruction):
            for argument in node.arguments:
                self.expr(argument.expression)
            self.instructions(node.body)
        elif isinstance(node, syntax.Retry):
            self.state = State(frozenset())  # what follows is never reached
        elif isinstance(node, syntax.CallInstruction):
            self.expr(node.call)
        else:
            for child in walk.children(node):
                self.expr(child)

    def attach(self, target) -> None:
        if isinstance(target, syntax.UnqualifiedCall) and not target.arguments:
            feature = self.feature_named(target.name.key)
            if feature is not None and feature.kind == "attribute":
                self.set_attribute(feature.name)

    def conditional(self, node) -> None:
        self.expr(node.condition)
        start, ends = self.state, []
        parts = [(None, node.then_part)] + [(p.condition, p.then_part) for p in node.elseif_parts]
        for condition, body in parts:
            if condition is not None:
                self.expr(condition)
            branch_start = self.state
            self.instructions(body)
            ends.append(self.state)
            self.state = branch_start
        self.instructions(node.else_part)
        ends.append(self.state)
        self.state = _join_all(ends, start)

    def branches(self, parts, else_part, walk_part) -> None:
        start, ends = self.state, []
        for part in parts:
            self.state = start
            walk_part(part)
            ends.append(self.state)
        if else_part is not None:
            self.state = start
            walk_part(else_part)
            ends.append(self.state)
        self.state = _join_all(ends, start)

    def loop(self, node) -> None:
        if isinstance(node, syntax.Across):
            self.expr(node.iteration.expression)
            self.qualified_call()  # new_cursor, after, forth
        self.instructions(node.initialization)
        for clause in node.invariant:
            if clause.expression is not None:
                self.expr(clause.expression)
        if node.until is not None:
            self.expr(node.until)
        before = self.state
        self.instructions(node.body)
        self.state = _join(before, self.state)  # the body may not run at all
        if node.variant is not None:
            self.expr(node.variant.expression)
        until = node.until
        if isinstance(node, syntax.Loop) and isinstance(until, syntax.ManifestBoolean) and not until.value:
            self.state = State(frozenset())  # never ends: what follows is never reached

    def check(self, node) -> None:
        for clause in node.assertions:
            if clause.expression is not None:
                self.expr(clause.expression)
        if any(isinstance(c.expression, syntax.ManifestBoolean) and not c.expression.value for c in node.assertions):
            self.state = State(frozenset())  # the check always fails
        self.instructions(node.then_part)

    # --- expressions ----------------------------------------------------------------------
    def expr(self, node) -> None:
        if node is None:
            return
        if isinstance(node, syntax.UnqualifiedCall):
            self.unqualified(node)
        elif isinstance(node, syntax.QualifiedCall):
            self.expr(node.target)
            self.each(node.arguments)
            self.qualified_call()
        elif isinstance(node, syntax.Current):
            self.use_current(node.span)
        elif isinstance(node, syntax.Agent):
            self.agent(node)
        elif isinstance(node, syntax.InlineAgent):
            self.each(node.actuals or ())
            if self.complete:
                self.use_current(node.span)
        elif isinstance(node, syntax.BinaryExpression):
            self.expr(node.left)
            self.expr(node.right)
            if node.operator not in EQUALITY:
                self.qualified_call()
        elif isinstance(node, syntax.UnaryExpression):
            self.expr(node.operand)
            self.qualified_call()
        elif isinstance(node, syntax.Old):
            self.expr(node.expression)
        elif isinstance(node, syntax.CreationExpression):
            self.creation(node, None)
        elif isinstance(node, syntax.Precursor):
            self.each(node.arguments)
            for _, version in self.routine.precursors if self.routine is not None else ():
                if not version.deferred:
                    self.process(version)
        elif isinstance(node, syntax.ConditionalExpression):
            self.expr(node.condition)
            parts = [node.then_part] + [p for p in node.elseif_parts]
            self.branches(parts, node.else_part, self._expression_part)
        elif isinstance(node, syntax.InspectExpression):
            self.expr(node.expression)
            self.branches([w.then_part for w in node.when_parts], node.else_part, self.expr)
        elif isinstance(node, syntax.AcrossExpression):
            self.expr(node.iteration.expression)
            self.qualified_call()
            saved = self.state
            for child in walk.children(node):
                if child is not node.iteration:
                    self.expr(child)
            self.state = _join(saved, self.state)
        else:
            for child in walk.children(node):
                self.expr(child)

    def _expression_part(self, node) -> None:
        if isinstance(node, syntax.ElseifExpression):
            self.expr(node.condition)
            self.expr(node.then_part)
        else:
            self.expr(node)

    def each(self, nodes) -> None:
        for node in nodes:
            self.expr(node)

    def unqualified(self, node) -> None:
        self.each(node.arguments)
        feature = self.feature_named(node.name.key)
        if feature is None:
            return
        if feature.kind == "attribute":
            self.read_attribute(feature, node.name.span)
        elif feature.is_routine:
            self.process(feature)
            if feature.is_once and feature.is_query and not _is_basic(self.universe, feature):
                self.qualified_call()  # its result may be an object that reaches `Current`

    def agent(self, node) -> None:
        if node.target is not None:
            self.expr(node.target)
        self.each(node.arguments or ())
        if node.target is None and self.complete:
            self.use_current(node.name.span)

    def creation(self, node, target) -> None:
        """A creation call: its arguments, then (EiffelStudio's `record_creation`) if `Current`
        is out while attributes are unset and the creation procedure takes references, it must
        not make a qualified call (directly or through creations it makes in turn)."""
        self.each(node.arguments)
        if node.procedure is None or self.state.current_at is None or not self.state.unset:
            return
        created = _created_class(self, node, target)
        procedure = created.features.get(node.procedure.key) if created is not None else None
        if procedure is None or not _takes_references(self.universe, procedure):
            return
        if qualified_call_in(self.universe, created, procedure, self.probes):
            self.check_attributes(
                f"where `Current` is used here, and is passed to {created.name}.{procedure.text}, "
                "which makes qualified calls"
            )


def qualified_call_in(universe, info, procedure, probes: dict) -> bool:
    """Does creating `info` with `procedure` make a qualified call (EiffelStudio's
    `has_qualified_call` of the creation procedure and of the creations it makes in turn)?"""
    key = (info.name, procedure.name)
    known = probes.get(key)
    if known is not None:
        return known
    if info.from_library or universe.get(procedure.written_in) is None:
        probes[key] = False
        return False
    probes[key] = False  # a cycle of creations adds nothing
    probe = CreationWalk(universe, info, [], False, probes)  # records the calls, reports nothing
    probe.creator = procedure
    probe.process(procedure)
    probes[key] = probe.has_qualified_call
    return probe.has_qualified_call


def _created_class(walker, node, target):
    universe = walker.universe
    if getattr(node, "type", None) is not None and isinstance(node.type, syntax.ClassType):
        return universe.get(universe.canonical(node.type.name.text))
    if isinstance(target, syntax.UnqualifiedCall):
        feature = walker.feature_named(target.name.key)
        result = feature.signature.result if feature is not None and feature.signature is not None else None
        if result is not None and not result.is_formal:
            return universe.get(result.name)
    return None


def _takes_references(universe, procedure) -> bool:
    signature = procedure.signature
    return signature is not None and any(
        a is not None and not scoop.is_expanded(universe, a) for a in signature.arguments
    )


def _is_basic(universe, feature) -> bool:
    result = feature.signature.result if feature.signature is not None else None
    return result is not None and scoop.is_expanded(universe, result)


def _join(a: State, b: State) -> State:
    return State(a.unset | b.unset, a.current_at or b.current_at)


def _join_all(states, start: State) -> State:
    if not states:
        return start
    result = states[0]
    for state in states[1:]:
        result = _join(result, state)
    return result


def _local_names(feature, features) -> frozenset:
    names = {a.name.key for a in feature.arguments}
    body = feature.decl.body
    if isinstance(feature.decl, (syntax.Routine, syntax.Attribute)) and body is not None:
        names.update(d.name.key for d in body.locals)
        for node in _nodes(body):
            local = getattr(node, "local", None) if isinstance(node, syntax.ObjectTest) else None
            if isinstance(node, (syntax.Iteration, syntax.SeparateArgument)):
                local = node.name
            if local is not None and local.key not in features:
                names.add(local.key)  # one named like a feature is an error reported elsewhere
    return frozenset(names)


def _nodes(node):
    yield node
    for child in walk.children(node):
        yield from _nodes(child)


def required_attributes(universe, info) -> set:
    """Attributes EiffelStudio requires to be set (`is_initialization_required`): of an attached
    type that is not expanded, or of a formal generic type marked neither `detachable` nor
    `expanded`, without an `attribute` body."""
    names = set()
    for feature in info.features.values():
        if feature.kind != "attribute" or feature.decl.body is not None:
            continue
        if feature.signature is None:
            continue
        result = member_signature(universe, info.own_type(), feature).result  # G of a parent: its actual here
        if result is not None and _requires_value(universe, info, result):
            names.add(feature.name)
    return names


def _requires_value(universe, info, ty) -> bool:
    if not ty.attached:
        return False
    if ty.is_formal:
        generics = info.decl.formal_generics
        return ty.formal >= len(generics) or generics[ty.formal].mark != "expanded"
    return not scoop.is_expanded(universe, ty)


def end_keyword(span) -> Span:
    """The closing `end` of a construct whose span ends with it."""
    return Span(span.file, span.end_line, max(1, span.end_column - 3), span.end_line, span.end_column)


def check_creation_procedures(universe, info, found: list, void_level: int) -> None:
    """VEVI for each creation procedure of a class of the program (not deferred, not expanded)."""
    if info.is_deferred or info.is_expanded or info.from_library or void_level < 2:
        return
    creators = info.creators if info.creators is not None else {"default_create": None}
    probes: dict = {}
    for name in creators:
        feature = info.features.get(name)
        if feature is None or not feature.is_routine:
            continue
        walker = CreationWalk(universe, info, found, void_level >= 3, probes)
        walker.run(feature, _end_span(info, feature, name))


def _end_span(info, feature, name: str):
    """Where a creation procedure's end is reported: its own `end`, or for one inherited, its
    name in the creation clause (EiffelStudio points into the parent's text)."""
    if feature.written_in == info.name:
        return end_keyword(feature.decl.body.span)
    for clause in info.decl.creation_clauses:
        for ident in clause.procedures:
            if ident.key == name:
                return ident.span
    return info.decl.name.span
