"""Every user-facing diagnostic message, by code: the one table of wording.

Codes of the Eiffel validity rules are spelled as EiffelStudio prints them (VEEN, VUTA(3), ...).
Codes of our own, for conditions ECMA-367 gives no code, are listed here with their meaning:

- SYNTAX: a token the grammar does not allow at that place.
- SYNTAX-END: a construct is not closed by its `end`.
- SYNTAX-RESERVED: a reserved word used where a name is expected.
- SYNTAX-LEXICAL: a character or literal that is not part of any Eiffel token.
- SYNTAX-CLASS: the file does not hold exactly one class.
- SYNTAX-OBSOLETE: pre-ECMA syntax: `indexing`, `is` before a routine body or a constant, `?T`,
  `!T` and `{x: T} e` (an error at the .ecf's `standard` syntax level, the default; a warning at
  `transitional` and `obsolete`), and `creation`, `infix`/`prefix` names (errors at every level).
- SYNTAX-DEPTH: constructs nested deeper than the compiler handles: more than 2,000 pairs of
  parentheses, `not`s, operators, calls, `if`s, loops, `inspect`s, agents ... inside one another
  (docs/GUARANTEES.md, Limits).
- SYNTAX-FEATURE: an `attribute` body on a feature without a type, or an attribute or
  constant declared with arguments.
- SOURCE: a file that cannot be read (missing, not UTF-8).
- ECF: a problem in an .ecf project file; ECF-NOTE: an .ecf setting we ignore.
- ECF-LIBRARY: an .ecf names a library scoopc does not have, or a library .ecf file that is missing.
- ECF-CYCLE: (a warning) libraries whose .ecf files name each other in a cycle.
- ECF-CAPABILITY: (a warning) a library whose .ecf says it does not support the application's
  concurrency (EiffelStudio's order of the capability: thread < none < scoop).
- EXTERNAL: an `external` routine of the program that cannot be bound: an unknown language
  string or form, a Python module or function that is not there, a type that cannot cross to C.
- EXTERNAL-BUILD: the program's C or C++ externals cannot be built (no compiler, a missing
  header or library, a compiler error).
- ONCE-KEY: a once key other than "PROCESS", "THREAD" or "OBJECT".
- FORMAL-TRAITOR (a warning): a value of an unmarked formal generic type `G` passed to a
  non-separate formal in a call on a separate target, or a `G` result of such a call then used as
  non-separate (attached to a non-separate entity or argument, or a call's target). EiffelStudio
  accepts both (it applies VUAR(3) and result adaptation to
  `reference G` only); if an actual generic is a reference type, the value is a traitor.

The validity codes are ECMA-367's as EiffelStudio prints them; for SCOOP, EiffelStudio's
spelling, Gobo's finer conditions being accepted by `scoopc check --explain` as aliases.

Each entry has a `text` template (str.format fields) and a `hint` template a student can act on.
"""

from __future__ import annotations

from typing import NamedTuple


class Message(NamedTuple):
    text: str
    hint: str = ""


