"""The AST: what the parser builds and every later stage reads.

Input: built by scoopc/parse/builders from parser reductions. Output: frozen dataclasses, one per
construct, each with a `span`; `dump(node)` gives a stable indented text form for tests.

Conventions:
- Nodes are named with Eiffel's own terms (ECMA-367) and compare by identity (`eq=False`), so
  later passes keep their results in side tables keyed by node.
- Names are `Identifier` nodes: `text` as written, `key` lowercased. Eiffel names are
  case-insensitive: compare and look up by `key`, print `text`.
- Optional parts are None when absent; lists are tuples (empty when absent).
- Type marks (`attached`, `detachable`, `separate`, `frozen`, `variant`) are fields of the type.
- The nodes live in one module per family; import them from here (`from scoopc import syntax`,
  `syntax.Assignment`).
"""

from .base import *  # noqa: F401,F403
from .declarations import *  # noqa: F401,F403
from .dump import dump, where  # noqa: F401
from .expressions import *  # noqa: F401,F403
from .instructions import *  # noqa: F401,F403
from .types import *  # noqa: F401,F403
