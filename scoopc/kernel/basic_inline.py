"""`inline`: the Python expression (stdlib `ast`) of a built-in feature of a basic class, for
the code generator. Semantics and sources: scoopc/kernel/basic.py.

Each feature is a list of templates over the names X (Current), Y, Z (the arguments), R (the
region, `here` by default) and _B (the module scoopc.kernel.basic). The first template whose
guard holds and that evaluates every non-trivial operand at most once is used (an operand that
is a name or a constant may be repeated); the last one always applies. An operand a template
does not use is still evaluated (`_B.seq (x, result)`) unless it is a name or a constant.
The nodes returned have no positions: run `ast.fix_missing_locations` on the module.
"""

import ast

_PLACES = ("X", "Y", "Z")


class Spec:
    """How to inline one feature: `arity` arguments, templates `alts` ((guard, (tree, counts)), ...)
    as _parse makes them."""

    __slots__ = ("arity", "alts")

    def __init__(self, arity, alts):
        self.arity = arity
        self.alts = alts

    def build(self, current, arguments, region):
        if len(arguments) != self.arity:
            raise TypeError(f"{self.arity} arguments expected, got {len(arguments)}")
        nodes = dict(zip(_PLACES, (current, *arguments)))
        nodes["R"] = region
        for guard, (tree, counts) in self.alts:
            if guard is not None and not guard(nodes):
                continue
            if any(counts.get(k, 0) > 1 and not _trivial(v) for k, v in nodes.items()):
                continue
            result = _instantiate(tree, nodes)
            dropped = [nodes[k] for k in _PLACES if k in nodes and not counts.get(k) and not _trivial(nodes[k])]
            if dropped:
                result = ast.Call(_b("seq"), dropped + [result], [])
            return result
        raise AssertionError("no template applies")


def _parse(text):
    tree = ast.parse(text, mode="eval").body
    counts = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and node.id in ("X", "Y", "Z", "R"):
            counts[node.id] = counts.get(node.id, 0) + 1
    return tree, counts


def _instantiate(node, nodes):
    """A fresh copy of template `node` with the place names X, Y, Z, R replaced by the given
    expressions (copies of the trivial ones, which a template may use twice; copying by hand:
    copy.deepcopy costs ten times more)."""
    if isinstance(node, ast.Name) and node.id in nodes and nodes[node.id] is not None:
        value = nodes[node.id]  # an operand used twice is trivial: copying the others costs time for nothing
        return _clone(value) if _trivial(value) else value
    if isinstance(node, ast.AST):
        new = node.__class__.__new__(node.__class__)
        for field in node._fields:
            setattr(new, field, _instantiate(getattr(node, field, None), nodes))
        return new
    if isinstance(node, list):
        return [_instantiate(item, nodes) for item in node]
    return node


def _clone(node):
    if isinstance(node, ast.AST):
        new = node.__class__.__new__(node.__class__)
        for field in node._fields:
            setattr(new, field, _clone(getattr(node, field, None)))
        for attribute in node._attributes:
            if hasattr(node, attribute):
                setattr(new, attribute, getattr(node, attribute))
        return new
    if isinstance(node, list):
        return [_clone(item) for item in node]
    return node


def _b(name):
    return ast.Attribute(ast.Name("_B", ast.Load()), name, ast.Load())


def _constant(node):
    """The numeric value of a constant operand (`3`, `-2.5`), else None."""
    sign = 1
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        sign = -1 if isinstance(node.op, ast.USub) else 1
        node = node.operand
    if isinstance(node, ast.Constant) and type(node.value) in (int, float) and node.value == node.value:
        return sign * node.value
    return None


def _trivial(node):
    """May the operand be evaluated twice, or not at all (a name or a constant)?"""
    return isinstance(node, (ast.Name, ast.Constant)) or (
        isinstance(node, ast.UnaryOp) and isinstance(node.operand, ast.Constant)
    )


def _y_const(nodes):  # Y is a number (not NaN)
    return _constant(nodes["Y"]) is not None


def _x_const(nodes):
    return _constant(nodes["X"]) is not None


def _y_positive(nodes):
    value = _constant(nodes["Y"])
    return value is not None and value > 0


def _y_nonzero(nodes):
    value = _constant(nodes["Y"])
    return value is not None and value != 0


def _y_name(nodes):
    return isinstance(nodes["Y"], ast.Name)


def inline(class_name, feature_name, current, arguments, region=None):
    """The expression computing `current.feature_name (arguments)`, `feature_name` declared in
    basic class `class_name` (or ANY). `region`: the expression of the current processor
    (default: the local `here`). KeyError for an unknown feature."""
    spec = specs()[(class_name, feature_name)]
    return spec.build(current, list(arguments), region if region is not None else ast.Name("here", ast.Load()))


