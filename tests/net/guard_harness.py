"""Helpers of the guard tests (tests/net/test_net_guard.py): hooks that kill a peer at the
right moment, a peer started on its own, a log watched with wall times, and crafted ENet
datagrams (the layout of ENet's protocol.h, lsalzman/enet: a 4-byte header {peerID | flags,
sentTime}, then commands {command | flags, channelID, reliableSequenceNumber, body},
big-endian), sent to 127.0.0.1 only.
"""

from __future__ import annotations

import os
import random
import signal
import socket
import struct
import time
from pathlib import Path

from net_harness import DRIVER_SCENE, SERVER_PEER, TRANSFER_TAKEOVER, Peer, Relay, udp_ports

ENET_MAXIMUM_PEER_ID = 0xFFF
ENET_FLAG_SENT_TIME = 0x8000
ENET_FLAG_ACKNOWLEDGE = 0x80
ENET_SESSION_SHIFT = 12
ENET_COMMAND_ACKNOWLEDGE = 1
ENET_COMMAND_CONNECT = 2
ENET_COMMAND_VERIFY_CONNECT = 3
ENET_COMMAND_MASK = 0x0F
# A CONNECT as an ENet 1.3 client sends it: 4 header bytes, 48 of command (the 12
# datagrams were 624 bytes).
CONNECT_BYTES = 52
# The rogue peer (tests/net/rogue/): with --rogue=mark it prints HIT_MARK when its paddle hit
# the ball and it became the master.
ROGUE_SCENE = "res://tests/net/rogue/rogue_peer.tscn"
HIT_MARK = "PongNet rogue: my paddle hit the ball, I am the master"


def connect_datagram(connect_id: int, data: int) -> bytes:
    """An ENet CONNECT from a new client: header (no peer yet, sent time), the command (with
    the acknowledge flag, channel 0xFF, reliable sequence 1) and its body: our peer index 0,
    sessions 0xFF (any), MTU 1400, window 32 KiB, 8 channels, no bandwidth limits, ENet's
    throttle defaults, the connect id, and the user data Godot takes as the client's peer id
    (2 or more)."""
    header = struct.pack(">HH", ENET_FLAG_SENT_TIME | ENET_MAXIMUM_PEER_ID,
                         int(time.monotonic() * 1000) & 0xFFFF)
    command = struct.pack(">BBH", ENET_FLAG_ACKNOWLEDGE | ENET_COMMAND_CONNECT, 0xFF, 1)
    body = struct.pack(">HBBIIIIIIIIII", 0, 0xFF, 0xFF, 1400, 32768, 8, 0, 0, 5000, 2, 2,
                       connect_id, data)
    datagram = header + command + body
    assert len(datagram) == CONNECT_BYTES
    return datagram


def _new_ids(rng: random.Random) -> tuple[int, int]:
    return rng.getrandbits(32), rng.randint(2, 2**31 - 1)


def flood_connects(port: int, count: int, seed: int = 1) -> int:
    """Sends [count] CONNECTs to 127.0.0.1:[port] from one socket, each with its own connect id
    (ENet takes each as a new client), and never answers; returns the bytes sent."""
    rng = random.Random(seed)
    sent = 0
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("127.0.0.1", 0))
        for _ in range(count):
            sent += sock.sendto(connect_datagram(*_new_ids(rng)), ("127.0.0.1", port))
    return sent


# Sizes of the commands a server's first answer may hold (ENet's commandSizes).
_COMMAND_BYTES = {ENET_COMMAND_ACKNOWLEDGE: 8, ENET_COMMAND_VERIFY_CONNECT: 44}


def _find_verify_connect(data: bytes) -> tuple[int, int, int, int, int] | None:
    """(sent time, channel, reliable sequence, the server's peer index, the session to send
    with) of the VERIFY_CONNECT in a server's datagram, or None."""
    if len(data) < 4:
        return None
    flags_and_peer, sent_time = struct.unpack(">HH", data[:4])
    if not flags_and_peer & ENET_FLAG_SENT_TIME:
        return None
    offset = 4
    while offset + 4 <= len(data):
        command, channel, sequence = struct.unpack(">BBH", data[offset:offset + 4])
        kind = command & ENET_COMMAND_MASK
        size = _COMMAND_BYTES.get(kind)
        if size is None or offset + size > len(data):
            return None
        if kind == ENET_COMMAND_VERIFY_CONNECT:
            server_peer, _incoming, outgoing = struct.unpack(">HBB", data[offset + 4:offset + 8])
            return sent_time, channel, sequence, server_peer, outgoing
        offset += size
    return None


