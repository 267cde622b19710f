"""What `scoopc check --explain CODE` prints: for every diagnostic code, the rule in plain words,
a wrong example and its fix. Gobo's finer SCOOP codes are accepted as aliases of ours.
"""

from __future__ import annotations

import textwrap
from typing import NamedTuple


class Explanation(NamedTuple):
    rule: str  # the validity rule, 1-4 sentences
    wrong: str  # a short Eiffel example that breaks the rule
    fix: str  # the corrected example, a blank line, then one sentence saying what changed


def _x(rule: str, wrong: str, fix: str, why: str) -> Explanation:
    def block(text: str) -> str:
        return textwrap.dedent(text).strip("\n")

    return Explanation(" ".join(rule.split()), block(wrong), block(fix) + "\n\n" + " ".join(why.split()))


EXPLANATIONS: dict[str, Explanation] = {
    # --- input files ------------------------------------------------------------------------------
    "SOURCE": _x(
        """A file given on the command line or found in a cluster could not be read: it does not exist,
        cannot be opened, or is not UTF-8 text. Eiffel sources are read as UTF-8.""",
        """
        scoopc check aplication.e
        """,
        """
        scoopc check application.e
        """,
        "Name a file that exists; re-save a source written in another encoding as UTF-8.",
    ),
    "ECF": _x(
        """An .ecf project file could not be used: it is not well-formed XML, defines no target, has no
        target of the name given with `--target`, or names a cluster directory that does not exist.""",
        """
        <cluster name="app" location="./scr/"/>
        """,
        """
        <cluster name="app" location="./src/"/>
        """,
        "Make every cluster location point at an existing directory (relative to the .ecf file).",
    ),
    "ECF-NOTE": _x(
        """Not an error: the .ecf file holds a setting or element that scoopc does not use (for example
        a `<setting>` for the C compiler), so it is ignored.""",
        """
        <setting name="console_application" value="true"/>
        """,
        """
        <!-- nothing to change: the setting is simply not needed by scoopc -->
        """,
        "Leave the setting if the project is also built with EiffelStudio; scoopc just says it skips it.",
    ),
    "ECF-LIBRARY": _x(
        """An .ecf file names a library that scoopc cannot load: one of EiffelStudio's that scoopc does
        not have (scoopc has EiffelBase, EiffelThread, EiffelTime and Roboscoop, found through
        `$ISE_LIBRARY/library/<name>/<name>.ecf` or by name), or a library of your own whose `location`
        is not an .ecf file. A library of your own is read from its .ecf file, with the libraries it names.""",
        """
        <library name="shapes" location="../shape/shapes.ecf"/>
        """,
        """
        <library name="shapes" location="../shapes/shapes.ecf"/>
        """,
        "Give the location of the library's .ecf file, relative to the .ecf file that names it.",
    ),
    "ECF-CYCLE": _x(
        """A warning: libraries name each other in a cycle (a library's .ecf names a library whose .ecf,
        directly or through others, names the first). scoopc reads each library once and goes on;
        the cycle is reported because it usually is a mistake in a location.""",
        """
        <!-- a.ecf -->  <library name="b" location="../b/b.ecf"/>
        <!-- b.ecf -->  <library name="a" location="../a/a.ecf"/>
        """,
        """
        <!-- a.ecf -->  <library name="b" location="../b/b.ecf"/>
        <!-- b.ecf -->  (no library a: move what both need into a third library)
        """,
        "Make the libraries depend on each other in one direction only.",
    ),
    "ECF-CAPABILITY": _x(
        """A warning: a library's .ecf says which concurrency it supports (`<capability><concurrency
        support="..."/></capability>`), and the application uses one the library does not support
        (EiffelStudio orders the values thread < none < scoop: supporting one means supporting those
        before it). The application's setting applies to every class, the library's too.""",
        """
        <!-- app.ecf -->   <capability><concurrency support="scoop"/></capability>
        <!-- tools.ecf --> <capability><concurrency support="thread"/></capability>
        """,
        """
        <!-- app.ecf -->   <capability><concurrency support="thread"/></capability>
        <!-- tools.ecf --> <capability><concurrency support="thread"/></capability>
        """,
        "Use a concurrency every library supports, or make the library support the application's.",
    ),
    # --- syntax -----------------------------------------------------------------------------------
    "SYNTAX": _x(
        """The text does not follow Eiffel's grammar at this point: a token appears where the language
        expects something else. The message lists what could come here; the mistake is often just
        before the reported place (a missing `then`, `do`, `:=` or closing parenthesis).""",
        """
        if x > 0
            print (x)
        end
        """,
        """
        if x > 0 then
            print (x)
        end
        """,
        "The condition of an `if` is followed by `then`.",
    ),
    "SYNTAX-END": _x(
        """Every compound construct (`class`, routine body, `if`, `inspect`, `from`/`loop`, `across`,
        `check`, `debug`, `separate`, `attached ... then` block) is closed by its own `end`. The error
        names the construct whose `end` is missing and where it was opened.""",
        """
        if x > 0 then
            print (x)
        -- the `if` is never closed
        """,
        """
        if x > 0 then
            print (x)
        end
        """,
        "Close the `if` with `end` before the routine's own `end`.",
    ),
    "SYNTAX-RESERVED": _x(
        """Keywords such as `end`, `from`, `loop`, `class`, `result`, `current` or `old` are reserved:
        they cannot name a feature, an argument or a local. Keywords are case-insensitive, so `Loop`
        and `LOOP` are reserved too.""",
        """
        set_range (from: INTEGER; to: INTEGER)
        """,
        """
        set_range (a_from: INTEGER; a_to: INTEGER)
        """,
        "Choose a name that is not a keyword; the `a_` prefix is the usual Eiffel style for arguments.",
    ),
    "SYNTAX-LEXICAL": _x(
        """A character or literal that is no Eiffel token: an unterminated string or character constant,
        a stray character such as `\\` or `$`, or a character outside Eiffel text. Special characters in
        strings are written with `%`: `%N` (new line), `%T` (tab), `%"` (quote), `%%` (percent).""",
        """
        print ("Hello\\n")
        """,
        """
        print ("Hello%N")
        """,
        "Eiffel escapes special characters with `%`, not with a backslash.",
    ),
    "SYNTAX-CLASS": _x(
        """Each .e file holds exactly one class, and the file is named after it in lower case
        (class SHAPE lives in shape.e). An empty file or a second class in the same file is an
        error.""",
        """
        -- shapes.e
        class CIRCLE ... end
        class SQUARE ... end
        """,
        """
        -- circle.e
        class CIRCLE ... end
        -- square.e
        class SQUARE ... end
        """,
        "Move each class into its own file.",
    ),
    "SYNTAX-DEPTH": _x(
        """scoopc checks, compiles and runs constructs nested up to 2,000 deep inside one
        instruction: pairs of parentheses, `not`s, chains of operators (`a + b + ...` counts one
        level per operator), calls whose argument is a call, `if`s inside `if`s, loops, `across`,
        `inspect` and separate blocks inside one another, manifest tuples and arrays, inline agents.
        Each expression and instruction is a level; their parts (an `elseif` or `when` branch) are
        not, and an `elseif` chain does not nest. Anything deeper is reported at the first
        construct past the limit, before the checker looks at it.""",
        """
        x := ((((((... 2,001 pairs ... (a + 1) ...))))))
        """,
        """
        inner := (... a first part ...)
        x := (... the rest, using inner ...)
        """,
        "Split the expression with a local variable, or the nested instructions with a routine.",
    ),
    "SYNTAX-OBSOLETE": _x(
        """Pre-ECMA syntax that modern EiffelStudio only accepts in its obsolete-syntax mode:
        `indexing` (now `note`), `is` before a routine body or a constant's value, `creation` (now
        `create`), `infix`/`prefix` names (now `alias`), `?T` (now `detachable T`) and the object
        test `{x: T} e` (now `attached {T} e as x`). scoopc reads ECMA-367 syntax only.""",
        """
        indexing
            description: "A counter"
        class COUNTER
        feature
            increment is
                do count := count + 1 end
        """,
        """
        note
            description: "A counter"
        class COUNTER
        feature
            increment
                do count := count + 1 end
        """,
        "Write `note` instead of `indexing`, and drop `is` before a routine body.",
    ),
    "SYNTAX-FEATURE": _x(
        """An attribute has a type and no arguments; a routine may have arguments. An `attribute` body
        therefore needs a type, and an attribute or constant cannot be declared with arguments.""",
        """
        scale (factor: INTEGER): INTEGER = 10
        """,
        """
        scale (factor: INTEGER): INTEGER
            do
                Result := 10 * factor
            end
        """,
        "A feature with arguments is a routine: give it a `do` body.",
    ),
    # --- Eiffel validity rules: classes and types ------------------------------------------------
    "VSCN": _x(
        """Class names are unique in a program: two files of the clusters (or a file and a class of the
        standard library) may not declare classes with the same name, compared without regard to
        case.""",
        """
        -- src/point.e        class POINT ...
        -- old/point.e        class POINT ...
        """,
        """
        -- src/point.e        class POINT ...
        -- old/old_point.e    class OLD_POINT ...
        """,
        "Rename one of the classes (and its file), or leave the old copy out of the clusters you check.",
    ),
    "VTCT": _x(
        """Every class name used in a type must name a class of the program: a class of one of its
        clusters, a class of the standard library, or a built-in name such as INTEGER or STRING.
        Usually the name is misspelt or the file holding the class is not part of the project.""",
        """
        shape: detachable SHAPE   -- there is no class SHAPE
        """,
        """
        shape: detachable FIGURE  -- FIGURE is declared in figure.e
        """,
        "Spell the class as it is declared, or add its file to a cluster of the project.",
    ),
    "VTUG(1)": _x(
        """Only a generic class, declared with formal parameters such as `class BOX [G]`, accepts actual
        generic parameters in brackets. Writing `POINT [INTEGER]` for a class that has none is
        invalid.""",
        """
        origin: POINT [INTEGER]   -- class POINT has no generic parameter
        """,
        """
        origin: POINT
        """,
        "Drop the brackets, or declare the class generic if it should hold values of a chosen type.",
    ),
    "VTUG(2)": _x(
        """A generic type gives exactly as many actual parameters as its class declares formal ones:
        `PAIR [G, H]` needs two, `ARRAY [G]` one.""",
        """
        names: PAIR [STRING]              -- class PAIR [G, H]
        """,
        """
        names: PAIR [STRING, STRING]
        """,
        "Give one actual type for each formal generic parameter of the class.",
    ),
    "VTCG": _x(
        """When a formal generic parameter is constrained (`G -> ANIMAL`), every actual parameter must
        conform to the constraint: ANIMAL itself or one of its descendants. If the constraint names
        creation procedures (`G -> ANIMAL create make end`), the actual must offer them as creation
        procedures.""",
        """
        class CAGE [G -> ANIMAL] ...
        rock_cage: CAGE [ROCK]            -- ROCK does not inherit from ANIMAL
        """,
        """
        dog_cage: CAGE [DOG]              -- DOG inherits from ANIMAL
        """,
        "Use an actual type that conforms to the constraint, or loosen the constraint.",
    ),
    "VTGC(3)": _x(
        """The creation procedures a constraint lists (`G -> A create make end`) must be procedures
        of the constraint: each name, after the constraint's own renaming, must be a feature of
        exactly one of the constraining types, so that `create x.make` on a G knows what it calls
        (EiffelStudio's code; ECMA-367-2 numbers the rule VTGC, later editions VGGC).""",
        """
        class POOL [G -> RESOURCE create open end]   -- RESOURCE has `make`, not `open`
        """,
        """
        class POOL [G -> RESOURCE create make end]
        """,
        "Name a creation procedure the constraint class has, or add it to that class.",
    ),
    "VTAT(1)": _x(
        """In an anchored type `like x`, the anchor `x` must be a query of the class, an argument or a
        local of the enclosing routine, or `Current`.""",
        """
        total: INTEGER
        average: like totl
        """,
        """
        total: INTEGER
        average: like total
        """,
        "Anchor the type to an entity that exists (here the misspelt `totl` is `total`).",
    ),
    # --- inheritance -------------------------------------------------------------------------------
    "VHPR(1)": _x(
        """Inheritance may not go round in a circle: a class cannot be its own ancestor, directly
        (`class A inherit A`) or through other classes (A inherits from B and B from A).""",
        """
        class NODE
        inherit
            NODE
        """,
        """
        class NODE
        feature
            next: detachable NODE
        """,
        "A class that needs another object of its own kind refers to it through an attribute.",
    ),
    "VHRC(1)": _x(
        """A `rename` clause can only rename a feature that the parent really has, under the name it
        has in that parent.""",
        """
        inherit
            ANIMAL
                rename fly as soar end    -- ANIMAL has no `fly`
        """,
        """
        inherit
            ANIMAL
                rename speak as talk end
        """,
        "Rename only features of the parent, spelt as the parent spells them.",
    ),
    "VDRS(1)": _x(
        """A `redefine` clause may only list features that the parent has (under their name in the
        parent, after any renaming). A brand-new feature needs no `redefine`: just declare it.""",
        """
        inherit
            ANIMAL
                redefine fly end          -- ANIMAL has no `fly`
        """,
        """
        inherit
            ANIMAL
        feature
            fly do print ("flap%N") end
        """,
        "Remove the name from `redefine` when the feature is new in this class.",
    ),
    "VDRS(4)": _x(
        """Every feature listed in a `redefine` clause must be given a new declaration in the class
        body. Listing it without redeclaring it is a mistake.""",
        """
        inherit
            ANIMAL
                redefine speak end
        feature
            purr do print ("Purr%N") end  -- but no new `speak`
        """,
        """
        inherit
            ANIMAL
                redefine speak end
        feature
            speak do print ("Meow%N") end
        """,
        "Write the new version of the feature, or remove its name from the `redefine` clause.",
    ),
    "VDUS(1)": _x(
        """An `undefine` clause may only name features that the parent has (under their name in the
        parent, after any renaming).""",
        """
        inherit
            ANIMAL
                undefine fly end          -- ANIMAL has no `fly`
        """,
        """
        inherit
            ANIMAL
                undefine speak end
        """,
        "Undefine only features the parent has, spelt as the parent spells them.",
    ),
    "VDUS(2)": _x(
        """`undefine` turns an inherited routine into a deferred one. It therefore applies only to
        effective routines that descendants may change: not to attributes, constants or `frozen`
        features.""",
        """
        inherit
            MACHINE
                undefine serial end       -- `serial` is an attribute
        """,
        """
        inherit
            MACHINE
                undefine describe end     -- `describe` is a routine
        """,
        "Undefine only routines that are not frozen; keep attributes and constants as they are.",
    ),
    "VMSS(1)": _x(
        """A `select` clause may only name features that the parent has (under their final name after
        renaming). It chooses which version of a repeatedly inherited feature dynamic binding uses.""",
        """
        inherit
            ANIMAL
                select fly end            -- ANIMAL has no `fly`
        """,
        """
        inherit
            DOG
                rename speak as bark select bark end
            CAT
                rename speak as meow end
        """,
        "Select a feature the parent has, and only where a repeated ancestor gives two versions.",
    ),
    "VMRC(2)": _x(
        """When a class inherits a feature of a common ancestor along two paths and ends up with two
        different versions of it, a call of the ancestor's feature on an object of the class would be
        ambiguous. The class must `select` exactly one of the versions.""",
        """
        class CAT_DOG
        inherit
            DOG rename speak as bark end
            CAT rename speak as meow end
        """,
        """
        class CAT_DOG
        inherit
            DOG rename speak as bark select bark end
            CAT rename speak as meow end
        """,
        "Name one version in a `select` clause: calls through ANIMAL then use `bark`.",
    ),
    "VMFN": _x(
        """In a class each final feature name denotes exactly one feature. Declaring a name twice,
        declaring again a feature a parent already has without listing it in `redefine`, or
        inheriting two different effective features under the same name all break this rule.""",
        """
        class DOG
        inherit
            ANIMAL
        feature
            speak do print ("Woof%N") end   -- ANIMAL already has `speak`
        """,
        """
        class DOG
        inherit
            ANIMAL
                redefine speak end
        feature
            speak do print ("Woof%N") end
        """,
        """List an inherited feature in `redefine` to give it a new version; rename one of two clashing
        features, or undefine one of them to join them.""",
    ),
    "VDRD(2)": _x(
        """A redeclared feature keeps a signature that conforms to its parent's: the same number of
        arguments, argument and result types that conform to the inherited ones, and a query stays a
        query.""",
        """
        -- in ANIMAL:  legs: INTEGER
        legs: BOOLEAN
            do Result := False end
        """,
        """
        legs: INTEGER
            do Result := 0 end
        """,
        "Keep the inherited types (or descendants of them) when redefining a feature.",
    ),
    "VCCH(1)": _x(
        """A class that has a deferred feature, declared `deferred` in the class or inherited and not
        effected, must itself be declared `deferred class`. Only classes with no deferred feature can
        be effective.""",
        """
        class SHAPE
        feature
            area: REAL_64 deferred end
        """,
        """
        deferred class SHAPE
        feature
            area: REAL_64 deferred end
        """,
        "Mark the class `deferred`, or give every deferred feature an implementation.",
    ),
    "VDPR(1)": _x(
        """`Precursor` calls the parent's version of the routine being redefined. It may only appear in
        a routine that redefines an inherited effective routine.""",
        """
        class ROBOT            -- no parent has `speak`
        feature
            speak do Precursor; print ("Beep%N") end
        """,
        """
        class ROBOT
        feature
            speak do print ("Beep%N") end
        """,
        "Use `Precursor` only in a redefinition, where there is a parent version to call.",
    ),
    "VDPR(2)": _x(
        """In `Precursor {P}`, P must be a parent of the class (named in its `inherit` clause) from
        which the routine being redefined comes.""",
        """
        class DOG
        inherit ANIMAL redefine speak end
        feature
            speak do Precursor {CAT} end     -- CAT is not a parent
        """,
        """
        speak do Precursor {ANIMAL} end
        """,
        "Name the parent whose version you want, or write plain `Precursor`.",
    ),
    # --- names ------------------------------------------------------------------------------------
    "VRFA": _x(
        """A formal argument may not have the name of a feature of the class (names are compared
        without regard to case): inside the routine it would hide that feature.""",
        """
        count: INTEGER
        set_count (count: INTEGER) do ... end
        """,
        """
        count: INTEGER
        set_count (a_count: INTEGER) do count := a_count end
        """,
        "Give arguments names of their own; the `a_` prefix is the usual Eiffel style.",
    ),
    "VRLE(1)": _x(
        """A local variable may not have the name of a feature of the class (compared without regard
        to case): it would hide the feature.""",
        """
        count: INTEGER
        show
            local count: INTEGER do ... end
        """,
        """
        show
            local l_count: INTEGER do ... end
        """,
        "Rename the local; the `l_` prefix is the usual Eiffel style.",
    ),
    "VRLE(2)": _x(
        """A local variable may not have the name of an argument of the same routine.""",
        """
        show (n: INTEGER)
            local n: INTEGER do ... end
        """,
        """
        show (n: INTEGER)
            local i: INTEGER do ... end
        """,
        "Use a different name for the local; the argument already holds the value passed in.",
    ),
    "VREG": _x(
        """Within one routine, each name among its arguments and locals is declared only once.""",
        """
        shift (dx: INTEGER; dx: INTEGER)
        """,
        """
        shift (dx: INTEGER; dy: INTEGER)
        """,
        "Give the second entity its own name.",
    ),
    "VEEN": _x(
        """Every name must be known where it is used. Unqualified, it must be a feature of the class,
        an argument, a local, `Result`, or an object-test, iteration or separate-block local in
        scope; in a qualified call `x.f`, `f` must be a feature of the class of `x`'s type.""",
        """
        total := totl + 1        -- misspelt
        print (p.z)              -- POINT has only x and y
        """,
        """
        total := total + 1
        print (p.y)
        """,
        "Check the spelling, and the class of the target's type, which decides the features you may call.",
    ),
    "VEEN(2)": _x(
        """`Result` exists only in functions (and attribute bodies) and their postconditions: a
        procedure returns nothing and a class invariant belongs to no routine.""",
        """
        reset
            do
                count := 0
                Result := count
            end
        """,
        """
        reset: INTEGER
            do
                count := 0
                Result := count
            end
        """,
        "Make the routine a function (give it a result type), or drop the use of `Result`.",
    ),
    "VUEX(2)": _x(
        """A qualified call `x.f` is allowed only if `f` is exported to the calling class. Features
        under `feature {NONE}` can only be called unqualified, by the class and its descendants;
        features under `feature {A, B}` only by A, B and their descendants.""",
        """
        -- in ACCOUNT:  feature {NONE} pin: INTEGER
        print (acc.pin)
        """,
        """
        -- in ACCOUNT:  feature {NONE} pin: INTEGER
        --              feature is_valid_pin (n: INTEGER): BOOLEAN do Result := n = pin end
        print (acc.is_valid_pin (1234))
        """,
        "Call a feature the class exports to you, or export the feature if clients really need it.",
    ),
    "VUAR(1)": _x(
        """A call passes exactly as many actual arguments as the routine declares formal arguments
        (also for creation calls and agents' closed arguments).""",
        """
        -- move (dx, dy: INTEGER)
        p.move (1, 2, 3)
        """,
        """
        p.move (1, 2)
        """,
        "Pass one actual argument for each formal argument, in order.",
    ),
    "VUAR(2)": _x(
        """Each actual argument must conform (or convert) to the type of its formal argument. In
        void-safe code a detachable actual cannot be passed to an attached formal, and with SCOOP a
        separate actual cannot be passed to a non-separate formal: the object may belong to another
        processor. That holds even for a value read from the call's own target (`x.f (x.g)`), as in
        EiffelStudio: the rule looks at separateness, not at which processor the value is on.""",
        """
        -- show (s: STRING);  name: detachable STRING
        p.move ("one", 2)
        show (name)
        -- SCOOP: in take (buffer: separate BUFFER), whose `last: STRING` is on buffer's processor
        show (buffer.last)
        """,
        """
        p.move (1, 2)
        if attached name as l_name then
            show (l_name)
        end
        show (create {STRING}.make_from_separate (buffer.last))     -- or: show (s: separate STRING)
        """,
        """Pass a value of the formal's type; test a detachable value with an object test first (and for
        a separate value, declare the formal `separate`).""",
    ),
    "VKCN(1)": _x(
        """A query (attribute, function or constant) returns a value; written alone as an instruction
        its value would be lost. Only procedures can be called as instructions.""",
        """
        p.x
        """,
        """
        print (p.x)
        """,
        "Use the value of the query: assign it, pass it on, or test it.",
    ),
    "VKCN(2)": _x(
        """A procedure returns nothing, so it cannot be used where a value is needed: on the right of
        `:=`, as an argument, or as an operand.""",
        """
        n := reset            -- `reset` is a procedure
        """,
        """
        reset
        n := count
        """,
        "Call the procedure as an instruction, then read the value from a query.",
    ),
    "VWBE": _x(
        """Conditions are BOOLEAN: the test of `if`/`elseif`, a loop's `until`, the assertions of
        `require`, `ensure`, `invariant` and `check`, and the operands of `and`, `or`, `xor`,
        `implies` and `not`. Eiffel does not treat numbers as truth values.""",
        """
        if count then
            print ("some%N")
        end
        """,
        """
        if count > 0 then
            print ("some%N")
        end
        """,
        "Write the comparison you mean; a number is not a truth value.",
    ),
    "VWOE": _x(
        """An operator expression `a + b` calls the feature of `a`'s class that carries the alias
        `"+"` (with one argument; a unary operator with none). If that class has no such feature,
        the expression is invalid.""",
        """
        class POINT feature x, y: INTEGER end
        print (p + q)
        """,
        """
        class POINT
        feature
            x, y: INTEGER
            plus alias "+" (other: POINT): POINT do ... end
        """,
        "Give the class a feature with that operator as its alias, or call a named feature.",
    ),
    "VJAR": _x(
        """In `target := source`, the type of the source must conform to the type of the target, or
        convert to it through a `convert` clause. A detachable value cannot go into an attached
        target, and with SCOOP a separate value cannot go into a non-separate target.""",
        """
        n: INTEGER;  name: STRING;  found_name: detachable STRING
        n := "seven"
        name := found_name
        -- SCOOP: in take (buffer: separate BUFFER), whose `last: STRING` is on buffer's processor
        name := buffer.last
        """,
        """
        n := 7
        if attached found_name as l_name then
            name := l_name
        end
        name := create {STRING}.make_from_separate (buffer.last)   -- a copy on this processor
        """,
        """Assign a value of the target's type; test a detachable source with an object test first; copy a
        separate object with `make_from_separate`, or declare the target `separate` too.""",
    ),
    "VJAW": _x(
        """Only a variable can be the target of an assignment or of a creation: an attribute of the
        current class, a local or `Result`. Formal arguments, functions, `Current`, and the locals
        bound by object tests, `across` and separate blocks are read-only.""",
        """
        set_count (a_count: INTEGER)
            do
                a_count := 0
            end
        """,
        """
        set_count (a_count: INTEGER)
            do
                count := a_count
            end
        """,
        "Assign to an attribute or a local; copy an argument into a local if you need to change it.",
    ),
    "VBAC(1)": _x(
        """`x.f := v` is a short form of a call to `f`'s assigner command (`f: T assign set_f`), so `v`
        must conform (or convert) to the argument type of that command, as for any call.""",
        """
        -- value: INTEGER assign set_value
        box.value := "ten"
        """,
        """
        box.value := 10
        """,
        "Give the assigner a value of the type it expects.",
    ),
    "VBAC(2)": _x(
        """`x.f := v` and `x [i] := v` are allowed only if the query `f` (or the feature with alias
        `"[]"`) declares an assigner command with `assign`.""",
        """
        -- size: INTEGER   (no assigner)
        box.size := 3
        """,
        """
        -- size: INTEGER assign set_size
        box.size := 3
        """,
        "Declare an assigner (`assign set_size`) in the supplier, or call the setter procedure directly.",
    ),
    "VFAC(1)": _x(
        """`f: T assign set_f` names the command that `x.f := v` calls: it must be a procedure of the
        same class (not a query, not a misspelt name).""",
        """
        value: INTEGER assign set_valu
        """,
        """
        value: INTEGER assign set_value
        set_value (v: INTEGER) do value := v end
        """,
        "Name an existing procedure of the class after `assign`, or declare it.",
    ),
    "VFAC(2)": _x(
        """`x.f (a, b) := v` calls the assigner as `set_f (v, a, b)`: the assigner takes the new value
        followed by every argument of the query, so one argument more than the query.""",
        """
        item (i: INTEGER): G assign put
        put (v: G) do ... end
        """,
        """
        item (i: INTEGER): G assign put
        put (v: G; i: INTEGER) do ... end
        """,
        "Give the assigner the new value first, then the query's arguments.",
    ),
    "VFAC(3)": _x(
        """The assigner's first argument receives the value assigned to the query, so it has the
        query's type (attachment marks may differ).""",
        """
        name: STRING assign set_name
        set_name (n: INTEGER) do ... end
        """,
        """
        name: STRING assign set_name
        set_name (n: STRING) do ... end
        """,
        "Declare the first argument `v: like name`, or with the query's type.",
    ),
    "VFAC(4)": _x(
        """The assigner's arguments after the first receive the query's arguments in order, so each
        has the type of the query's argument in that place.""",
        """
        item (i: INTEGER): G assign put
        put (v: G; i: STRING) do ... end
        """,
        """
        item (i: INTEGER): G assign put
        put (v: G; i: INTEGER) do ... end
        """,
        "Give the assigner's later arguments the types of the query's arguments, in the same order.",
    ),
    "VNCP": _x(
        """A `convert` clause lists conversion procedures, creation procedures of the class with one
        argument (`from_integer ({INTEGER})`), and conversion queries without arguments
        (`to_real: {REAL_64}`). Each routine is listed once, each type once per direction, and the
        types fit the routine's signature.""",
        """
        convert
            scale ({INTEGER})   -- scale is not a creation procedure
        """,
        """
        create
            from_integer
        convert
            from_integer ({INTEGER})
        """,
        "List creation procedures with one argument, or queries without arguments, whose types fit.",
    ),
    "VYCP(2)": _x(
        """A conversion procedure converts from a type that does not conform to the class: where the
        type conforms, assignment works already, without conversion.""",
        """
        class BOX convert from_small ({SMALL_BOX}) ...   -- SMALL_BOX inherits BOX
        """,
        """
        class BOX convert from_integer ({INTEGER}) ...
        """,
        "Remove the conforming type from the convert clause.",
    ),
    "VYCP(3)": _x(
        """VYCP(2) in a generic class: the type converted from conforms to the class already.""",
        """
        class BOX [G] convert from_small ({SMALL_BOX [G]}) ...   -- SMALL_BOX [G] inherits BOX [G]
        """,
        """
        class BOX [G] convert from_array ({ARRAY [G]}) ...
        """,
        "Remove the conforming type from the convert clause.",
    ),
    "VYCQ(2)": _x(
        """A conversion query converts to a type the class does not conform to: where the class
        conforms, assignment works already, without conversion.""",
        """
        class BOX inherit ANCESTOR convert to_ancestor: {ANCESTOR} ...
        """,
        """
        class BOX inherit ANCESTOR convert to_integer: {INTEGER} ...
        """,
        "Remove the type the class conforms to from the convert clause.",
    ),
    "VYCQ(3)": _x(
        """VYCQ(2) in a generic class: the class conforms to the type converted to already.""",
        """
        class BOX [G] inherit ANCESTOR convert to_ancestor: {ANCESTOR} ...
        """,
        """
        class BOX [G] inherit ANCESTOR convert to_array: {ARRAY [G]} ...
        """,
        "Remove the type the class conforms to from the convert clause.",
    ),
    "VUOT(1)": _x(
        """The local introduced by `attached e as x` has a fresh name: not a feature of the class, an
        argument, a local, nor another object-test local whose scope includes this test.""",
        """
        name: STRING
        ...
        if attached found_name as name then ... end
        """,
        """
        if attached found_name as l_name then ... end
        """,
        "Give the object-test local a name of its own (`l_name`).",
    ),
    "VOIT(1)": _x(
        """The expression after `across` must be of a type that conforms to ITERABLE [G]: arrays,
        lists, hash tables, strings and integer intervals (`1 |..| n`) are; plain numbers and
        ordinary classes are not.""",
        """
        across 10 as i loop print (i.item) end
        """,
        """
        across 1 |..| 10 as i loop print (i.item) end
        """,
        "Iterate over a structure or an interval, not over a single value.",
    ),
    "VOIT(2)": _x(
        """The name bound by `across e as c` (or `is x`) is fresh: not a feature, an argument, a local,
        nor another iteration or object-test local in scope.""",
        """
        total: INTEGER
        across numbers as total loop ... end
        """,
        """
        across numbers as n loop total := total + n.item end
        """,
        "Give the cursor a name of its own.",
    ),
    "VAOL(1)": _x(
        """`old e` stands for the value `e` had on entry to the routine; it may only appear in a
        postcondition (`ensure`). In the body, keep an earlier value in a local instead.""",
        """
        increment
            do
                count := old count + 1
            end
        """,
        """
        increment
            do
                count := count + 1
            ensure
                one_more: count = old count + 1
            end
        """,
        "Use `old` in the postcondition, where it checks the change the body made.",
    ),
    "VXRT": _x(
        """`retry` may only appear in a routine's `rescue` clause, where it starts the body again
        after an exception.""",
        """
        do
            attempts := attempts + 1
            if attempts < 3 then retry end
        end
        """,
        """
        do
            connect
        rescue
            attempts := attempts + 1
            if attempts < 3 then retry end
        end
        """,
        "Move the `retry` into the `rescue` clause.",
    ),
    "VOMB(2)": _x(
        """Each choice of an `inspect` is a constant of the inspected expression's type: a manifest
        constant (`3`, `'a'`), a constant attribute (`zero: INTEGER = 0`) or an interval of such
        constants. Variables, function calls and values of another type are not allowed.""",
        """
        inspect n
        when "one" then ...
        when limit then ...        -- `limit` is a variable
        end
        """,
        """
        inspect n
        when 1 then ...
        else
            if n = limit then ... end
        end
        """,
        "Use constants of the inspected type as choices, and test variables with `if`.",
    ),
    "VOMB(3)": _x(
        """Each value may appear in only one `when` of an `inspect`: two choices (values or intervals)
        that overlap would make the instruction ambiguous.""",
        """
        inspect n
        when 1 then ...
        when 2, 1 then ...
        end
        """,
        """
        inspect n
        when 1 then ...
        when 2 then ...
        end
        """,
        "List each value once; merge the branches if they should do the same thing.",
    ),
    # --- creation ---------------------------------------------------------------------------------
    "VGCC(1)": _x(
        """A deferred class has features with no implementation, so no object of it can be created.
        Create an object of an effective descendant instead.""",
        """
        s: SHAPE                   -- deferred class SHAPE
        create s
        """,
        """
        s: SHAPE
        create {CIRCLE} s.make (2)  -- CIRCLE inherits SHAPE and is effective
        """,
        "Name an effective descendant as the creation type.",
    ),
    "VGCC(3)": _x(
        """In `create {T} x`, the explicit creation type T must conform to the type of the target
        x.""",
        """
        pet: ANIMAL
        create {ROCK} pet
        """,
        """
        pet: ANIMAL
        create {DOG} pet
        """,
        "Create an object of the target's type or of one of its descendants.",
    ),
    "VGCC(5)": _x(
        """When the class of the new object has a `create` clause that does not list `default_create`,
        the creation must call one of the listed creation procedures.""",
        """
        -- class POINT create make ...
        create p
        """,
        """
        create p.make (0, 0)
        """,
        "Call one of the creation procedures the class lists.",
    ),
    "VGCC(6)": _x(
        """In `create x.p (...)`, `p` must be listed in the `create` clause of the class of `x`, and
        that clause must make it available to the class doing the creation: `create {A} make` lets
        only A and its descendants use `make`.""",
        """
        -- class POINT create make ... feature move (dx, dy: INTEGER)
        create p.move (1, 2)
        """,
        """
        create p.make (0, 0)
        p.move (1, 2)
        """,
        "Create with a creation procedure, then call other procedures on the new object.",
    ),
    # --- void safety ------------------------------------------------------------------------------
    "VEVI": _x(
        """Void safety: a variable of an attached type must hold an object before it is read. An
        attached local or `Result` must be set on every path before its first use (and `Result`
        before the function returns, reported at its `end`), and each creation procedure must set
        every attached attribute before it reads it, also in the routines it calls. `Current` may
        be handed out before every attribute is set, but then no qualified call may follow (it
        could reach the unset attribute through that reference) until they all are.""",
        """
        name: STRING
            do
                if count > 0 then Result := "many" end
            end
        """,
        """
        name: STRING
            do
                if count > 0 then Result := "many" else Result := "none" end
            end
        """,
        "Set the variable on every path, or declare it `detachable` and test it before use.",
    ),
    "VUTA(2)": _x(
        """The target of a call must be attached. A call on an expression of detachable type could
        meet Void, so first test it with an object test, or declare the entity attached.""",
        """
        owner: detachable PERSON
        print (owner.age)
        """,
        """
        if attached owner as l_owner then
            print (l_owner.age)
        end
        """,
        "Call the feature on the object-test local, which is attached inside the `then` part.",
    ),
    "VWMQ": _x(
        """A typed manifest constant such as `{INTEGER_8} 100` must be a value its type can hold:
        INTEGER_8 holds -128 .. 127, NATURAL_8 holds 0 .. 255, and so on.""",
        """
        small := {INTEGER_8} 200
        """,
        """
        small := {INTEGER_16} 200
        """,
        "Choose a type large enough for the value, or a value within the type's range.",
    ),
    "VQMC(3)": _x(
        """An integer constant attribute must hold a value of its declared type: INTEGER_8 holds
        -128 .. 127, INTEGER_32 (INTEGER) -2147483648 .. 2147483647, NATURAL_8 0 .. 255, and so on.
        A literal that no integer type holds at all (beyond 18446744073709551615, or below
        -9223372036854775808) is a syntax error already.""",
        """
        Limit: INTEGER_8 = 200
        """,
        """
        Limit: INTEGER_16 = 200
        """,
        "Declare the constant with a type large enough for its value, or change the value.",
    ),
    "ONCE-KEY": _x(
        """The key of a once routine says how often its body runs: plain `once` once per processor,
        `once ("PROCESS")` once for the whole program, `once ("THREAD")` once per processor and
        `once ("OBJECT")` once per object. Keys are case-insensitive; no other key is accepted.""",
        """
        shared_count: INTEGER
            once ("PROGRAM")
                Result := 42
            end
        """,
        """
        shared_count: INTEGER
            once ("PROCESS")
                Result := 42
            end
        """,
        "Use one of the keys PROCESS, THREAD or OBJECT.",
    ),
    "EXTERNAL": _x(
        """An `external` routine binds to code outside Eiffel. Its language string is one of
        EiffelStudio's forms (`"C"`, `"C signature (double): double use <math.h>"`, `"C inline use
        <math.h>"`, `"C++ inline"`) or `"Python"`; an external "Python" names a function of a
        module beside the program's classes (or on the .ecf's python_path, or installed) with its
        alias "module.function" or "module.Class.method".""",
        """
        twice (x: INTEGER): INTEGER
            external "Python"
            alias "double"
            end
        """,
        """
        twice (x: INTEGER): INTEGER
            external "Python"
            alias "arith.double"
            end
        """,
        "Name the module and the function in the alias; put arith.py beside the class.",
    ),
    "EXTERNAL-BUILD": _x(
        """The program's C and C++ externals are compiled (with cffi) when the program is compiled.
        This fails when no C compiler is installed, when a header named in `use` or a library named
        in the .ecf is missing, or when the C code does not compile; the message quotes the
        compiler.""",
        """
        c_sin (x: REAL_64): REAL_64
            external "C signature (double): double use <maths.h>"
            alias "sin"
            end
        """,
        """
        c_sin (x: REAL_64): REAL_64
            external "C signature (double): double use <math.h>"
            alias "sin"
            end
        """,
        "Name a header that exists (here math.h), or install the compiler or library the message names.",
    ),
    # --- SCOOP ------------------------------------------------------------------------------------
    "VUTA(3)": _x(
        """A call on a target of separate type is allowed only when the target is controlled, that
        is, the routine holds its processor: a formal argument of the enclosing routine, a local of
        a `separate ... as x do ... end` block, an object-test or across local over a controlled
        expression, or a query result on a controlled target within the same expression. Attributes,
        ordinary locals and `Result` of separate type are not controlled.""",
        """
        buffer: separate BUFFER
        ...
        buffer.put (1)
        """,
        """
        put_into (buffer, 1)
        ...
        put_into (b: separate BUFFER; v: INTEGER)
            do
                b.put (v)
            end
        """,
        """Pass the separate object as an argument (or use `separate buffer as b do b.put (1) end`):
        the call then reserves its processor for the routine.""",
    ),
    "VUAR(3)": _x(
        """In a call on a separate target, a non-separate reference passed as an argument would reach
        another processor, which would take it for one of its own objects (a "traitor"). Such an
        actual is allowed only if the formal argument's type is separate.""",
        """
        -- in WORKER:  take (items: LIST [INTEGER])
        worker.take (my_list)          -- worker: separate WORKER, controlled
        """,
        """
        -- in WORKER:  take (items: separate LIST [INTEGER])
        worker.take (my_list)
        """,
        "Declare the formal argument `separate` in the supplier, so it treats the object as remote.",
    ),
    "FORMAL-TRAITOR": _x(
        """A warning, not an error. In a call on a separate target, a value whose type is a formal
        generic `G` is passed to a non-separate formal argument, or a `G` result of the call is
        then used as non-separate (attached to a non-separate entity or argument, or the target
        of a call; a result kept in a separate entity is fine). EiffelStudio accepts both (it
        applies VUAR(3) and result type adaptation only to a generic declared `reference G`), but
        if some actual generic
        parameter is a reference type, a non-separate reference crosses processors (a traitor).""",
        """
        class NODE [G]  ...  put (v: G) ...
        class TREE [G]  ...  node.put (value)     -- node: separate NODE [G], value: G
        """,
        """
        class TREE [expanded G]  ...  node.put (value)
        """,
        """Constrain the generic to expanded types (`expanded G`) when only values such as INTEGER
        are meant, or declare the supplier's formal argument separate.""",
    ),
    "VUAR(4)": _x(
        """In a call on a separate target, an expanded actual argument is copied to the other
        processor. It must not contain, directly or through other expanded fields, attributes of
        non-separate reference type: the copy would share those objects across processors.""",
        """
        expanded class LABELLED  feature text: STRING ... end
        worker.store (label)           -- worker: separate WORKER;  label: LABELLED
        """,
        """
        expanded class LABELLED  feature text: separate STRING ... end
        worker.store (label)
        """,
        "Make the reference fields of the expanded class separate, or pass plain values instead.",
    ),
    "VUER": _x(
        """A query called on a separate target returns its value to the caller's processor. If its
        result type is expanded and contains non-separate reference attributes, those references
        would point into the other processor's objects, so such a query cannot be called on a
        separate target. (Reference results are fine: the caller sees them as separate.)""",
        """
        -- in SENSOR:  reading: LABELLED   (expanded, with a STRING field)
        print (sensor.reading)         -- sensor: separate SENSOR
        """,
        """
        -- in SENSOR:  value: REAL_64
        print (sensor.value)
        """,
        "Across processors, query basic values or separate references, not expanded objects with references.",
    ),
    "FRESH_IDENTIFIER": _x(
        """The name introduced by `separate e as x` is fresh: not a feature, an argument, a local, an
        object-test or iteration local in scope, nor another name of the same or an enclosing
        separate block.""",
        """
        buffer: separate BUFFER
        ...
        separate buffer as buffer do buffer.put (1) end
        """,
        """
        separate buffer as b do b.put (1) end
        """,
        "Give the separate-block local a name of its own.",
    ),
    "V1SE": _x(
        """A separate block reserves the processors of the objects its expressions denote, so each
        expression must be of a separate type (EiffelStudio 21.11+): a value of expanded type
        (INTEGER, BOOLEAN, ...) has no processor to reserve, and a non-separate object is already
        on the current processor.""",
        """
        separate count as c do print (c) end      -- count: INTEGER
        """,
        """
        print (count)
        """,
        "Use expanded values directly; reserve only separate objects.",
    ),
    "V1SE(3)": _x(
        """The locals of a separate block stand for the reserved objects for the whole block and are
        read-only: they cannot be assigned to or used as a creation target.""",
        """
        separate buffer as b do
            b := other_buffer
        end
        """,
        """
        separate other_buffer as b do
            b.put (1)
        end
        """,
        "Name the object you want in the block's header instead of reassigning the local.",
    ),
    "VWEQ": _x(
        """An equality `a = b` (or `/=`, `~`, `/~`) compares two values of compatible types: one must
        conform or convert to the other. Comparing a number with a string, say, is always false and
        is a mistake.""",
        """
        if count = answer then   -- count: INTEGER; answer: STRING
        """,
        """
        if count.out ~ answer then
        """,
        "Bring both sides to one type first (`out`, `to_integer`), then compare.",
    ),
    "VFAV(1)": _x(
        """An operator alias makes a query usable as an operator: a binary operator (`a + b`) names a
        query with exactly one argument, a unary one (`- a`, `not a`) a query with none. Procedures
        cannot have operator aliases.""",
        """
        scale alias "*" (a, b: INTEGER): VECTOR
        """,
        """
        scale alias "*" (factor: INTEGER): VECTOR
        """,
        "Give the operator's feature one argument (binary) or none (unary), or drop the alias.",
    ),
    "VFAV(2)": _x(
        """A bracket alias (`alias "[]"`) lets `x [i]` call a query with the bracketed values as its
        arguments, so it names a query with at least one argument.""",
        """
        value alias "[]": INTEGER
        """,
        """
        item alias "[]" (i: INTEGER): INTEGER
        """,
        "Put the bracket alias on a query that takes the index (or key) as an argument.",
    ),
    "VFAV(3)": _x(
        """A parenthesis alias (`alias "()"`) lets `x (a)` call a routine with the parenthesized values
        as its arguments, so it names a routine with at least one argument, and a class has at
        most one feature with a parenthesis alias.""",
        """
        value alias "()": INTEGER
        """,
        """
        item alias "()" (i: INTEGER): INTEGER
        """,
        "Put the parenthesis alias on one routine that takes the values as arguments.",
    ),
    "VFAV(4)": _x(
        """A `convert` mark on an operator alias lets the operator apply when the left operand only
        converts to the class (`1 + money`): the operator must then be binary, so the feature
        takes exactly one argument.""",
        """
        negated alias "-" convert: MONEY
        """,
        """
        negated alias "-": MONEY
        """,
        "The unary operator loses its `convert` mark: there is no other operand to convert from.",
    ),
    "VFAV(5)": _x(
        """Only an operator alias can carry a `convert` mark (it converts the left operand of a
        binary operator); a bracket or parenthesis alias cannot.""",
        """
        item alias "[]" convert (i: INTEGER): G
        """,
        """
        item alias "[]" (i: INTEGER): G
        """,
        "The bracket alias loses its `convert` mark.",
    ),
    "VDJR": _x(
        """When a class inherits several features with one name, at most one of them effective, they
        are joined into one feature: their signatures (argument and result types) must then be the
        same.""",
        """
        deferred class SHAPE feature area: REAL_64 deferred end end
        deferred class TILE feature area: INTEGER deferred end end
        deferred class SQUARE_TILE inherit SHAPE TILE end
        """,
        """
        deferred class SQUARE_TILE
        inherit
            SHAPE
            TILE rename area as tile_count end
        end
        """,
        "Rename one of the inherited features when they mean different things.",
    ),
    "VTEC(1)": _x(
        """A value of an expanded type is created as soon as an entity of that type exists, so the
        class must be effective: an expanded class cannot be deferred.""",
        """
        deferred expanded class AMOUNT
        """,
        """
        expanded class AMOUNT
        """,
        "Make the class effective, or make it a reference class if it is meant to be inherited.",
    ),
    "VTEC(2)": _x(
        """Values of an expanded type are created without arguments (when a local or an attribute of
        that type comes into existence), so `default_create` must be one of its creation
        procedures; a class with no creation clause has it implicitly.""",
        """
        expanded class POINT
        create
            make
        """,
        """
        expanded class POINT
        create
            default_create, make
        """,
        "List `default_create` among the creation procedures (redefine it to set the fields).",
    ),
    "VFFD(7)": _x(
        """A once function computes its result once and shares it, so its type cannot depend on the
        object it is called on: no formal generic parameter and no `like Current` in it. A
        `once ("OBJECT")` function has one result per object and may use them.""",
        """
        class REGISTRY [G] feature
            shared_item: detachable G
                once
                end
        end
        """,
        """
        class REGISTRY [G] feature
            shared_item: detachable G
                once ("OBJECT")
                end
        end
        """,
        "Make the once per object, or give the function a type that does not depend on the object.",
    ),
    "VGCP(2)": _x(
        """Every name in a `create` clause must be a procedure of the class: the creation procedure
        that initialises new objects. A function, an attribute or an unknown name cannot create.""",
        """
        create
            make, count
        """,
        """
        create
            make, make_with_count
        """,
        "List procedures only; write a procedure that sets the attribute if you need one.",
    ),
    "VGCP(3)": _x(
        """A creation procedure is listed once: the same name in two creation clauses (or twice in
        one) is a mistake, usually left over from editing the export of the clause.""",
        """
        create
            make
        create {ANY}
            make
        """,
        """
        create {ANY}
            make
        """,
        "Keep one clause naming the procedure, with the clients it is meant for.",
    ),
    "VOMB(1)": _x(
        """`inspect` compares its expression with constant values, so the expression must be of an
        integer, natural, character or string type; reals and references cannot be inspected.""",
        """
        inspect speed      -- speed: REAL_64
        when 0 then stop
        end
        """,
        """
        if speed = 0.0 then
            stop
        end
        """,
        "Use a conditional for other types, or inspect an integer computed from the value.",
    ),
    "VAVE": _x(
        """A loop variant proves that the loop ends: it is an INTEGER expression that stays
        non-negative and decreases at each iteration, so it must be of an integer type.""",
        """
        from distance := 8.0 until distance < 1.0 loop
            distance := distance / 2
        variant
            distance
        end
        """,
        """
        from steps := 3 until steps = 0 loop
            steps := steps - 1
        variant
            steps
        end
        """,
        "Count the remaining iterations with an integer and use that as the variant.",
    ),
    "VFFD(8)": _x(
        """The result of a `once ("PROCESS")` function is shared by all processors, so its type must
        be separate (or expanded): a non-separate reference would be used by several processors as
        if each owned it.""",
        """
        log: LOGGER
            once ("PROCESS")
                create Result.make
            end
        """,
        """
        log: separate LOGGER
            once ("PROCESS")
                create Result.make
            end
        """,
        "Declare the result `separate`; callers then use it through separate arguments or blocks.",
    ),
    "VAPE": _x(
        """A precondition is what a client must make true before a call, so every client that may
        call the routine must be able to test it: a feature called (unqualified) in the
        precondition must be exported to every class the routine is exported to.""",
        """
        feature withdraw (n: INTEGER) require n <= balance do balance := balance - n end
        feature {NONE} balance: INTEGER
        """,
        """
        feature withdraw (n: INTEGER) require n <= balance do balance := balance - n end
        feature balance: INTEGER
        """,
        "`balance` is exported as widely as `withdraw`, so a client can check `n <= balance` first.",
    ),
    "VSRT": _x(
        """The root class is the type of the object the program starts with: the system creates it
        before any code runs, so it must be an effective (not deferred) class without generic
        parameters.""",
        """
        deferred class APPLICATION create make feature make do end end
        """,
        """
        class APPLICATION create make feature make do end end
        """,
        "The root class is effective now; for a generic class, make a non-generic heir the root.",
    ),
    "VSRP(1)": _x(
        """The root procedure (the .ecf's `feature` of `<root>`, or `--root CLASS.feature`) is how the
        system creates the root object, so it must be one of the root class's creation
        procedures.""",
        """
        class APPLICATION create make feature start do end make do end end
        -- root: APPLICATION.start
        """,
        """
        class APPLICATION create make, start feature start do end make do end end
        """,
        "`start` is listed in the `create` clause, so it can create the root object.",
    ),
    "VSRP(2)": _x(
        """Nothing calls the root procedure but the system when the program starts, and it has no
        values to pass: the root procedure takes no arguments.""",
        """
        make (n: INTEGER) do print (n) end
        """,
        """
        make do print ((create {ARGUMENTS_32}).argument_count) end
        """,
        "The root procedure takes no argument; command-line arguments come from ARGUMENTS_32.",
    ),
    "VSRP(3)": _x(
        """Nothing could establish a precondition of the root procedure before the program starts,
        so the root procedure has none.""",
        """
        make require ready: is_ready do run end
        """,
        """
        make do if is_ready then run end end
        """,
        "The condition is tested in the body instead of being required of a caller that does not exist.",
    ),
}
# VUAR(2) and VJAR also cover their SCOOP conditions (separate to non-separate); see their rule text.

ALIASES: dict[str, str] = {
    # Gobo's finer SCOOP conditions, mapped by meaning (DESIGN section 4). Gobo prints the V1SE ones
    # as V1SE-G1 .. V1SE-G3; the spelling V1SE-1G .. V1SE-3G is accepted too.
    "VUTA-4G": "VUTA(3)",  # call on an uncontrolled separate target
    "VUAR-3G": "VUAR(3)",  # reference actual of a separate call needs a separate formal
    "VUAR-4G": "VUAR(4)",  # expanded actual of a separate call holds non-separate references
    "V1SE-G1": "FRESH_IDENTIFIER",  # two names of one separate block are the same
    "V1SE-1G": "FRESH_IDENTIFIER",
    "V1SE-G2": "FRESH_IDENTIFIER",  # a separate-block name clashes with another entity
    "V1SE-2G": "FRESH_IDENTIFIER",
    "V1SE-G3": "V1SE",  # a separate-block expression is not of a separate (reference) type
    "V1SE-3G": "V1SE",
}
