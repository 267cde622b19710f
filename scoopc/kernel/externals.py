"""Kernel, the program's own externals at run time: `external "Python"` routines of the user's
classes bound to functions of the user's modules, and `external "C"`/`"C++ inline"` routines
bound to the C wrappers the driver built with cffi (docs/LANGUAGE.md, Externals).

Each external is one function made here when its class loads; a call converts the arguments
(`kind`s of scoopc.semantics.externals: basic types as they are, strings as Python text, ARRAY
and SPECIAL of numbers as numpy views of their items, BOOLEAN's copied in and back), runs the
host function through the runtime (scoopc.runtime.externals: the processor is marked inside the
external and, when the external is `blocking`, lets the others run), and converts the result back. A Python exception
escaping the host function becomes an EXTERNAL_FAILURE, EiffelStudio's exception for a failed
external, with the Python exception as its cause (shown by `--debug`).
"""

from __future__ import annotations

import importlib
import operator
import sys
from array import array
from pathlib import Path

from ..runtime import Shutdown, externals as rt_externals
from . import CLASSES, strings as KS, types as T
from .basic_ops import r32
from .errors import EiffelFailure
from .support import ContractViolation, EiffelRuntimeError, create

PYTHON_FOLDER = "_python"  # the program's Python modules, copied into its package
_BOUNDS = {f"INTEGER_{n}": (-(2 ** (n - 1)), 2 ** (n - 1) - 1) for n in (8, 16, 32, 64)}
_BOUNDS |= {f"NATURAL_{n}": (0, 2**n - 1) for n in (8, 16, 32, 64)}
_DTYPES = {k: v.lower() for k, v in (("REAL_32", "float32"), ("REAL_64", "float64"), ("BOOLEAN", "bool"))}
_DTYPES |= {f"INTEGER_{n}": f"int{n}" for n in (8, 16, 32, 64)} | {f"NATURAL_{n}": f"uint{n}" for n in (8, 16, 32, 64)}
# array.array kinds of the numeric items kept in a buffer numpy views (BOOLEAN's are copied)
_TYPECODES = {f"INTEGER_{n}": c for n, c in ((8, "b"), (16, "h"), (32, "i"), (64, "q"))}
_TYPECODES |= {f"NATURAL_{n}": c for n, c in ((8, "B"), (16, "H"), (32, "I"), (64, "Q"))}
_TYPECODES |= {"REAL_32": "f", "REAL_64": "d"}
# Exceptions that are Eiffel's already (raised by Eiffel code the external called back) or the runtime's.
_PASSED_THROUGH = (EiffelFailure, ContractViolation, EiffelRuntimeError, Shutdown)


# --- binding ----------------------------------------------------------------------------------------
def python_external(package: str, feature: str, target: str, arguments: tuple, result, blocking: bool = False):
    """The method for `feature` ("CLASS.name"), bound to `target` ("module.function" or
    "module.Class.method") of the user's modules, found in the program's package first; a
    `blocking` one lets the other processors run while it runs (scoopc.runtime.externals)."""
    found: list = []

    def resolve():
        _use_program_modules(package)
        module, path = _import_longest(target)
        value = module
        for name in path:
            value = getattr(value, name)
        found.append(value)
        return value

    def external(current, *args):
        fn = found[0] if found else _resolving(current, feature, target, resolve)
        return _call(current, feature, f"Python {target}", fn, arguments, result, args, None, blocking)

    external.__name__ = feature.split(".")[-1]
    external.__qualname__ = feature
    return external


def c_external(lib, ffi, symbol: str, feature: str, alias: str, arguments: tuple, result, blocking: bool = False):
    """The method for `feature` bound to the C wrapper `symbol` of the cffi module (lib, ffi)."""
    fn = getattr(lib, symbol)

    def external(current, *args):
        return _call(current, feature, f"C {alias}", fn, arguments, result, args, ffi, blocking)

    external.__name__ = feature.split(".")[-1]
    external.__qualname__ = feature
    return external


_FOLDERS: list[str] = []  # the programs' module folders put on sys.path by this process, latest last


