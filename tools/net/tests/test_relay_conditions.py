"""The rough networks through the real relay on 127.0.0.1: numbered datagrams in, what
arrives out. Every run is seeded, so what the relay decides is the same each time; only the
machine's timing varies, and the assertions bound it generously (timers are only late)."""

from __future__ import annotations

import time

import pytest
from relay_fixtures import (EchoServer, RelayProcess, address_of, balanced, client, collect,
                            send_numbered, stats_of)

ROUGH_DELAY = ["--delay-ms", "200", "--jitter-ms", "60", "--jitter-centred"]


@pytest.fixture
def sink():
    server = EchoServer(p_echo=False)
    yield server
    server.close()


@pytest.fixture
def echo():
    server = EchoServer()
    yield server
    server.close()


def numbers(p_payloads: list[bytes]) -> list[int]:
    return [int(p[-5:]) for p in p_payloads]


def through(p_server: EchoServer, p_stats, p_count: int, p_per_ms: float,
            *p_args: str, p_expect: float = 0) -> tuple[list[float], dict]:
    """Sends [p_count] numbered datagrams up through a relay with [p_args] and waits for
    them at [p_server] ([p_expect] of them; 0: the count; inf: until quiet); the send times
    and the relay's counts."""
    relay = RelayProcess(p_server.port, p_stats, *p_args)
    try:
        sock = client(relay.port)
        sent_at = send_numbered(sock, p_count, p_per_ms)
        p_server.wait_for(p_expect or p_count, 1.5)
        sock.close()
    finally:
        assert relay.stop() == 0
    stats = stats_of(p_stats)
    assert balanced(stats["up"]) and stats["up"]["undelivered"] == 0
    return sent_at, stats


def late_ones(p_order: list[int]) -> int:
    """Arrivals after a datagram sent later (what the relay counts as reordered)."""
    newest, late = -1, 0
    for n in p_order:
        late += n < newest
        newest = max(newest, n)
    return late


def overtakers(p_order: list[int]) -> int:
    """Arrivals before a datagram sent earlier (what the relay counts as overtaking)."""
    lowest_after, count = float("inf"), 0
    for n in reversed(p_order):
        count += lowest_after < n
        lowest_after = min(lowest_after, n)
    return count


def test_centred_jitter_reorders_and_loses_nothing(sink, tmp_path):
    count = 400
    sent_at, stats = through(sink, tmp_path / "stats.json", count, 0.2, *ROUGH_DELAY,
                             "--seed", "5")
    order = numbers(sink.payloads())
    assert sorted(order) == list(range(count))
    # Datagrams 5 ms apart with delays 200 +- 60 ms: nearly half of the neighbours swap.
    swapped = sum(1 for a, b in zip(order, order[1:]) if b < a)
    assert swapped >= 0.2 * count, swapped
    # Loopback keeps the relay's release order: its counts are what the receiver saw.
    assert stats["up"]["reordered"] == late_ones(order) > 0
    assert stats["up"]["overtaking"] == overtakers(order) > 0
    assert stats["up"]["delivered"] == count and stats["up"]["dropped"] == 0
    one_way = [t - sent_at[int(data[-5:])] for t, _, data in sink.arrivals]
    # Never before the shortest draw (timers are only late); some beyond the longest-but-one
    # tenth of the draws, which a fixed delay never gives.
    assert min(one_way) >= 0.139
    assert max(one_way) >= 0.248


def test_in_order_keeps_the_jitter_and_the_order(sink, tmp_path):
    count = 400
    sent_at, stats = through(sink, tmp_path / "stats.json", count, 0.2, *ROUGH_DELAY,
                             "--in-order", "--seed", "5")
    order = numbers(sink.payloads())
    assert order == list(range(count))
    assert stats["up"]["reordered"] == stats["up"]["overtaking"] == 0
    one_way = [t - sent_at[int(data[-5:])] for t, _, data in sink.arrivals]
    assert min(one_way) >= 0.139 and max(one_way) >= 0.248


