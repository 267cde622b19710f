"""The version of scoopc (the scheme is in CHANGELOG.md), and what a wheel's build compiled ahead
for it (driver/library.py, build_prebuilt)."""

import os
from pathlib import Path

__version__ = "0.2.0"

# In a wheel: the compiled standard library, its checked declarations and the serialized parser,
# each named by a key of what it was made from, so that it is used only by a compiler it matches.
# Absent in a source checkout (and an editable install).
PREBUILT = Path(__file__).resolve().parent / "prebuilt"


def prebuilt(name: str) -> Path | None:
    """The file or folder `name` the wheel ships in PREBUILT, if it does; None when it does not or
    when SCOOPC_NO_PREBUILT is set (then everything is compiled into the cache, as in a checkout)."""
    if os.environ.get("SCOOPC_NO_PREBUILT"):
        return None
    path = PREBUILT / name
    return path if path.exists() else None
