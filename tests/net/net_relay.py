"""The network between the peers: its conditions (Network) and the relay process that gives
them (tools/net/udp_relay.py), which a test can tell to cut one client's path."""

from __future__ import annotations

import json
import os
import queue
import signal
import subprocess
import sys
import threading
from dataclasses import dataclass
from pathlib import Path

RELAY = Path(__file__).resolve().parents[2] / "tools" / "net" / "udp_relay.py"
# Generous bound for the relay's answers and exit on a loaded 2-core machine.
RELAY_PATIENCE_S = 20.0


@dataclass
class Network:
    """Each leg's conditions through the relay (both ways; each way draws its own fates)."""

    delay_ms: float = 0.0
    jitter_ms: float = 0.0
    loss: float = 0.0
    # Jitter in delay +- jitter_ms (uniform) instead of delay + 0..jitter_ms.
    centred: bool = False
    # Each datagram leaves at its own drawn time, so later ones overtake earlier ones (the
    # relay's default); False: the jitter keeps the order.
    reorder: bool = True
    # Average loss in Gilbert-Elliott bursts of burst_length datagrams on average (the
    # relay derives the chain), on top of the independent [loss].
    burst_loss: float = 0.0
    burst_length: float = 0.0
    duplicate: float = 0.0
    # Everything the server sends is lost for this long from the first client's first datagram.
    answers_lost_first_ms: float = 0.0
    # An asymmetric path: the delay towards the server (up) and towards the client (down),
    # each instead of delay_ms.
    up_delay_ms: float | None = None
    down_delay_ms: float | None = None

    @property
    def legs_ms(self) -> tuple[float, float]:
        """The delay up (client to server) and down, ms."""
        return (self.delay_ms if self.up_delay_ms is None else self.up_delay_ms,
                self.delay_ms if self.down_delay_ms is None else self.down_delay_ms)

    @property
    def label(self) -> str:
        jitter = f"±{self.jitter_ms:g}" if self.centred else f"+{self.jitter_ms:g}j"
        up, down = self.legs_ms
        text = f"{self.delay_ms:g}ms{jitter}" if up == down else f"{up:g}/{down:g}ms{jitter}"
        if self.loss > 0 or self.burst_loss == 0:
            text += f"/{self.loss * 100:g}%"
        if not self.reorder:
            text += " in order"
        if self.burst_loss > 0:
            text += f" {self.burst_loss * 100:g}% lost in bursts of {self.burst_length:g}"
        if self.duplicate > 0:
            text += f" {self.duplicate * 100:g}% twice"
        if self.answers_lost_first_ms > 0:
            text += f", the first {self.answers_lost_first_ms:g} ms of answers lost"
        return text

    @property
    def impaired(self) -> bool:
        return any(x > 0 for x in (*self.legs_ms, self.jitter_ms, self.loss, self.burst_loss,
                                   self.duplicate, self.answers_lost_first_ms))

    @property
    def path_s(self) -> float:
        """Worst one-way delay between two players through the relay (two legs when both
        are clients; an in-order leg still releases each datagram within its own draw's
        reach)."""
        return (sum(self.legs_ms) + 2.0 * self.jitter_ms) / 1000.0

    @property
    def round_trip_s(self) -> float:
        """Worst client-to-client round trip through the relay (two legs each way)."""
        return 2.0 * (sum(self.legs_ms) + 2.0 * self.jitter_ms) / 1000.0

    def relay_args(self) -> list[str]:
        """udp_relay.py's options for these conditions."""
        args = ["--delay-ms", str(self.delay_ms), "--jitter-ms", str(self.jitter_ms),
                "--loss", str(self.loss)]
        for direction, delay_ms in zip(("up", "down"), (self.up_delay_ms, self.down_delay_ms)):
            if delay_ms is not None:
                args += [f"--{direction}-delay-ms", str(delay_ms)]
        if self.centred:
            args.append("--jitter-centred")
        if not self.reorder:
            args.append("--in-order")
        if self.burst_loss > 0:
            args += ["--burst-loss", str(self.burst_loss),
                     "--burst-length", str(self.burst_length)]
        if self.duplicate > 0:
            args += ["--duplicate", str(self.duplicate)]
        if self.answers_lost_first_ms > 0:
            args += ["--answers-lost-first-ms", str(self.answers_lost_first_ms)]
        return args


