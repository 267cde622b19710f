"""Codegen, expressions: one `x_<Node>` method per expression kind, each returning a Python
`ast.expr`. Types, features and entities come from the checker's tables only."""

from __future__ import annotations

import ast

from .. import syntax
from ..kernel.strings import utf8_bytes
from ..semantics.types import BASIC, Ty
from . import pyast as P
from .calls import declared_name
from .context import fail

EQUALITY = {"=": ast.Is, "/=": ast.IsNot}
INTEGER_KINDS = (
    "INTEGER_8",
    "INTEGER_16",
    "INTEGER_32",
    "INTEGER_64",
    "NATURAL_8",
    "NATURAL_16",
    "NATURAL_32",
    "NATURAL_64",
)
INTEGER_BITS = {name: int(name.rsplit("_", 1)[1]) for name in INTEGER_KINDS}
# Integer operations that commute with reduction modulo 2^n: a tree of them is computed exactly
# and brought into its type once (scoopc/kernel/basic.py).
RING_BINARY = {"plus": ast.Add, "minus": ast.Sub, "product": ast.Mult}
RING_UNARY = {"opposite": ast.USub, "identity": ast.UAdd}
# Classes a value of a basic type conforms to: calls on them may meet a Python int/float/str/bool.
BASIC_ANCESTORS = frozenset({"ANY", "COMPARABLE", "PART_COMPARABLE", "HASHABLE", "NUMERIC", "DEBUG_OUTPUT"})
WIDE_STRINGS = frozenset({"STRING_32", "READABLE_STRING_32", "IMMUTABLE_STRING_32"})


def manifest_text(value: str, wide: bool) -> str:
    """The characters a manifest string holds: a 32-bit string its code points, an 8-bit one
    the UTF-8 bytes of its text, as EiffelStudio keeps them (its scanner builds a manifest string
    in UTF-8, `%/code/` included; STRING_32 manifests are decoded from it)."""
    return value if wide else utf8_bytes(value)


