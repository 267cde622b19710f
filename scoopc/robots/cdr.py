"""Our own CDR (OMG Common Data Representation, version 1, as ROS 2 uses it) for type-store messages.

`serialize(msg, typename)` gives the 4-byte encapsulation header (00 01 00 00: CDR, little endian)
followed by the fields in order; `deserialize(data, typename)` reads it back (either byte order).
The rules (equal byte for byte to rosbags' `typestore.serialize_cdr`):

* a primitive of size n (bool, byte, char, int8, uint8: 1; int16, uint16: 2; int32, uint32,
  float32: 4; int64, uint64, float64: 8) is aligned to a multiple of n, counted from the first byte
  AFTER the encapsulation header; padding bytes are zero;
* a string (bounded or not) is a uint32 length that counts a terminating NUL, the UTF-8 bytes, NUL;
* a nested message is its fields in order, no alignment of its own;
* a fixed array `T[n]` is n elements, no length; a sequence `T[]` / `T[<=n]` is a uint32 count then
  the elements (the first element aligned as an element is; an empty sequence adds no padding);
* a message is not padded at its end.
"""
from __future__ import annotations

import struct
from typing import Any

import numpy as np

from . import messages
from .messages import ARRAY, BASE, DTYPES, NAME

HEADER_LE = b"\x00\x01\x00\x00"
HEADER_BE = b"\x00\x00\x00\x00"
_FORMATS = {"bool": "?", "byte": "b", "char": "B", "int8": "b", "uint8": "B", "int16": "h",
            "uint16": "H", "int32": "i", "uint32": "I", "int64": "q", "uint64": "Q",
            "float32": "f", "float64": "d"}
_UINT32 = struct.Struct("<I")


class _Writer:
    def __init__(self, store):
        self.out = bytearray()
        self.store = store

    def align(self, size: int) -> None:
        pad = -len(self.out) % size
        if pad:
            self.out += bytes(pad)

    def primitive(self, name: str, value: Any) -> None:
        if name in messages.STRING_TYPES:
            if name == "wstring":
                raise NotImplementedError("wstring fields are not supported (rosbags has none either)")
            data = value.encode("utf-8")
            self.align(4)
            self.out += _UINT32.pack(len(data) + 1) + data + b"\x00"
            return
        dtype = DTYPES[name]
        self.align(dtype.itemsize)
        self.out += struct.pack("<" + _FORMATS[name], value)

    def value(self, desc: tuple, value: Any) -> None:
        kind, detail = desc
        if kind == BASE:
            self.primitive(detail[0], value)
        elif kind == NAME:
            self.message(value, detail)
        else:
            element, size = detail
            if kind == ARRAY:
                if len(value) != size:
                    raise ValueError(f"fixed array of {size} elements given {len(value)}")
            else:
                if size and len(value) > size:
                    raise ValueError(f"bounded sequence (<= {size}) given {len(value)} elements")
                self.align(4)
                self.out += _UINT32.pack(len(value))
            if len(value) == 0:
                return
            if messages.is_numeric(element):
                dtype = DTYPES[element[1][0]]
                self.align(dtype.itemsize)
                self.out += np.asarray(value, dtype=dtype).tobytes()
            else:
                for item in value:
                    self.value(element, item)

    def message(self, msg: Any, typename: str) -> None:
        for name, desc in messages.fields(typename, self.store):
            self.value(desc, getattr(msg, name))


def serialize(msg: Any, typename: str | None = None, store=None) -> bytes:
    """The CDR bytes (little endian, with the encapsulation header) of a type-store message."""
    writer = _Writer(store)
    writer.message(msg, typename or messages.typename_of(msg))
    return HEADER_LE + bytes(writer.out)


class _Reader:
    def __init__(self, data: bytes, store):
        header = bytes(data[:4])
        if header[:2] not in (HEADER_LE[:2], HEADER_BE[:2]):
            raise ValueError(f"not a plain CDR encapsulation header: {header.hex()}")
        self.order = "<" if header[1] == 1 else ">"
        self.data = memoryview(data)[4:]
        self.pos = 0
        self.store = store

    def align(self, size: int) -> None:
        self.pos += -self.pos % size

    def take(self, count: int) -> memoryview:
        if self.pos + count > len(self.data):
            raise ValueError("CDR data ends early")
        chunk = self.data[self.pos:self.pos + count]
        self.pos += count
        return chunk

    def uint32(self) -> int:
        self.align(4)
        return struct.unpack(self.order + "I", self.take(4))[0]

    def primitive(self, name: str) -> Any:
        if name in messages.STRING_TYPES:
            if name == "wstring":
                raise NotImplementedError("wstring fields are not supported")
            length = self.uint32()
            raw = bytes(self.take(length))
            return raw[:-1].decode("utf-8") if length else ""
        size = DTYPES[name].itemsize
        self.align(size)
        return struct.unpack(self.order + _FORMATS[name], self.take(size))[0]

    def value(self, desc: tuple) -> Any:
        kind, detail = desc
        if kind == BASE:
            return self.primitive(detail[0])
        if kind == NAME:
            return self.message(detail)
        element, size = detail
        count = size if kind == ARRAY else self.uint32()
        if messages.is_numeric(element):
            dtype = DTYPES[element[1][0]].newbyteorder(self.order)
            if count:
                self.align(dtype.itemsize)
            raw = self.take(count * dtype.itemsize)
            return np.frombuffer(raw, dtype=dtype).astype(DTYPES[element[1][0]])
        return [self.value(element) for _ in range(count)]

    def message(self, typename: str) -> Any:
        values = {name: self.value(desc) for name, desc in messages.fields(typename, self.store)}
        return messages.message_class(typename, self.store)(**values)


def deserialize(data: bytes, typename: str, store=None) -> Any:
    """The type-store message encoded in CDR `data` (with its encapsulation header)."""
    return _Reader(data, store).message(typename)