# The network players really have (issue 24): 200 ms each way, each datagram +- 60 ms
# on its own (they overtake each other), about 10 % lost in bursts of 3-10 (6.5 on average;
# a Markov chain's bursts are geometric, so only the mean is held), 1 % duplicated.
ROUGH = Network(delay_ms=200, jitter_ms=60, centred=True, burst_loss=0.10, burst_length=6.5,
                duplicate=0.01)


class Relay:
    """tools/net/udp_relay.py in front of the server, taking commands on its stdin."""

    def __init__(self, server_port: int, workdir: Path, network: Network,
                 seed: int = 1, max_seconds: float = 240.0) -> None:
        """[max_seconds]: the relay's own deadline, past the longest run it serves (a 10-minute
        soak once lost its relay at 240 s and took that for a dead path)."""
        self.stats_path = workdir / f"relay-{seed}.json"
        self._stderr_path = workdir / f"relay-{seed}.err"
        with open(self._stderr_path, "w") as stderr:
            self.proc = subprocess.Popen(
                [sys.executable, str(RELAY), "--server", f"127.0.0.1:{server_port}",
                 "--listen-port", "0", *network.relay_args(), "--seed", str(seed),
                 "--max-seconds", f"{max_seconds:g}", "--stats", str(self.stats_path), "--control"],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=stderr, text=True,
            )
        first = self.proc.stdout.readline()
        if not first:
            self.stop()
            raise RuntimeError(f"the relay did not start ({network}): "
                               f"{self._stderr_path.read_text().strip()}")
        self.port = json.loads(first)["listen_port"]
        self.stats: dict = {}
        # "HOST:PORT" of each client, by the relay's number (order of first datagram).
        self.clients: list[str] = []
        self._answers: queue.Queue[dict] = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.proc.stdout:
            message = json.loads(line)
            if "client" in message:
                self.clients.append(message["address"])
            else:
                self._answers.put(message)

    def blackhole(self, client: int | str) -> dict:
        """Cuts [client]'s path (its number, or HOST:PORT as the relay sees it) both ways
        from now on; the relay's answer. RuntimeError when the relay refused."""
        return self._command(f"blackhole {client}")

    def restore(self, client: int | str) -> dict:
        return self._command(f"restore {client}")

    def rebind(self, client: int | str) -> dict:
        """[client]'s datagrams reach the server from a new port from now on (a NAT that
        rebound it, a laptop on another network); the relay's answer."""
        return self._command(f"rebind {client}")

    def _command(self, line: str) -> dict:
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()
        answer = self._answers.get(timeout=RELAY_PATIENCE_S)
        if "error" in answer:
            raise RuntimeError(f"the relay refused {line!r}: {answer['error']}")
        return answer

    def stop(self) -> None:
        if self.proc.poll() is None:
            os.kill(self.proc.pid, signal.SIGTERM)
        try:
            self.proc.wait(timeout=RELAY_PATIENCE_S)
        finally:
            if self.proc.poll() is None:
                os.kill(self.proc.pid, signal.SIGKILL)
                self.proc.wait()
            self.proc.stdin.close()
            # The process is gone: its reader meets the end of its output.
            if hasattr(self, "_reader"):
                self._reader.join(timeout=RELAY_PATIENCE_S)
            self.proc.stdout.close()
        if self.stats_path.exists():
            self.stats = json.loads(self.stats_path.read_text())


def udp_ports(pid: int) -> set[int]:
    """The local ports of process [pid]'s UDP sockets (/proc), e.g. to tell the relay which of
    its clients a peer is."""
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        try:
            target = os.readlink(fd)
        except OSError:
            continue  # closed meanwhile
        if target.startswith("socket:["):
            inodes.add(target[len("socket:["):-1])
    ports = set()
    for table in ("udp", "udp6"):
        for line in Path(f"/proc/{pid}/net/{table}").read_text().splitlines()[1:]:
            columns = line.split()
            if columns[9] in inodes:
                ports.add(int(columns[1].rsplit(":", 1)[1], 16))
    return ports
