"""Networked Haptic Battle Pong's guards, real processes on 127.0.0.1 (issue 24, items 3 and 4).

- Dead peers: the master killed right after its own paddle hit (the issue's case: the host
  noticed after 14.7 s, and meanwhile the ball lay dead in the dead player's half) and a
  dedicated server killed under its two clients (noticed after 8.5 and 9.8 s) are noticed
  within NOTICE_BOUND_S by the heartbeat, the dead master's ball is taken over at once and
  the match goes on.
- The authority checks what it is told: a master forging floor hurts against the host's
  seat (the issue's 120 were accepted) costs the host nothing and is disconnected; a peer
  sending bytes that decode to no message (too short, cut off, unknown layouts, fields out of
  the schema's limits, NaN, huge strings, a flood) or messages that are not its to send is
  logged once, disconnected at the budget, and no engine error line is written (the issue,
  with variadic RPCs before them: 3,600 in 11 s).
- The lobby: a crafted connect flood (the issue's 12 datagrams locked every slot for 30 s)
  and connections that complete ENet's handshake and then say nothing do not keep a player
  out; a refused client is told why.
- Floods (issue 36): 200 crafted CONNECTs a second from fresh source ports for 30 s, in a
  network namespace of the test's own: from another address, against a dedicated server
  behind the kernel's guard (tools/net/flood-guard.sh), and from the player's own address
  against a player's host that nobody has joined yet, with nothing but the game's defences.
  A player joins at 5, 15 and 25 s into it (at 25 s a server without a defence has been
  full for 4.5 s), each within 5 s, and the server logs the flood once (before, joins failed
  from 5 s in and the server said nothing).
Every bound is generous for a loaded 2-core machine; the measured figures are printed.
"""

from __future__ import annotations

import time

import pytest

from flood_harness import flood_joins, missing_tools
from guard_harness import (CONNECT_BYTES, HIT_MARK, ROGUE_SCENE, LogWatch, check_taken_over,
                           flood_connects, half_open_clients, kill_on_line, start_peer)
from net_harness import (DRIVER_SCENE, ROUGH, SERVER_PEER, START_PATIENCE_S, TRANSFER_TAKEOVER,
                         Network, Peer, Relay, check_health, detection_s, engine_errors,
                         free_udp_port, killer, logs, run_match, transfers, workspace)

# The promise (docs/pong-networking.md): a dead peer is noticed within this, on any path.
NOTICE_BOUND_S = 3.0
# A connection to a live server completes in a few round trips; ENet's connect gives up after
# 3 s (PongNetProtocol.CONNECT_TIMEOUT_MAX_MS), so a player locked out fails instead.
JOIN_BOUND_S = 3.0
# A griefing master's stream runs dry after 2 s (PongNetStreamWatch.DRY_S): the ball then
# changes hands; in an honest match it does every second or two.
FREEZE_BOUND_S = 8.0
# PongNetProtocol.MISBEHAVIOUR_BUDGET and HALF_OPEN_PER_ADDRESS.
BUDGET = 16
HALF_OPEN_PER_ADDRESS = 4
# The sustained flood: its rate and length, the moments into it a player joins at, and the
# promise (issue 36: within 5 s). A join's time runs from the player's "Connecting to" to its
# "Connected;" (its log is read every 20 ms).
FLOOD_RATE = 200
FLOOD_S = 30.0
FLOOD_JOINS_AT_S = (5.0, 15.0, 25.0)
FLOOD_JOIN_BOUND_S = 5.0
# PongNetFlood.START_LINE and OVER_LINE.
FLOOD_LINE = "PongNet: a flood of connection requests"
FLOOD_OVER_LINE = "PongNet: the flood of connection requests is over"
NETWORKS = {
    "lan": Network(0, 0, 0.0),
    "150ms": Network(150, 20, 0.05),
    "rough": ROUGH,
}



def _port_of(peer: Peer) -> int:
    return int(next(a for a in peer.args if a.startswith("--port=")).split("=")[1])


