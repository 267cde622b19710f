"""Codegen, SCOOP fast paths: the facts the runtime's fast entry points need, proved over the
whole program (closed world), and the choice of entry point for each separate call and
reservation (docs/RUNTIME.md sections 2-3, "Choosing an entry point").

Facts, per routine version (a declaration, identified by its class and first name):
- leaf (`@_rt.leaf`): no loop (nor `across`, nor `retry`), no separate call, no reservation
  (separate argument or separate block), no creation of a processor, no `once`, no external
  call except short host operations that never block (SAFE_EXTERNALS), no agent call, and
  every routine it may call is a leaf: for a call on a target of static class C, every
  version of the feature in C and in every class that inherits from C (the closed world).
  Recursion is not a leaf (least fixpoint). A program with an expanded class of its own has
  no leaves (default values would run its creation procedures unseen); a library's expanded class
  whose default value runs no code (UTF_CONVERTER) does not count.
- single implementation: the universe has one version of a feature for a static class and
  all its descendants, so a separate call can name the Python function (`C.f`) at compile
  time instead of looking it up on the target at run time.

The standard library is compiled once, in a universe of its own, before any program exists:
its routines are never decorated as leaves (an heir in a program could break the promise).
Their local facts (verdict on the body alone, and what it calls) are saved beside the
compiled library (FACTS_FILE) and joined with the program's classes when a program is
compiled, so a program's routine that calls a short library routine can still be a leaf.
"""

from __future__ import annotations

import json
from pathlib import Path

from .. import syntax
from ..semantics.types import BASIC
from ..semantics.walk import children

FACTS_FILE = "_scoop_facts.json"
FACTS_FORMAT = 1

# Classes whose external features are short host operations that never block nor call back
# into Eiffel code (the basic types' built-ins are inlined).
SAFE_EXTERNAL_CLASSES = frozenset(
    {
        "SPECIAL",
        "TUPLE",
        "TYPE",
        "STRING_8",
        "STRING_32",
        "IMMUTABLE_STRING_8",
        "IMMUTABLE_STRING_32",
        "READABLE_STRING_8",
        "READABLE_STRING_32",
        "READABLE_STRING_GENERAL",
        "STRING_GENERAL",
        "IMMUTABLE_STRING_GENERAL",
        "DOUBLE_MATH",
        "SINGLE_MATH",
        "PLATFORM",
    }
) | frozenset(BASIC)
# Single external features of other classes that are as short: a read of the runtime's clock,
# ARRAY's accessors.
SAFE_EXTERNAL_FEATURES = frozenset({("TIMER", "now"), ("ARRAY", "item"), ("ARRAY", "put")})
# External features that call an Eiffel feature of Current (its versions are their callees).
CALLING_EXTERNALS = {("ARRAY", "item"): "valid_index", ("ARRAY", "put"): "valid_index"}
SAFE_ANY_EXTERNALS = frozenset(
    {
        "generator",
        "generating_type",
        "conforms_to",
        "same_type",
        "standard_is_equal",
        "is_equal",
        "standard_copy",
        "copy",
        "standard_twin",
        "tagged_out",
    }
)
# Nodes that make a routine a non-leaf wherever they occur.
NEVER = frozenset({"Loop", "Across", "AcrossExpression", "Retry", "SeparateInstruction", "ManifestArray", "Unique"})
# Nodes with no call of their own: only their children matter.
PLAIN = frozenset(
    {
        "Assignment",
        "AssignmentAttempt",
        "CallInstruction",
        "Conditional",
        "ElseifPart",
        "MultiBranch",
        "WhenPart",
        "Choice",
        "Check",
        "Parenthesized",
        "Old",
        "ManifestInteger",
        "ManifestReal",
        "ManifestString",
        "ManifestCharacter",
        "ManifestBoolean",
        "TypedConstant",
        "ManifestType",
        "TupleExpression",
        "ObjectTest",
        "Current",
        "Result",
        "Void",
        "ConditionalExpression",
        "ElseifExpression",
        "InspectExpression",
        "WhenExpression",
        "Address",
        "AssertionClause",
        "Precondition",
        "Postcondition",
        "OpenOperand",
        "ClassAssertion",
    }
)
TYPES = frozenset({"ClassType", "TupleType", "AnchoredType", "FormalGeneric", "EntityDeclaration"})


