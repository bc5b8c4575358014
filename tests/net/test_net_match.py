"""Networked Haptic Battle Pong, real processes on 127.0.0.1: headless Godot peers under the
computer player play through tools/net/udp_relay.py (latency, jitter that reorders, loss).

Stated bounds (docs/pong-networking.md): the ball's divergence between a follower and the
master, p99, lined up on this machine's wall clock, stays under DIVERGENCE_P99_M for each
network; two peers never believe they are master at once for longer than one round trip
(by design they never do: the server sequences every transfer); a SIGKILLed peer is noticed
within DETECTION_BOUND_S; the master's contact force for a scripted hit matches a local game's
within CONTACT_TOLERANCE at every latency.
"""

from __future__ import annotations

import pytest

from net_harness import (Network, Peer, check_health, detection_s, divergences, engine_errors,
                         free_udp_port, killer, logs, master_overlaps, misbehaviour, quantile,
                         refusal_story, run_match, transfers, transfers_missed, workspace)

NETWORKS = {
    "lan": Network(0, 0, 0.0),
    "50ms": Network(50, 10, 0.05),
    "150ms": Network(150, 20, 0.05),
}
# p99 of |ball(follower) - ball(master)|, metres. A hit is only seen by followers one path
# delay (plus jitter) later, and meanwhile the two balls fly apart at up to twice the top
# speed (src/renderers/pong/pong_config.h, max_ball_speed_m_per_s). The bound is what a LAN shows
# plus that separation, with half as much again for the stream and frame periods at both
# ends, the relay's timers and the wall-clock alignment on a loaded machine.
LAN_DIVERGENCE_P99_M = 0.3
# Four peers share this machine's two cores: a follower may wait a time slice (~30 ms) for
# a core before it renders its ball, while the master's flies on (what the LAN p99 measured
# on a quiet and a busy machine: docs/pong-networking.md).
FOUR_PLAYER_MARGIN_M = 2.0 * 9.0 * 0.03
MAX_BALL_SPEED_M_PER_S = 9.0
DIVERGENCE_P99_M = {
    label: LAN_DIVERGENCE_P99_M
    + 1.5 * 2.0 * MAX_BALL_SPEED_M_PER_S * (net.delay_ms + net.jitter_ms) / 1000.0
    for label, net in NETWORKS.items()
}
# ENet's hard timeout follows the measured round trip (1 s on a LAN, about 1.6 s at 50 ms
# each way once ENet has measured it; its first estimates run high), plus a ping interval.
DETECTION_BOUND_S = 6.0
CONTACT_TOLERANCE = 0.10
RALLY_SECONDS = 12
# Each side follows the other's ball for about half a match; a loaded machine stalls a master's
# samples (a gap is not compared), and 12 s once left the client 0.9 s of comparable following.
ASYMMETRIC_SECONDS = 20



def _stream_story(peers: list[Peer], follower: dict, sent: int) -> str:
    """What each peer did with the ball stream, for a follower that took too few states:
    pytest's own repr of the peers is cut before the numbers that tell why."""
    lines = [f"peer {follower['peer']} took {follower['states']} of the {sent} states sent"]
    for p in peers:
        r = p.report
        lines.append(f"{p.name} {r['peer']}: sent {r['sent']} took {r['states']} late {r['late']} "
                     f"refused {r['refused']} stream {r['extra'].get('ball_stream')} "
                     f"master {r['master_intervals']} transfers "
                     f"{[(t['epoch'], t['master'], round(t['wall_s'], 2)) for t in r['transfers']]}")
    return "\n".join(lines) + "\n" + logs(peers)


