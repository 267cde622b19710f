"""YAML files users write besides Eiffel (simulator worlds, robot profiles): a safe loader and a
small schema language over PyYAML's node tree, which keeps each value's position. Input: text and
the file's name; output: plain Python values, or a `SchemaError` whose text is
`file:line:col: key.path[0].sub: what is wrong`. The same schema gives a JSON Schema for editors.

The loader refuses anchors and aliases (a billion-laughs file expands exponentially) and files
over 1 MiB, before anything is built."""

from __future__ import annotations

import difflib
import json
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

MAX_BYTES = 1 << 20


class SchemaError(ValueError):
    """A file that cannot be used: `str()` is `file:line:col: key.path: what is wrong`."""


def _shown(node) -> str:
    if isinstance(node, yaml.ScalarNode):
        return str(node.value)
    return "a list" if isinstance(node, yaml.SequenceNode) else "a mapping"


class Reader:
    """Reports mistakes with the file's name and the node's position; remembers where each path is."""

    def __init__(self, path: str, error: type[SchemaError] = SchemaError, positions: bool = True):
        self.path, self.error, self.positions = path, error, positions
        self.marks: dict[str, Any] = {}

    def fail(self, node_or_mark, where: str, text: str):
        mark = getattr(node_or_mark, "start_mark", node_or_mark)
        if mark is None or not self.positions:
            place = self.path
        else:
            place = f"{self.path}:{mark.line + 1}:{mark.column + 1}"
        raise self.error(f"{place}: {where}: {text}" if where else f"{place}: {text}")

    def fail_at(self, where: str, text: str):
        """A mistake found after reading (a start outside the arena): at the position of `where`."""
        self.fail(self.marks.get(where), where, text)


def compose(text: str, reader: Reader):
    """The node tree of `text` (None for an empty document), refusing oversized files, anchors and aliases."""
    if len(text.encode("utf-8", "surrogatepass")) > MAX_BYTES:
        reader.fail(None, "", "larger than 1 MiB: not a file a person wrote")
    try:
        for event in yaml.parse(text, Loader=yaml.SafeLoader):
            if isinstance(event, yaml.AliasEvent) or getattr(event, "anchor", None) is not None:
                reader.fail(event, "", "YAML anchors and aliases (&name, *name) are not accepted: write the values out")
        return yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        reader.fail(mark, "", f"not valid YAML: {e.problem or e.context}")
    except yaml.YAMLError as e:
        reader.fail(None, "", f"not valid YAML: {e}")


def read_text(path, reader: Reader, what: str) -> str:
    try:
        file = Path(path)
        if file.is_file() and file.stat().st_size > MAX_BYTES:
            reader.fail(None, "", f"larger than 1 MiB: not a {what}")
        return file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        reader.fail(None, "", f"cannot read the {what}: {getattr(e, 'strerror', None) or e}")
    return ""  # not reached


def _scalar(node, reader: Reader, where: str):
    if not isinstance(node, yaml.ScalarNode):
        reader.fail(node, where, f"must be a single value, not {_shown(node)}")
    return yaml.SafeLoader(yaml.serialize(node)).get_single_data() if node.tag != "tag:yaml.org,2002:null" else None


# ---- the schema language ---------------------------------------------------------------------------


class Schema:
    description = ""

    def read(self, node, reader: Reader, where: str):
        reader.marks[where] = node.start_mark
        return self.value(node, reader, where)

    def value(self, node, reader: Reader, where: str):
        raise NotImplementedError

    def json(self) -> dict:
        raise NotImplementedError


@dataclass
class Number(Schema):
    """A number (int or float, never a boolean), within bounds; `whole`: an integer."""

    low: float | None = None
    high: float | None = None
    above: float | None = None  # strictly greater than
    whole: bool = False

    def value(self, node, reader, where):
        value = _scalar(node, reader, where)
        ok = not isinstance(value, bool) and isinstance(value, int if self.whole else (int, float))
        ok = ok and math.isfinite(value)
        ok = ok and (self.low is None or value >= self.low) and (self.high is None or value <= self.high)
        ok = ok and (self.above is None or value > self.above)
        if not ok:
            reader.fail(node, where, f"must be {self.wanted()}, not {value!r}")
        return value if self.whole else float(value)

    def wanted(self) -> str:
        kind = "a whole number" if self.whole else "a number"
        if self.low is not None and self.high is not None:
            return f"{kind} from {_num(self.low)} to {_num(self.high)}"
        if self.above is not None:
            return f"{kind} greater than {_num(self.above)}" + (f" and at most {_num(self.high)}" if self.high else "")
        if self.low is not None:
            return f"{kind} of at least {_num(self.low)}"
        return kind

    def json(self):
        out: dict = {"type": "integer" if self.whole else "number"}
        if self.low is not None:
            out["minimum"] = self.low
        if self.high is not None:
            out["maximum"] = self.high
        if self.above is not None:
            out["exclusiveMinimum"] = self.above
        return out