class NotLeaf(Exception):
    """The routine being examined breaks one of the leaf rules."""


def version_key(feature) -> str:
    """One routine version (declaration): its class and its first declared name."""
    return f"{feature.written_in}.{feature.decl.names[0].name.key}"


def analysis(program) -> Analysis:
    """The program's SCOOP facts, computed once per program (on first use)."""
    found = getattr(program, "_scoop_analysis", None)
    if found is None:
        found = program._scoop_analysis = Analysis(
            program.universe, program.tables, program.assertions_for, program.library_facts
        )
    return found


class Analysis:
    def __init__(self, universe, tables, assertions_for, library_facts=None):
        self.universe, self.tables, self.assertions_for = universe, tables, assertions_for
        self.heirs: dict[str, set] = {}  # class -> itself and every class inheriting from it
        for info in universe.classes.values():
            for ancestor in set(info.all_ancestors) | {info.name}:
                self.heirs.setdefault(ancestor, set()).add(info.name)
        self._by_seed: dict[str, dict] = {}  # class -> seed -> its features with that seed
        self._own: dict[str, dict] = {}  # class -> first name -> version declared there
        self.closed = not any(
            i.is_expanded and i.name not in BASIC and not _default_runs_nothing(i) for i in universe.classes.values()
        )
        self._library = library_facts
        self._versions: dict = {}
        self._local: dict = {}
        self._leaf: dict = {}

    # --- the closed world ----------------------------------------------------------------------
    def versions(self, cls: str, seeds) -> list:
        """Every effective version of the feature with `seeds` in `cls` and its heirs (one per
        declaration); None when `cls` is unknown."""
        key = (cls, frozenset(seeds))
        found = self._versions.get(key, False)
        if found is not False:
            return found
        heirs = self.heirs.get(cls)
        if heirs is None:
            self._versions[key] = None
            return None
        found, seen = [], set()
        for heir in sorted(heirs):
            table = self.by_seed(heir)
            for seed in key[1]:
                for feature in table.get(seed, ()):
                    if feature.deferred or id(feature.decl) in seen:
                        continue
                    seen.add(id(feature.decl))
                    found.append(feature)
        self._versions[key] = found
        return found

    def by_seed(self, cls: str) -> dict:
        table = self._by_seed.get(cls)
        if table is None:
            table = self._by_seed[cls] = {}
            info = self.universe.classes[cls]
            joined: dict = {}
            for name, versions in info.joins:  # inherited versions joined into one feature
                for version in versions:
                    joined.setdefault(name, set()).update(version.seeds())
            for feature in info.features.values():
                for seed in feature.seeds() | joined.get(feature.name, set()):
                    table.setdefault(seed, []).append(feature)
        return table

    def version(self, key: str):
        """The version `CLASS.name` (declared in CLASS under that first name), or None."""
        cls, _, name = key.rpartition(".")
        table = self._own.get(cls)
        if table is None:
            info = self.universe.classes.get(cls)
            table = self._own[cls] = (
                {}
                if info is None
                else {
                    f.decl.names[0].name.key: f
                    for f in info.features.values()
                    if f.written_in == cls and getattr(f.decl, "names", None)
                }
            )
        return table.get(name)

    def single(self, cls: str, feature):
        """The one version of `feature` for static class `cls` and its heirs, or None."""
        found = self.versions(cls, feature.seeds())
        return found[0] if found is not None and len(found) == 1 else None

    # --- leaves ------------------------------------------------------------------------------------
    def is_leaf(self, feature) -> bool:
        if not self.closed or not feature.decl.names:
            return False
        return self._leaf_of(version_key(feature), [])

    def _leaf_of(self, key: str, stack: list) -> bool:
        found = self._leaf.get(key)
        if found is not None:
            return found
        if key in stack:  # recursion: not a leaf
            return False
        local = self.local_facts(key)
        verdict = local is not None and local[0]
        if verdict:
            stack.append(key)
            try:
                verdict = all(self._callee_is_leaf(callee, stack) for callee in local[1])
            finally:
                stack.pop()
        # A false verdict met through the stack means a cycle through `key`: false for good.
        self._leaf[key] = verdict
        return verdict

    def _callee_is_leaf(self, callee, stack) -> bool:
        kind, cls, what = callee
        if kind == "v":
            return self._leaf_of(f"{cls}.{what}", stack)
        found = self.versions(cls, what)
        return found is not None and all(self._leaf_of(version_key(f), stack) for f in found)

    def local_facts(self, key: str):
        """(verdict on the body alone, callees) of a version, or None when unknown."""
        if key in self._local:
            return self._local[key]
        feature = self.version(key)
        found = None
        if feature is not None:
            info = self.universe.get(feature.written_in)
            if info is not None and info.from_library and self._library is not True:
                found = self._library_facts(key)
            else:
                found = local_facts(self, info, feature)
        self._local[key] = found
        return found

    def _library_facts(self, key: str):
        """A library version's saved facts, in this program's names: the library was compiled
        alone, so a library class that a user class shadows (MUTEX, kept as MUTEX@BASE here) is
        named as the library named it; its name, in the key, the callees and the seeds, is
        translated."""
        shadowed = self.universe.shadowed
        if shadowed:
            library_name = {ours: theirs for theirs, ours in shadowed.items()}
            cls, _, name = key.rpartition(".")
            key = f"{library_name.get(cls, cls)}.{name}"
        entry = (self._library or {}).get(key)
        if entry is None:
            return None
        if not shadowed:
            return entry[0], [tuple(c[:2]) + ((c[2] if c[0] == "v" else frozenset(c[2])),) for c in entry[1]]

        def ours(dotted: str) -> str:
            cls, _, name = dotted.rpartition(".")
            return f"{shadowed.get(cls, cls)}.{name}"

        return entry[0], [
            (kind, shadowed.get(cls, cls), what if kind == "v" else frozenset(ours(seed) for seed in what))
            for kind, cls, what in (tuple(c) for c in entry[1])
        ]


