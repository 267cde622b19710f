"""DDS domain ids for the tests that talk over loopback DDS.

Each call gives a domain of its own within one pytest run: the ids 100..229 are split between the
pytest-xdist workers (PYTEST_XDIST_WORKER gwN of PYTEST_XDIST_WORKER_COUNT), and a worker hands its
slice out in turn, so two tests running at the same time never share a domain. The first id of a
slice depends on the process id, so that two test runs on one machine seldom start in step. Domain
ids above 232 have no valid ports (7400 + 250 * id must stay below 65536).
"""

import itertools
import os

FIRST, LAST = 100, 229


def _slice() -> range:
    workers = max(1, int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1") or 1))
    name = os.environ.get("PYTEST_XDIST_WORKER", "gw0")
    index = int(name[2:]) if name.startswith("gw") and name[2:].isdigit() else 0
    width = max(1, (LAST - FIRST + 1) // workers)
    start = FIRST + (index % workers) * width
    return range(start, min(start + width, LAST + 1))


_ids = _slice()
_turn = itertools.count(os.getpid() % len(_ids))


def next_domain() -> int:
    """A domain id no other test of this run is using now."""
    return _ids[next(_turn) % len(_ids)]
