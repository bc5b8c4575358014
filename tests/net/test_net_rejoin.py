"""A player whose game dies in the middle of a match and who starts it again (issue 36: "a
rejoin with the same identity within that time reclaims it"), with real headless peers
through tools/net/udp_relay.py: the client is SIGKILLed (no goodbye: the host hears only
silence), a stranger tries to join meanwhile, then the same player's game starts again with
the identity the first one presented and joins the running match.

- The stranger is refused: a match is running, and the kept seat is not its own.
- The restarted game gets its seat back: the host gives the seat to the new connection, the
  new game plays the match as it stands (each seat's health, not the start's), and both end
  it with the same health.
"""

from __future__ import annotations

import time

from net_harness import (Network, Peer, engine_errors, logs, recounted_health, run_match,
                         workspace)

IDENTITY = "5eed" * 8
STRANGER = "0bad" * 8
# A path of 25 ms each way: the heartbeat's limit is its floor, 1 s.
PATH = Network(25, 5, 0.0)
SECONDS = 24.0
KILL_AFTER_S = 5.0
STRANGER_AFTER_S = 1.5
REJOIN_AFTER_S = 3.0


def kill_and_rejoin(events: dict):
    """An on_running hook for run_match: kills client 1, sends a stranger, then starts the
    client again with its identity; the two new peers join the run's list (it waits for them
    and stops them)."""

    def hook(peers: list[Peer], _relay) -> None:
        client = peers[1]
        time.sleep(KILL_AFTER_S)
        client.kill()
        events["killed"] = time.time()
        time.sleep(STRANGER_AFTER_S)
        args = [a for a in client.args if not a.startswith(("--identity=", "--name="))]
        stranger = Peer("stranger", [*args, "--name=stranger", f"--identity={STRANGER}"],
                        client.workdir)
        stranger.start()
        peers.append(stranger)
        time.sleep(REJOIN_AFTER_S - STRANGER_AFTER_S)
        again = Peer("client1-again", list(client.args), client.workdir)
        again.start()
        peers.append(again)
        events["rejoined"] = time.time()

    return hook


def test_a_player_whose_game_restarts_within_the_grace_takes_the_seat_back():
    events: dict[str, float] = {}
    with workspace() as work:
        peers, _ = run_match(work, 2, PATH, SECONDS, force_relay=True,
                             client_args=((f"--identity={IDENTITY}",),),
                             on_running=kill_and_rejoin(events))
        assert len(peers) == 4, logs(peers)
        host, _, stranger, again = peers
        assert host.report["exit_code"] == 0 and host.report["exit"] == "time", logs(peers)
        for peer in (host, again):
            assert not engine_errors(peer), engine_errors(peer)[:10]
        # The stranger is told why, and goes.
        assert stranger.report["exit_code"] == 2, logs([stranger])
        assert "a match is running" in stranger.log(), stranger.log()[-2000:]
        # The host stood in for the silent player, then gave the seat to its new connection.
        assert "client1 rejoined" in host.log(), host.log()[-3000:]
        back = host.report["extra"].get("seats_back", [])
        assert len(back) == 1 and back[0]["seats"] == [1], back
        assert back[0]["peer"] == again.report["peer"], (back, again.report["peer"])
        took = back[0]["wall_s"] - events["rejoined"]
        assert took < 20.0, took  # A restart under load: the court is prepared first.
        assert host.report["controllers"][1] == "remote", host.report["controllers"]
        # The new game played the match on: it saw the ball change hands, and it ended with
        # the host's health (less the hurts in flight when one of them quit).
        assert again.report["exit_code"] == 0, logs([host, again])
        assert again.report["exit"] in ("time", "server lost"), logs([host, again])
        assert len(again.report["transfers"]) >= 2, again.report["transfers"]
        # It took up the match with the health the host had then, not the start's, and its
        # own hurts since are all it lost.
        resumed = again.report["extra"]["health_at_start"]
        assert resumed == back[0]["health"], (resumed, back[0])
        assert again.report["health"] == recounted_health(again.report, resumed), (
            again.report["health"], resumed)
        lost = [a - b for a, b in zip(host.report["health"], again.report["health"])]
        in_flight = 2 * 10  # LAST_IN_FLIGHT hurts of the dearest cause.
        assert sum(abs(d) for d in lost) <= in_flight, (host.report["health"],
                                                        again.report["health"])
        start = host.report["start_health"]
        print(f"rejoin: seat back {took:.2f} s after the game started again, with health "
              f"{resumed} (start {start}); at the end host {host.report['health']}, rejoined "
              f"game {again.report['health']}")