def _no_engine_errors(peer: Peer) -> None:
    errors = engine_errors(peer)
    assert not errors, f"{peer.name}: engine errors:\n" + "\n".join(errors[:10])


@pytest.mark.parametrize("label", list(NETWORKS))
def test_a_master_killed_after_its_hit_is_noticed_within_3_s_and_the_match_goes_on(
        label: str) -> None:
    killed_at: list[float] = []
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS[label], 24,
                             client_args=(("--rogue=mark",),), client_scenes=(ROGUE_SCENE,),
                             on_running=kill_on_line(1, HIT_MARK, killed_at))
        host = peers[0]
        assert killed_at, "the client never hit the ball as master:\n" + logs(peers)
        report = host.report
        assert report["exit_code"] == 0 and report["exit"] == "time", logs(peers)
        _no_engine_errors(host)
        notice = detection_s(report, killed_at[0])
        print(f"{label}: master killed after its hit, noticed after {notice:.2f} s")
        assert notice is not None and 0.0 < notice < NOTICE_BOUND_S, logs(peers)
        assert "silent for" in host.log(), "the heartbeat noticed it, not ENet"
        check_taken_over(report)


def test_a_killed_dedicated_server_is_noticed_by_its_clients_within_3_s() -> None:
    killed_at: list[float] = []
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["lan"], 20, dedicated=True,
                             on_running=killer(10.0, 0, killed_at))
        clients = peers[1:]
        notices = []
        for client in clients:
            report = client.report
            # Each player sees the trouble; the seat is kept past the match's end (the grace:
            # tests/net/test_net_outage.py).
            assert report["exit_code"] == 0 and report["exit"] in ("time", "server lost"), (
                logs(peers))
            _no_engine_errors(client)
            trouble = report["extra"].get("absent", [])
            assert trouble and trouble[0]["peer"] == 1, (trouble, logs(peers))
            notices.append(trouble[0]["wall_s"] - killed_at[0])
        print(f"dedicated server killed: clients noticed after "
              f"{', '.join(f'{n:.2f}' for n in notices)} s")
        assert all(0.0 < n < NOTICE_BOUND_S for n in notices), notices


def _cheat_match(work, mode: str, mark: str) -> tuple[Peer, dict, int, str]:
    """A 14 s match on the LAN against the rogue client in [mode]: the host, its report, the
    cheat's peer id and the rogue's last [mark] line. The cheat must have been master, been
    disconnected at the budget, and cost the host no hurt at an epoch it was master of (the
    host's health is what its own hurts say)."""
    peers, _ = run_match(work, 2, NETWORKS["lan"], 14,
                         client_args=((f"--rogue={mode}",),), client_scenes=(ROGUE_SCENE,))
    host, rogue = peers
    report = host.report
    assert report["exit_code"] == 0, logs(peers)
    _no_engine_errors(host)
    marks = [line for line in rogue.log().splitlines() if mark in line]
    assert marks, "the rogue never was the master:\n" + logs(peers)
    left = report["extra"].get("peers_left", [])
    assert len(left) == 1 and left[0]["seats"] == [1], (left, logs(peers))
    cheat = left[0]["peer"]
    assert host.log().count(f"disconnecting peer {cheat}: {BUDGET} bad messages") == 1
    master_of = {t["epoch"]: t["master"] for t in report["transfers"]}
    own = [h for h in report["hurts"] if h[1] == 0]
    assert all(master_of.get(h[0]) == 1 for h in own), (own, master_of)
    check_health([report])
    return host, report, cheat, marks[-1]


def test_a_master_forging_floor_hurts_costs_the_host_nothing_and_is_disconnected() -> None:
    with workspace() as work:
        host, report, cheat, forged = _cheat_match(work, "forge", "forged floor hurts sent")
        assert host.log().count(f"peer {cheat} sent a bad") == 1, "warned once"
        refused = report["refused"].get("floor claim", 0) + report["refused"].get("hurt", 0)
        assert refused >= BUDGET, report["refused"]
        print(f"{forged}; host refused {report['refused']}; host health "
              f"{report['health']} of {report['start_health']}")


