"""threadring (SCOOP/Qs, benchmarks game): 503 processors in a ring pass a token N times.

Node 1 gets the token N; a node holding t > 0 passes t - 1 on; the node that gets 0 wins.
Baseline: 503 threads, each blocking on its own queue.Queue mailbox.
"""

import queue

from scoopc.runtime import leaf

from common import check, join_all, run_program, start_all, where

SIZES = {
    "full": {"nodes": 503, "hops": 300_000},
    "quick": {"nodes": 503, "hops": 20_000},
    "smoke": {"nodes": 503, "hops": 1_000},
}


def ops(nodes, hops):
    return hops


def expected_winner(nodes, hops):
    """Nodes are numbered from 1; the token starts at node 1."""
    return hops % nodes + 1


# --- hand-written threading --------------------------------------------------

STOP = -1


def _thread_node(ident, inbox, outbox, winner):
    while True:
        token = inbox.get()
        if token == STOP:
            outbox.put(STOP)
            return
        if token == 0:
            winner.append(ident)
            outbox.put(STOP)
            return
        outbox.put(token - 1)


def baseline(nodes, hops):
    boxes = [queue.Queue() for _ in range(nodes)]
    winner = []
    targets = [(_thread_node, (i + 1, boxes[i], boxes[(i + 1) % nodes], winner)) for i in range(nodes)]
    threads = start_all(targets)
    boxes[0].put(hops)
    join_all(threads)
    check("threadring baseline winner", winner, [expected_winner(nodes, hops)])


# --- SCOOP, as generated code calls the runtime ----------------------------------
# (@leaf where codegen would put it: routines without loops, separate or blocking calls)
# class NODE:   receive (t) do if t = 0 then finish (result) else pass (next, t - 1) end end
#               pass (n: separate NODE; t) do n.receive (t) end
#               finish (r: separate RESULT) do r.set_winner (id) end
# class ROOT:   make: create the nodes (each knowing the next), close the ring, pass (first, N)

W_PASS = where("NODE", "pass", 12)
W_FINISH = where("NODE", "finish", 16)
W_CLOSE = where("ROOT", "close_ring", 30)
W_START = where("ROOT", "start", 34)


class Result:
    @leaf
    def make(self):
        self.winner = None

    @leaf
    def set_winner(self, ident):
        self.winner = ident


class Node:
    @leaf
    def make(self, ident, result, next_node):
        self.ident, self.result, self.next = ident, result, next_node

    @leaf
    def set_next(self, next_node):
        self.next = next_node

    def receive(self, token):
        if token == 0:
            self.finish(self.result)
        else:
            self.pass_token(self.next, token - 1)

    def pass_token(self, n, token):
        here = self._region_
        here.command1(n, Node.receive, (token,), W_PASS)  # INTEGER: passes no lock

    def finish(self, r):
        here = self._region_
        here.command1(r, Result.set_winner, (self.ident,), W_FINISH)


class Root:
    def make(self, nodes, hops, out):
        here = self._region_
        out["result"] = result = here.new_separate(Result, Result.make)
        last = next_node = here.new_separate(Node, Node.make, (nodes, result, None))
        for ident in range(nodes - 1, 0, -1):
            next_node = here.new_separate(Node, Node.make, (ident, result, next_node))
        self.first = next_node
        self.close_ring(last)
        self.start(self.first, hops)

    def close_ring(self, last):
        here = self._region_
        with here.reserve1(last, W_CLOSE):
            here.call(last, Node.set_next, (self.first,))

    def start(self, first, hops):
        here = self._region_
        here.command1(first, Node.receive, (hops,), W_START)


def scoop(nodes, hops):
    out = {}
    run_program(Root, (nodes, hops, out))
    check("threadring scoop winner", out["result"].winner, expected_winner(nodes, hops))


# --- the dialect version (benchmarks/threadring/*.e), compiled by scoopc -------------


def program_args(nodes, hops):
    return [str(hops), str(nodes)]


def program_output(nodes, hops):
    return f"threadring: nodes={nodes} hops={hops} winner={expected_winner(nodes, hops)}\n"