def _use_program_modules(package: str) -> None:
    """Put the program's copy of the user's modules first on sys.path (as Python puts a script's
    folder), once. A program run after another in the same process (the Python API, tests) does
    not see the other's modules: its folder leaves sys.path and its modules sys.modules."""
    owner = sys.modules.get(package.rpartition(".")[0] or package)
    folder = str(Path(getattr(owner, "__file__", "") or ".").parent / PYTHON_FOLDER)
    if not Path(folder).is_dir() or (_FOLDERS and _FOLDERS[-1] == folder):
        return
    for old in _FOLDERS:
        if old in sys.path:
            sys.path.remove(old)
        for name, module in list(sys.modules.items()):
            if (getattr(module, "__file__", None) or "").startswith(old + "/"):
                del sys.modules[name]
    _FOLDERS[:] = [folder]
    sys.path.insert(0, folder)


def _import_longest(target: str):
    """(module, attribute path): the longest prefix of `target` that imports as a module."""
    parts = target.split(".")
    for split in range(len(parts) - 1, 0, -1):
        name = ".".join(parts[:split])
        try:
            module = importlib.import_module(name)
            if hasattr(sys.modules.get(parts[0]), "CLASSES_BY_NAME"):
                raise ImportError(f"`{parts[0]}` is the name of a compiled Eiffel package: rename the module")
            return module, parts[split:]
        except ModuleNotFoundError as missing:
            if missing.name is None or not name.startswith(missing.name):
                raise  # a module the user's module imports is missing: say so
    raise ModuleNotFoundError(f"No module named {parts[0]!r}", name=parts[0])


def _resolving(current, feature, target, resolve):
    try:
        return resolve()
    except Exception as problem:  # noqa: BLE001 - any failure to load the user's module is the external's
        raise _failure(
            current, f"external {feature} cannot load Python {target}: {_text(problem)}", problem
        ) from problem


# --- calling ----------------------------------------------------------------------------------------
def _call(current, feature, what, fn, kinds, result, args, ffi, blocking):
    region = getattr(current, "_region_", None)
    keep: list = []
    try:
        values: list | None = [_to_host(kind, value, keep, ffi) for kind, value in zip(kinds, args)]
        try:
            value = rt_externals.call(region, feature, what, fn, values, blocking)
        finally:
            values = None  # the host's views of Eiffel's items end with the call (see _array_in)
            for back in keep:
                back()
        return None if result is None else _from_host(region, result, value, ffi)
    except _PASSED_THROUGH:
        raise
    except Exception as problem:  # noqa: BLE001 - every host failure is the external's failure
        raise _failure(current, f"{what} failed in external {feature}: {_text(problem)}", problem) from problem


def _to_host(kind, value, keep: list, ffi):
    if value is None or kind == "OBJECT":
        return value
    if kind.startswith("STRING"):
        if ffi is None:
            return KS.shown(value)  # an 8-bit string's bytes read as UTF-8
        data = KS.raw_bytes(value._s) if KS.is8(value) else value._s.encode("utf-8", "surrogatepass")
        return ffi.new("char[]", data)  # alive while `values` holds it
    if kind.startswith(("ARRAY:", "SPECIAL:")):
        return _array_in(kind, value, keep, ffi)
    if ffi is not None:
        if kind == "CHARACTER_8":
            return value.encode("latin-1")
        if kind == "CHARACTER_32":
            return ord(value)
        if kind == "POINTER":
            return ffi.cast("void *", value)
    return value


def _array_in(kind, value, keep: list, ffi):
    """The items of an ARRAY or SPECIAL for the host: for a basic numeric type, a numpy array (or a
    C pointer) that is a view of the SPECIAL's items, which move into an `array.array` the first
    time (ext/special.py); for BOOLEAN, a numpy copy whose items are copied back after the call."""
    import numpy  # deferred: start-up (only programs passing arrays to externals need numpy)

    container, item = kind.split(":")
    special = value.area if container == "ARRAY" else value
    code = _TYPECODES.get(item)
    if code is None:
        return _array_copy(special, item, keep, ffi, numpy)
    items = special._items
    if type(items) is not array:
        items = special._items = array(code, items)
    keep.append(lambda: _release(special, items))
    view = numpy.frombuffer(items, dtype=_DTYPES[item])
    return view if ffi is None else ffi.from_buffer(f"{_c_item(item)}[]", view)


def _release(special, items) -> None:
    """After the call: when the host kept a view of the items (a buffer export is still alive,
    so the array cannot grow), the SPECIAL goes on with a copy of its own, as EiffelStudio's C
    externals must not keep a SPECIAL's address past the call."""
    try:
        items.append(0)
        del items[-1]
    except BufferError:
        special._items = array(items.typecode, items)


