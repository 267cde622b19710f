"""The types the runtime's API speaks in (annotations only: nothing here runs).

Generated code is not type-checked; these types describe what it passes and what it gets,
and let mypy check the runtime itself (tests/test_habits.py)."""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import TYPE_CHECKING, Optional, Protocol

if TYPE_CHECKING:
    from .processor import Processor
    from .sched import Block


class Separate(Protocol):
    """An object of generated code (or an `Agent`): it lives in the region `_region_`."""

    _region_: Processor


# A feature of generated code, called as `routine(target, *args)`; it returns an Eiffel value
# (None for a command). The runtime marks leaves with the attribute `_scoop_leaf_`.
Routine = Callable[..., object]

# The actual arguments of a call.
Args = tuple[object, ...]

# A position in the Eiffel source: (class, routine, file, line).
Where = tuple[str, str, str, int]

# A precondition clause `(pred, targets, tag, where)`: `pred()` or `pred(*pre_args)` is its value,
# `targets` the indexes of the reserved arguments it calls (a wait condition if any is newly
# reserved), `tag` its label.
Clause = tuple[Callable[..., object], tuple[int, ...], str | None, Where | None]

# A logged call in a private queue: (routine, target, args, Block of the waiting client or None
# for a command, the processor passing its locks or None).
Call = tuple[Routine, Separate, Args, Optional["Block"], Optional["Processor"]]

# The key of a once routine's value (its class and name, as generated code writes it).
OnceKey = Hashable

# A table of once values: key -> value, or the failure of its first call.
OnceTable = dict[Hashable, object]
