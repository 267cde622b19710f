"""chameneos (SCOOP/Qs, chameneos-redux): creatures meet pairwise at a mall and swap colours.

A creature arriving at the empty mall waits there; the next one meets it; N meetings in all.
Baseline: a lock around the mall; the waiting creature parks on its own threading.Event.
"""

import threading

from scoopc.runtime import leaf

from common import check, join_all, run_program, start_all, where

SIZES = {
    "full": {"creatures": 10, "meetings": 300_000},
    "quick": {"creatures": 10, "meetings": 10_000},
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


# --- SCOOP, as generated code calls the runtime ----------------------------------
# (@leaf where codegen would put it: routines without loops, separate or blocking calls)
# class MALL:     arrive (id, colour): the first waits, the second meets it (outcome_of (id));
#                 partner_of (id) / has_partner (id) / forget_partner (id) for the first
# class CREATURE: live: loop: visit (mall); if FIRST then collect (mall) end; change colour
#                 visit (m: separate MALL) do m.arrive (id, colour); r := m.outcome_of (id) end
#                 collect (m: separate MALL) require m.has_partner (id)
#                 do partner := m.partner_of (id); m.forget_partner (id) end

FIRST, CLOSED = "first", "closed"
W_VISIT = where("CREATURE", "visit", 20)
W_OUTCOME = where("CREATURE", "visit", 21)
W_COLLECT = where("CREATURE", "collect", 25)
W_HAS_PARTNER = where("CREATURE", "collect", 26)
W_PARTNER = where("CREATURE", "collect", 27)
W_LAUNCH = where("ROOT", "launch", 40)


class Mall:
    @leaf
    def make(self, meetings):
        self.left, self.waiting = meetings, None
        self.outcome, self.partner = {}, {}

    @leaf
    def arrive(self, ident, colour):
        if self.left == 0:
            self.outcome[ident] = CLOSED
        elif self.waiting is None:
            self.waiting, self.outcome[ident] = (ident, colour), FIRST
        else:
            first, first_colour = self.waiting
            self.waiting, self.left = None, self.left - 1
            self.partner[first], self.outcome[ident] = colour, first_colour

    @leaf
    def outcome_of(self, ident):
        return self.outcome[ident]

    @leaf
    def has_partner(self, ident):
        return ident in self.partner

    @leaf
    def partner_of(self, ident):
        return self.partner[ident]

    @leaf
    def forget_partner(self, ident):
        del self.partner[ident]


# Codegen's clause table for `collect` (see bench_condition.PRE_CHANGE).
PRE_COLLECT = (
    (
        lambda here, current, m: here.leaf_query(m, Mall.has_partner, (current.ident,), W_HAS_PARTNER),
        (0,),
        "has_partner",
        W_HAS_PARTNER,
    ),
)


class Creature:
    @leaf
    def make(self, ident, colour, mall):
        self.ident, self.colour, self.mall, self.count = ident, colour, mall, 0

    def live(self):
        while True:
            partner = self.visit(self.mall)
            if partner == CLOSED:
                return
            if partner == FIRST:
                partner = self.collect(self.mall)
            self.colour = complement(self.colour, partner)
            self.count += 1

    def visit(self, m):
        here = self._region_
        with here.reserve1(m, W_VISIT):  # id, colour: expanded (INTEGER, COLOUR)
            here.leaf_call(m, Mall.arrive, (self.ident, self.colour))
            return here.leaf_query(m, Mall.outcome_of, (self.ident,), W_OUTCOME)

    def collect(self, m):
        here = self._region_
        with here.reserve1(m, W_COLLECT, PRE_COLLECT, (here, self, m)):
            partner = here.leaf_query(m, Mall.partner_of, (self.ident,), W_PARTNER)
            here.leaf_call(m, Mall.forget_partner, (self.ident,))
            return partner


class Root:
    def make(self, creatures, meetings, out):
        here = self._region_
        mall = here.new_separate(Mall, Mall.make, (meetings,))
        out["team"] = [
            here.new_separate(Creature, Creature.make, (i, c, mall)) for i, c in enumerate(colours(creatures))
        ]
        for creature in out["team"]:
            self.launch(creature)

    def launch(self, c):
        here = self._region_
        here.command1(c, Creature.live, (), W_LAUNCH)


def scoop(creatures, meetings):
    out = {}
    run_program(Root, (creatures, meetings, out))
    check_counts("chameneos scoop", [c.count for c in out["team"]], meetings)


# --- the dialect version (benchmarks/chameneos/*.e), compiled by scoopc --------------


def program_args(creatures, meetings):
    return [str(meetings), str(creatures)]


def program_output(creatures, meetings):
    return f"chameneos: creatures={creatures} meetings={meetings} seen={2 * meetings}\n"
