"""EXCEPTION.raise, EXCEPTION_MANAGER (per-region state), EXCEPTIONS.die."""

import pytest

from scoopc import kernel
from scoopc.kernel import support, types as TY
from scoopc.kernel.errors import EiffelFailure
from scoopc.kernel.ext import exception, exception_manager as EM, exceptions
from scoopc.runtime.anchor import Anchor


class Region:
    def __init__(self, pid=1):
        self.id = pid
        self.flushed = 0
        self.anchor = Anchor(self)  # what per-region state is kept by, as a Processor's

    def new(self, cls):
        obj = cls.__new__(cls)
        obj._region_ = self
        return obj

    def flush_output(self):
        self.flushed += 1


class Obj:
    def __init__(self, region):
        self._region_ = region


class EXC:
    _key_ = "EXC"


class DEVELOPER_EXCEPTION(EXC):
    _key_ = "DEVELOPER_EXCEPTION"


@pytest.fixture
def classes():
    saved = dict(kernel.CLASSES)
    yield kernel.CLASSES
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)


def type_object(desc):
    t = object.__new__(type("TYPE", (), {}))
    t._gen_ = (desc,)
    return t


def test_raise_throws_the_object():
    e = Obj(Region())
    with pytest.raises(EiffelFailure) as info:
        exception.raise_(e)
    assert info.value.exception is e


def test_failure_builds_a_predefined_exception(classes):
    class STRING_32:
        pass

    class IO_FAILURE:
        def set_description(self, d):
            self.description = d

    classes["STRING_32"] = STRING_32
    classes["IO_FAILURE@BASE"] = IO_FAILURE  # found by its class name too
    region = Region()
    err = exception.failure(region, "IO_FAILURE", "disk full")
    assert isinstance(err, EiffelFailure) and type(err.exception) is IO_FAILURE
    assert err.exception._region_ is region and err.exception.description._s == "disk full"
    plain = exception.failure(region, "NO_SUCH_EXCEPTION", "x")
    assert isinstance(plain, OSError) and not isinstance(plain, EiffelFailure)


def test_ignore_and_catch_are_per_region_and_per_exact_type():
    r1, r2 = Region(1), Region(2)
    m1, m2 = Obj(r1), Obj(r2)
    dev = TY.t("DEVELOPER_EXCEPTION")
    dev_detachable = TY.t("DEVELOPER_EXCEPTION", (), False)
    assert not EM.is_ignored(m1, dev)
    EM.ignore(m1, type_object(dev))  # a TYPE object ...
    assert EM.is_ignored(m1, dev) and EM.is_ignored(m1, dev_detachable)  # ... or a TypeDesc
    assert not EM.is_ignored(m2, dev)
    assert not EM.is_ignored(m1, TY.t("EXC"))
    assert EM.exception_is_ignored(r1, DEVELOPER_EXCEPTION()) and not EM.exception_is_ignored(r2, DEVELOPER_EXCEPTION())
    assert not EM.exception_is_ignored(r1, EXC())
    EM.catch(m1, dev_detachable)
    assert not EM.is_ignored(m1, dev)


def test_last_exception(monkeypatch):
    region = Region()
    m = Obj(region)
    assert EM.last_exception(m) is None
    e = Obj(region)
    monkeypatch.setattr(support, "last_caught", lambda here: EiffelFailure(e) if here is region else None)
    assert EM.last_exception(m) is e  # recorded by the rescue clause
    monkeypatch.setattr(support, "last_caught", lambda here: ValueError("host"))
    assert EM.last_exception(m) is None
    other = Obj(region)
    EM.set_last_exception(region, other)  # recorded by the runtime
    assert EM.last_exception(m) is other
    EM.set_last_exception(region, None)
    assert EM.last_exception(Obj(Region())) is None


def test_die_flushes_and_exits(monkeypatch):
    codes = []
    monkeypatch.setattr(exceptions, "_exit", codes.append)
    region = Region()
    exceptions.die(Obj(region), 4)
    assert codes == [4] and region.flushed == 1
