"""OPERATING_ENVIRONMENT's `external "Python"` features
(stdlib/base/kernel/operating_environment.e)."""

import os


def directory_separator(current):
    return os.sep


def case_sensitive_path_names(current):
    """False on Windows only (EiffelStudio answers True on macOS too)."""
    return os.name != "nt"
