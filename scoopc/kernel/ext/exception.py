"""EXCEPTION's `external "Python"` feature (stdlib/base/exceptions/exception.e): `raise`.

Also `failure`, used by the other externals to raise a predefined Eiffel exception (IO_FAILURE,
OPERATING_SYSTEM_FAILURE, ...) with a message, as EiffelStudio's run-time does.
"""

from scoopc import kernel
from scoopc.kernel.errors import EiffelFailure


def raise_(current):
    """`raise`: throw `current` (the runtime fills recipient, class, line and trace when it
    catches it)."""
    raise EiffelFailure(current)


def new_exception(region, class_name, message=None):
    """A new object of the exception class `class_name` in `region`, with `message` as its
    description; None when that class is not part of the program (not registered)."""
    pycls = _class(class_name)
    if pycls is None:
        return None
    exc = region.new(pycls)
    if message is not None:
        from scoopc.kernel import strings

        text = strings.new_string_32(region, message)
        setter = getattr(exc, "set_description", None)
        if setter is not None:
            setter(text)
        else:
            exc.description = text
    return exc


def failure(region, class_name, message, cause=None):
    """The Python exception to raise for a failure of kind `class_name` (e.g. "IO_FAILURE"):
    an EiffelFailure carrying a new exception object, or, when the class is not registered
    (unit tests, a program without it), an OSError (which the runtime turns into an
    EXTERNAL_FAILURE like any Python exception escaping an external)."""
    exc = new_exception(region, class_name, message)
    if exc is None:
        err = OSError(f"{class_name}: {message}")
    else:
        err = EiffelFailure(exc)
    if cause is not None:
        err.__cause__ = cause
    return err


def _class(name):
    found = kernel.CLASSES.get(name)
    if found is None:
        for key, pycls in list(kernel.CLASSES.items()):
            if key.split("@")[0] == name:
                return pycls
    return found
