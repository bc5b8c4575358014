"""A player joining through a bad moment of the network (issue 36, "joins that retry"), with
real headless peers through tools/net/udp_relay.py: everything the server sends is lost for
the first 3 s (a loss burst while the player presses Join). The client tries again, says so,
and gets in; the host sees it join. Bounds are the person's outcome: joined, no error line.
"""

from __future__ import annotations

from net_harness import Network, engine_errors, logs, run_match, workspace

BURST = Network(25, 5, 0.0, answers_lost_first_ms=3000)


def test_a_join_gets_through_when_the_servers_first_answers_are_lost_for_3_s():
    with workspace() as work:
        peers, relay = run_match(work, 2, BURST, 4)
        host, client = peers
        assert relay["down"]["blackholed"] > 0, relay
        assert "client1 joined" in host.log(), logs(peers)
        assert "trying again (try 2)" in client.log(), logs(peers)
        assert client.report["exit_code"] == 0, logs(peers)
        assert client.report["exit"] in ("time", "server lost"), logs(peers)
        for peer in peers:
            assert not engine_errors(peer), engine_errors(peer)[:10]
        tries = client.log().count("trying again")
        print(f"a join through 3 s of lost answers: in after {tries + 1} tries")