MESSAGES: dict[str, Message] = {
    # --- input files --------------------------------------------------------------------
    "SOURCE": Message("cannot read {path}: {reason}"),
    "ECF": Message("{reason}"),
    "ECF-NOTE": Message("{reason}"),
    "ECF-LIBRARY": Message("library `{name}`{location}: {reason}", "{hint}"),
    "ECF-CYCLE": Message(
        "library `{name}` closes a cycle of libraries: {cycle}",
        "each library is read once; break the cycle if EiffelStudio should build the libraries",
    ),
    "ECF-CAPABILITY": Message(
        "library `{name}` supports {capability} `{support}`, not the system's `{wanted}`",
        "the application's setting applies to the library's classes too; "
        "check that the library works under `{wanted}` or change the system's {capability}",
    ),
    # --- syntax ---------------------------------------------------------------------------
    "SYNTAX": Message("{found} is not allowed here; expected {expected}", "{hint}"),
    "SYNTAX-END": Message(
        "missing `end` of the `{construct}`{owner} opened at {opened}",
        "every `{construct}` needs its own `end`: add it before {due}, aligned with the `{construct}`",
    ),
    "SYNTAX-RESERVED": Message(
        "`{word}` is a reserved word and cannot be used as a name",
        "choose another name, for example `{word}_value`",
    ),
    "SYNTAX-LEXICAL": Message("{reason}"),
    "SYNTAX-OBSOLETE": Message("{what}", "{instead}"),
    "SYNTAX-DEPTH": Message(
        "too deeply nested: more than {limit} expressions and instructions inside one another",
        "compute the inner part into a local variable, or move it into a routine of its own",
    ),
    "SYNTAX-CLASS": Message("{reason}", "Eiffel puts one class in each .e file"),
    "SYNTAX-FEATURE": Message(
        "the feature `{name}` mixes an attribute and a routine: an attribute has a type and no arguments",
        "write `{name}: TYPE` (with `attribute ... end` if needed) for an attribute, or `do ... end` for a routine",
    ),
    # --- classes, inheritance, features ---------------------------------------------------
    "VSCN": Message("class {name} is declared twice (also at {other})", "rename one of the classes"),
    "VTCT": Message(
        "type based on unknown class {name}",
        "{hint}",
    ),
    "VTUG(1)": Message(
        "{type} is not generic but is given {given} actual generic parameter(s)", "remove the `[...]` after {type}"
    ),
    "VTUG(2)": Message(
        "{type} needs {expected} actual generic parameter(s), {given} given",
        "write one type for each formal generic parameter of {type}",
    ),
    "VTCG": Message(
        "actual generic {actual} does not conform to the constraint {constraint} of {formal}",
        "use a type that conforms to {constraint}",
    ),
    "VTGC(3)": Message(
        "`{name}` in the creation constraint of {formal} is {how}",
        "list a procedure of exactly one constraining type, by its name after the constraint's renaming",
    ),
    "VTAT(1)": Message(
        "anchor `{anchor}` of `like {anchor}` is not a query, argument or local",
        "anchor the type to an attribute, a function, an argument or a local",
    ),
    "VHPR(1)": Message(
        "{name} inherits from {parent}, which inherits from {name}: a cycle",
        "remove one of the inherit clauses that close the cycle",
    ),
    "VHRC(1)": Message(
        "`{name}` is renamed but {parent} has no feature `{name}`",
        "rename a feature of {parent} (names are case-insensitive)",
    ),
    "VDRS(1)": Message(
        "`{name}` is listed in `redefine` but {parent} has no feature `{name}`",
        "list only features of {parent}, under their name after `rename`",
    ),
    "VDRS(4)": Message(
        "`{name}` is listed in `redefine` but the class does not redeclare it",
        "declare `{name}` in this class, or remove it from the `redefine` clause",
    ),
    "VDUS(1)": Message(
        "`{name}` is listed in `undefine` but {parent} has no feature `{name}`",
        "list only features of {parent}, under their name after `rename`",
    ),
    "VDUS(2)": Message(
        "`{name}` cannot be undefined: it is {what}", "only effective, non-frozen routines can be undefined"
    ),
    "VMSS(1)": Message(
        "`{name}` is listed in `select` but {parent} has no feature `{name}`",
        "list only features of {parent}, under their name after `rename`",
    ),
    "VMRC(2)": Message(
        "`{name}` is inherited in several versions ({versions}) and none is selected",
        "add `select {name}` to the inherit clause of the version to use",
    ),
    "VMFN": Message(
        "two features named `{name}`: {where}", "give the features different names (or `rename` an inherited one)"
    ),
    "VCCH(1)": Message(
        "class {name} has deferred features ({features}) but is not declared `deferred`",
        "implement them, or declare the class `deferred class {name}`",
    ),
    "VDRD(2)": Message(
        "the redeclaration of `{name}` does not match the version of {parent}: {reason}",
        "keep the same number of arguments; argument and result types must conform to the parent's",
    ),
    "VTEC(1)": Message(
        "expanded class {name} cannot be deferred: its values are created directly",
        "remove `deferred` (and implement the deferred features), or remove `expanded`",
    ),
    "VTEC(2)": Message(
        "expanded class {name} must have `default_create` as a creation procedure",
        "add `default_create` to the `create` clause (redefine it to initialise the fields)",
    ),
    "VDJR": Message(
        "`{name}` is inherited from {first} and {second} with different signatures and joined into one feature",
        "make the signatures equal, or rename one of the inherited features",
    ),
    "VFAV(1)": Message(
        "operator `{operator}` on `{name}`: {problem}",
        "remove the alias, give the feature the right number of arguments, or use another operator",
    ),
    "VFAV(2)": Message(
        "bracket alias on `{name}`: {problem}", 'declare one feature like `item alias "[]" (i: INTEGER): G`'
    ),
    "VFAV(3)": Message("parenthesis alias on `{name}`: {problem}", 'declare one routine like `call alias "()" (a: A)`'),
    "VFAV(4)": Message(
        "`convert` mark on alias `{operator}` of `{name}`, which has {count} arguments: "
        "a converting operator takes exactly one",
        "remove `convert`, or give `{name}` one argument",
    ),
    "VFAV(5)": Message(
        "`convert` mark on alias `{operator}` of `{name}`: only an operator alias can convert its target",
        "remove `convert`",
    ),
    "VDPR(1)": Message(
        "`Precursor` in `{name}`, which does not redefine an effective inherited feature",
        "use Precursor only inside a redefinition (listed in `redefine`)",
    ),
    "VDPR(2)": Message(
        "`Precursor {{{parent}}}`: {parent} is not a parent of {cls}",
        "name the parent whose version you redefine, or write `Precursor` alone",
    ),
    # --- entities ------------------------------------------------------------------------
    "VRFA": Message(
        "argument `{name}` has the name of a feature of {cls}", "rename the argument, for example `a_{name}`"
    ),
    "VRLE(1)": Message(
        "local `{name}` has the name of a feature of {cls} (or is called Result)",
        "rename the local, for example `l_{name}`",
    ),
    "VRLE(2)": Message("local `{name}` has the name of an argument", "rename the local, for example `l_{name}`"),
    "VREG": Message("`{name}` is declared twice in the same routine", "remove one declaration or rename it"),
    "VEEN": Message("unknown identifier `{name}` {where}", "{hint}"),
    "VEEN(2)": Message(
        "`Result` is not available in {where}", "only functions (and their postconditions) have a Result"
    ),
    # --- calls and expressions ---------------------------------------------------------
    "VUEX(2)": Message(
        "feature `{name}` of {cls} is not exported to {client}",
        "call it from a class listed in its `feature {{...}}` clause, or export it",
    ),
    "VUAR(1)": Message(
        "wrong number of arguments: {expected} expected, {given} given",
        "check the feature's declaration: give one actual argument per formal argument",
    ),
    "VUAR(2)": Message("actual argument of type {actual} does not fit formal type {formal}: {reason}", "{hint}"),
    "VKCN(1)": Message(
        "`{name}` is a query: its value cannot be used as an instruction",
        "assign the result to a variable, or call a procedure",
    ),
    "VKCN(2)": Message(
        "`{name}` is a procedure: it has no value to use in an expression",
        "call it as an instruction, or use a function",
    ),
    "VWBE": Message("a condition must be BOOLEAN, this is {type}", "compare it, for example `x /= 0` or `x > 0`"),
    "VWEQ": Message(
        "`{operator}` compares values of types {left} and {right}: neither conforms or converts to the other",
        "compare values of the same type, e.g. `n.out ~ s` or `n = s.to_integer`",
    ),
    "VWOE": Message(
        "no feature of {type} has the operator `{operator}`", "check the types of the operands; convert one if needed"
    ),
    "VWMQ": Message(
        "the constant {constant} is not a value of {type}",
        "use a value within the type's range, or a larger type such as INTEGER_64",
    ),
    "VQMC(3)": Message(
        "the integer constant {value} is not a value of {type} ({low} to {high})",
        "use a value within that range, or declare the constant with a larger type such as INTEGER_64",
    ),
    "VJAR": Message("source of type {source} cannot be assigned to a target of type {target}: {reason}", "{hint}"),
    "VJAW": Message(
        "`{name}` cannot be assigned: it is {what}", "assign to a local, to Result or to an attribute of the class"
    ),
    "VBAC(1)": Message(
        "source of type {source} does not fit the assigner's argument type {target}: {reason}",
        "`a.f := v` calls f's assigner command with v: give it a value of type {target}",
    ),
    "VNCP": Message(
        "invalid `convert` clause: {reason}",
        "a conversion procedure is a creation procedure with one argument (`make ({T})`); "
        "a conversion query has no argument (`to_t: {T}`)",
    ),
    "VYCP(2)": Message(
        "`{name}` converts from {type}, which conforms to this class already: conformance needs no conversion",
        "remove {type} from the convert clause",
    ),
    "VYCP(3)": Message(
        "`{name}` converts from {type}, which conforms to this generic class already: conformance needs no conversion",
        "remove {type} from the convert clause",
    ),
    "VYCQ(2)": Message(
        "`{name}` converts to {type}, to which this class conforms already: conformance needs no conversion",
        "remove {type} from the convert clause",
    ),
    "VYCQ(3)": Message(
        "`{name}` converts to {type}, to which this generic class conforms already: conformance needs no conversion",
        "remove {type} from the convert clause",
    ),
    "VFAC(1)": Message(
        "the assigner `{assigner}` of `{name}` is {what}: an assigner must be a procedure of the class",
        "declare `{assigner}` as a procedure (like `set_{name} (v: T) do ... end`), or correct the name after `assign`",
    ),
    "VFAC(2)": Message(
        "the assigner `{assigner}` of `{name}` takes {count} arguments: it needs {needed}, the new value "
        "followed by `{name}`'s own arguments",
        "give `{assigner}` the new value as first argument, then `{name}`'s arguments in their order",
    ),
    "VFAC(3)": Message(
        "the assigner `{assigner}` of `{name}` takes a first argument of type {type}: it must be "
        "`{name}`'s type, {result}",
        "declare `{assigner}`'s first argument as `v: like {name}`",
    ),
    "VFAC(4)": Message(
        "argument {index} of the assigner `{assigner}` of `{name}` has type {type}: it must be {expected}, "
        "the type of `{name}`'s argument in that place",
        "declare `{assigner}`'s arguments after the first with the types of `{name}`'s arguments",
    ),
    "VBAC(2)": Message(
        "`{name}` has no assigner command, so it cannot be the target of `:=`",
        "declare it `{name}: T assign set_{name}`, or call the setter",
    ),
    "VUOT(1)": Message(
        "object-test local `{name}` has the name of another entity or feature",
        "choose another name, for example `l_{name}`",
    ),
    "VOIT(1)": Message(
        "`across` needs an ITERABLE, this is {type}",
        "iterate over a list, array, interval (`1 |..| n`) or another ITERABLE",
    ),
    "VOIT(2)": Message(
        "iteration cursor `{name}` has the name of another entity or feature", "choose another name, for example `ic`"
    ),
    "VAOL(1)": Message("`old` is only allowed in postconditions", "move the expression into an `ensure` clause"),
    "VXRT": Message(
        "`retry` is only allowed in a `rescue` clause",
        "to repeat work in the body, use a loop; `retry` restarts a routine after an exception",
    ),
    "VOMB(2)": Message(
        "inspect choice is not a constant of type {type}",
        "use manifest constants or constant attributes of the inspected type",
    ),
    "VOMB(3)": Message(
        "this inspect choice repeats a value of an earlier one", "each value may appear in one `when` only"
    ),
    "VGCC(1)": Message(
        "cannot create an object of deferred class {cls}",
        "create an object of an effective descendant: `create {{MY_{cls}}} x.make`",
    ),
    "VGCC(3)": Message(
        "creation type {type} does not conform to the target's type {target}",
        "create an object of a descendant of {target} (or change the target's type)",
    ),
    "VGCC(5)": Message(
        "creating a {cls} needs a creation procedure ({procedures})", "write `create x.make (...)` with one of them"
    ),
    "VGCC(6)": Message(
        "`{name}` is not a creation procedure of {cls} available here (creation procedures: {procedures})",
        "use a procedure listed in the class's `create` clause",
    ),
    "VEVI": Message(
        "`{name}` {where}",
        "give it a value on every path first (an attached entity is never Void), or declare it `detachable`",
    ),
    "VUTA(2)": Message(
        "call on `{target}`, which may be Void (type {type})",
        "test it first: `if attached {target} as l_x then l_x.f end`, or make it attached",
    ),
    # --- SCOOP ------------------------------------------------------------------------------
    "VUTA(3)": Message(
        "call on separate `{target}` (type {type}) that is not controlled",
        "pass `{target}` as an argument of a routine (which reserves it) and call it there, "
        "or wrap the call in `separate {target} as {fresh} do {fresh}.f end`",
    ),
    "VUAR(3)": Message(
        "`{actual}` is a non-separate reference passed in a call on a separate target to a formal of "
        "non-separate type {type}: the supplier would hold a reference into this processor (a traitor)",
        "declare the formal `separate`; when the supplier needs its own copy of a STRING it "
        "makes one with `create s.make_from_separate (the_formal)`",
    ),
    "FORMAL-TRAITOR": Message(
        "{what} of formal generic type {formal} {how}: if an actual generic for {formal} is a reference type, "
        "{risk} (a traitor)",
        "declare {formal} `expanded` in the class header when only values such as INTEGER are meant, or use "
        "separate types; EiffelStudio accepts this, so it is a warning",
    ),
    "VUAR(4)": Message(
        "expanded actual of type {type} holds non-separate references and is passed to another processor",
        "make the expanded class's reference attributes `separate`, or pass the values separately",
    ),
    "VUER": Message(
        "the result of type {type} holds non-separate references and would come from another processor",
        "return the values as separate references, or copy them explicitly",
    ),
    "FRESH_IDENTIFIER": Message(
        "separate block local `{name}` has the name of another entity or feature",
        "choose another name, for example `l_{name}`",
    ),
    "V1SE": Message(
        "an expression used in a separate instruction must be of a separate type, this is {type}", "{hint}"
    ),
    "V1SE(3)": Message(
        "separate block local `{name}` cannot be assigned",
        "it stands for the reserved object; assign to a local declared in the routine instead",
    ),
    "VFFD(7)": Message(
        "once function `{name}` has a type that depends on the object (a formal generic or `like Current`), "
        "but its one result is shared",
        'give it a fixed type, or make it `once ("OBJECT")` to have one result per object',
    ),
    "VGCP(2)": Message("`{name}` in the creation clause is {what}", "list procedures of this class after `create`"),
    "VGCP(3)": Message("`{name}` is listed twice in the creation clauses", "list each creation procedure once"),
    "VOMB(1)": Message(
        "`inspect` needs an integer, character or string expression, this is {type}",
        "use `if ... elseif ...` for other types",
    ),
    "VAVE": Message(
        "a loop variant must be an INTEGER expression, this is {type}",
        "write the variant as an integer that decreases at each iteration, e.g. `n - i`",
    ),
    "VFFD(8)": Message(
        '`once ("PROCESS")` function `{name}` has the non-separate type {type}: '
        "all processors would share an object of one processor",
        "declare the result `separate {type}`",
    ),
    "VAPE": Message(
        "`{name}` in the precondition of `{routine}` is exported to {exports} only, but `{routine}` is "
        "available to {client}: that client could not test what it must ensure",
        "export `{name}` at least as widely as `{routine}` (e.g. move it to the `feature` clause of `{routine}`)",
    ),
    "VSRT": Message(
        "root class {name} is {what}",
        "choose an effective, non-generic class as the root (an heir that fixes the generics, if need be)",
    ),
    "VSRP(1)": Message(
        "root procedure `{creator}` is not a creation procedure of {name} (it has: {listed})",
        "list `{creator}` in {name}'s `create` clause, or name one of its creation procedures as the root",
    ),
    "VSRP(2)": Message(
        "root procedure {name}.{creator} has arguments: nothing could pass them when the program starts",
        "remove the arguments (read command-line arguments with ARGUMENTS_32), or use another creation procedure",
    ),
    "VSRP(3)": Message(
        "root procedure {name}.{creator} has a precondition: nothing could establish it when the program starts",
        "remove the `require` clause and check the condition in the body instead",
    ),
    "ONCE-KEY": Message(
        'unknown once key "{key}"', 'use "PROCESS", "THREAD" or "OBJECT" (or none: once per processor)'
    ),
    "EXTERNAL": Message("{reason}", "see docs/LANGUAGE.md, Externals, for the forms scoopc accepts"),
    "EXTERNAL-BUILD": Message("{reason}", "{hint}"),
}