def test_an_asymmetric_path_delays_each_direction_by_its_own_delay(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--delay-ms", "500",
                         "--up-delay-ms", "50", "--down-delay-ms", "250")
    sock = client(relay.port)
    try:
        sent_at = send_numbered(sock, 20, 0.05)
        got = collect(sock, 20, 3.0)
        back_at = time.monotonic()
    finally:
        sock.close()
        assert relay.stop() == 0
    assert sorted(numbers(got)) == list(range(20))
    # Timers are only late: up no earlier than 50 ms, the whole trip no earlier than 300 ms;
    # the server heard every datagram long before the down leg's 250 ms could have passed
    # (the --delay-ms both directions override would have made it 500).
    up = [t - sent_at[int(data[-5:])] for t, _, data in echo.arrivals]
    assert min(up) >= 0.049 and sorted(up)[len(up) // 2] < 0.2, up
    assert back_at - sent_at[0] >= 0.299
    stats = stats_of(tmp_path / "stats.json")
    assert stats["up"]["delivered"] == stats["down"]["delivered"] == 20


def test_bursts_lose_about_the_asked_share_in_bursts_of_about_the_asked_length(sink, tmp_path):
    count = 4000
    _, stats = through(sink, tmp_path / "stats.json", count, 2.0,
                       "--burst-loss", "0.1", "--burst-length", "6.5", "--seed", "2")
    arrived = set(numbers(sink.payloads()))
    lost = [n not in arrived for n in range(count)]
    runs, length = [], 0
    for gone in lost + [False]:
        if gone:
            length += 1
        elif length:
            runs.append(length)
            length = 0
    # About 60 bursts: the share and the mean vary by a sixth or so from seed to seed.
    assert 0.05 <= sum(lost) / count <= 0.16, sum(lost) / count
    assert 4.0 <= sum(runs) / len(runs) <= 10.0, sum(runs) / len(runs)
    # Independent loss of 10 % would give runs of 1.1 on average.
    assert stats["up"]["received"] == count
    assert stats["up"]["dropped"] == sum(lost) and stats["up"]["loss_runs"] == len(runs)


def test_duplicates_about_one_in_a_hundred(sink, tmp_path):
    count = 3000
    _, stats = through(sink, tmp_path / "stats.json", count, 1.0, "--duplicate", "0.01",
                       "--seed", "3", p_expect=float("inf"))
    order = numbers(sink.payloads())
    twice = len(order) - len(set(order))
    assert set(order) == set(range(count))
    # Binomial(3000, 0.01): mean 30, sd 5.4.
    assert 10 <= twice <= 55 and twice == stats["up"]["duplicated"]
    assert len(order) == stats["up"]["delivered"]
    assert max(order.count(n) for n in set(order)) == 2


def test_blackhole_cuts_one_path_both_ways_while_the_other_flows(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--seed", "4", p_control=True)
    a, b = client(relay.port), client(relay.port)
    a_address, b_address = address_of(a), address_of(b)
    try:
        for sock, name in ((a, b"a"), (b, b"b")):
            send_numbered(sock, 20, 1.0, name)
            assert len(collect(sock, 20, 2.0)) == 20
        a_upstream = echo.sender_of(b"a")
        assert relay.command(f"blackhole {a_address}") == {"blackhole": 0,
                                                           "address": a_address}
        before = len(echo.payloads(b"a"))
        send_numbered(a, 30, 1.0, b"a")
        send_numbered(b, 30, 1.0, b"b")
        for i in range(30):
            echo.push(a_upstream, b"p%05d" % i)
        assert len(collect(b, 30, 2.0)) == 30
        assert collect(a, 60, 1.0) == []
        assert len(echo.payloads(b"a")) == before
        # Restored, the same path carries again.
        assert relay.command("restore 0") == {"restore": 0, "address": a_address}
        send_numbered(a, 10, 1.0, b"a")
        assert len(collect(a, 10, 2.0)) == 10
    finally:
        a.close()
        b.close()
        assert relay.stop() == 0
    stats = stats_of(tmp_path / "stats.json")
    cut, other = stats["paths"]
    assert cut["address"] == a_address and other["address"] == b_address
    assert cut["up"]["blackholed"] == 30 and cut["down"]["blackholed"] == 30
    assert other["up"]["blackholed"] == other["down"]["blackholed"] == 0
    assert other["down"]["delivered"] == 50
    assert all(balanced(path[d]) for path in stats["paths"] for d in ("up", "down"))


def test_rebind_moves_a_client_to_a_new_port_and_the_old_one_reaches_nobody(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", p_control=True)
    a, b = client(relay.port), client(relay.port)
    try:
        for sock, name in ((a, b"a"), (b, b"b")):
            send_numbered(sock, 5, 1.0, name)
            assert len(collect(sock, 5, 2.0)) == 5
        old = echo.sender_of(b"a")
        assert relay.command("rebind 0") == {"rebind": 0, "address": address_of(a)}
        send_numbered(a, 10, 1.0, b"A")
        # The server hears the same client from a new port, and answers it there.
        assert len(collect(a, 10, 2.0)) == 10
        new = echo.sender_of(b"A")
        assert new != old and new[0] == old[0], (old, new)
        assert echo.sender_of(b"b") != new, "the other client keeps its own port"
        # What the server sends to the old port goes nowhere.
        echo.push(old, b"stale")
        assert collect(a, 1, 0.5) == []
        for bad in ("rebind 5", "rebind"):
            assert set(relay.command(bad)) == {"error"}, bad
    finally:
        a.close()
        b.close()
        assert relay.stop() == 0
    stats = stats_of(tmp_path / "stats.json")
    assert stats["clients"] == 2, "a rebound client is still the one client"


def test_blackhole_new_cuts_the_clients_that_come_meanwhile_until_restored(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", p_control=True)
    a, b, c = client(relay.port), client(relay.port), client(relay.port)
    try:
        send_numbered(a, 3, 1.0, b"a")
        assert len(collect(a, 3, 2.0)) == 3
        assert relay.command("blackhole new") == {"blackhole": "new", "clients": []}
        send_numbered(b, 3, 1.0, b"b")
        assert collect(b, 3, 0.5) == [] and echo.payloads(b"b") == [], "a new client, cut"
        send_numbered(a, 3, 1.0, b"a")
        assert len(collect(a, 3, 2.0)) == 3, "a client seen before still flows"
        assert relay.command("restore new") == {"restore": "new", "clients": [1]}
        send_numbered(b, 3, 1.0, b"B")
        assert len(collect(b, 3, 2.0)) == 3
        send_numbered(c, 3, 1.0, b"c")
        assert len(collect(c, 3, 2.0)) == 3, "after the restore, new clients flow"
    finally:
        for sock in (a, b, c):
            sock.close()
        assert relay.stop() == 0
    stats = stats_of(tmp_path / "stats.json")
    assert stats["paths"][1]["up"]["blackholed"] == 3, stats["paths"][1]


def test_bad_commands_are_answered_and_change_nothing(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", p_control=True)
    sock = client(relay.port)
    try:
        sock.send(b"hello")
        assert collect(sock, 1, 2.0) == [b"hello"]
        for bad in ("blackhole 1", "blackhole 127.0.0.1:1", "blackhole", "restore 0 up",
                    "drop everything", "\xff\xfe", "blackhole " + "9" * 2000):
            answer = relay.command(bad)
            assert set(answer) == {"error"}, (bad, answer)
        # Still the one client, still flowing.
        sock.send(b"again")
        assert collect(sock, 1, 2.0) == [b"again"]
    finally:
        sock.close()
        assert relay.stop() == 0
    stats = stats_of(tmp_path / "stats.json")
    assert stats["clients"] == 1 and stats["up"]["blackholed"] == 0
