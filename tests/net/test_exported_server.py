"""The exported dedicated server (make export-server), as an operator runs it.

The self-contained build in $HAPTICS_SERVER (its launcher) starts with an emptied environment
(only HOME, pointing into the test's folder, so user:// is there) and referees a match between
two clients of the source tree through the relay at 50 ms. An export holds no test driver
(tests/ is not exported): the server runs with the game's own options, writes no report and
serves until its deadline (--pong-net-max-seconds). It must announce itself as a dedicated
server, relay each client's ball states to the other, sequence the same hand-offs for both,
serve on after they have quit, exit 0 at its deadline, and print no error: neither the
engine's nor ours. make test-export-server runs it; make test-net leaves it out (it needs the
export).
"""

from __future__ import annotations

import os
from pathlib import Path

from net_harness import (SERVER_PEER, TRANSFER_TAKEOVER, Network, engine_errors, run_match,
                         transfers, workspace)

SECONDS = 10


def test_the_exported_server_referees_a_match_with_an_empty_environment() -> None:
    launcher = Path(os.environ.get("HAPTICS_SERVER", "")).resolve()
    assert os.access(launcher, os.X_OK), f"no exported server at {launcher}: make export-server"
    with workspace() as work:
        home = work / "home"
        home.mkdir()
        command = ("env", "-i", f"HOME={home}", str(launcher), "--headless")
        peers, relay = run_match(work, 2, Network(50, 5, 0.0), SECONDS, dedicated=True,
                                 server_command=command)
        server, clients = peers[0], peers[1:]
        logs = "\n".join(f"--- {p.name}:\n{p.log()[-3000:]}" for p in peers)
        for peer in peers:
            assert peer.report.get("exit_code") == 0, logs
        assert "PongNet: done (deadline)" in server.log(), logs
        for peer in peers:
            errors = engine_errors(peer)
            assert errors == [], (peer.name, errors[:5])
        assert "(dedicated server)" in server.log(), logs
        assert relay["up"]["delivered"] > 0 and relay["down"]["delivered"] > 0, relay
        # It refereed: both clients were masters in turn, never the server, and each took the
        # other's states through the server's relay, less what the path lost and what arrived
        # too late to play (about half on a quiet machine; docs/pong-networking.md), hence a
        # floor well below that.
        first, second = (c.report for c in clients)
        for taker, sender in ((first, second), (second, first)):
            assert sender["sent"] > 0 and taker["states"] > 0.3 * sender["sent"], (
                taker["peer"], taker["states"], sender["sent"])
        # The hand-offs every peer saw are the server's (a peer may miss the last one in
        # flight when its match clock ends), and a dedicated server never masters the ball
        # while both play: the one takeover allowed is the last, when the first client to end
        # its match left with the ball (the server takes it over so it never lacks a master).
        theirs = max((transfers(c.report) for c in clients), key=len)
        assert len(theirs) >= 2, theirs
        while_both = theirs[:-1] if theirs[-1][1] == TRANSFER_TAKEOVER else theirs
        assert all(master != SERVER_PEER for _, _, _, master in while_both), theirs
        for client in clients:
            mine = transfers(client.report)
            assert mine == theirs[:len(mine)] and len(mine) >= len(theirs) - 1, (mine, theirs)