# --- the facts of one routine's body -------------------------------------------------------------
def local_facts(analysis: Analysis, info, feature):
    """(ok, callees): whether the version breaks no leaf rule by itself, and the calls it may
    make: ("v", class, name) one exact version, ("d", class, seeds) any version in the heirs."""
    decl = feature.decl
    if isinstance(decl, syntax.Constant):
        return True, []
    if isinstance(decl, syntax.Attribute):
        body = getattr(decl, "body", None)
        if body is None:
            return True, []
        return _walk_body(analysis, info, body, ())
    body = decl.body
    inner = body.body
    if isinstance(inner, syntax.DeferredBody):
        return True, []
    if isinstance(inner, syntax.ExternalBody):
        return _external_ok(info, feature, inner), _external_callees(info, feature, inner)
    if not isinstance(inner, syntax.InternalBody) or inner.once:
        return False, []
    signature = feature.signature
    types = signature.arguments if signature is not None else (None,) * len(decl.arguments)
    return _walk_body(analysis, info, body, list(zip((a.name.key for a in decl.arguments), types)))


def _external_ok(info, feature, inner) -> bool:
    if inner.language.lower() not in ("python", "built_in"):
        return False
    if info.name in SAFE_EXTERNAL_CLASSES:
        return True
    name = feature.decl.names[0].name.key
    return (info.name == "ANY" and name in SAFE_ANY_EXTERNALS) or (info.name, name) in SAFE_EXTERNAL_FEATURES


