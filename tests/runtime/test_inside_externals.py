"""A processor inside an external (scoopc.runtime.externals): a blocking one gives up its run
permit, one not marked blocking keeps it; the live dump and `inside_externals` name it, and it is
marked no longer once the external returns."""

from __future__ import annotations

import threading

import scoopc.runtime as rt
from scoopc.runtime import externals, monitor

from rt_helpers import result_of, spawn


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


def test_an_external_not_marked_blocking_keeps_the_permit():
    runtime, root = rt.start()
    seen = {}

    def host():
        seen["permit"] = root.exec.permit
        seen["inside"] = [r.feature for r in rt.inside_externals(runtime)]

    try:
        externals.call(root, "APP.f", "C f", host, [], blocking=False)
        assert rt.inside_externals(runtime) == [] and root.exec.permit
    finally:
        rt.finish(runtime, root)
    assert seen == {"permit": True, "inside": ["APP.f"]}


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


class Device:
    """A supplier whose `read` is an external that blocks until the test opens a gate."""

    def make(self):
        self.value = 7

    def read(self, gate, entered):
        def host():
            entered.set()
            assert gate.wait(10), "gate never opened"

        externals.call(self._region_, "DEVICE.read", "C read", host, [])

    def get(self):
        return self.value


def test_the_dump_and_a_waiting_client_name_the_external(h):
    root = h.root
    device = root.new_separate(Device, Device.make)
    gate, entered = threading.Event(), threading.Event()
    with root.reserve((device,)):
        root.call(device, Device.read, (gate, entered))
    assert entered.wait(10)
    waiting = h.rt.watch_blocks(lambda b: b.kind == "sync")

    def client(here):
        with here.reserve((device,)):
            return here.query(device, Device.get)

    runner = spawn(root, client)
    assert waiting.wait(10)
    text = rt.dump()
    assert "waits for the result of Device.get on P2(Device), which is inside external DEVICE.read (C read)" in text
    assert "inside external: P2(Device) is inside external DEVICE.read (C read) for" in text
    gate.set()
    assert result_of(root, runner) == 7
    assert h.finish() == 0