def _check_consistent(peers: list[Peer], network: Network, min_handoffs: int = 3) -> None:
    reports = [p.report for p in peers]
    errors = [f"{p.name}: {line}" for p in peers for line in engine_errors(p)]
    assert not errors, "engine errors:\n" + "\n".join(errors[:10]) + "\n" + logs(peers)
    for peer in peers:
        assert peer.report.get("exit_code") == 0, logs(peers)
        assert misbehaviour(peer.report) == {}, f"{peer.name}: {refusal_story(peer.report)}"
    longest = max((transfers(r) for r in reports), key=len)
    handoffs = [t for t in longest if t[1] == 1]
    assert len(handoffs) >= min_handoffs, f"too few hand-offs to judge: {longest}\n" + logs(peers)
    missed = transfers_missed(reports, network)
    assert not missed, "\n".join(missed)
    # Never two masters longer than one round trip.
    overlaps = master_overlaps(reports)
    assert all(o <= network.round_trip_s + 0.05 for o in overlaps), overlaps
    # Each follower took the states the masters sent, less what the path lost and what its
    # jitter buffer found the play had passed (test_net_rough.py holds the used share of
    # what arrived to the 90 %). These floors date from the ordered channel, which
    # dropped every state overtaken by a newer one, and still hold for the worst case the
    # buffer meets: processes on two cores that send in bursts after each wait for a core,
    # and a server that relays once per frame. A hosted pair keeps 0.6 of what survives the
    # loss. Between two clients (four players, a dedicated server) a state crosses two legs,
    # and four peers on two cores burst the most: a quiet CI run's host took about a third of
    # what three client masters sent at 150 ms with the ordered channel, hence 0.2 for them
    # (docs/pong-networking.md, "Floors the tests hold").
    # With two players on a player's host (a core each) the master streams at 60 Hz or more.
    players = len([r for r in reports if r["seat"] >= 0])
    hosted_pair = players == 2 and len(reports) == 2
    kept = (1.0 - network.loss) * 0.6 if hosted_pair else (1.0 - network.loss) ** 2 * 0.2
    for follower in reports:
        others = [r for r in reports if r is not follower]
        sent = sum(r["sent"] for r in others)
        assert follower["states"] >= sent * kept, _stream_story(peers, follower, sent)
        others_master_s = sum(b - a for r in others for a, b in r["master_intervals"])
        if hosted_pair and others_master_s > 2.0:
            rate = follower["states"] / others_master_s
            assert rate >= 60.0 * kept, (rate, follower["peer"])
    # Health went the same way everywhere (reliable messages from the master and the
    # victims' peers), but for what was in flight when a peer quit.
    check_health(reports)


@pytest.mark.parametrize("players", [2, 4])
@pytest.mark.parametrize("label", list(NETWORKS))
def test_rally(label: str, players: int) -> None:
    network = NETWORKS[label]
    with workspace() as work:
        peers, relay = run_match(work, players, network, RALLY_SECONDS)
        _check_consistent(peers, network)
        reports = [p.report for p in peers]
        # Four players: four territories; the ball went through three of them at least.
        assert all(len(r["health"]) == players for r in reports), [r["health"] for r in reports]
        masters = {t[3] for t in transfers(reports[0])}
        assert len(masters) >= min(players, 3), (masters, transfers(reports[0]))
        spread = divergences(reports, network.path_s + 0.1)
        assert len(spread) > 200
        bound = DIVERGENCE_P99_M[label] + (FOUR_PLAYER_MARGIN_M if players == 4 else 0.0)
        print(f"rally {label}, {players} players: divergence p99 {quantile(spread, 0.99):.3f} m "
              f"(bound {bound:.2f} m)")
        assert quantile(spread, 0.99) < bound, quantile(spread, 0.99)
        if network.loss > 0:
            assert relay["up"]["dropped"] > 0 and relay["down"]["reordered"] > 0, relay


# The same round trip split evenly and 50/250 (the client's leg up, the host's leg down).
SYMMETRIC = Network(150, 20, 0.02)
ASYMMETRIC = Network(up_delay_ms=50, down_delay_ms=250, jitter_ms=20, loss=0.02)


