"""`scoopc msg`: Eiffel classes for ROS 2 message types (from rosbags' type store or a .msg file).

Naming scheme (documented in docs/ROBOTS.md, "ROS 2 messages"):
* class: package and message name in upper case, CamelCase split at lower-to-upper changes:
  geometry_msgs/msg/Twist -> GEOMETRY_MSGS_TWIST, sensor_msgs/msg/LaserScan -> SENSOR_MSGS_LASER_SCAN;
  file: the class name in lower case + ".e";
* attributes: the field names; an Eiffel keyword or a feature name of ANY (or of the generated class
  itself: make, ros_type) gets `_value` appended (`class` -> `class_value`);
* constants: `Ros_type: STRING` (the ROS type name) and the message's constants, first letter
  upper case (`Status_no_fix: INTEGER_8 = -1`); a constant clashing with an attribute gets `_constant`;
* `make` gives ROS 2 default values; `set_<attribute> (a_value)` per field.
"""

from __future__ import annotations

import functools
import os
import re
import sys

from ..exits import UsageError
from . import ros_messages
from .ros_messages import ARRAY, BASE, NAME

BASIC = {
    "bool": "BOOLEAN",
    "byte": "INTEGER_8",
    "char": "NATURAL_8",
    "int8": "INTEGER_8",
    "uint8": "NATURAL_8",
    "int16": "INTEGER_16",
    "uint16": "NATURAL_16",
    "int32": "INTEGER_32",
    "uint32": "NATURAL_32",
    "int64": "INTEGER_64",
    "uint64": "NATURAL_64",
    "float32": "REAL_32",
    "float64": "REAL_64",
    "string": "STRING",
    "wstring": "STRING",
}
DEFAULTS = {"BOOLEAN": "False", "REAL_32": "{REAL_32} 0.0", "REAL_64": "0.0"}
KEYWORDS = set(
    """across agent alias all and as assign attached attribute check class convert create current
debug deferred detachable do else elseif end ensure expanded export external false feature from frozen if
implies inherit inspect invariant like local loop not note obsolete old once only or precursor redefine
rename require rescue result retry select separate some then true tuple undefine until variant void when
xor""".split()
)
ANY_FEATURES = set(
    """generator generating_type conforms_to same_type consistent is_equal standard_is_equal
equal standard_equal deep_equal is_deep_equal copy standard_copy twin standard_twin deep_twin deep_copy
setup default default_pointer default_create default_rescue do_nothing out tagged_out print io
operating_environment frozen_type conforms_to""".split()
)
RESERVED = KEYWORDS | ANY_FEATURES | {"make", "ros_type", "i"}


def class_name(typename: str) -> str:
    """geometry_msgs/msg/LaserScan -> GEOMETRY_MSGS_LASER_SCAN."""
    package, _, name = typename.split("/")
    words = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name)
    return f"{package}_{words}".upper()


def attribute_name(field: str) -> str:
    return f"{field}_value" if field.lower() in RESERVED else field.lower()


def _constant_name(name: str, taken: set[str]) -> str:
    lower = name.lower()
    if lower in RESERVED or lower in taken:
        lower += "_constant"
    return lower[0].upper() + lower[1:]


def eiffel_type(desc: tuple) -> str:
    kind, detail = desc
    if kind == BASE:
        return BASIC[detail[0]]
    if kind == NAME:
        return class_name(detail)
    return f"ARRAY [{eiffel_type(detail[0])}]"