def _array_copy(special, item, keep: list, ffi, numpy):
    array_ = numpy.array(special._items, dtype=_DTYPES[item])

    def back():
        special._items[:] = array_.tolist()

    keep.append(back)
    return array_ if ffi is None else ffi.from_buffer(f"{_c_item(item)}[]", array_)


def _c_item(item: str) -> str:
    return {"REAL_32": "float", "REAL_64": "double", "BOOLEAN": "unsigned char"}.get(item) or f"{_DTYPES[item]}_t"


def _from_host(region, kind, value, ffi):
    if kind in _BOUNDS:
        number = operator.index(value)
        low, high = _BOUNDS[kind]
        if not low <= number <= high:
            raise ValueError(f"the result {number} does not fit in {kind}")
        return number
    if kind == "REAL_64":
        return float(value)
    if kind == "REAL_32":
        return r32(float(value))  # rounded to single precision, as every REAL_32
    if kind == "BOOLEAN":
        return bool(operator.index(value)) if not isinstance(value, bool) else value
    if kind in ("CHARACTER_8", "CHARACTER_32"):
        return _character(value)
    if kind == "POINTER":
        return _address(value, ffi)
    if value is None or kind == "OBJECT":
        return value
    if kind.startswith("STRING"):
        return _string(region, kind, value, ffi)
    return _array_out(region, kind, value)


def _character(value):
    if isinstance(value, bytes):
        value = value.decode("latin-1")
    elif isinstance(value, int):
        value = chr(value)
    if not isinstance(value, str) or len(value) != 1:
        raise ValueError(f"a CHARACTER result must be one character, not {value!r}")
    return value


def _address(value, ffi):
    if ffi is not None and isinstance(value, ffi.CData):
        return int(ffi.cast("uintptr_t", value))
    return value  # a Python object held as a POINTER: an opaque handle


def _string(region, kind, value, ffi):
    """A new string from the host's: bytes (Python's, or C's `char *`) become a STRING_8's
    characters one for one, a STRING_32's by UTF-8; a Python `str` is a STRING_32's characters
    and a STRING_8's UTF-8 bytes."""
    if ffi is not None and isinstance(value, ffi.CData):
        if value == ffi.NULL:
            return None
        value = ffi.string(value)
    if isinstance(value, (bytes, bytearray)):
        data = bytes(value)
        if kind == "STRING_8":
            return KS.new_string_8(region, data.decode("latin-1"))
        return KS.new_string_32(region, data.decode("utf-8", "replace"))
    text = str(value)
    return KS.new_string_8_of(region, text) if kind == "STRING_8" else KS.new_string_32(region, text)


def _array_out(region, kind, value):
    """An ARRAY (indexed from 1) or SPECIAL made from the host's sequence or numpy array."""
    container, item = kind.split(":")
    items = value.tolist() if hasattr(value, "tolist") else list(value)
    convert = {"REAL_64": float, "REAL_32": lambda v: r32(float(v)), "BOOLEAN": bool}.get(item, operator.index)
    items = [convert(v) for v in items]
    gen = (T.t(item),)
    default = gen[0].default(region)
    if container == "SPECIAL":
        special = create(region, CLASSES["SPECIAL"], gen, "make_filled", (default, len(items)))
        special._items[:] = items
        return special
    made = create(region, CLASSES["ARRAY"], gen, "make_filled", (default, 1, len(items)))
    made.area._items[:] = items
    return made


# --- failures ---------------------------------------------------------------------------------------
def _text(problem: BaseException) -> str:
    return f"{type(problem).__name__}: {problem}" if str(problem) else type(problem).__name__


def _failure(current, message: str, cause: BaseException) -> Exception:
    """EXTERNAL_FAILURE (EiffelStudio's exception for an external, code 18) with `message` as
    its description and the host's exception as its cause."""
    region = getattr(current, "_region_", None)
    cls = CLASSES.get("EXTERNAL_FAILURE")
    if cls is None or region is None:
        error: Exception = EiffelRuntimeError("external_failure", message)
    else:
        exception = create(region, cls, None, None, ())
        text = KS.new_string_32(region, message)
        setter = getattr(exception, "set_description", None)
        if setter is not None:
            setter(text)
        else:
            exception.description = text
        error = EiffelFailure(exception)
    error.__cause__ = cause
    return error
