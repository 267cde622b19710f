"""The version of scoopc (the scheme is in CHANGELOG.md)."""

__version__ = "0.2.0"
