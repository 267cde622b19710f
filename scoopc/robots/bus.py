"""In-process publish/subscribe bus: synchronous delivery to subscribers, in subscription order.

Topic names are full names including the namespace ("/robot1/cmd_vel" or "/cmd_vel"). A message
is whatever the publisher passes (by convention an instance of the rosbags type store's dataclass,
scoopc.robots.ros_messages); the bus neither copies nor converts it. `publish` runs every callback on
the publisher's thread, in subscription order; a callback subscribed or closed during a delivery
takes effect from the next `publish`. A callback that raises does not stop the others: the first
exception is re-raised to the publisher once every subscriber has had the message.

`tap(callback)` sees every message published on the bus, whatever its topic: `callback(topic, msg)`
runs before the topic's subscribers (a recorder uses it; a tap does not count as a subscriber).
"""

import threading


class Subscription:
    """A subscription to one topic; `close()` stops deliveries (idempotent)."""

    def __init__(self, bus, topic, callback):
        self.bus = bus
        self.topic = topic
        self.callback = callback
        self.closed = False

    def close(self):
        if not self.closed:
            self.closed = True
            self.bus._remove(self)

    def __repr__(self):
        return f"<Subscription {self.topic!r}{' closed' if self.closed else ''}>"


class Tap:
    """A callback seeing every message of a bus; `close()` stops it (idempotent)."""

    def __init__(self, owner, callback):
        self.owner = owner
        self.callback = callback
        self.closed = False

    def close(self):
        if not self.closed:
            self.closed = True
            self.owner._untap(self)

    def __call__(self, topic, msg):
        if not self.closed:
            self.callback(topic, msg)


class Tapped:
    """The taps of a bus (`tap`, `_untap`): a list replaced on change, read without the lock.
    The bus has `_lock` and `_taps`; a transport bus (DDS, rclpy) also has `errors`, where
    `_tapped` keeps what a broken tap raised instead of breaking the transport."""

    def tap(self, callback):
        """Call `callback(topic, msg)` for every message published on this bus; returns a Tap (`close()`)."""
        tap = Tap(self, callback)
        with self._lock:
            self._taps = self._taps + [tap]
        return tap

    def _untap(self, tap):
        with self._lock:
            self._taps = [t for t in self._taps if t is not tap]

    def _tapped(self, topic, msg):
        for tap in self._taps:
            try:
                tap(topic, msg)
            except Exception as e:  # a broken tap must not break the transport
                if len(self.errors) < 100:
                    self.errors.append(e)


class Bus(Tapped):
    """Topic -> subscribers; `publish` calls each open subscriber's callback with the message."""

    #: Are callbacks called on a thread of the bus's own, never one that runs a processor? (The
    #: library then runs a leaf listener's call on that thread: OutsideClient.call's `leaf`.)
    #: Not here: `publish` calls back on the publisher's thread, which may be a processor's.
    own_thread_callbacks = False

    def __init__(self):
        self._lock = threading.Condition(threading.Lock())
        self._subs = {}  # [_lock] topic -> list of Subscription (subscription order)
        self._taps = []  # Taps (a list replaced on change: read without the lock)

    def subscribe(self, topic, callback, msgtype=None):
        """Call `callback(msg)` for every message on `topic` (`msgtype`: ignored, the in-process bus
        carries any message; transports that must know the type take it too)."""
        sub = Subscription(self, topic, callback)
        with self._lock:
            self._subs.setdefault(topic, []).append(sub)
            self._lock.notify_all()
        return sub

    def _remove(self, sub):
        with self._lock:
            subs = self._subs.get(sub.topic, [])
            if sub in subs:
                subs.remove(sub)
            if not subs:
                self._subs.pop(sub.topic, None)

    def publish(self, topic, msg):
        with self._lock:
            subs = tuple(self._subs.get(topic, ()))
        error = None
        for tap in tuple(self._taps):
            try:
                tap(topic, msg)
            except Exception as e:
                error = error or e
        for sub in subs:
            if not sub.closed:
                try:
                    sub.callback(msg)
                except Exception as e:  # the other subscribers still get the message
                    error = error or e
        if error is not None:
            raise error

    def wants(self, topic):
        """Would a message on `topic` reach anyone (a subscriber of the topic, or a tap)?"""
        return bool(self._taps) or topic in self._subs

    def subscriber_count(self, topic):
        with self._lock:
            return len(self._subs.get(topic, ()))

    def topics(self):
        """The topics that have at least one subscriber, sorted."""
        with self._lock:
            return sorted(self._subs)

    def wait_for_subscriber(self, topic, timeout=None):
        """Block until `topic` has a subscriber (True) or `timeout` seconds pass (False)."""
        with self._lock:
            return self._lock.wait_for(lambda: bool(self._subs.get(topic)), timeout)
