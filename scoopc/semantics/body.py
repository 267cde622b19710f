"""Checker, bodies pass: each routine, attribute body, contract and invariant of a class, typed
and checked by one walker assembled from the rule modules (expressions, calls, agents, creation,
instructions, contracts, onces, scoop). Also VEVI for attributes a creation procedure leaves unset.

Input: a flattened class with signatures. Output: diagnostics and the recorded tables.
"""

from __future__ import annotations

from contextlib import contextmanager

from .. import diagnostics, syntax
from . import contracts, initialization, onces, scoop
from .agents import AgentChecks
from .calls import CallChecks
from .conformance import manifest_fits
from .creation import CreationChecks
from .expressions import ExpressionChecks
from .features import member_signature
from .flow import UNREACHABLE, Facts
from .instructions import InstructionChecks
from .resolve import Scopes, clashes, declare_routine_entities
from .typeresolve import TypeResolver
from .types import RANGES
from .values import Value, manifest_kind, meet


class RoutineChecker(ExpressionChecks, CallChecks, AgentChecks, CreationChecks, InstructionChecks):
    def __init__(self, universe, info, tables, found: list, void_level: int):
        self.universe, self.info, self.tables, self.found = universe, info, tables, found
        self.void_level = void_level
        self.current = info.own_type()
        self.feature = None
        self.scopes = Scopes()
        self.facts = Facts()
        self.result_type = None
        self.result_context = "a procedure"
        self.in_postcondition = False
        self.in_precondition = False  # the routine's own precondition: VAPE
        self.in_agent = False  # inside an inline agent: not the feature's own body
        self.in_rescue = False
        self.object_tests: dict = {}
        self.reported_unset: set = set()
        self.assigned_in: dict = {}  # instructions.loop_parts: what each compound instruction assigns

    def report(self, code: str, span, **arguments) -> None:
        self.found.append(diagnostics.make(code, span, **arguments))

    def warn(self, code: str, span, **arguments) -> None:
        self.found.append(diagnostics.make(code, span, severity=diagnostics.WARNING, **arguments))

    # --- helpers the rule modules share -----------------------------------------------------
    def resolve_type(self, node):
        resolver = TypeResolver(self.universe, self.info, self.report, self._anchor)
        if isinstance(node, syntax.AnchoredType) and isinstance(node.anchor, syntax.Current):
            ty = self.current.with_marks(attached=node.attachment != "detachable", separate=node.separate)
        else:
            ty = resolver.resolve(node)
        if ty is not None:
            self.tables.types[node] = ty  # the type as written: codegen's run-time types
        return ty

    def resolve_quiet(self, node, info):
        return TypeResolver(self.universe, info, lambda *a, **k: None, constraints=False).resolve(node)

    def _anchor(self, name: str):
        entity = self.scopes.lookup(name)
        if entity is not None:
            return entity.ty
        feature = self.info.features.get(name)
        if feature is None or not feature.is_query:
            return None
        return member_signature(self.universe, self.current, feature).result

    def meets(self, node, value: Value, target):
        return meet(self.universe, node, value, target, self.info, self.tables)

    def clashes(self, name: str) -> bool:
        return clashes(self, name)

    def use_entity(self, node, name: str) -> None:
        if (
            self.void_level >= 2
            and self.facts is not UNREACHABLE
            and name in self.facts.unset
            and name not in self.reported_unset
        ):
            self.reported_unset.add(name)
            self.report(
                "VEVI",
                node.span,
                name="Result" if name == "result" else name,
                where="is used before it is given a value",
            )

    def branches(self, node):
        """What holds when a condition is true and when it is false: (entities, attached names)."""
        none = ((), frozenset())
        if isinstance(node, syntax.Parenthesized):
            return self.branches(node.expression)
        if isinstance(node, syntax.ObjectTest):
            entity = self.object_tests.get(node)
            names = _entity_name(node.expression)
            return ((entity,) if entity is not None else (), frozenset(names)), none
        if isinstance(node, syntax.UnaryExpression) and node.operator == "not":
            t, f = self.branches(node.operand)
            return f, t
        if isinstance(node, syntax.BinaryExpression):
            op = node.operator
            if op in ("=", "/="):
                names = _void_comparison(node)
                tested = ((), frozenset(names))
                return (tested, none) if op == "/=" else (none, tested)
            if op in ("and", "and then"):
                (t1, _), (t2, _) = self.branches(node.left), self.branches(node.right)
                return (t1[0] + t2[0], t1[1] | t2[1]), none
            if op in ("or", "or else"):
                (_, f1), (_, f2) = self.branches(node.left), self.branches(node.right)
                return none, (f1[0] + f2[0], f1[1] | f2[1])
        return none, none

    @contextmanager
    def assuming(self, branch):
        entities, attached = branch
        saved = self.facts
        self.scopes.push(entities)
        if self.facts is not UNREACHABLE:
            self.facts = self.facts.with_attached(attached)
        try:
            yield
        finally:
            self.scopes.pop()
            self.facts = saved

    # the state an inline agent's body replaces, and gives back when it is checked
    _NESTED_STATE = (
        "scopes",
        "facts",
        "result_type",
        "result_context",
        "in_rescue",
        "in_postcondition",
        "in_precondition",
        "in_agent",
        "reported_unset",
    )

    def enter_nested(self):
        saved = tuple(getattr(self, name) for name in self._NESTED_STATE)
        self.scopes, self.facts, self.in_rescue, self.in_postcondition = Scopes(), Facts(), False, False
        self.in_precondition, self.in_agent = False, True
        self.reported_unset = set()
        return saved

    def leave_nested(self, saved) -> None:
        for name, value in zip(self._NESTED_STATE, saved):
            setattr(self, name, value)

    # --- routines ---------------------------------------------------------------------------
    def check_feature(self, feature) -> None:
        self.feature = feature
        self.object_tests = {}
        signature = feature.signature
        if signature is None or not signature.complete or (feature.is_query and signature.result is None):
            return  # its type was reported: the body would only repeat it
        own = member_signature(self.universe, self.current, feature)
        decl = feature.decl
        self.scopes, self.facts, self.reported_unset = Scopes(), Facts(), set()
        self.result_type = own.result
        self.result_context = "a procedure" if not feature.is_query else "this feature"
        if isinstance(decl, syntax.Constant):
            self.check_constant(decl, own.result)
            return
        body = decl.body
        if body is None:
            return
        locals_ = body.locals
        declare_routine_entities(self, feature.arguments, locals_, own.arguments, self.resolve_type)
        onces.check_once(self, feature, own.result)
        self.check_routine_body(body, own.result)

    def check_constant(self, decl, ty) -> None:
        value = self.expr(decl.value, ty)
        if value is None or ty is None:
            return
        kind = manifest_kind(decl.value)
        integer = kind is not None and kind[0] == "integer" and ty.name in RANGES
        if integer and not manifest_fits("integer", kind[1], ty):
            # EiffelStudio: an integer constant outside its type's range is VQMC(3), not a VJAR
            low, high = RANGES[ty.name]
            self.report("VQMC(3)", decl.value.span, value=kind[1], type=str(ty), low=low, high=high)
            return
        self.expect(decl.value, value, ty, "VJAR")

    def check_routine_body(self, body, result) -> None:
        saved = (self.result_type, self.result_context)
        self.result_type, self.result_context = None, "a precondition (it is evaluated before the body)"
        contracts.check_precondition(self, body.precondition)
        self.result_type, self.result_context = saved
        inner = body.body
        if isinstance(inner, (syntax.InternalBody, syntax.AttributeBody)):
            self.facts = Facts(frozenset(), self._unset_at_start(body.locals, result))
            self.instructions(inner.instructions)
            if (
                self.facts is not UNREACHABLE
                and "result" in self.facts.unset
                and self.void_level >= 2
                and "result" not in self.reported_unset
            ):
                self.report(
                    "VEVI",
                    initialization.end_keyword(body.span),
                    name="Result",
                    where="is not given a value on every path to the end of the routine",
                )
        self.facts = Facts()
        contracts.check_postcondition(self, body.postcondition)
        if body.rescue is not None:
            self.in_rescue = True
            self.facts = Facts()
            self.instructions(body.rescue)
            self.in_rescue = False

    def _unset_at_start(self, locals_, result) -> frozenset:
        names = set()
        for decl in locals_:
            entity = self.scopes.lookup(decl.name.key)
            if entity is not None and entity.kind == "local" and self._needs_value(entity.ty):
                names.add(entity.name)
        if result is not None and self._needs_value(result):
            names.add("result")
        return frozenset(names)

    def _needs_value(self, ty) -> bool:
        return (
            ty is not None
            and ty.attached
            and not ty.is_formal
            and not scoop.is_expanded(self.universe, ty)
            and ty.name != "<Current>"
        )

    def check_invariant(self) -> None:
        self.feature = None
        self.scopes, self.facts = Scopes(), Facts()
        self.result_type = None
        contracts.check_invariant(self, self.info.decl.invariant)


def _entity_name(node):
    while isinstance(node, syntax.Parenthesized):
        node = node.expression
    if isinstance(node, syntax.UnqualifiedCall) and not node.arguments:
        return (node.name.key,)
    if isinstance(node, syntax.Result):
        return ("result",)
    return ()


def _void_comparison(node) -> tuple:
    if isinstance(node.right, syntax.Void):
        return _entity_name(node.left)
    if isinstance(node.left, syntax.Void):
        return _entity_name(node.right)
    return ()


def check_class(universe, info, tables, found, void_level: int) -> None:
    checker = RoutineChecker(universe, info, tables, found, void_level)
    for feature in info.features.values():
        if feature.written_in == info.name:
            checker.check_feature(feature)
    checker.check_invariant()
    initialization.check_creation_procedures(universe, info, found, void_level)