_SPECS = {}


def specs():
    """{(class_name, feature_name): Spec}, built on first use."""
    if not _SPECS:
        _SPECS.update(_build())
    return _SPECS


# --- The tables ----------------------------------------------------------------------------

INTEGER_CLASSES = {
    "INTEGER_8": (8, True),
    "INTEGER_16": (16, True),
    "INTEGER_32": (32, True),
    "INTEGER_64": (64, True),
    "NATURAL_8": (8, False),
    "NATURAL_16": (16, False),
    "NATURAL_32": (32, False),
    "NATURAL_64": (64, False),
}


def _range(bits, signed):
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)


def _wrap_text(expr, bits, signed):
    mask = (1 << bits) - 1
    if signed:
        half = 1 << (bits - 1)
        return f"((({expr}) + {half}) & {mask}) - {half}"
    return f"({expr}) & {mask}"


def _integer(name, bits, signed):
    p = f"{'i' if signed else 'n'}{bits}"
    low, high = _range(bits, signed)

    def wrap(e):
        """Signed results: one helper call (`_B.i32(X + Y)`: the value itself when in range);
        unsigned results: a mask."""
        if not signed:
            return _wrap_text(e, bits, signed)
        return f"_B.{p}({e})"

    t = {
        "item": "X",
        "hash_code": "X & 2147483647",
        "sign": [(None, "(X > 0) - (X < 0)"), (None, "_B.isign(X)")] if signed else "(1 if X > 0 else 0)",
        "one": "1",
        "zero": "0",
        "is_less": "X < Y",
        "is_less_equal": "X <= Y",
        "is_greater": "X > Y",
        "is_greater_equal": "X >= Y",
        "is_equal": "X == Y",
        "three_way_comparison": [(None, "(X > Y) - (X < Y)"), (None, "_B.cmp(X, Y)")],
        "max": [(None, "(X if X >= Y else Y)"), (None, "_B.imax(X, Y)")],
        "min": [(None, "(X if X <= Y else Y)"), (None, "_B.imin(X, Y)")],
        "divisible": "Y != 0",
        "exponentiable": "_B.exponentiable(X, Y)",
        "is_hashable": "X != 0",
        "is_valid_character_8_code": "0 <= X <= 255" if signed else "X <= 255",
        "is_valid_character_32_code": "0 <= X <= 1114111" if signed else "X <= 1114111",
        "plus": wrap("X + Y"),
        "minus": wrap("X - Y"),
        "product": wrap("X * Y"),
        "quotient": [(_y_nonzero, "X / Y"), (_y_name, "(X / Y if Y else _B.fdiv(X, Y))"), (None, "_B.fdiv(X, Y)")]
        if bits < 64
        else "_B.fquot(X, Y)",  # x / 0 is an infinity, as in C
        "identity": "X",
        "power": "_B.power(X, Y)",
        "interval": "_B.interval(R, X, Y)",
        "to_boolean": "X != 0",
        "to_real": "_B.r32(X + 0.0)" if bits < 64 else "_B.i2r32(X)",
        "to_double": "X + 0.0",
        "to_character_8": "_B.chr(X & 255)",
        "to_character_32": "_B.chr(X)",  # C casts
        "to_hex_string": f"_B.hex_string(R, X, {bits})",
        "to_hex_character": "_B.HEX_DIGITS[X]",
        "bit_and": "X & Y",
        "bit_or": "X | Y",
        "bit_xor": "X ^ Y",
        "bit_not": "~X" if signed else f"X ^ {(1 << bits) - 1}",
        "bit_shift": f"_B.shift_{p}(X, Y)",
        "bit_shift_left": wrap("X << Y"),
        "bit_shift_right": "X >> Y",
        "bit_test": "(X >> Y) & 1 != 0",
        "set_bit": f"_B.set_bit_{p}(X, Y, Z)",
        "set_bit_with_mask": f"_B.set_bit_mask_{p}(X, Y, Z)",
        "out": "_B.out_int(R, X)",
    }
    t["to_real_32"], t["to_real_64"] = t["to_real"], t["to_double"]
    if signed:
        t["abs"] = [(None, f"(X if X >= 0 else {wrap('-X')})"), (None, f"_B.abs_{p}(X)")]
        t["opposite"] = wrap("-X")
        t["integer_quotient"] = [(_y_positive, "(X // Y if X >= 0 else -(-X // Y))"), (None, f"_B.idiv_{p}(X, Y)")]
        t["integer_remainder"] = [(_y_positive, "(X % Y if X >= 0 else -(-X % Y))"), (None, f"_B.irem_{p}(X, Y)")]
    else:
        t["unapplicable_opposite"] = "X"
        t["integer_quotient"] = "X // Y"
        t["integer_remainder"] = "X % Y"
    for target, (tbits, tsigned) in INTEGER_CLASSES.items():
        tlow, thigh = _range(tbits, tsigned)
        convert = "X" if tlow <= low and high <= thigh else _wrap_text("X", tbits, tsigned)
        suffix = target.lower().split("_")[0] + "_" + str(tbits)
        t["as_" + suffix] = t["to_" + suffix] = convert
    if name == "INTEGER_32":
        t["to_integer"] = "X"
    return t


