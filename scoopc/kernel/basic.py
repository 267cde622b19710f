"""Built-in features of the basic classes (stdlib/base/kernel: INTEGER_8..64, NATURAL_8..64,
REAL_32/64, BOOLEAN, CHARACTER_8/32, POINTER): the run-time helpers generated code calls as
`B.name(...)` (`from scoopc.kernel import basic as B`), plus the code generator's entry points.
The helpers are defined in scoopc/kernel/basic_ops.py (which imports nothing of the kernel, so
the dispatch can use them) and re-exported here, along with:

- `inline(class_name, feature_name, current, arguments, region=None) -> ast.expr`
  (scoopc/kernel/basic_inline.py): the Python expression of a built-in feature;
- `call(target, name, arguments=(), region=None)`, `query(target, name, region=None)`,
  `call_as(kind, ...)`, `query_as(kind, ...)` (scoopc/kernel/basic_dispatch.py): dynamic
  dispatch when the static type is ANY, COMPARABLE, NUMERIC, HASHABLE, a formal generic, ...;
- `same(a, b)` (Eiffel `=`) and `equal(a, b)` (Eiffel `~`) (scoopc/kernel/basic_dispatch.py).

Semantics are EiffelStudio's (finalized C code on x86-64), with these sources:
- `out`: Src/C/run-time/out.c (EiffelStudio 20.x): c_outi/c_outi64/c_outu/c_outu64 print "%d",
  "%u" (decimal); c_buffero_outr64 prints "NaN", "Infinity", "-Infinity", else "%.17g";
  c_buffero_outr32 the same with "%g"; c_outc the character; eif_out__c4_s1 (CHARACTER_32 to
  STRING_8) the character if its code is below 0x80, else "U+" and at least 4 upper-case hex
  digits; c_outp "0x%lX". BOOLEAN prints "True"/"False". Python's "%.17g"/"%g" give the same
  digits as glibc's printf (both are correctly rounded).
- REAL comparisons: Src/C/run-time/eif_helpers.h (no EIF_IEEE_BEHAVIOR): NaN is the smallest
  value and equal to itself (`eif_is_less_real_64 (d1, d2) = d1 == d1 ? d1 < d2 : d2 == d2`,
  ...), max/min/three_way_comparison through these; `abs` is `d > 0 ? d : -d` (so 0.0.abs is
  -0.0), integer `abs` wraps (`i > 0 ? i : -i`).
- ELKS library/base/elks/kernel/*_ref.e (19.05): hash codes (integers: value with the sign bit
  cleared, `& 0x7FFFFFFF`; reals: `truncated_to_integer.hash_code`; characters: the code;
  BOOLEAN 1/0), `sign`, `rounded = sign * (abs + 0.5).floor`, `rounded_real_32` adds
  {REAL_32} 0.5, `to_hex_string` (upper case, all digits), `exponentiable`, `is_hashable`,
  CHARACTER_8's ASCII-only classification table (codes 128..255 have no property).
- Real to integer conversions are C casts (`(EIF_INTEGER_32) d`): x86-64's cvttsd2si gives the
  smallest integer ("integer indefinite") for NaN, infinities and values out of range.
- Integer `//` and `\\` truncate toward zero (C); a zero divisor raises ZeroDivisionError (also
  for integer `/`). REAL `/` is IEEE (x / 0.0 is an infinity or NaN, as in EiffelStudio).
- Shifts by the whole width (allowed by the preconditions, undefined in C) shift every bit out.

Integer `+`, `-` and `*` (binary and unary) are ring operations: reducing modulo 2^n commutes
with them, so the code generator computes a whole tree of them with Python's exact integers and
brings the result into the type once (scoopc/codegen/exprs.py: `_B.i32(a * b + c)`, or a range
test after an assignment); every other signed result that can overflow is one helper call
(`_B.i32(x << n)`), unsigned ones a mask.
"""

# The dependencies go one way: basic_ops (the helpers) <- basic_dispatch <- this module, which
# generated code imports as `B`; basic_inline is independent.
from .basic_dispatch import call, call_as, equal, query, query_as, same
from .basic_inline import inline, specs
from .basic_ops import *  # noqa: F403  (every helper is `B.name` for generated code and templates)

__all__ = ["inline", "specs", "call", "call_as", "query", "query_as", "same", "equal"]
