"""The relay delays, drops and reorders as configured, keeps clients apart and always exits."""

from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest
from relay_fixtures import RELAY, PATIENCE_S, Collector, EchoServer, RelayProcess, client, collect


@pytest.fixture
def echo():
    server = EchoServer()
    yield server
    server.close()


def test_clean_path_echoes_everything_and_keeps_clients_apart(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json")
    try:
        a, b = client(relay.port), client(relay.port)
        for i in range(50):
            a.send(b"a%03d" % i)
            b.send(b"b%03d" % i)
        got_a, got_b = collect(a, 50, 2.0), collect(b, 50, 2.0)
        assert sorted(got_a) == [b"a%03d" % i for i in range(50)]
        assert sorted(got_b) == [b"b%03d" % i for i in range(50)]
        # The server sees two peers, each from one of the relay's own upstream sockets.
        assert len(echo.senders) == 2
        assert relay.port not in {port for _, port in echo.senders}
        a.close()
        b.close()
    finally:
        assert relay.stop() == 0
    stats = json.loads((tmp_path / "stats.json").read_text())
    assert stats["clients"] == 2
    assert stats["up"]["delivered"] == stats["down"]["delivered"] == 100
    assert stats["up"]["dropped"] == 0 and stats["up"]["bytes_delivered"] == 400


def test_delay_applies_each_way(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--delay-ms", "80")
    try:
        sock = client(relay.port)
        round_trips = []
        for i in range(5):
            start = time.monotonic()
            sock.send(b"%d" % i)
            assert sock.recv(100) == b"%d" % i
            round_trips.append(time.monotonic() - start)
        sock.close()
    finally:
        relay.stop()
    # Two 80 ms legs: never faster than 160 ms (the timer may only be late, never early).
    assert min(round_trips) >= 0.159
    assert max(round_trips) < PATIENCE_S


def test_loss_drops_about_the_stated_fraction_each_way(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--loss", "0.2", "--seed", "7")
    try:
        sock = client(relay.port)
        reader = Collector(sock, 1000, 1.5)
        for i in range(1000):
            sock.send(b"%04d" % i)
            if i % 10 == 9:
                # About one a millisecond: well under the socket buffers even where the
                # kernel caps them at 200 datagrams and the relay waits for a core.
                time.sleep(0.01)
        got = reader.join()
        sock.close()
    finally:
        relay.stop()
    stats = json.loads((tmp_path / "stats.json").read_text())
    up, down = stats["up"], stats["down"]
    assert up["received"] == 1000
    assert up["received"] == up["dropped"] + up["delivered"]
    assert down["received"] == down["dropped"] + down["delivered"]
    # Binomial(1000, 0.2): mean 200, sd 12.6; 6 sd either side.
    assert 124 <= up["dropped"] <= 276
    # Both legs: 0.8^2 = 64 % survive.
    assert 560 <= len(got) <= 720
    assert len(got) == down["delivered"]


def test_jitter_reorders_and_counts_it(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--jitter-ms", "40", "--seed", "3")
    try:
        sock = client(relay.port)
        reader = Collector(sock, 200, 1.5)
        for i in range(200):
            sock.send(b"%04d" % i)
            time.sleep(0.001)
        got = reader.join()
        sock.close()
    finally:
        relay.stop()
    stats = json.loads((tmp_path / "stats.json").read_text())
    assert sorted(got) == [b"%04d" % i for i in range(200)]
    out_of_order = sum(1 for x, y in zip(got, got[1:]) if y < x)
    assert out_of_order > 0
    assert stats["up"]["reordered"] > 0


def test_same_seed_same_fate(echo, tmp_path):
    dropped = []
    for run in range(2):
        relay = RelayProcess(echo.port, tmp_path / f"s{run}.json", "--loss", "0.3", "--seed", "11")
        try:
            sock = client(relay.port)
            reader = Collector(sock, 100, 1.0)
            for i in range(100):
                sock.send(b"%03d" % i)
            got = reader.join()
            sock.close()
        finally:
            relay.stop()
        dropped.append(set(range(100)) - {int(x) for x in got})
    assert dropped[0] == dropped[1] and dropped[0]


def test_exits_by_itself_after_max_seconds(echo, tmp_path):
    stats = tmp_path / "stats.json"
    proc = subprocess.Popen(
        [sys.executable, str(RELAY), "--server", f"127.0.0.1:{echo.port}",
         "--max-seconds", "0.5", "--stats", str(stats)],
        stdout=subprocess.PIPE, text=True,
    )
    try:
        assert proc.wait(timeout=PATIENCE_S) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        proc.stdout.close()
    assert json.loads(stats.read_text())["clients"] == 0


@pytest.mark.parametrize(
    "bad", [["--server", "nohost"], ["--server", "127.0.0.1:7", "--loss", "1.5"],
            ["--server", "127.0.0.1:7", "--delay-ms", "-3"],
            ["--server", "127.0.0.1:7", "--duplicate", "1"],
            # Bursts need both numbers, a mean of at least one datagram, and a possible chain:
            # bursts of 1 on average cannot lose more than half.
            ["--server", "127.0.0.1:7", "--burst-loss", "0.1"],
            ["--server", "127.0.0.1:7", "--burst-length", "4"],
            ["--server", "127.0.0.1:7", "--burst-loss", "0.1", "--burst-length", "0.5"],
            ["--server", "127.0.0.1:7", "--burst-loss", "0.6", "--burst-length", "1"],
            # A centred jitter larger than the delay would ask for negative delays.
            ["--server", "127.0.0.1:7", "--delay-ms", "20", "--jitter-ms", "30",
             "--jitter-centred"]],
)
def test_bad_arguments_are_refused(bad):
    result = subprocess.run([sys.executable, str(RELAY), *bad], capture_output=True, text=True,
                            timeout=PATIENCE_S)
    assert result.returncode == 2
    assert "error:" in result.stderr
    assert result.stdout == ""  # it never listened


def test_control_needs_a_pipe(echo, tmp_path):
    not_a_pipe = tmp_path / "commands.txt"
    not_a_pipe.write_text("blackhole 0\n")
    with open(not_a_pipe) as stdin:
        result = subprocess.run(
            [sys.executable, str(RELAY), "--server", f"127.0.0.1:{echo.port}", "--control",
             "--max-seconds", "5"], stdin=stdin, capture_output=True, text=True,
            timeout=PATIENCE_S)
    assert result.returncode == 2
    assert "--control needs stdin to be a pipe" in result.stderr
    assert result.stdout == ""


def test_the_servers_first_answers_to_each_client_can_be_lost(echo, tmp_path):
    relay = RelayProcess(echo.port, tmp_path / "stats.json", "--answers-lost-first-ms", "400")
    try:
        sock = client(relay.port)
        sock.send(b"first")
        assert collect(sock, 1, 0.2) == [], "an answer within the first 400 ms is lost"
        time.sleep(0.3)
        sock.send(b"later")
        assert collect(sock, 1, 2.0) == [b"later"], "after them the path carries again"
        sock.close()
    finally:
        relay.stop()
    stats = json.loads((tmp_path / "stats.json").read_text())
    assert stats["up"]["delivered"] == 2, "what the client sends always goes through"
    assert stats["down"]["blackholed"] == 1 and stats["down"]["delivered"] == 1, stats["down"]