def test_a_master_forging_the_ball_gains_nothing_and_is_disconnected() -> None:
    """The issue's cheat: once master, the rogue stopped its real stream and sent a ball of
    its own bouncing in the host's territory, claiming each bounce (61 claims accepted then,
    the opponent 99 -> 32). The server checks each state against its own simulation."""
    with workspace() as work:
        _, report, _, forged = _cheat_match(work, "forge-ball", "forged ball states sent")
        checked = report["extra"]["ball_check"]["verdicts"]
        assert checked.get("unreachable", 0) >= 1, checked
        assert report["refused"].get("ball state", 0) >= 1, report["refused"]
        print(f"{forged}; host's check {checked}; refused {report['refused']}; host health "
              f"{report['health']} of {report['start_health']}")


def test_a_master_streaming_nothing_cannot_freeze_the_rally() -> None:
    """The griefer: whenever it is the ball's master it streams nothing, its heartbeat going
    on (before, the rally froze for everyone: the server followed a ball that never came, and
    its referee saw it still moving). The server takes the ball and counts it each time, and
    the ball goes on changing hands."""
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["lan"], 14, client_args=(("--rogue=mute",),),
                             client_scenes=(ROGUE_SCENE,))
        host, rogue = peers
        report = host.report
        assert report["exit_code"] == 0, logs(peers)
        _no_engine_errors(host)
        muted = [line for line in rogue.log().splitlines() if "streaming nothing" in line]
        assert muted, "the rogue never was the master:\n" + logs(peers)
        taken = [t for t in report["transfers"]
                 if t["kind"] == TRANSFER_TAKEOVER and t["master"] == SERVER_PEER]
        assert taken, (transfers(report), logs(peers))
        assert report["refused"].get("ball state", 0) >= len(taken), report["refused"]
        assert "no state the server could play" in host.log(), logs(peers)
        times = [t["wall_s"] for t in report["transfers"]]
        longest = max(b - a for a, b in zip(times, times[1:]))
        assert longest < FREEZE_BOUND_S, (longest, transfers(report))
        print(f"{len(muted)} epochs muted; the server took the ball {len(taken)} times; "
              f"refused {report['refused']}; the ball changed hands {len(times)} times, at most "
              f"{longest:.1f} s apart")


def test_the_server_forwards_to_the_other_client_only_what_it_accepted() -> None:
    """Clients reach each other only through the server, which forwards what it accepted:
    the forged ball it refused never reaches the other player (Godot's own relay passed on
    everything; in the issue 21,392 stale states in about 7 s)."""
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["lan"], 14, dedicated=True,
                             client_args=((), ("--rogue=forge-ball",)),
                             client_scenes=(DRIVER_SCENE, ROGUE_SCENE))
        server, honest, rogue = (p.report for p in peers)
        assert "forged ball states sent" in peers[2].log(), logs(peers)
        assert server["refused"].get("ball state", 0) >= 1, server["refused"]
        cheat = rogue["peer"]
        forwarded = server["forwarded"].get(f"{cheat} ball state", 0)
        taken = honest["states_from"].get(str(cheat), 0)
        # Of the cheat's states the honest client took only what the server forwarded (its
        # honest ones, if it streamed any before forging), while the honest client's poses
        # reached the cheat through the server.
        assert taken <= forwarded, (taken, forwarded, server["forwarded"])
        assert server["forwarded"].get(f"{honest['peer']} pose", 0) > 0, server["forwarded"]
        assert rogue["poses"] > 0, rogue
        _no_engine_errors(peers[1])
        print(f"server forwarded {server['forwarded']}; refused {server['refused']}; the honest "
              f"client took {taken} of the cheat's states")


