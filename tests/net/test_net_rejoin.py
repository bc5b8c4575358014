"""A player whose game dies in the middle of a match and who starts it again (issue 36: "a
rejoin with the same identity within that time reclaims it"), with real headless peers
through tools/net/udp_relay.py: the client is SIGKILLed (no goodbye: the host hears only
silence), a stranger tries to join meanwhile, then the same player's game starts again with
the identity the first one presented and joins the running match.

- The stranger is refused: a match is running, and the kept seat is not its own.
- The restarted game gets its seat back: the host gives the seat to the new connection, the
  new game plays the match as it stands (each seat's health, not the start's), and both end
  it with the same health.

And a player whose address changes in the middle of the match (a NAT that rebinds its port,
a laptop that roams to another Wi-Fi: the relay's `rebind`), which no packet of the old
connection survives: the game notices the silence, connects again by itself and takes the
seat back, without the player doing anything and without its process ending.
"""

from __future__ import annotations

import time

from net_harness import (Network, Peer, engine_errors, logs, misbehaviour, protocol_seconds,
                         recounted_health, refusal_story, run_match, workspace)

IDENTITY = "5eed" * 8
STRANGER = "0bad" * 8
# A path of 25 ms each way: the heartbeat's limit is its floor, 1 s.
PATH = Network(25, 5, 0.0)
SECONDS = 24.0
KILL_AFTER_S = 5.0
STRANGER_AFTER_S = 1.5
REJOIN_AFTER_S = 3.0
# The silence after which a client connects again.
RECONNECT_AFTER_S = protocol_seconds("REJOIN_AFTER_S")
# From the address change to the seat back: the silence, then a new handshake and the
# court prepared again; generous for a loaded machine (the time taken is printed).
RECONNECT_BOUND_S = RECONNECT_AFTER_S + 8.0


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
        # The rejoined game's messages were good ones: its shots numbered on, its ball on the
        # epoch it was handed.
        assert misbehaviour(host.report) == {}, refusal_story(host.report)
        lost = [a - b for a, b in zip(host.report["health"], again.report["health"])]
        in_flight = 2 * 10  # LAST_IN_FLIGHT hurts of the dearest cause.
        assert sum(abs(d) for d in lost) <= in_flight, (host.report["health"],
                                                        again.report["health"])
        start = host.report["start_health"]
        print(f"rejoin: seat back {took:.2f} s after the game started again, with health "
              f"{resumed} (start {start}); at the end host {host.report['health']}, rejoined "
              f"game {again.report['health']}")


def test_a_player_whose_address_changes_mid_match_rejoins_by_itself():
    events: dict[str, float] = {}

    def rebind(_peers, relay) -> None:
        time.sleep(KILL_AFTER_S)
        relay.rebind(0)
        events["rebound"] = time.time()

    with workspace() as work:
        peers, _ = run_match(work, 2, PATH, SECONDS, force_relay=True, on_running=rebind)
        host, client = peers
        assert "rebound" in events, logs(peers)
        for peer in peers:
            assert peer.report["exit_code"] == 0, logs(peers)
            assert not engine_errors(peer), engine_errors(peer)[:10]
        assert host.report["exit"] == "time", logs(peers)
        assert client.report["exit"] in ("time", "server lost"), logs(peers)
        if client.report["exit"] == "server lost":
            assert client.report["extra"]["server_lost"]["why"] == "the server left", logs(peers)
        # The client connected again by itself, and the host gave the seat to that connection.
        rejoined = client.report["extra"].get("rejoined", [])
        assert len(rejoined) == 1, (rejoined, logs(peers))
        back = [b for b in host.report["extra"].get("seats_back", [])
                if b["wall_s"] > events["rebound"]]
        assert back and back[0]["seats"] == [1], (back, logs(peers))
        assert back[0]["peer"] == rejoined[0]["peer"], (back, rejoined)
        took = back[0]["wall_s"] - events["rebound"]
        assert took < RECONNECT_BOUND_S, took
        assert host.report["controllers"][1] == "remote", host.report["controllers"]
        # It played on from the host's health of that moment, and ended with the host's.
        assert rejoined[0]["health"] == back[0]["health"], (rejoined, back)
        assert client.report["health"] == recounted_health(client.report,
                                                           rejoined[0]["health"])
        assert misbehaviour(host.report) == {}, refusal_story(host.report)
        later = [t for t in client.report["transfers"] if t["wall_s"] > rejoined[0]["wall_s"]]
        assert len(later) >= 2, ("the rally went on after the rejoin", later)
        lost = [a - b for a, b in zip(host.report["health"], client.report["health"])]
        assert sum(abs(d) for d in lost) <= 2 * 10, (host.report["health"],
                                                     client.report["health"])
        print(f"address change: seat back {took:.2f} s after it (silence, then a new "
              f"connection), with health {rejoined[0]['health']}; at the end host "
              f"{host.report['health']}, client {client.report['health']}; bad messages "
              f"counted: host {host.report['refused']}, client {client.report['refused']}")