def test_an_asymmetric_path_ages_each_state_by_its_own_leg() -> None:
    # A follower carries each state on by its age. Taken as half the round trip each way, the
    # host aged the client's states (50 ms old) as 150 ms and carried them 100 ms too far: its
    # median divergence was 1.7 times the symmetric path's (issue 36).
    medians: dict[str, dict[str, float]] = {}
    with workspace() as work:
        for name, network in (("symmetric", SYMMETRIC), ("asymmetric", ASYMMETRIC)):
            peers, _ = run_match(work, 2, network, ASYMMETRIC_SECONDS)
            _check_consistent(peers, network, min_handoffs=2)
            host, client = (p.report for p in peers)
            medians[name] = {"host": 0.0, "client": 0.0, "all": 0.0}
            for label, follower in (("host", host), ("client", client)):
                spread = divergences([host, client], network.path_s + 0.1, followers=(follower,))
                assert len(spread) > 100, (name, label, len(spread))
                medians[name][label] = quantile(spread, 0.5)
            medians[name]["all"] = quantile(divergences([host, client], network.path_s + 0.1), 0.5)
            print(f"{name}: state ages p50 host {host['age_p50_s']:.3f} s, client "
                  f"{client['age_p50_s']:.3f} s; divergence p50, m: {medians[name]}")
            # Each side's states arrive over its own leg: up 50 ms to the host, down 250 ms to
            # the client (the jitter adds up to 20 ms; the estimate uses the fastest beats).
            up, down = network.legs_ms
            assert abs(host["age_p50_s"] - (up + 10) / 1000.0) < 0.05, host["age_p50_s"]
            assert abs(client["age_p50_s"] - (down + 10) / 1000.0) < 0.05, client["age_p50_s"]
    # The host's ball no longer runs ahead of the client's (0.38 m against 0.02 m aged by
    # halves); the pooled median is printed (a 250 ms leg's follower has more to guess).
    assert medians["asymmetric"]["host"] <= medians["symmetric"]["host"] + 0.05, medians


def test_a_slow_lossy_handshake_still_connects() -> None:
    # The relay's seed 1 at 25 % loss drops the client's first two connects and a reply of
    # the server's: the version check then took more than Godot's default 3 s.
    with workspace() as work:
        peers, relay = run_match(work, 2, Network(150, 20, 0.25), 3, seed=1)
        host, client = peers
        assert relay["up"]["dropped"] > 0 and relay["down"]["dropped"] > 0, relay
        assert "client1 joined" in host.log(), logs(peers)
        assert host.report["exit"] == "time" and host.report["exit_code"] == 0, logs(peers)
        assert client.report["exit"] in ("time", "server lost"), logs(peers)
        # Whether the match then reached the client within the host's 3 s is up to ENet's
        # resends at 25 % loss: not what this test is about.
        assert client.report["exit_code"] == 0, logs(peers)


def _contact(peers: list[Peer]) -> dict:
    seat_one = [p for p in peers if p.report.get("seat") == 1]
    assert seat_one, [(p.name, p.report.get("exit"), p.report.get("error"), p.log()[-600:])
                      for p in peers]
    return seat_one[0].report["contact"]


def test_contact_profile_does_not_depend_on_latency() -> None:
    with workspace() as work:
        local = Peer("local", ["--pong-net=local"], work)
        try:
            local.start()
            assert local.wait() == 0, local.log()
        finally:
            local.kill()
        reference = local.report["contact"]
        assert reference["complete"] and reference["peak_n"] > 0.5, reference
        for label, network in NETWORKS.items():
            peers, _ = run_match(work, 2, network, 5,
                                 host_args=("--pong-net-script=hit",),
                                 client_args=(("--pong-net-script=hit",),))
            contact = _contact(peers)
            assert contact["complete"], (label, contact)
            for key in ("peak_n", "impulse_n_s", "duration_s"):
                assert contact[key] == pytest.approx(reference[key], rel=CONTACT_TOLERANCE), (
                    label, key, contact[key], reference[key])


def test_killed_peer_is_taken_over_by_the_computer() -> None:
    network = NETWORKS["50ms"]
    killed_at: list[float] = []
    with workspace() as work:
        peers, _ = run_match(work, 2, network, 12, on_running=killer(4.0, 1, killed_at))
        host = peers[0].report
        assert host["exit_code"] == 0, peers[0].log()
        left = host["extra"].get("peers_left", [])
        assert len(left) == 1 and left[0]["seats"] == [1], left
        assert 0.0 < detection_s(host, killed_at[0]) < DETECTION_BOUND_S, left
        # The computer took the seat; the host kept playing and is the only master since
        # (a takeover if the ball was with the peer, then every transfer is to the host).
        assert host["controllers"] == ["computer", "computer"], host["controllers"]
        later = [t for t in host["transfers"] if t["wall_s"] > left[0]["wall_s"]]
        assert all(t["master"] == 1 for t in later), later
        assert len([t for t in later if t["kind"] == 2]) <= 1