def _num(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else str(x)


@dataclass
class Text(Schema):
    choices: tuple = ()
    pattern: str | None = None
    pattern_says: str = ""

    def value(self, node, reader, where):
        value = _scalar(node, reader, where)
        if not isinstance(value, str) or not value:
            reader.fail(node, where, f"must be a text, not {node.value!r}")
        if self.choices and value not in self.choices:
            reader.fail(node, where, f"must be one of {', '.join(self.choices)}, not {value!r}")
        if self.pattern and not re.match(self.pattern, value):
            reader.fail(node, where, f"{self.pattern_says}: {value!r}")
        return value

    def json(self):
        out: dict = {"type": "string", "minLength": 1}
        if self.choices:
            out["enum"] = list(self.choices)
        if self.pattern:
            out["pattern"] = self.pattern
        return out


class Flag(Schema):
    def value(self, node, reader, where):
        value = _scalar(node, reader, where)
        if not isinstance(value, bool):
            reader.fail(node, where, f"must be true or false, not {node.value}")
        return value

    def json(self):
        return {"type": "boolean"}


@dataclass
class Seq(Schema):
    item: Schema
    low: int = 0
    high: int | None = None

    def value(self, node, reader, where):
        if not isinstance(node, yaml.SequenceNode):
            reader.fail(node, where, f"must be a list, not {_shown(node)}")
        count = len(node.value)
        if count < self.low or (self.high is not None and count > self.high):
            size = (
                f"{self.low}"
                if self.low == self.high
                else f"{self.low} to {self.high}"
                if self.high
                else f"at least {self.low}"
            )
            reader.fail(node, where, f"must be a list of {size} items, not {count}")
        return [self.item.read(each, reader, f"{where}[{i}]") for i, each in enumerate(node.value)]

    def json(self):
        out: dict = {"type": "array", "items": self.item.json(), "minItems": self.low}
        if self.high is not None:
            out["maxItems"] = self.high
        return out


def point(n: int = 2, low: float | None = None) -> Seq:
    return Seq(Number(low=low), n, n)


@dataclass
class Map(Schema):
    """A mapping with known keys, a schema each (an unknown key is reported with the nearest known one)."""

    keys: dict = field(default_factory=dict)
    required: tuple = ()
    description: str = ""

    def value(self, node, reader, where):
        if not isinstance(node, yaml.MappingNode):
            reader.fail(node, where, f"must be a mapping (key: value lines), not {_shown(node)}")
        found: dict = {}
        for key, value in node.value:
            name = key.value if isinstance(key, yaml.ScalarNode) else None
            here = f"{where}.{name}" if where else str(name)
            if name not in self.keys:
                close = difflib.get_close_matches(str(name), list(self.keys), n=1)
                hint = f"did you mean `{close[0]}`? " if close else ""
                reader.fail(key, here, f"unknown key ({hint}expected one of: {', '.join(self.keys)})")
            if name in found:
                reader.fail(key, here, "given twice")
            found[name] = self.keys[name].read(value, reader, here)
        missing = [k for k in self.required if k not in found]
        if missing:
            reader.fail(node, where, f"needs {', '.join(missing)}")
        return found

    def json(self):
        out = {
            "type": "object",
            "properties": {k: s.json() for k, s in self.keys.items()},
            "additionalProperties": False,
        }
        if self.required:
            out["required"] = list(self.required)
        if self.description:
            out["description"] = self.description
        return out


@dataclass
class OneOf(Schema):
    """A value that may take one of several shapes, chosen by the node's kind (scalar, list, mapping)
    and, among mappings, by a key only that shape has."""

    choices: tuple
    says: str = ""
    pick: Callable | None = None  # (node) -> the schema, for mappings told apart by their keys

    def value(self, node, reader, where):
        kinds = {Map: yaml.MappingNode, Seq: yaml.SequenceNode}
        fitting = [c for c in self.choices if isinstance(node, kinds.get(type(c), yaml.ScalarNode))]
        if len(fitting) > 1 and self.pick is not None:
            fitting = [self.pick(node, fitting)]
        if not fitting:
            reader.fail(node, where, f"must be {self.says}, not {_shown(node)}")
        return fitting[0].value(node, reader, where)

    def json(self):
        return {"anyOf": [c.json() for c in self.choices]}


def load(text: str, schema: Schema, reader: Reader):
    """The values of `text` read against `schema` ({} for an empty file)."""
    root = compose(text, reader)
    if root is None:
        return {}
    return schema.read(root, reader, "")


def check_data(data, schema: Schema, reader: Reader):
    """Plain data (a dict given through the API) read against `schema`: the same rules, no positions."""
    try:
        text = yaml.safe_dump(data, sort_keys=False)
    except yaml.YAMLError as e:
        reader.fail(None, "", f"not plain data: {e}")
    return load(text, schema, reader)


def json_schema(schema: Schema, title: str) -> str:
    """The JSON Schema document (draft 2020-12) of `schema`, for editors' completion and checks."""
    document = {"$schema": "https://json-schema.org/draft/2020-12/schema", "title": title, **schema.json()}
    return json.dumps(document, indent=2) + "\n"


def keys_of(node) -> set:
    return {k.value for k, _ in node.value if isinstance(k, yaml.ScalarNode)}
