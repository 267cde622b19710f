"""Eiffel exceptions in flight (docs codegen_spec.md): an exception being raised is the Python
exception `EiffelFailure(exception_object)`, where `exception_object` is the Eiffel EXCEPTION
(an instance of the generated class of one of its descendants)."""


class EiffelFailure(Exception):
    """An Eiffel exception in flight; `.exception` is the EXCEPTION object."""

    def __init__(self, exception):
        super().__init__(exception)
        self.exception = exception