def test_bad_messages_are_logged_once_and_the_sender_disconnected_at_the_budget() -> None:
    with workspace() as work:
        peers, _ = run_match(work, 2, NETWORKS["lan"], 8, client_scenes=(ROGUE_SCENE,))
        host, rogue = peers
        assert "sending bad messages" in rogue.log(), logs(peers)
        report = host.report
        assert report["exit_code"] == 0, logs(peers)
        # Malformed, out of range, without authority, a flood: none is an engine error (an RPC
        # with a wrong count or type was one per call), none is a log line of its own.
        _no_engine_errors(host)
        log = host.log()
        assert "RPC - " not in log
        left = report["extra"].get("peers_left", [])
        assert len(left) == 1 and left[0]["seats"] == [1], (left, logs(peers))
        rogue_id = left[0]["peer"]
        assert log.count("sent a bad") == 1 and f"peer {rogue_id} sent a bad" in log, log
        assert log.count(f"disconnecting peer {rogue_id}: {BUDGET} bad messages") == 1
        refused = report["refused"]
        assert sum(refused.values()) >= BUDGET - 1, refused
        kinds = {"message", "ball state", "pose", "transfer", "hurt", "owners", "bullet", "mine",
                 "weapon hurt", "hello", "start", "lobby", "refusal"}
        assert len(kinds & set(refused)) >= 8, refused
        # The match went on without it: the computer took its seat and the host played on.
        assert report["controllers"] == ["computer", "computer"], report["controllers"]
        later = [t for t in report["transfers"] if t["wall_s"] > left[0]["wall_s"]]
        assert later and all(t["master"] == 1 for t in later), later
        print(f"rogue disconnected; host refused {refused}")


def test_a_client_refused_by_a_running_match_is_told_why() -> None:
    refused: list[Peer] = []
    with workspace() as work:

        def join_late(peers: list[Peer], _relay: Relay | None) -> None:
            time.sleep(2.0)
            late = start_peer(work, "late", ["--pong-net=join", f"--port={_port_of(peers[0])}",
                                             "--name=late", "--pong-net-max-seconds=20"])
            refused.append(late)
            try:
                late.wait()
            finally:
                late.kill()

        # The match lasts long enough for a third engine to start on a busy machine.
        peers, _ = run_match(work, 2, NETWORKS["lan"], 25, on_running=join_late)
        late = refused[0]
        assert late.report["exit"] == "failed" and late.proc.returncode == 2, late.log()
        assert late.report["error"] == "the server refused us: a match is running", late.report
        assert "refused peer" in peers[0].log() and "a match is running" in peers[0].log()
        assert peers[0].report["exit_code"] == 0
        print(f"late client: {late.report['error']}")


def test_a_client_refused_by_a_full_lobby_is_told_why() -> None:
    with workspace() as work:
        port = free_udp_port()
        common = ["--pong-net-autopilot", "--pong-net-max-seconds=20"]
        started: list[Peer] = []
        try:
            host = start_peer(work, "host", ["--pong-net=host", f"--port={port}", "--name=host",
                                             "--pong-net-seats=2", "--pong-net-peers=3",
                                             *common])
            started.append(host)
            assert host.wait_for_log("Hosting on port"), host.log()
            first = start_peer(work, "client1", ["--pong-net=join", f"--port={port}",
                                                 "--name=client1", *common])
            started.append(first)
            assert host.wait_for_log("client1 joined"), host.log()
            second = start_peer(work, "client2", ["--pong-net=join", f"--port={port}",
                                                  "--name=client2", *common])
            started.append(second)
            assert second.wait() == 2, second.log()
            assert second.report["error"] == "the server refused us: the server is full"
            assert "the server is full" in host.log()
            print(f"third player on two seats: {second.report['error']}")
        finally:
            for peer in started:
                peer.kill()