def _external_callees(info, feature, inner) -> list:
    """The Eiffel features an external may call back: ARRAY's accessors ask a descendant's
    `valid_index` (scoopc/kernel/ext/array.py), so a redefinition counts as their callee."""
    name = feature.decl.names[0].name.key
    if inner.language.lower() != "python" or (info.name, name) not in CALLING_EXTERNALS:
        return []
    found = info.features.get(CALLING_EXTERNALS[info.name, name])
    return [("d", info.name, frozenset(found.seeds()))] if found is not None else []


def _walk_body(analysis: Analysis, info, body, arguments):
    walker = _Walker(analysis, info)
    try:
        for name, ty in arguments:
            if ty is None:
                raise NotLeaf("unknown argument type")
            if ty.separate and not _expanded(analysis.universe, ty) and not only_stored(analysis, body, name):
                raise NotLeaf("separate argument: a reservation")
        if body.rescue is not None:
            raise NotLeaf("rescue")
        for part in (body.precondition, body.postcondition):
            if part is not None:
                walker.visit(part)
        inner = body.body
        for instruction in getattr(inner, "instructions", ()):
            walker.visit(instruction)
    except NotLeaf:
        return False, []
    return True, walker.callees


def only_stored(analysis: Analysis, body, name: str) -> bool:
    """Whether argument `name` only ever appears as `attribute := name` (then it is not
    reserved: scoop_calls.reserved drops it by the same rule)."""
    entities, features = analysis.tables.entities, analysis.tables.features
    uses, stored = 0, 0
    pending = [body.precondition, body.postcondition, body.body] + list(body.rescue or ())
    while pending:
        node = pending.pop()
        if node is None:
            continue
        if isinstance(node, syntax.UnqualifiedCall) and node.name.key == name:
            entity = entities.get(node)
            if entity is not None and entity.kind == "argument":
                uses += 1
        elif (
            isinstance(node, syntax.Assignment)
            and isinstance(node.source, syntax.UnqualifiedCall)
            and node.source.name.key == name
            and not node.source.arguments
            and node.source not in analysis.tables.conversions
        ):
            target = entities.get(node.target)
            if (target is None or target.kind == "attribute") and features.get(node.target) is not None:
                stored += 1
        pending.extend(children(node))
    return uses == stored


def _default_runs_nothing(info) -> bool:
    """An expanded class of the standard library whose default value runs no code: no parent but
    ANY, no creation clause, no attribute, no invariant (UTF_CONVERTER); it takes no leaf away."""
    decl = info.decl
    return (
        info.from_library
        and not decl.inherit_clauses
        and not decl.creation_clauses
        and not decl.invariant
        and not any(isinstance(f, syntax.Attribute) for clause in decl.feature_clauses for f in clause.features)
    )


def _expanded(universe, ty) -> bool:
    found = universe.get(ty.name) if not ty.is_formal else None
    return found is not None and found.is_expanded