INTEGER_RANGES = {
    "byte": (-(2**7), 2**7 - 1),
    "char": (0, 2**8 - 1),
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
MAX_DEFINITION_BYTES = 1 << 20


def read_definition(path: str, what: str) -> str:
    """The text of a .msg or .srv file given with --file: a readable UTF-8 text file, or a usage error."""
    try:
        if not os.path.isfile(path):
            raise UsageError(f"{path} is not a {what} file")
        if os.path.getsize(path) > MAX_DEFINITION_BYTES:
            raise UsageError(f"{path} is larger than 1 MiB: not a {what} definition")
        with open(path, encoding="utf-8") as source:
            text = source.read()
    except OSError as problem:
        raise UsageError(f"cannot read {path}: {problem.strerror}") from None
    except UnicodeDecodeError:
        raise UsageError(f"{path} is not a text file (UTF-8): not a {what} definition") from None
    if "\0" in text:
        raise UsageError(f"{path} holds NUL bytes: not a {what} definition")
    return text


def _field_problem(name: str, desc: tuple) -> str | None:
    kind, detail = desc
    if kind == BASE:
        bound = detail[1]
        return f"field `{name}`: a string bound must be positive, not {bound}" if bound < 0 else None
    if kind == NAME:
        return None
    element, size = detail
    if size < 0:
        kind_name = "array size" if kind == ARRAY else "sequence bound"
        return f"field `{name}`: the {kind_name} must not be negative, not {size}"
    return _field_problem(name, element)


def _constant_problem(name: str, base: str, value) -> str | None:
    if base in INTEGER_RANGES:
        low, high = INTEGER_RANGES[base]
        if not low <= int(value) <= high:
            return f"constant `{name}`: {value} is not a value of {base} ({low} to {high})"
    return None


def check_definitions(typename: str, store) -> None:
    """Refuse (a usage error) a definition whose classes would not check: an unknown message type
    used by a field, an integer constant out of its type's range, a negative array size or bound."""
    try:
        typenames = ros_messages.nested_types(typename, store)
    except KeyError as problem:
        raise UsageError(f"{typename} uses an {problem.args[0]} (give its definition too)") from None
    for each in typenames:
        problems = [_field_problem(name, desc) for name, desc in ros_messages.fields(each, store)]
        problems += [_constant_problem(*const) for const in ros_messages.constants(each, store)]
        found = [p for p in problems if p is not None]
        if found:
            raise UsageError(f"{each}: " + "; ".join(found))


def check_output(output: str) -> None:
    if os.path.exists(output) and not os.path.isdir(output):
        raise UsageError(f"-o {output} names a file, not a folder: give a folder for the .e files")


def _default(type_: str) -> str:
    if type_ in DEFAULTS:
        return DEFAULTS[type_]
    if type_.startswith(("INTEGER", "NATURAL")):
        return f"{{{type_}}} 0"
    return f"create {{{type_}}}.make" if type_ != "STRING" else "create {STRING}.make_empty"


def _manifest(base: str, value) -> str | None:
    type_ = BASIC.get(base)
    if type_ == "BOOLEAN":
        return "True" if value else "False"
    if type_ == "STRING":
        return '"' + str(value).replace("%", "%%").replace('"', '%"') + '"'
    if type_ in ("REAL_32", "REAL_64"):
        text = repr(float(value))
        return text if "inf" not in text and "nan" not in text else None
    return str(int(value)) if type_ else None


def _fields_and_constants(typename: str, store):
    """The fields and constants a class carries: the library's classes (store None) those of every
    supported distribution (Jazzy's sensor_msgs/Range `variance` too), so that one compiled
    program runs on each; other types those of `store` (the chosen distribution's by default)."""
    if store is None and typename in library_types():
        constants: dict = {}
        for distro in reversed(list(ros_messages.DISTROS)):
            each = ros_messages.store_of(distro)
            if typename in each.fielddefs:
                for const, base, value in each.fielddefs[typename][0]:
                    constants.setdefault(const, (const, base, value))
        return ros_messages.union_fields(typename), list(constants.values())
    return ros_messages.fields(typename, store), ros_messages.constants(typename, store)


def generate_class(typename: str, store=None) -> str:
    """The text of the Eiffel class for one message type."""
    name = class_name(typename)
    described, constants = _fields_and_constants(typename, store)
    fields = [(attribute_name(f), desc) for f, desc in described]
    attrs = {a for a, _ in fields}
    body_make, needs_index = [], False
    for attr, desc in fields:
        type_ = eiffel_type(desc)
        if desc[0] == BASE:
            if type_ == "STRING":
                body_make.append(f"\t\t\tcreate {attr}.make_empty")
        elif desc[0] == NAME:
            body_make.append(f"\t\t\tcreate {attr}.make")
        else:
            element = eiffel_type(desc[1][0])
            if desc[0] == ARRAY:
                size = desc[1][1]
                body_make.append(f"\t\t\tcreate {attr}.make_filled ({_default(element)}, 1, {size})")
                if desc[1][0][0] == NAME or element == "STRING":
                    needs_index = True
                    body_make.append(
                        f"\t\t\tfrom i := 1 until i > {size} loop\n"
                        f"\t\t\t\t{attr}.put ({_default(element)}, i)\n"
                        f"\t\t\t\ti := i + 1\n\t\t\tend"
                    )
            else:
                body_make.append(f"\t\t\tcreate {attr}.make_empty")
    lines = [
        "note",
        f'\tdescription: "ROS 2 message {typename} (generated by `scoopc msg`)."',
        f'\tros_type: "{typename}"',
        "",
        "class",
        f"\t{name}",
        "",
        "inherit",
        "\tROS_MESSAGE",
        "",
        "create",
        "\tmake",
        "",
        "feature {NONE} -- Initialization",
        "",
        "\tmake",
        "\t\t\t-- ROS 2 default values.",
    ]
    if needs_index:
        lines += ["\t\tlocal", "\t\t\ti: INTEGER"]
    lines += (
        ["\t\tdo"]
        + (body_make or ["\t\t\t-- nothing to create"])
        + [
            "\t\tend",
            "",
            "feature -- Constants",
            "",
            f'\tRos_type: STRING = "{typename}"',
            "\t\t\t-- The ROS 2 type name.",
        ]
    )
    for const, base, value in constants:
        manifest = _manifest(base, value)
        if manifest is not None:
            lines += ["", f"\t{_constant_name(const, attrs)}: {BASIC[base]} = {manifest}"]
    lines += ["", "feature -- Access"]
    for (attr, desc), (field, _) in zip(fields, described):
        lines += ["", f"\t{attr}: {eiffel_type(desc)}", f"\t\t\t-- Field `{field}'."]
    lines += ["", "feature -- Element change"]
    for attr, desc in fields:
        lines += [
            "",
            f"\tset_{attr} (a_value: {eiffel_type(desc)})",
            f"\t\t\t-- Set `{attr}' to `a_value'.",
            "\t\tdo",
            f"\t\t\t{attr} := a_value",
            "\t\tensure",
            f"\t\t\t{attr}_set: {attr} = a_value",
            "\t\tend",
        ]
    return "\n".join(lines + ["", "end", ""])


# The message types whose classes the Roboscoop library has (stdlib/roboscoop/communication/messages/,
# written by `generate_library`), with every type they use.
LIBRARY_TYPES = (
    "geometry_msgs/msg/Twist",
    "geometry_msgs/msg/TwistStamped",
    "geometry_msgs/msg/Pose",
    "geometry_msgs/msg/PoseStamped",
    "geometry_msgs/msg/Point",
    "geometry_msgs/msg/Quaternion",
    "geometry_msgs/msg/Vector3",
    "nav_msgs/msg/Odometry",
    "sensor_msgs/msg/LaserScan",
    "sensor_msgs/msg/Range",
    "sensor_msgs/msg/BatteryState",
    "std_msgs/msg/Bool",
    "std_msgs/msg/Float64",
    "std_msgs/msg/Int32",
    "std_msgs/msg/String",
    "std_msgs/msg/Empty",
    "std_msgs/msg/Header",
    "rosgraph_msgs/msg/Clock",
)


@functools.cache
def _library_types(distro: str) -> tuple:
    found = []
    for typename in LIBRARY_TYPES:
        for each in ros_messages.nested_types(typename):
            if each not in found:
                found.append(each)
    return tuple(found)


def library_types() -> list[str]:
    """Every type with a class in the library (LIBRARY_TYPES and the types their fields use)."""
    return list(_library_types(ros_messages.distro()))


def generate_library(output: str) -> list[str]:
    """(Re)write the library's message classes into `output`; the paths."""
    return generate_types(library_types(), output)


def generate(typename: str, output: str, store=None, include_library: bool = False) -> list[str]:
    """Write the classes of `typename` and of every message type it uses into `output` (not those
    the library has, unless `include_library`); the paths."""
    library = set() if include_library else set(library_types())
    wanted = [each for each in ros_messages.nested_types(typename, store) if each not in library]
    return generate_types(wanted, output, store)


def generate_types(typenames, output: str, store=None) -> list[str]:
    os.makedirs(output, exist_ok=True)
    written = []
    for each in typenames:
        path = os.path.join(output, class_name(each).lower() + ".e")
        with open(path, "w", encoding="utf-8") as out:
            out.write(generate_class(each, store))
        written.append(path)
    return written


def _command_srv(args, srvtype: str, distro: str) -> int:
    """`scoopc msg pkg/srv/Name`: the classes of its request and response (a known service, or
    the `.srv` given with --file) and of the message types they use."""
    extra = ()
    if args.file:
        extra = ((srvtype, read_definition(args.file, ".srv")),)
    elif srvtype not in ros_messages.SRV_DEFINITIONS:
        known = ", ".join(sorted(ros_messages.SRV_DEFINITIONS))
        raise UsageError(f"unknown ROS 2 service type `{srvtype}` (give its .srv with --file; known: {known})")
    try:
        store = ros_messages.service_store(distro, extra)
    except Exception as problem:  # rosbags' parser errors
        raise UsageError(f"{args.file}: not a valid .srv definition: {problem}") from None
    for half in ("Request", "Response"):
        check_definitions(f"{srvtype}_{half}", store)
    written = []
    for half in ("Request", "Response"):
        written += generate(f"{srvtype}_{half}", args.output, store, include_library=args.all)
    for path in written:
        print(path)
    return 0


def _command_action(args, actiontype: str, distro: str) -> int:
    """`scoopc msg pkg/action/Name`: the classes of its goal, result and feedback (a known action of
    the distribution, or the `.action` given with --file) and of the message types they use."""
    extra = ()
    if args.file:
        try:
            with open(args.file, encoding="utf-8") as source:
                extra = ((actiontype, source.read()),)
        except OSError as problem:
            raise UsageError(f"cannot read {args.file}: {problem.strerror}") from None
    elif distro not in ros_messages.ACTION_DEFINITIONS.get(actiontype, {}):
        known = ", ".join(sorted(ros_messages.ACTION_DEFINITIONS))
        raise UsageError(f"unknown ROS 2 action type `{actiontype}` (give its .action with --file; known: {known})")
    try:
        store = ros_messages.action_store(distro, extra)
    except Exception as problem:  # rosbags' parser errors
        raise UsageError(f"{args.file}: not a valid .action definition: {problem}") from None
    written = []
    for part in ("Goal", "Result", "Feedback"):
        written += generate(f"{actiontype}_{part}", args.output, store, include_library=args.all)
    for path in written:
        print(path)
    return 0


def command_msg(args) -> int:
    """`scoopc msg TYPE [-o DIR]` / `scoopc msg --file X.msg --type pkg/msg/X [-o DIR]`."""
    try:
        distro, source = ros_messages.resolve_distro(getattr(args, "ros_distro", None))
    except ros_messages.DistroError as e:
        raise UsageError(str(e)) from None
    ros_messages.use_distro(distro)
    print(f"scoopc: ROS 2 {distro} ({source})", file=sys.stderr)
    store = None
    typename = args.type or args.typename
    if not typename:
        raise UsageError("`scoopc msg` needs a type name (pkg/msg/Name), or --file with --type")
    if re.fullmatch(r"\w+/srv/\w+", typename):
        check_output(args.output)
        return _command_srv(args, typename, distro)
    if re.fullmatch(r"\w+/action/\w+", typename):
        check_output(args.output)
        return _command_action(args, typename, distro)
    if not re.fullmatch(r"\w+/msg/\w+", typename):
        raise UsageError(
            f"`{typename}` is not a ROS 2 message, service or action type name (pkg/msg/Name, pkg/srv/Name, "
            "pkg/action/Name)"
        )
    check_output(args.output)
    if args.file:
        text = read_definition(args.file, ".msg")
        try:
            store = ros_messages.store_with({typename: text})
        except Exception as problem:  # rosbags' parser errors
            raise UsageError(f"{args.file}: not a valid .msg definition: {problem}") from None
    if not ros_messages.has_type(typename, store):
        raise UsageError(f"unknown ROS 2 message type `{typename}` (give its definition with --file)")
    check_definitions(typename, store)
    written = generate(typename, args.output, store, include_library=args.all)
    for path in written:
        print(path)
    if not args.all:
        kept = [class_name(each) for each in ros_messages.nested_types(typename, store) if each in library_types()]
        if kept:
            print(
                f"scoopc: the Roboscoop library already has {', '.join(kept)} (--all writes them too)", file=sys.stderr
            )
    return 0