class Expressions:
    def x(self, node) -> ast.expr:
        method = getattr(self, "x_" + type(node).__name__, None)
        if method is None:
            fail(f"no code for {type(node).__name__}", getattr(node, "span", None))
        result = method(node)
        conversion = self.tables.conversions.get(node)
        if conversion is not None and not isinstance(node, syntax.BinaryExpression):
            result = self.convert(node, result, conversion)
        return P.at(result, getattr(node, "span", None))

    def type_of(self, node) -> Ty:
        ty = self.tables.types.get(node)
        if ty is None:
            fail("no recorded type", getattr(node, "span", None))
        return ty

    # --- manifest constants ------------------------------------------------------------------
    def x_ManifestInteger(self, node):
        ty = self.tables.types.get(node)
        if ty is not None and ty.name in ("REAL_32", "REAL_64"):
            return self.real_constant(float(node.value), ty)
        return P.const(node.value)

    def x_ManifestReal(self, node):
        return self.real_constant(float(node.value), self.tables.types.get(node))

    def real_constant(self, value: float, ty):
        """A manifest real: a REAL_32 constant is rounded to single precision at compile time."""
        if ty is not None and ty.name == "REAL_32":
            from ..kernel.basic import r32  # deferred: start-up (loaded on first use only)

            value = r32(value)
        return P.const(value)

    def x_ManifestCharacter(self, node):
        return P.const(node.value)

    def x_ManifestBoolean(self, node):
        return P.const(bool(node.value))

    def x_ManifestString(self, node):
        ty = self.tables.types.get(node)
        wide = ty is not None and ty.name in WIDE_STRINGS
        maker = "s32" if wide else "s8"
        if ty is not None and ty.name.startswith("IMMUTABLE_STRING"):
            maker = "i32" if wide else "i8"
        value = P.const(manifest_text(node.value, wide))
        if node.once:
            key = self.module.constant("ONCE_STRING", P.call("object", []))
            return P.call("_S.once_string", [P.name("here"), key, value, P.dotted("_KS." + maker)])
        return P.call("_KS." + maker, [P.name("here"), value])

    def x_TypedConstant(self, node):
        return self.x(node.constant)

    def x_Unique(self, node):
        fail("unique constants are not supported", node.span)

    def x_ClassAssertion(self, node):
        return P.const(True)  # `ensure class`: a static routine, nothing to check at run time

    def x_Address(self, node):
        return P.const(0)

    def x_ManifestType(self, node):
        return P.call("_S.type_object", [P.name("here"), self.type_desc(self.type_of(node.type))])

    def x_TupleExpression(self, node):
        ty = self.type_of(node)
        items = [self.copied(item, self.x(item)) for item in node.items]
        return P.call("_S.new_tuple", [P.name("here"), P.lst(items), self.generics_desc(ty)])

    def x_ManifestArray(self, node):
        ty = self.type_of(node)
        element = ty.generics[0] if ty.generics else None
        items = [self.reattached(item, self.copied(item, self.x(item)), element) for item in node.items]
        return P.call(
            "_S.manifest_array", [P.name("here"), self.class_ref(ty.name), self.generics_desc(ty), P.lst(items)]
        )

    # --- entities ------------------------------------------------------------------------------
    def x_Current(self, node):
        return P.name("self")

    def x_Result(self, node):
        return self.result_ref()

    def x_Void(self, node):
        return P.const(None)

    def x_Parenthesized(self, node):
        return self.x(node.expression)

    def x_Old(self, node):
        return P.name(self.olds[node])

    # --- operators -----------------------------------------------------------------------------
    def x_BinaryExpression(self, node):
        kind = self.ring_kind(node)
        if kind is not None:
            return self.ring_value(self.ring_raw(node, kind), kind)
        op = node.operator
        if op == "and then" or (op == "and" and node not in self.tables.features):
            return P.boolop(ast.And(), [self.x(node.left), self.x(node.right)])
        if op == "or else" or (op == "or" and node not in self.tables.features):
            return P.boolop(ast.Or(), [self.x(node.left), self.x(node.right)])
        if op == "implies":
            return P.boolop(ast.Or(), [P.not_(self.x(node.left)), self.x(node.right)])
        if op == "xor" and node not in self.tables.features:
            return P.compare(self.x(node.left), ast.NotEq(), self.x(node.right))
        if op in ("=", "/=", "~", "/~"):
            return self.equality(node)
        feature = self.tables.features.get(node)
        if feature is None:
            fail(f"operator {op} without a feature", node.span)
        target = self.x(node.left)
        conversion = self.tables.conversions.get(node.left)
        return self.call_feature(node, node.left, target, feature, [node.right], conversion=conversion)

    def equality(self, node):
        left_ty, right_ty = self.tables.types.get(node.left), self.tables.types.get(node.right)
        left, right = self.x(node.left), self.x(node.right)
        negate = node.operator in ("/=", "/~")
        if isinstance(node.right, syntax.Void) or isinstance(node.left, syntax.Void):
            return P.compare(left, ast.IsNot() if negate else ast.Is(), right)
        if node.operator in ("~", "/~") or self.is_user_expanded(left_ty) or self.is_user_expanded(right_ty):
            test = P.call("_B.equal", [left, right])  # `=` on expanded values compares them
        elif self.is_basic(left_ty) or self.is_basic(right_ty):
            return P.compare(left, ast.NotEq() if negate else ast.Eq(), right)
        elif self.may_hold_basic(left_ty) or self.may_hold_basic(right_ty):
            test = P.call("_B.same", [left, right])
        else:
            return P.compare(left, ast.IsNot() if negate else ast.Is(), right)
        return P.not_(test) if negate else test

    def x_UnaryExpression(self, node):
        if node.operator == "not" and node not in self.tables.features:
            return P.not_(self.x(node.operand))
        folded = self.negative_constant(node)
        if folded is not None:
            return folded
        kind = self.ring_kind(node)
        if kind is not None:
            return self.ring_value(self.ring_raw(node, kind), kind)
        feature = self.tables.features.get(node)
        if feature is None:
            fail(f"operator {node.operator} without a feature", node.span)
        return self.call_feature(
            node, node.operand, self.x(node.operand), feature, [], conversion=self.tables.conversions.get(node.operand)
        )

    def negative_constant(self, node):
        """`-5`, `-2.5`: a manifest constant, when its value fits the type (no wrap needed)."""
        operand = node.operand
        if (
            node.operator != "-"
            or not isinstance(operand, (syntax.ManifestInteger, syntax.ManifestReal))
            or self.tables.conversions.get(operand) is not None
        ):
            return None
        ty = self.tables.types.get(node)
        value = self.x(operand).value
        if ty is None or not isinstance(value, (int, float)):
            return None
        if ty.name in ("REAL_32", "REAL_64"):
            return P.const(-float(value)) if value else None
        bits = INTEGER_BITS.get(ty.name)
        if bits is None or not ty.name.startswith("INTEGER") or -value < -(1 << (bits - 1)):
            return None
        return P.const(-value)

    # --- integer arithmetic: one range check per tree of `+ - *` -------------------------------------
    def ring_kind(self, node) -> str | None:
        """The integer class of `node` when it is a built-in `+`, `-` or `*` of that class."""
        if not isinstance(node, (syntax.BinaryExpression, syntax.UnaryExpression)):
            return None
        feature = self.tables.features.get(node)
        if feature is None or feature.written_in not in INTEGER_BITS or not self.is_builtin_basic(feature):
            return None
        table = RING_BINARY if isinstance(node, syntax.BinaryExpression) else RING_UNARY
        return feature.written_in if declared_name(feature) in table else None

    def ring_raw(self, node, kind: str) -> ast.expr:
        """The exact value of ring operation `node` (Python's integers), its operands that are
        ring operations of the same class included as they are: they are brought into the type
        once, for the whole tree. The operands' order of evaluation is the source's."""
        if isinstance(node, syntax.UnaryExpression):
            folded = self.negative_constant(node)
            if folded is not None:
                return folded
            operand = self.ring_operand(node.operand, kind)
            if declared_name(self.tables.features[node]) == "identity":
                return operand
            return ast.UnaryOp(ast.USub(), operand)
        op = RING_BINARY[declared_name(self.tables.features[node])]
        return ast.BinOp(self.ring_operand(node.left, kind), op(), self.ring_operand(node.right, kind))

    def ring_operand(self, node, kind: str) -> ast.expr:
        inner = node
        while isinstance(inner, syntax.Parenthesized) and inner not in self.tables.conversions:
            inner = inner.expression
        if inner not in self.tables.conversions and self.ring_kind(inner) == kind:
            return P.at(self.ring_raw(inner, kind), inner.span)
        return self.x(node)

    def ring_value(self, raw: ast.expr, kind: str) -> ast.expr:
        """`_B.i32(raw)` (in range: raw itself; else wrapped); `raw & 255` for NATURAL_8."""
        bits = INTEGER_BITS[kind]
        if kind.startswith("NATURAL"):
            return ast.BinOp(raw, ast.BitAnd(), P.const((1 << bits) - 1))
        wrapped = P.call(f"_B.i{bits}", [raw])
        step = _name_step(raw)
        if step is None:
            return wrapped
        # `n - 1` as an argument: `n - 1 if n > -2147483648 else _B.i32(n - 1)`, no call in the common case
        name, delta = step
        low, high = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
        test = P.compare(P.name(name), ast.LtE(), P.const(high - delta)) if delta >= 0 else None
        if delta < 0:
            test = P.compare(P.name(name), ast.GtE(), P.const(low - delta))
        return ast.IfExp(test, _copy_step(raw), wrapped)

    def ring_assignment(self, target: ast.expr, source) -> list | None:
        """`x := a + b` into a local or an attribute of Current: the exact value assigned, then
        one range test (`if x > 2147483647: x = _B.wrap_i32(x)`), as fast as Python's own `+`
        when nothing overflows."""
        inner = source
        while isinstance(inner, syntax.Parenthesized) and inner not in self.tables.conversions:
            inner = inner.expression
        kind = self.ring_kind(inner)
        if kind is None or not kind.startswith("INTEGER") or source in self.tables.conversions:
            return None
        if not (isinstance(target, ast.Name) or (isinstance(target, ast.Attribute) and _is_self(target.value))):
            return None
        raw = self.ring_raw(inner, kind)
        if isinstance(raw, ast.Constant):
            return None
        bits = INTEGER_BITS[kind]
        low, high = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
        read = _load(target)
        if _adds_constant(raw, ast.Add) or _adds_constant(raw, ast.Sub, negative=True):
            test = P.compare(read, ast.Gt(), P.const(high))
        elif _adds_constant(raw, ast.Sub) or _adds_constant(raw, ast.Add, negative=True):
            test = P.compare(read, ast.Lt(), P.const(low))
        else:
            test = P.not_(ast.Compare(P.const(low), [ast.LtE(), ast.LtE()], [read, P.const(high)]))
        wrapped = P.assign(_load(target), P.call(f"_B.wrap_i{bits}", [_load(target)]))
        return [P.assign(target, raw), P.if_(test, [wrapped])]

    def is_user_expanded(self, ty) -> bool:
        if ty is None or ty.is_formal or ty.name in BASIC:
            return False
        info = self.universe.get(ty.name)
        return info is not None and info.is_expanded

    def is_basic(self, ty) -> bool:
        return ty is not None and not ty.is_formal and ty.name in BASIC

    def may_hold_basic(self, ty) -> bool:
        """Could a value of static type `ty` be a Python int/float/str/bool at run time?"""
        if ty is None:
            return True
        if ty.is_formal:
            return self.formal_may_be_basic(ty)
        return ty.name in BASIC_ANCESTORS or ty.name in BASIC

    def formal_may_be_basic(self, ty) -> bool:
        constraints = self.info.constraints[ty.formal] if ty.formal < len(self.info.constraints) else ()
        return not constraints or any(c.name in BASIC_ANCESTORS or c.name in BASIC for c in constraints)

    # --- conditionals, object tests --------------------------------------------------------------
    def x_ConditionalExpression(self, node):
        result = self.x(node.else_part)
        for part in reversed(node.elseif_parts):
            result = ast.IfExp(self.x(part.condition), self.x(part.then_part), result)
        return ast.IfExp(self.x(node.condition), self.x(node.then_part), result)

    def x_InspectExpression(self, node):
        """`(b1 if (t := e) == c1 else b2 if t == c2 else ... )`: the subject evaluated once; no
        matching branch and no `else` raises as the instruction does."""
        subject = self.temp("inspect")
        if node.else_part is not None:
            result = self.x(node.else_part)
        else:
            result = P.call("_S.bad_inspect", [P.name(subject), self.where(node)])
        first = True
        tests = []
        subject_value, text = self.inspect_subject(node)
        for part in node.when_parts:
            part_tests = []
            for choice in part.choices:
                value = ast.NamedExpr(P.name(subject, store=True), subject_value) if first else P.name(subject)
                first = False
                part_tests.append(self.choice(value, choice, text))
            tests.append(P.boolop(ast.Or(), part_tests) if len(part_tests) > 1 else part_tests[0])
        for part, test in reversed(list(zip(node.when_parts, tests))):
            result = ast.IfExp(test, self.x(part.then_part), result)
        if first:  # no `when`: the subject is still evaluated, then the rest
            result = ast.Subscript(P.tup([self.x(node.expression), result]), P.const(1), ast.Load())
        return result

    def x_ObjectTest(self, node):
        value = self.x(node.expression)
        if node.local is not None:
            value = ast.NamedExpr(P.name(self.local_name(node.local.key), store=True), value)
        if node.type is None:
            return P.is_not_none(value)
        ty = self.type_of(node.type)
        desc = self.type_desc(ty)
        if node.local is None:
            return P.call("_S.conforms", [value, desc])
        return P.boolop(
            ast.And(),
            [P.is_not_none(value), P.call(P.attr(desc, "accepts"), [P.name(self.local_name(node.local.key))])],
        )

    def x_AcrossExpression(self, node):
        iteration = node.iteration
        var = self.local_name(iteration.name.key)
        body = self.x(node.body)
        source = self.iteration_source(iteration)
        if node.until is not None:  # stop before the first position where `until` holds
            stop = P.lambda_([var], P.not_(self.x(node.until)))
            source = P.call("_S.take_while", [stop, source])
        comp = ast.GeneratorExp(body, [ast.comprehension(P.name(var, store=True), source, [], 0)])
        return P.call("all" if node.quantifier == "all" else "any", [comp])

    def iteration_source(self, iteration) -> ast.expr:
        helper = "_S.cursors" if iteration.cursor_mode else "_S.items"
        return P.call(helper, [self.x(iteration.expression)])

    # --- creation expressions ------------------------------------------------------------------
    def x_CreationExpression(self, node):
        ty = self.type_of(node.type)
        feature = self.tables.features.get(node)
        return self.creation_value(node, ty, feature, node.arguments, node.processor is not None)