class _Walker:
    """Collects the callees of one body; raises NotLeaf on a node that breaks a rule."""

    def __init__(self, analysis: Analysis, info):
        self.analysis, self.info = analysis, info
        self.tables, self.universe = analysis.tables, analysis.universe
        self.callees: list = []
        self.seen: set = set()

    def add(self, callee) -> None:
        if callee not in self.seen:
            self.seen.add(callee)
            self.callees.append(callee)

    def visit(self, node) -> None:
        kind = type(node).__name__
        if kind in NEVER:
            raise NotLeaf(kind)
        if kind in TYPES:
            return
        handler = getattr(self, "v_" + kind, None)
        if handler is not None:
            handler(node)
        elif kind in PLAIN:
            self.visit_children(node)
        else:
            raise NotLeaf(f"unknown node {kind}")
        conversion = self.tables.conversions.get(node)
        if conversion is not None:
            self.conversion(node, conversion)

    def visit_children(self, node) -> None:
        for child in children(node):
            self.visit(child)

    # --- calls ---------------------------------------------------------------------------------------
    def dynamic(self, ty, feature, current=False) -> None:
        """A call of `feature` on a target of static type `ty`, or on Current."""
        if feature is None:
            raise NotLeaf("unresolved call")
        for cls in self.classes_of(ty, current):
            self.add(("d", cls, frozenset(feature.seeds())))

    def exact(self, feature) -> None:
        self.add(("v", feature.written_in, feature.decl.names[0].name.key))

    def classes_of(self, ty, current=False) -> list:
        if current or (ty is not None and ty.name == "<Current>"):
            return [self.info.name]
        if ty is None:
            raise NotLeaf("unknown target type")
        if ty.is_formal:
            constraints = self.info.constraints[ty.formal] if ty.formal < len(self.info.constraints) else ()
            return [c.name for c in constraints] or ["ANY"]
        if ty.is_none:
            raise NotLeaf("call on Void")
        found = self.universe.get(ty.name)
        if found is None:
            raise NotLeaf("unknown class")
        return [found.name]

    def v_UnqualifiedCall(self, node) -> None:
        entity = self.tables.entities.get(node)
        if node in self.tables.agent_calls:
            raise NotLeaf("agent call")
        if entity is None or entity.kind == "attribute":
            self.dynamic(None, self.tables.features.get(node), current=True)
        elif node.arguments:
            raise NotLeaf("agent call")
        self.visit_children(node)

    def v_QualifiedCall(self, node) -> None:
        if node in self.tables.separate_calls or node in self.tables.agent_calls:
            raise NotLeaf("separate call or agent call")
        feature = self.tables.features.get(node)
        if feature is not None:  # None: a TUPLE label
            self.dynamic(self.tables.types.get(node.target), feature)
        self.visit_children(node)

    v_BracketExpression = v_QualifiedCall

    def v_StaticCall(self, node) -> None:
        feature = self.tables.features.get(node)
        if feature is None:
            raise NotLeaf("unresolved call")
        self.exact(feature)
        self.visit_children(node)

    def v_Precursor(self, node) -> None:
        feature = self.tables.features.get(node)
        if feature is None:
            raise NotLeaf("unresolved Precursor")
        self.exact(feature)
        self.visit_children(node)

    def v_BinaryExpression(self, node) -> None:
        if node in self.tables.separate_calls:
            raise NotLeaf("separate call")
        feature = self.tables.features.get(node)
        if node.operator in ("~", "/~"):  # `B.equal`: the left operand's `is_equal`
            left = self.tables.types.get(node.left)
            if left is None or left.is_formal or left.name not in BASIC:
                self.dynamic(left, self._any_feature("is_equal"))
        elif node.operator in ("=", "/="):  # identity, or values (closed: no user expanded)
            pass
        elif feature is not None:
            self.dynamic(self.tables.types.get(node.left), feature)
        self.visit_children(node)

    def v_UnaryExpression(self, node) -> None:
        if node in self.tables.separate_calls:
            raise NotLeaf("separate call")
        feature = self.tables.features.get(node)
        if feature is not None:
            self.dynamic(self.tables.types.get(node.operand), feature)
        self.visit_children(node)

    def v_AssignerCall(self, node) -> None:
        if node.target in self.tables.separate_calls:
            raise NotLeaf("separate call")
        assigner = self.tables.features.get(node)
        target = node.target
        if assigner is not None:
            owner = getattr(target, "target", None)
            if owner is None:
                self.dynamic(None, assigner, current=True)
            else:
                self.dynamic(self.tables.types.get(owner), assigner)
        self.visit_children(node)

    def _any_feature(self, name: str):
        info = self.universe.get("ANY")
        feature = info.features.get(name) if info is not None else None
        if feature is None:
            raise NotLeaf("ANY." + name)
        return feature

    # --- creation, agents ------------------------------------------------------------------------
    def creation(self, node, processor) -> None:
        ty = self.tables.types.get(node)
        if ty is None and getattr(node, "type", None) is not None:
            ty = self.tables.types.get(node.type)
        if ty is None or ty.separate or processor is not None or ty.is_formal:
            raise NotLeaf("creation of a processor, or of a formal type")
        info = self.universe.get(ty.name)
        if info is None or (getattr(info, "_has_invariant", False) and self.assertions() == "all"):
            raise NotLeaf("creation checks an invariant")
        feature = self.tables.features.get(node)
        if feature is not None:
            own = info.features.get(feature.name, feature)
            self.exact(own)
        for argument in node.arguments:
            self.visit(argument)

    def v_CreationInstruction(self, node) -> None:
        self.creation(node, node.processor)

    def v_CreationExpression(self, node) -> None:
        self.creation(node, node.processor)

    def assertions(self) -> str:
        return self.analysis.assertions_for(self.info)

    def v_Agent(self, node) -> None:
        for child in children(node):
            self.visit(child)

    def v_InlineAgent(self, node) -> None:
        for actual in node.actuals or ():
            self.visit(actual)

    def v_Debug(self, node) -> None:
        return None  # no code is generated for debug instructions

    def conversion(self, node, conversion) -> None:
        converter, target_ty = conversion
        source_ty = self.tables.types.get(node)
        source = self.universe.get(source_ty.name) if source_ty is not None and not source_ty.is_formal else None
        feature = source.features.get(converter) if source is not None else None
        if feature is not None and feature.is_query:
            self.dynamic(source_ty, feature)
            return
        target = self.universe.get(target_ty.name)
        creator = target.features.get(converter) if target is not None else None
        if creator is None or (getattr(target, "_has_invariant", False) and self.assertions() == "all"):
            raise NotLeaf("conversion")
        self.exact(creator)


