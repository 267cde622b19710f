"""chameneos (SCOOP/Qs, chameneos-redux): creatures meet pairwise at a mall and swap colours.

A creature arriving at the empty mall waits there; the next one meets it; N meetings in all.
Baseline: a lock around the mall; the waiting creature parks on its own threading.Event.
"""
import threading

from common import check, join_all, start_all

SIZES = {
    "full": {"creatures": 10, "meetings": 200_000},
    "quick": {"creatures": 10, "meetings": 15_000},
    "smoke": {"creatures": 4, "meetings": 200},
}

BLUE, RED, YELLOW = "blue", "red", "yellow"
START_COLOURS = [BLUE, RED, YELLOW, RED, YELLOW, BLUE, RED, YELLOW, RED, BLUE]


def ops(creatures, meetings):
    return meetings


def complement(mine, other):
    if mine == other:
        return mine
    return ({BLUE, RED, YELLOW} - {mine, other}).pop()


def colours(creatures):
    return [START_COLOURS[i % len(START_COLOURS)] for i in range(creatures)]


def check_counts(label, counts, meetings):
    check(label + " meetings seen by creatures", sum(counts), 2 * meetings)


# --- hand-written threading --------------------------------------------------

class ThreadMall:
    """The first creature to arrive parks on its own Event; the second hands it its colour."""

    def __init__(self, meetings):
        self.lock = threading.Lock()
        self.left = meetings
        self.waiting = None

    def meet(self, creature):
        """The partner's colour, or None once all meetings have taken place."""
        with self.lock:
            if self.left == 0:
                return None
            first = self.waiting
            if first is None:
                self.waiting = creature
            else:
                self.waiting, self.left = None, self.left - 1
                first.partner = creature.colour
                first.met.set()
                return first.colour
        creature.met.wait()
        creature.met.clear()
        return creature.partner


class ThreadCreature:
    def __init__(self, colour):
        self.colour, self.partner = colour, None
        self.met = threading.Event()
        self.count = 0

    def run(self, mall):
        while True:
            partner = mall.meet(self)
            if partner is None:
                return
            self.colour = complement(self.colour, partner)
            self.count += 1


def baseline(creatures, meetings):
    mall = ThreadMall(meetings)
    team = [ThreadCreature(c) for c in colours(creatures)]
    join_all(start_all([(c.run, (mall,)) for c in team]))
    check_counts("chameneos baseline", [c.count for c in team], meetings)