_REAL_COMPARISONS = {
    # eif_helpers.h: NaN is the smallest value, equal to itself.
    "is_less": [
        (_y_const, "not (X >= Y)"),
        (_x_const, "X < Y"),
        (None, "(X < Y or (X != X and Y == Y))"),
        (None, "_B.flt(X, Y)"),
    ],
    "is_less_equal": [
        (_y_const, "not (X > Y)"),
        (_x_const, "X <= Y"),
        (None, "(X <= Y or X != X)"),
        (None, "_B.fle(X, Y)"),
    ],
    "is_greater": [
        (_y_const, "X > Y"),
        (_x_const, "not (X <= Y)"),
        (None, "(X > Y or (Y != Y and X == X))"),
        (None, "_B.fgt(X, Y)"),
    ],
    "is_greater_equal": [
        (_y_const, "X >= Y"),
        (_x_const, "not (X < Y)"),
        (None, "(X >= Y or Y != Y)"),
        (None, "_B.fge(X, Y)"),
    ],
    "is_equal": [
        (_y_const, "X == Y"),
        (_x_const, "X == Y"),
        (None, "(X == Y or (X != X and Y != Y))"),
        (None, "_B.feq(X, Y)"),
    ],
}


def _real(bits):
    single = bits == 32
    rnd = (lambda e: f"_B.r32({e})") if single else (lambda e: e)  # noqa: E731
    t = {
        "item": "X",
        "hash_code": "_B.trunc32(X) & 2147483647",
        "sign": "_B.fsign(X)",
        "one": "1.0",
        "zero": "0.0",
        "nan": "_B.NAN",
        "negative_infinity": "_B.NEG_INF",
        "positive_infinity": "_B.POS_INF",
        "ieee_is_equal": "X == Y",
        "three_way_comparison": "_B.fcmp(X, Y)",
        "max": "_B.fmax(X, Y)",
        "min": "_B.fmin(X, Y)",
        "divisible": "Y != 0.0",
        "exponentiable": "_B.exponentiable(X, Y)",
        "is_hashable": "X != 0.0",
        "is_nan": [(None, "X != X"), (None, "_B.isnan(X)")],
        "is_negative_infinity": "X == _B.NEG_INF",
        "is_positive_infinity": "X == _B.POS_INF",
        "abs": [(None, "(X if X > 0 else -X)"), (None, "_B.fabs(X)")],
        "plus": rnd("X + Y"),
        "minus": rnd("X - Y"),
        "product": rnd("X * Y"),
        "quotient": [
            (_y_nonzero, rnd("X / Y")),
            (_y_name, rnd("(X / Y if Y else _B.fdiv(X, Y))")),
            (None, rnd("_B.fdiv(X, Y)")),
        ],
        "power": "_B.power(X, Y)",
        "identity": "X",
        "opposite": "-X",
        "truncated_to_integer": "_B.trunc32(X)",
        "truncated_to_integer_64": "_B.trunc64(X)",
        "ceiling": "_B.trunc32(_B.fceil(X))",
        "floor": "_B.trunc32(_B.ffloor(X))",
        "rounded": "_B.rounded(X)",
        f"ceiling_real_{bits}": "_B.fceil(X)",
        f"floor_real_{bits}": "_B.ffloor(X)",
        f"rounded_real_{bits}": "_B.rounded_real_32(X)" if single else "_B.rounded_real(X)",
        "out": "_B.out_r32(R, X)" if single else "_B.out_r64(R, X)",
    }
    t.update(_REAL_COMPARISONS)
    if single:
        t["to_double"] = t["to_real_64"] = "X"
    else:
        t["truncated_to_real"] = "_B.r32(X)"
    return t


_BOOLEAN = {
    "item": "X",
    "hash_code": "(1 if X else 0)",
    "to_integer": "(1 if X else 0)",
    "is_equal": "X == Y",
    "conjuncted": "X & Y",
    "conjuncted_semistrict": "X and Y",
    "disjuncted": "X | Y",
    "disjuncted_semistrict": "X or Y",
    "disjuncted_exclusive": "X ^ Y",
    "implication": "not X or Y",
    "negated": "not X",
    "out": "_B.out_bool(R, X)",
}

