"""A processor's entry in the runtime's registry of live processors (`Runtime.processors`).

The registry must not keep a processor alive, so it refers to it weakly. A processor does not
refer to itself weakly: in a compiled runtime (docs/RUNTIME.md section 10) its class is a
native one, which takes no weak reference. Its anchor, a plain object made with it, stands in:
the processor and its anchor refer to each other, so they live and die together (the cyclic
garbage collector frees both), and the registry's weak reference to the anchor ends with them.
This module is never compiled.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .processor import Processor


class Anchor:
    __slots__ = ("proc", "__weakref__")
    proc: Processor

    def __init__(self, proc: Processor) -> None:
        self.proc = proc
