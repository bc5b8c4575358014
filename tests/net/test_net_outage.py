"""A player on a link that hiccups (issue 36, "seats survive outages"), with real headless
peers through tools/net/udp_relay.py, which cuts one client's path both ways and restores
it (the peer lives on, its datagrams vanish meanwhile):

- Outages of 0.5, 1, 2, 5 and 10 s at one client in one match: the host notices a silence
  past the heartbeat's limit within 3 s, the computer stands in at once, and when the
  packets return the player has the seat back; the client never loses its server, and both
  end the match with the same health. Past PongNetProtocol.REJOIN_AFTER_S of silence (the
  10 s outage) the client has connected again by itself, and the seat comes back to that
  connection a new handshake after the packets return.
- A 20 s outage: the seat is given up after the grace, and the client is told so.
Every bound is the person's outcome, with generous margins for a loaded two-core machine;
the measured figures are printed.
"""

from __future__ import annotations

import time

from net_harness import (Network, engine_errors, logs, protocol_seconds, recounted_health,
                         run_match, workspace)

OUTAGES_S = (0.5, 1.0, 2.0, 5.0, 10.0)
# Between two outages, and before the first: the match plays on its ordinary path.
GAP_S = 4.0
NOTICE_BOUND_S = 3.0
# The silence after which a client connects again, and how soon after the packets return a
# client that did has its seat back: ENet's next connect attempt (one every 3 s at most while
# the path is dead), the handshake and the court prepared again; generous for a loaded machine.
REJOIN_AFTER_S = protocol_seconds("REJOIN_AFTER_S")
REJOIN_BOUND_S = 8.0
GRACE_S = protocol_seconds("SEAT_GRACE_S")
# A path of 25 ms each way: the heartbeat's limit is its floor, 1 s.
PATH = Network(25, 5, 0.0)


def cut_for(outages: tuple[float, ...], log: list[tuple[float, float]]):
    """An on_running hook for run_match: cuts client 0's path for each of [outages] in turn,
    GAP_S apart, appending (cut, restored) wall times to [log]. A rejoin's new connection is
    a new relay client, cut with the old while the outage lasts and not by the next ones:
    the outages long enough to make the client rejoin come last."""

    def hook(_peers, relay) -> None:
        assert relay is not None, "an outage is the relay's: run the match through one"
        for seconds in outages:
            time.sleep(GAP_S)
            # The client's machine is off the network: its connection, and any new one its
            # game opens meanwhile (a rejoin, from a new port).
            relay.blackhole(0)
            relay.blackhole("new")
            cut = time.time()
            time.sleep(seconds)
            relay.restore(0)
            relay.restore("new")
            log.append((cut, time.time()))

    return hook


def _first_after(entries: list[dict], wall_s: float) -> dict | None:
    later = [e for e in entries if e["wall_s"] >= wall_s]
    return min(later, key=lambda e: e["wall_s"]) if later else None


def _kept_its_server(client, restored: float, peers) -> None:
    """The client played to its match's end, or to the host's: each peer counts its match's
    seconds from its own start, so the host, which started first, may end and leave a moment
    before the client's own clock runs out (the other match tests allow it too). What must not
    happen is the client losing its server to the outage: no silence after the path came
    back, and a host that left rather than went quiet."""
    if client.report["exit"] == "time":
        return
    assert client.report["exit"] == "server lost", (client.report["exit"], logs(peers))
    lost = client.report["extra"]["server_lost"]
    assert lost["why"] == "the server left", (lost, logs(peers))
    silent_after = [e for e in client.report["extra"].get("absent", []) if e["wall_s"] > restored]
    assert not silent_after, (silent_after, logs(peers))


