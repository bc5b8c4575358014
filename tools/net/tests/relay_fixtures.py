"""Servers, clients and the relay process for the relay's own tests (127.0.0.1 only; every
process is stopped by its PID, every socket closed)."""

from __future__ import annotations

import json
import queue
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

RELAY = Path(__file__).resolve().parents[1] / "udp_relay.py"
# Generous bound for anything that waits on the relay process on a loaded 2-core machine.
PATIENCE_S = 20.0
# The test's own sockets: room for a few thousand datagrams while a reader waits for a core.
RECEIVE_BUFFER_BYTES = 4 << 20


def udp_socket() -> socket.socket:
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RECEIVE_BUFFER_BYTES)
    return sock


class EchoServer:
    """Records every datagram with its sender and arrival time, sends it back when echoing,
    and can send to a sender on its own (push)."""

    def __init__(self, p_echo: bool = True) -> None:
        self.sock = udp_socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.settimeout(0.1)
        self.port = self.sock.getsockname()[1]
        self.echo = p_echo
        self.senders: set[tuple[str, int]] = set()
        # (monotonic arrival time, sender, payload) in arrival order.
        self.arrivals: list[tuple[float, tuple[str, int], bytes]] = []
        self._running = True
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        while self._running:
            try:
                data, addr = self.sock.recvfrom(65536)
            except socket.timeout:
                continue
            self.arrivals.append((time.monotonic(), addr, data))
            self.senders.add(addr)
            if self.echo:
                self.sock.sendto(data, addr)

    def payloads(self, p_prefix: bytes = b"") -> list[bytes]:
        return [data for _, _, data in list(self.arrivals) if data.startswith(p_prefix)]

    def sender_of(self, p_prefix: bytes) -> tuple[str, int]:
        return next(addr for _, addr, data in list(self.arrivals) if data.startswith(p_prefix))

    def push(self, p_to: tuple[str, int], p_data: bytes) -> None:
        self.sock.sendto(p_data, p_to)

    def wait_for(self, p_count: float, p_quiet_s: float) -> None:
        """Until [p_count] datagrams arrived in all, or none came for [p_quiet_s]."""
        seen, since = len(self.arrivals), time.monotonic()
        while len(self.arrivals) < p_count and time.monotonic() - since < p_quiet_s:
            time.sleep(0.02)
            if len(self.arrivals) != seen:
                seen, since = len(self.arrivals), time.monotonic()

    def close(self) -> None:
        self._running = False
        self._thread.join()
        self.sock.close()


class RelayProcess:
    """udp_relay.py on 127.0.0.1; with [p_control] its stdin takes commands (command())."""

    def __init__(self, p_server_port: int, p_stats: Path, *p_args: str,
                 p_control: bool = False) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, str(RELAY), "--server", f"127.0.0.1:{p_server_port}",
             "--stats", str(p_stats), "--max-seconds", "60", *p_args,
             *(["--control"] if p_control else [])],
            stdin=subprocess.PIPE if p_control else subprocess.DEVNULL,
            stdout=subprocess.PIPE, text=True,
        )
        line = self.proc.stdout.readline()
        self.port = json.loads(line)["listen_port"]
        self._lines: queue.Queue[dict] = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.proc.stdout:
            self._lines.put(json.loads(line))

    def command(self, p_line: str) -> dict:
        """Sends one control line; its answer (the new-client notices are skipped)."""
        self.proc.stdin.write(p_line + "\n")
        self.proc.stdin.flush()
        end = time.monotonic() + PATIENCE_S
        while True:
            answer = self._lines.get(timeout=max(0.0, end - time.monotonic()))
            if "client" not in answer:
                return answer

    def stop(self) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(timeout=PATIENCE_S)
        finally:
            if self.proc.poll() is None:
                self.proc.kill()
                self.proc.wait()
            self._reader.join(timeout=PATIENCE_S)
            self.proc.stdout.close()
            if self.proc.stdin is not None:
                self.proc.stdin.close()


def client(p_port: int) -> socket.socket:
    sock = udp_socket()
    sock.connect(("127.0.0.1", p_port))
    sock.settimeout(PATIENCE_S)
    return sock


def address_of(p_sock: socket.socket) -> str:
    host, port = p_sock.getsockname()
    return f"{host}:{port}"


def collect(p_sock: socket.socket, p_count: int, p_quiet_s: float) -> list[bytes]:
    """Datagrams until p_count arrived or nothing came for p_quiet_s."""
    got: list[bytes] = []
    p_sock.settimeout(p_quiet_s)
    while len(got) < p_count:
        try:
            got.append(p_sock.recv(65536))
        except socket.timeout:
            break
    return got


class Collector:
    """Reads a socket on a thread while the test sends (a burst would overflow its buffer)."""

    def __init__(self, p_sock: socket.socket, p_count: int, p_quiet_s: float) -> None:
        self.got: list[bytes] = []
        self._thread = threading.Thread(
            target=lambda: self.got.extend(collect(p_sock, p_count, p_quiet_s)), daemon=True
        )
        self._thread.start()

    def join(self) -> list[bytes]:
        self._thread.join()
        return self.got


def send_numbered(p_sock: socket.socket, p_count: int, p_per_ms: float,
                  p_prefix: bytes = b"") -> list[float]:
    """Sends p_prefix + 00000 .. p_count - 1, about p_per_ms a millisecond (paced in small
    groups to stay well under the socket buffers); the monotonic send time of each."""
    sent_at: list[float] = []
    group = max(1, round(p_per_ms * 10))
    for i in range(p_count):
        sent_at.append(time.monotonic())
        p_sock.send(p_prefix + b"%05d" % i)
        if i % group == group - 1:
            time.sleep(0.01)
    return sent_at


def stats_of(p_path: Path) -> dict:
    return json.loads(p_path.read_text())


def balanced(p_direction: dict) -> bool:
    """Every datagram and copy ended one way only (path_model.DirectionStats)."""
    d = p_direction
    return (d["received"] + d["duplicated"]
            == d["dropped"] + d["blackholed"] + d["delivered"] + d["undelivered"])