# --- the standard library's facts, kept beside its compiled package --------------------------------
def library_facts(universe, tables, options) -> dict:
    """{version key: [ok, callees]} for every routine version written in a library class."""

    def assertions_for(info):
        return options.library_assertions if info.from_library else options.assertions

    analysis = Analysis(universe, tables, assertions_for, library_facts=True)
    facts = {}
    for info in universe.classes.values():
        if not info.from_library:
            continue
        for feature in info.features.values():
            if feature.written_in != info.name or not getattr(feature.decl, "names", None):
                continue
            key = version_key(feature)
            if key not in facts:
                ok, callees = local_facts(analysis, info, feature)
                facts[key] = [ok, [[k, c, (w if k == "v" else sorted(w))] for k, c, w in callees]]
    return facts


# The library's interfaces whose routines a transport calls (scoopc/kernel/ext/ros_subscriber.py).
TRANSPORT_LISTENERS = frozenset(
    {"ODOMETRY_LISTENER", "RANGE_LISTENER", "SCAN_LISTENER", "BATTERY_LISTENER", "ROS_LISTENER"}
)


def library_leaves(program) -> list[str]:
    """ "CLASS.routine" (Python names) of the routine versions of the library's transport listeners
    (TRANSPORT_LISTENERS and their heirs) that are leaves in this program's closed world. The
    compiled library is never decorated (an heir in some program could break the promise), so a
    program tells the runtime which of them it may treat as leaves: a transport delivers a message
    to a signaler's leaf callback on its own thread (scoopc.kernel.link.is_leaf_routine). Only the
    listeners: the whole library's leaves would cost half a second per compilation."""
    facts = analysis(program)
    if not facts.closed:
        return []
    found = []
    for info in program.universe.classes.values():
        if not info.from_library or not TRANSPORT_LISTENERS & (set(info.all_ancestors) | {info.name}):
            continue
        for feature in info.features.values():
            if (
                feature.written_in == info.name
                and feature.is_routine
                and not feature.deferred
                and not feature.is_once
                and facts.is_leaf(feature)
            ):
                found.append(f"{info.name}.{program.naming.primary(feature)}")
    return sorted(found)


def write_library_facts(folder: Path, universe, tables, options) -> None:
    facts = library_facts(universe, tables, options)
    (folder / FACTS_FILE).write_text(json.dumps({"format": FACTS_FORMAT, "facts": facts}, separators=(",", ":")))
