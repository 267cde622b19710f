"""scoopc.kernel: the support library that generated code imports (object model, built-ins of
the basic types, the `external "Python"` features of stdlib/base in ext/).

The registry maps a class's universe key ("STRING_8", "CELL@BASE") to its generated Python class;
every generated module registers its class when it is imported.
"""

CLASSES = {}


def register(key, pycls):
    """Register a generated class. A program's class named like a library class (CELL) is
    CELL; the library's own then answers to CELL@BASE (the checker's key for it)."""
    library = pycls.__module__.startswith("eiffel_base.")
    existing = CLASSES.get(key)
    if existing is not None and existing is not pycls:
        if library:
            CLASSES[key + "@BASE"] = pycls
            return
        if existing.__module__.startswith("eiffel_base."):
            CLASSES[key + "@BASE"] = existing
    CLASSES[key] = pycls


def cls(key):
    return CLASSES[key]
