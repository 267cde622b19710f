"""The run's report of what a ROS 2 robot did not say: after `--wait-robot` seconds, which topics
the program subscribes to are silent and what the graph holds nearby (a namespace mistake),
once; with `--require-robot` the run then stops; at the end, one line of what was heard."""

from __future__ import annotations

import threading
import time


def say(stderr, text):
    stderr.write(f"scoopc: {text}\n")
    stderr.flush()


def nearby(topic: str, graph) -> list[str]:
    """Topics of the graph that look like `topic` under another namespace (same last names)."""
    parts = [p for p in topic.split("/") if p]
    found = []
    for other in sorted(graph):
        if other == topic:
            continue
        theirs = [p for p in other.split("/") if p]
        for n in (2, 1):
            if (
                len(parts) >= n
                and len(theirs) >= n
                and theirs[-n:] == parts[-n:]
                and (n == 2 or parts[-1] not in ("left", "right", "center"))
            ):
                found.append(other)
                break
    return found


class Watch:
    """On a ROS 2 robot: after `wait` seconds, says once which subscribed topics are silent (no
    publisher, or no message) and what the graph holds nearby; with `require`, then stops the run
    (exit 3). Until the end it reports QoS incompatibilities (each topic once). `summary()`: one
    line of what was heard (Ctrl-C, the end of --duration)."""

    def __init__(self, bus, wait, require, stderr):
        self.bus, self.wait, self.require, self.stderr = bus, wait, require, stderr
        self.failed = False
        self.reported = False
        self._done = threading.Event()
        self._thread = None

    def start(self, rt):
        if not hasattr(self.bus, "heard"):
            return  # a bus without the graph queries (the in-process bus)
        self._thread = threading.Thread(target=self._run, args=(rt,), name="scoopc-robot-watch", daemon=True)
        self._thread.start()
        rt.shutdown_hooks.append(self._done.set)

    def _run(self, rt):
        deadline = time.monotonic() + self.wait
        while not self._done.is_set():
            try:
                self.bus.check_qos()
                if not self.reported and time.monotonic() >= deadline:
                    self.reported = True
                    silent = self.report_silence()
                    if silent and self.require:
                        self.failed = True
                        rt.stop()
                        return
            except Exception as e:  # noqa: BLE001 - the bus closed under us: the run is over
                if not self._done.is_set():
                    say(self.stderr, f"could not watch the robot's topics: {e}")
                return
            self._done.wait(min(0.25, max(0.0, deadline - time.monotonic())) if not self.reported else 0.5)

    def report_silence(self) -> list[str]:
        heard = self.bus.heard()
        silent = {
            topic: ("no publisher" if publishers == 0 else "a publisher, no message")
            for topic, (publishers, count) in sorted(heard.items())
            if publishers == 0 or count == 0
        }
        problems = self._command_mismatches()
        if not silent and not problems:
            return []
        graph = self.bus.graph_topics() if silent else {}
        lines = []
        if silent:
            what = "; ".join(f"{topic} ({why})" for topic, why in silent.items())
            lines.append(f"after {self.wait:g} s, nothing heard on {what}")
            hints = {}
            for topic in silent:
                for other in nearby(topic, graph):
                    hints.setdefault(other, topic)
            if hints:
                lines.append(
                    "the ROS graph has "
                    + ", ".join(f"{other} (this program asked {asked})" for other, asked in hints.items())
                    + ": is the namespace right? (--namespace)"
                )
            elif not graph:
                lines.append(
                    "no other ROS 2 node publishes anything in this domain: is the robot on, in the same "
                    "ROS_DOMAIN_ID, and reachable (ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS)?"
                )
            lines.append("exiting (--require-robot)" if self.require else "still waiting")
        for line in problems + lines:
            say(self.stderr, line)
        return list(silent) + problems

    def _command_mismatches(self) -> list[str]:
        """A velocity topic nobody reads, while a node reads it with another type (Twist/TwistStamped)."""
        wanted = getattr(self.bus, "unmatched_writers", None)
        if wanted is None:
            return []
        found = []
        for topic, ours, theirs in wanted():
            found.append(
                f"{topic}: the robot reads {theirs}, this program sends {ours}: it will not move "
                f"(a Jazzy robot takes TwistStamped: use its profile, e.g. TURTLEBOT3_ROBOT, or make_stamped)"
            )
        return found

    def finish(self):
        self._done.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(2.0)

    def summary(self):
        heard = getattr(self.bus, "heard", None)
        if heard is None:
            return
        try:
            counts = heard()
        except Exception:  # noqa: BLE001 - a closed bus: nothing to say
            return
        got = [f"{topic} ({count})" for topic, (_, count) in sorted(counts.items()) if count]
        silent = [topic for topic, (_, count) in sorted(counts.items()) if not count]
        parts = []
        if got:
            parts.append("heard " + ", ".join(got))
        if silent:
            parts.append("nothing on " + ", ".join(silent))
        if parts:
            say(self.stderr, "; ".join(parts))
        elif not counts:
            say(self.stderr, "the program subscribed to no topic")
