"""threadring (SCOOP/Qs, benchmarks game): 503 processors in a ring pass a token N times.

Node 1 gets the token N; a node holding t > 0 passes t - 1 on; the node that gets 0 wins.
Baseline: 503 threads, each blocking on its own queue.Queue mailbox.
"""
import queue

from common import check, join_all, start_all

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
    targets = [(_thread_node, (i + 1, boxes[i], boxes[(i + 1) % nodes], winner))
               for i in range(nodes)]
    threads = start_all(targets)
    boxes[0].put(hops)
    join_all(threads)
    check("threadring baseline winner", winner, [expected_winner(nodes, hops)])