class HalfOpenClient:
    """A client that completes ENet's handshake (it acknowledges the server's VERIFY_CONNECT,
    so the server reports a connection and starts the version check) and then says nothing
    more, holding the connection half-open."""

    def __init__(self, port: int, rng: random.Random) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.settimeout(0.2)
        self.server = ("127.0.0.1", port)
        self.sock.sendto(connect_datagram(*_new_ids(rng)), self.server)

    def complete(self, patience_s: float) -> bool:
        """Waits for the VERIFY_CONNECT and acknowledges it; whether it came."""
        end = time.monotonic() + patience_s
        while time.monotonic() < end:
            try:
                data = self.sock.recv(4096)
            except socket.timeout:
                continue
            verify = _find_verify_connect(data)
            if verify is None:
                continue
            sent_time, channel, sequence, server_peer, outgoing_session = verify
            header = struct.pack(">H", server_peer | (outgoing_session << ENET_SESSION_SHIFT))
            ack = struct.pack(">BBHHH", ENET_COMMAND_ACKNOWLEDGE, channel, sequence, sequence,
                              sent_time)
            self.sock.sendto(header + ack, self.server)
            return True
        return False

    def close(self) -> None:
        self.sock.close()


def half_open_clients(port: int, count: int, seed: int = 2) -> list[HalfOpenClient]:
    """[count] clients that complete ENet's handshake with 127.0.0.1:[port] and go silent
    (the caller closes them)."""
    rng = random.Random(seed)
    clients = [HalfOpenClient(port, rng) for _ in range(count)]
    for client in clients:
        client.complete(5.0)
    return clients


class LogWatch:
    """When each of some lines first showed in a peer's log, on this machine's wall clock
    (polled every 20 ms)."""

    def __init__(self, peer: Peer) -> None:
        self.peer = peer
        self.seen: dict[str, float] = {}

    def wait(self, texts: list[str], patience_s: float) -> bool:
        end = time.monotonic() + patience_s
        while time.monotonic() < end:
            log = self.peer.log()
            for text in texts:
                if text not in self.seen and text in log:
                    self.seen[text] = time.time()
            if all(text in self.seen for text in texts):
                return True
            if self.peer.proc is not None and self.peer.proc.poll() is not None:
                return False
            time.sleep(0.02)
        return False


def kill_on_line(index: int, text: str, killed_at: list[float], patience_s: float = 40.0):
    """An on_running hook for run_match: SIGKILLs peer [index] as soon as [text] shows in its
    log and appends the wall time to [killed_at] (nothing if it never shows)."""

    def hook(peers: list[Peer], _relay: Relay | None) -> None:
        target = peers[index]
        if LogWatch(target).wait([text], patience_s):
            os.kill(target.proc.pid, signal.SIGKILL)
            killed_at.append(time.time())

    return hook


def cut_on_line(index: int, text: str, cut_at: list[float], patience_s: float = 40.0):
    """An on_running hook for run_match: as soon as [text] shows in peer [index]'s log, the
    relay cuts that peer's path both ways (the peer lives on, its datagrams vanish), and any
    new connection it opens (its machine is off the network: a rejoin gets nowhere either);
    appends the wall time to [cut_at] (nothing if it never shows)."""

    def hook(peers: list[Peer], relay: Relay | None) -> None:
        assert relay is not None, "a path is cut in the relay: run the match through one"
        target = peers[index]
        ports = udp_ports(target.proc.pid)
        if LogWatch(target).wait([text], patience_s):
            address = next(a for a in relay.clients if int(a.rsplit(":", 1)[1]) in ports)
            relay.blackhole(address)
            relay.blackhole("new")
            cut_at.append(time.time())

    return hook


def start_peer(workdir: Path, name: str, args: list[str], scene: str = DRIVER_SCENE) -> Peer:
    """A peer of the source tree started now (the caller kills it in a finally)."""
    peer = Peer(name, args, workdir, scene=scene)
    peer.start()
    return peer


def check_taken_over(report: dict, seat: int = 1) -> None:
    """Asserts what the server [report] shows after the peer playing [seat] was lost: the
    lost master's ball was taken over at once, every transfer since is the server's (the
    ball was never left without a master), the computer plays the seat and the rally goes
    on."""
    left = report["extra"]["peers_left"]
    assert len(left) == 1 and left[0]["seats"] == [seat], left
    later = [t for t in report["transfers"] if t["wall_s"] >= left[0]["wall_s"]]
    assert later and later[0]["kind"] == TRANSFER_TAKEOVER, later[:3]
    assert later[0]["wall_s"] - left[0]["wall_s"] < 0.5, (later[0], left[0])
    assert all(t["master"] == SERVER_PEER for t in later), later
    assert all(c == "computer" for c in report["controllers"]), report["controllers"]
    # The rally goes on: the ball travels the court (a low hit skims the floor at 0.07-0.28 m
    # while it crosses from one end to the other, so its height alone does not tell). Counting
    # transfers does not tell: with both seats the server's, only a serve makes one, and one
    # rally of the two computers lasted the 11 s the match had left.
    moving = [s for s in report["samples"] if s[0] > left[0]["wall_s"] + 1.0]
    travel = max((max(s[i] for s in moving) - min(s[i] for s in moving) for i in (2, 3, 4)),
                 default=0.0)
    watched = moving[-1][0] - moving[0][0] if moving else 0.0
    transfers_after = [(round(t["wall_s"] - left[0]["wall_s"], 2), t["kind"]) for t in later]
    assert travel > 1.0, (f"the ball stopped: it moved {travel:.2f} m at most along any axis in "
                          f"the {watched:.1f} s watched from 1 s after the seat was taken over "
                          f"(transfers after it, s and kind: {transfers_after[:12]})")