def test_a_player_cut_off_for_up_to_10_s_gets_the_seat_back_and_the_match_goes_on():
    windows: list[tuple[float, float]] = []
    seconds = GAP_S * (len(OUTAGES_S) + 1) + sum(OUTAGES_S) + 4.0
    with workspace() as work:
        peers, relay = run_match(work, 2, PATH, seconds, force_relay=True,
                                 on_running=cut_for(OUTAGES_S, windows))
        host, client = peers
        assert len(windows) == len(OUTAGES_S), logs(peers)
        assert relay["up"]["blackholed"] > 0 and relay["down"]["blackholed"] > 0, relay
        for peer in peers:
            assert peer.report["exit_code"] == 0, logs(peers)
            assert not engine_errors(peer), engine_errors(peer)[:10]
        assert host.report["exit"] == "time", logs(peers)
        _kept_its_server(client, windows[-1][1], peers)
        extra = host.report["extra"]
        taken, back = extra.get("peers_left", []), extra.get("seats_back", [])
        lines = []
        for (cut, restored), outage in zip(windows, OUTAGES_S):
            stood_in = [e for e in taken if cut <= e["wall_s"] <= restored + NOTICE_BOUND_S]
            returned = _first_after(back, cut)
            theirs = _first_after(client.report["extra"].get("back", []), cut)
            rejoined = _first_after(client.report["extra"].get("rejoined", []), cut)
            if rejoined is not None and rejoined["wall_s"] > restored + REJOIN_BOUND_S:
                rejoined = None  # A later outage's.
            line = f"{outage:.1f} s out: "
            if stood_in:
                notice = stood_in[0]["wall_s"] - cut
                assert 0.0 < notice < NOTICE_BOUND_S, (outage, notice)
                assert returned is not None, (outage, back, logs(peers))
                again = returned["wall_s"] - restored
                assert again < (REJOIN_BOUND_S if rejoined else NOTICE_BOUND_S), (outage, again)
                line += f"stood in after {notice:.2f} s, seat back {again:.2f} s after the path"
                if rejoined:
                    assert returned["peer"] == rejoined["peer"], (returned, rejoined)
                    line += " (on a new connection)"
            else:
                # Shorter than the heartbeat's limit: nothing to notice, nothing to hand back.
                assert outage < 2.0, (outage, taken, logs(peers))
                line += "under the heartbeat's limit: the player kept the seat throughout"
            # Well past the limit the client connects again; well short of it, it does not.
            assert (rejoined is not None) == (outage >= REJOIN_AFTER_S), (outage, rejoined)
            if 2.0 <= outage < REJOIN_AFTER_S:
                assert stood_in, (outage, taken, logs(peers))
                assert theirs is not None and theirs["wall_s"] - restored < NOTICE_BOUND_S, (
                    "the client saw its trouble end", outage, theirs)
            lines.append(line)
        assert len(back) == len(taken), (taken, back)
        # The seat ended the match as the client's, moved from its peer.
        assert host.report["controllers"][1] == "remote", host.report["controllers"]
        later = [t for t in host.report["transfers"] if t["wall_s"] > windows[-1][1]]
        assert len(later) >= 2, ("the rally went on after the last outage", later)
        # The rejoined client took up the health the host had then, its own hurts since are
        # all it lost, and it ended with the host's health (less a hurt in flight at the end).
        resumed = client.report["extra"]["rejoined"][-1]["health"]
        assert client.report["health"] == recounted_health(client.report, resumed)
        lost = [a - b for a, b in zip(host.report["health"], client.report["health"])]
        assert sum(abs(d) for d in lost) <= 2 * 10, (host.report["health"],
                                                     client.report["health"])
        print("outages at one client: " + "; ".join(lines))
        print(f"bad messages counted: host {host.report['refused']}, "
              f"client {client.report['refused']}")


def test_a_player_silent_past_the_grace_loses_the_seat_and_is_told_so():
    windows: list[tuple[float, float]] = []
    with workspace() as work:
        peers, _ = run_match(work, 2, PATH, GAP_S + GRACE_S + 14.0, force_relay=True,
                             on_running=cut_for((GRACE_S + 8.0,), windows))
        host, client = peers
        assert windows, logs(peers)
        cut = windows[0][0]
        assert host.report["exit_code"] == 0 and host.report["exit"] == "time", logs(peers)
        for peer in peers:
            assert not engine_errors(peer), engine_errors(peer)[:10]
        taken = host.report["extra"].get("peers_left", [])
        assert len(taken) == 1 and taken[0]["seats"] == [1], taken
        assert taken[0]["wall_s"] - cut < NOTICE_BOUND_S, (taken, cut)
        assert host.report["extra"].get("seats_back", []) == [], "never heard again in time"
        assert "their seat is given up" in host.log(), host.log()[-2000:]
        assert host.report["controllers"][1] == "computer", host.report["controllers"]
        # The client saw the trouble, then learnt that its seat was given up.
        trouble = client.report["extra"].get("absent", [])
        assert trouble and trouble[0]["wall_s"] - cut < NOTICE_BOUND_S, trouble
        assert client.report["exit_code"] == 0 and client.report["exit"] == "server lost", (
            logs(peers))
        lost = client.report["extra"]["server_lost"]
        assert "your seat was given up" in lost["why"], lost
        after = lost["wall_s"] - cut
        # The grace counts from the last beat heard, up to a beat interval before the cut.
        assert GRACE_S - 0.5 <= after < GRACE_S + NOTICE_BOUND_S + 2.0, after
        print(f"20 s cut: stood in after {taken[0]['wall_s'] - cut:.2f} s; the client was told "
              f"its seat was given up after {after:.1f} s ({lost['why']})")