def _is_self(node) -> bool:
    return isinstance(node, ast.Name) and node.id == "self"


def _load(target: ast.expr) -> ast.expr:
    if isinstance(target, ast.Name):
        return P.name(target.id)
    return P.attr(P.name("self"), target.attr)


def _adds_constant(raw: ast.expr, op: type, negative: bool = False) -> bool:
    """Is `raw` `e + c` (`e - c`) with `e` a value of the type and a constant `c` >= 0 (< 0 when
    `negative`)? Then the result can only overflow on one side."""
    if not (isinstance(raw, ast.BinOp) and isinstance(raw.op, op)):
        return False
    if isinstance(raw.left, (ast.BinOp, ast.UnaryOp)):
        return False  # an exact value of the tree below, which may be out of range either way
    value = raw.right.value if isinstance(raw.right, ast.Constant) else None
    if not isinstance(value, int) or isinstance(value, bool):
        return False
    return value < 0 if negative else value >= 0


def _name_step(raw: ast.expr) -> tuple[str, int] | None:
    """(n, c) when `raw` is `n + c` or `n - c` (n a name, c a constant): the change of n."""
    if not (isinstance(raw, ast.BinOp) and isinstance(raw.op, (ast.Add, ast.Sub)) and isinstance(raw.left, ast.Name)):
        return None
    value = raw.right.value if isinstance(raw.right, ast.Constant) else None
    if not isinstance(value, int) or isinstance(value, bool):
        return None
    return raw.left.id, value if isinstance(raw.op, ast.Add) else -value


def _copy_step(raw: ast.BinOp) -> ast.expr:
    return ast.BinOp(P.name(raw.left.id), type(raw.op)(), P.const(raw.right.value))
