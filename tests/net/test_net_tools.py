"""The harness's own tools without Godot: Network's relay options, the Relay process and its
blackhole, the UDP port lookup, the process meter and the ball-state shares."""

from __future__ import annotations

import os
import socket
import subprocess
import sys

import pytest

from net_harness import ROOT, ROUGH, Network, Relay, udp_ports
from net_measure import ProcessMeter, ball_state_use, read_process

# The relay's own tests' echo server (tools/net/tests), one for both suites.
sys.path.insert(0, str(ROOT / "tools" / "net" / "tests"))
from relay_fixtures import EchoServer  # noqa: E402


def echoes(sock: socket.socket, count: int, quiet_s: float) -> int:
    """Sends [count] datagrams; how many came back before [quiet_s] of silence."""
    for i in range(count):
        sock.send(b"%04d" % i)
    got = 0
    sock.settimeout(quiet_s)
    try:
        while got < count:
            sock.recv(2048)
            got += 1
    except socket.timeout:
        pass
    return got


def test_existing_constructors_keep_their_meaning():
    network = Network(50, 10, 0.05)
    assert network.relay_args() == ["--delay-ms", "50", "--jitter-ms", "10", "--loss", "0.05"]
    assert network.impaired and network.reorder and not network.centred
    assert not Network(0, 0, 0.0).impaired
    assert network.path_s == pytest.approx(0.12)


def test_the_rough_network_asks_the_relay_for_the_issues_conditions():
    args = ROUGH.relay_args()
    assert args[:4] == ["--delay-ms", "200", "--jitter-ms", "60"]
    assert "--jitter-centred" in args and "--in-order" not in args
    assert args[args.index("--burst-loss") + 1] == "0.1"
    assert args[args.index("--burst-length") + 1] == "6.5"
    assert args[args.index("--duplicate") + 1] == "0.01"
    assert ROUGH.path_s == pytest.approx(0.52)
    assert Network(200, 60, centred=True, reorder=False).relay_args()[-2:] == [
        "--jitter-centred", "--in-order"]


def test_relay_cuts_and_restores_a_path(tmp_path):
    echo = EchoServer()
    relay = Relay(echo.port, tmp_path, Network(5, 5, 0.0), seed=3)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        sock.connect(("127.0.0.1", relay.port))
        assert echoes(sock, 20, 2.0) == 20
        me = "127.0.0.1:%d" % sock.getsockname()[1]
        assert relay.clients == [me]
        assert relay.blackhole(me) == {"blackhole": 0, "address": me}
        assert echoes(sock, 20, 0.5) == 0
        with pytest.raises(RuntimeError, match="no client"):
            relay.blackhole(1)
        assert relay.restore(0) == {"restore": 0, "address": me}
        assert echoes(sock, 20, 2.0) == 20
    finally:
        sock.close()
        relay.stop()
        echo.close()
    assert relay.stats["up"]["blackholed"] == 20
    assert relay.stats["up"]["delivered"] == relay.stats["down"]["delivered"] == 40


def test_relay_that_cannot_start_says_why(tmp_path):
    with pytest.raises(RuntimeError, match="--burst-loss and --burst-length go together"):
        Relay(9, tmp_path, Network(burst_loss=0.1))


def test_udp_ports_finds_a_process_socket():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("127.0.0.1", 0))
        assert sock.getsockname()[1] in udp_ports(os.getpid())


def test_meter_sees_a_busy_process_and_its_memory():
    # 64 MiB touched, then a second of spinning on one thread.
    child = subprocess.Popen([sys.executable, "-c",
                              "import time\nb = bytearray(64 << 20)\nend = time.time() + 1.0\n"
                              "while time.time() < end: pass\n"])
    meter = ProcessMeter()
    try:
        meter.start({"child": child.pid})
        child.wait(timeout=30)
    finally:
        meter.stop()
        if child.poll() is None:
            child.kill()
            child.wait()
    result = meter.result()["child"]
    assert result["peak_rss_kib"] >= 64 * 1024
    # One thread: at most a core (tick rounding aside), and some of it even on a loaded
    # machine.
    assert 0.05 < result["cpu_share"] <= 1.1, result
    assert read_process(child.pid) is None


def test_ball_state_shares_are_of_what_the_other_peers_sent():
    stream = {"received": 340, "late": 20, "used": 330, "duplicates": 4}
    reports = [{"peer": 1, "sent": 600, "states": 350, "late": 10,
                "extra": {"ball_stream": stream}},
               {"peer": 2, "sent": 400, "states": 540, "late": 0}]
    use = ball_state_use(reports)
    assert [p["offered"] for p in use["per_peer"]] == [400, 600]
    assert use["per_peer"][0]["taken_share"] == pytest.approx(350 / 400)
    assert use["per_peer"][0]["used_share"] == pytest.approx(330 / 360)
    assert use["per_peer"][1]["used_share"] is None  # A peer that never followed.
    assert use["taken_share"] == pytest.approx(890 / 1000)
    assert use["used_share"] == pytest.approx(330 / 360)