def test_version_mismatch_is_refused_on_both_sides() -> None:
    # Started by hand: the host waits (up to a minute) for a client slow to start on a loaded
    # machine, and goes as soon as the client has been refused (a host of 6 s was once gone
    # before such a client reached it).
    with workspace() as work:
        port = free_udp_port()
        host = Peer("host", ["--pong-net=host", f"--port={port}", "--name=host",
                             "--pong-net-max-seconds=60"], work)
        client = Peer("client1", ["--pong-net=join", f"--port={port}", "--name=client1",
                                  "--pong-net-version=hbp-net-0", "--pong-net-max-seconds=60"],
                      work)
        try:
            host.start()
            assert host.wait_for_log("Hosting on port"), host.log()
            client.start()
            assert client.wait() == 2, client.log()
            assert "refused" in client.report["error"] and "hbp-net-0" in client.report["error"]
            assert host.wait_for_log("refused: a client runs protocol 'hbp-net-0'"), host.log()
            assert not engine_errors(host), engine_errors(host)[:10]
        finally:
            client.kill()
            host.kill()


def test_dedicated_server_runs_a_match_between_two_clients() -> None:
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["50ms"], 10, dedicated=True)
        server, *clients = peers
        assert server.report["seat"] == -1
        _check_consistent(clients + [server], NETWORKS["50ms"], min_handoffs=1)


@pytest.mark.parametrize("who", ["host", "client"])
def test_a_slow_court_load_never_costs_a_player_the_seat(who: str) -> None:
    # A first match on a slow machine compiles the court's shaders (3.75 s measured on a
    # loaded two-core machine without a shader cache): that player keeps the seat. The slow
    # one plays 10 s after its court came up and quits first; the other plays on.
    slow = ("--pong-net-load-stall=5",)
    patient = ("--pong-net-seconds=25",)
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["lan"], 10,
                             host_args=slow if who == "host" else patient,
                             client_args=((slow if who == "client" else patient),))
        host, client = peers
        staller = host if who == "host" else client
        assert host.report["exit_code"] == 0 and client.report["exit_code"] == 0, logs(peers)
        stall = staller.report["extra"]["load_stall"]
        assert stall["to_wall_s"] - stall["from_wall_s"] >= 4.9, stall
        # The slow player played its whole match against the other.
        assert staller.report["exit"] == "time", (staller.report["exit"], logs(peers))
        theirs = ["local", "remote"] if who == "host" else ["remote", "local"]
        kinds = [k if k == "remote" else "local" for k in staller.report["controllers"]]
        assert kinds == theirs, staller.report["controllers"]
        # Nobody left the host before the slow player's match was over.
        over = stall["to_wall_s"] + 10.0 - 1.0
        early = [p for p in host.report["extra"].get("peers_left", []) if p["wall_s"] < over]
        assert early == [], (early, stall, logs(peers))


@pytest.mark.parametrize("seed", [1, 3, 5])
def test_four_players_joining_over_a_lossy_reordering_path_print_no_engine_error(seed: int) -> None:
    # These seeds of the relay at 25 % loss made a client's beat overtake its resent "auth
    # complete": the host's engine threw the beat away with an error line (4-51 a run).
    with workspace() as work:
        peers, _ = run_match(work, 4, Network(150, 20, 0.25), 3, seed=seed)
        errors = [f"{p.name}: {line}" for p in peers for line in engine_errors(p)]
        assert not errors, "\n".join(errors[:5]) + "\n" + logs(peers)
        # Whether every client gets in and stays through the match at 25 % loss is issue 36's
        # (joins without retries, outages), not this test's: some joined, the host ran.
        assert peers[0].report.get("exit_code") == 0, logs(peers)
        assert " joined (seat " in peers[0].log(), logs(peers)