_CLASSIFY = (
    "alpha",
    "upper",
    "lower",
    "digit",
    "hexa_digit",
    "space",
    "punctuation",
    "alpha_numeric",
    "printable",
    "graph",
    "control",
)


def _character(wide):
    code = "_B.ord(X)"
    t = {
        "item": "X",
        "code": code,
        "natural_32_code": code,
        "hash_code": code,
        "is_less": "X < Y",
        "is_less_equal": "X <= Y",
        "is_greater": "X > Y",
        "is_greater_equal": "X >= Y",
        "is_equal": "X == Y",
        "three_way_comparison": [(None, "(X > Y) - (X < Y)"), (None, "_B.cmp(X, Y)")],
        "max": [(None, "(X if X >= Y else Y)"), (None, "_B.imax(X, Y)")],
        "min": [(None, "(X if X <= Y else Y)"), (None, "_B.imin(X, Y)")],
        "difference": "_B.ord(X) - _B.ord(Y)",
        "to_character_32": "X",
        "to_hexa_digit": "_B.hexa_value(X)",
    }
    if wide:
        t.update(
            {
                "plus": "_B.chr(_B.ord(X) + Y)",
                "minus": "_B.chr(_B.ord(X) - Y)",
                "next": "_B.chr(_B.ord(X) + 1)",
                "previous": "_B.chr(_B.ord(X) - 1)",
                "to_character_8": "_B.chr(_B.ord(X) & 255)",
                "as_upper": "_B.upper32(X)",
                "as_lower": "_B.lower32(X)",
                "is_digit": "'0' <= X <= '9'",
                "is_hexa_digit": "X in _B.C8_HEXA",
                "is_character_8": "X <= '\\xff'",
                "out": "_B.out_c32(R, X)",
            }
        )
        for prop in _CLASSIFY:
            t.setdefault("is_" + prop, f"_B.is_{prop}32(X)")
    else:
        t.update(
            {
                "plus": "_B.chr((_B.ord(X) + Y) & 255)",
                "minus": "_B.chr((_B.ord(X) - Y) & 255)",
                "next": "_B.chr((_B.ord(X) + 1) & 255)",
                "previous": "_B.chr((_B.ord(X) - 1) & 255)",
                "to_character_8": "X",
                "as_upper": "_B.UPPER8[X]",
                "as_lower": "_B.LOWER8[X]",
                "out": "_B.out_c8(R, X)",
            }
        )
        for prop in _CLASSIFY:
            t["is_" + prop] = f"X in _B.C8_{'HEXA' if prop == 'hexa_digit' else prop.upper()}"
    t["upper"], t["lower"] = t["as_upper"], t["as_lower"]
    return t


_POINTER = {
    "item": "X",
    "hash_code": "X & 2147483647",
    "is_hashable": "X != 0",
    "is_default_pointer": "X == 0",
    "is_equal": "X == Y",
    "plus": "X + Y",
    "to_integer_32": _wrap_text("X", 32, True),
    "out": "_B.out_pointer(R, X)",
}

# ANY's built-ins on any target (a basic value or an object): through the dynamic dispatch.
_ANY = {
    name: f"_B.query(X, {name!r}, R)"
    for name in ("generator", "generating_type", "tagged_out", "twin", "standard_twin", "deep_twin")
}
_ANY.update(
    {
        name: f"_B.call(X, {name!r}, (Y,), R)"
        for name in ("conforms_to", "same_type", "standard_is_equal", "is_deep_equal", "copy", "standard_copy")
    }
)


def _arity(tree_and_counts):
    counts = tree_and_counts[1]
    return 2 if "Z" in counts else (1 if "Y" in counts else 0)


def _build():
    tables = {name: _integer(name, *shape) for name, shape in INTEGER_CLASSES.items()}
    tables.update(
        {
            "REAL_32": _real(32),
            "REAL_64": _real(64),
            "BOOLEAN": _BOOLEAN,
            "CHARACTER_8": _character(False),
            "CHARACTER_32": _character(True),
            "POINTER": _POINTER,
            "ANY": _ANY,
        }
    )
    result = {}
    for class_name, table in tables.items():
        for feature, alts in table.items():
            if isinstance(alts, str):
                alts = [(None, alts)]
            parsed = [(guard, _parse(text)) for guard, text in alts]
            result[(class_name, feature)] = Spec(max(_arity(tree) for _, tree in parsed), parsed)
    return result