def test_a_connect_flood_and_silent_connections_do_not_keep_a_player_out() -> None:
    flood = 200
    with workspace() as work:
        port = free_udp_port()
        common = ["--pong-net-autopilot", "--pong-net-peers=2", "--pong-net-seconds=3",
                  "--pong-net-max-seconds=40"]
        started: list[Peer] = []
        holders = []
        try:
            host = start_peer(work, "host", ["--pong-net=host", f"--port={port}", "--name=host",
                                             *common])
            started.append(host)
            assert host.wait_for_log("Hosting on port"), host.log()
            # Crafted CONNECTs that never go further (more than 30 times the six slots that
            # 12 of them used to fill), and clients that complete ENet's handshake and then
            # say nothing (each held its slot until the version check's 15 s ran out).
            sent = flood_connects(port, flood)
            assert sent == flood * CONNECT_BYTES
            holders = half_open_clients(port, 12)
            client = start_peer(work, "client1", ["--pong-net=join", f"--port={port}",
                                                  "--name=client1", *common])
            started.append(client)
            watch = LogWatch(client)
            assert watch.wait(["Connecting to", "Connected;"], START_PATIENCE_S), client.log()
            join_s = watch.seen["Connected;"] - watch.seen["Connecting to"]
            print(f"after {flood} crafted CONNECTs ({sent} bytes) and 12 silent connections: "
                  f"joined in {join_s:.2f} s (its log is read every 20 ms)")
            assert join_s < JOIN_BOUND_S
            assert client.wait() == 0 and host.wait() == 0, logs(started)
            # Each quits at its own match clock: the client may see the host go first.
            assert host.report["exit"] == "time", logs(started)
            assert client.report["exit"] in ("time", "server lost"), logs(started)
            assert client.report["seat"] == 1, client.report
            _no_engine_errors(host)
            # The silent connections from this address beyond the first few were let go.
            dropped = host.log().count("dropped unauthenticated peer")
            assert dropped >= 12 - HALF_OPEN_PER_ADDRESS, host.log()
        finally:
            for holder in holders:
                holder.close()
            for peer in started:
                peer.kill()


def _check_flood(label: str, result: dict) -> None:
    """The person's outcome under the sustained flood, and the server's word on it."""
    server, *clients = result["peers"]
    flood = result["flood"]
    joins = result["joins"]
    print(f"{label}: flood {flood}; guard {result['counters'] or 'none'}")
    print(f"{label}: joins " + ", ".join(
        f"at {j['at_s']:.1f} s in {j['join_s']:.2f} s" if j["join_s"] is not None
        else f"at {j['at_s']} s: never" for j in joins)
        + f"; the server logged the flood {result['logged_s']} s in")
    # The flood held its rate from fresh ports until after the last join.
    assert flood["rate"] >= 0.9 * FLOOD_RATE and flood["sent"] >= 0.9 * FLOOD_RATE * FLOOD_S, flood
    assert flood["source_ports"] >= 0.5 * flood["sent"], flood
    for join, client in zip(joins, clients):
        assert join["join_s"] is not None, f"{client.name} never joined:\n{client.log()}"
        assert join["join_s"] < FLOOD_JOIN_BOUND_S, (join, client.log())
        assert join["at_s"] < flood["stopped_s"], "it joined while the flood went on"
        assert client.report.get("exit") == "deadline", client.log()
        _no_engine_errors(client)
    log = server.log()
    assert log.count(FLOOD_LINE) == 1, log
    assert log.count(FLOOD_OVER_LINE) <= 1, log
    _no_engine_errors(server)


@pytest.mark.skipif(bool(missing_tools(True)), reason=missing_tools(True) or "-")
def test_a_sustained_connect_flood_from_another_address_lets_players_into_a_guarded_server(
) -> None:
    with workspace() as work:
        result = flood_joins(work, ["--server", "--pong-net-peers=4"], True, FLOOD_JOINS_AT_S,
                             FLOOD_RATE, FLOOD_S, "127.0.0.2", FLOOD_LINE)
        _check_flood("dedicated server, kernel guard, flood from 127.0.0.2", result)


@pytest.mark.skipif(bool(missing_tools(False)), reason=missing_tools(False) or "-")
def test_a_sustained_connect_flood_from_the_players_address_lets_them_into_a_waiting_host(
) -> None:
    with workspace() as work:
        result = flood_joins(work, ["--pong-net=host", "--name=host", "--pong-net-peers=4"],
                             False, FLOOD_JOINS_AT_S, FLOOD_RATE, FLOOD_S, "127.0.0.1",
                             FLOOD_LINE)
        _check_flood("player's host, no guard, flood from 127.0.0.1", result)
