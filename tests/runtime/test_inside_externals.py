"""A processor inside an external (scoopc.runtime.externals): it gives up its run permit, the
live dump and `inside_externals` name it, and it is marked no longer once the external returns."""

from __future__ import annotations

import scoopc.runtime as rt
from scoopc.runtime import externals, monitor


def test_inside_an_external_is_seen_and_the_permit_is_free():
    runtime, root = rt.start()
    seen = {}

    def host(x):
        seen["permit"] = root.exec.permit
        seen["inside"] = [(r.feature, r.what) for r in rt.inside_externals(runtime)]
        seen["dump"] = monitor.dump(runtime)
        return x + 1

    try:
        assert externals.call(root, "APP.f", "C f", host, [41]) == 42
        assert rt.inside_externals(runtime) == [] and root.exec.permit
    finally:
        rt.finish(runtime, root)
    assert seen["permit"] is False
    assert seen["inside"] == [("APP.f", "C f")]
    assert "inside external: P1(ROOT) is inside external APP.f (C f) for" in seen["dump"]


def test_an_exception_leaves_the_external():
    runtime, root = rt.start()
    try:
        try:
            externals.call(root, "APP.g", "Python m.g", lambda: 1 / 0, [])
        except ZeroDivisionError:
            pass
        assert rt.inside_externals(runtime) == [] and root.exec.permit
    finally:
        rt.finish(runtime, root)
