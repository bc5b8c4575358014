#!/usr/bin/env python3
"""A UDP relay that puts latency, jitter, reordering and loss between ENet peers.

Godot's ENet has no network emulation and netem is unavailable here, so the network tests put
this relay between the clients and the server (shared/pong/FACTS.md §1.8). Clients connect to
the relay's port; for each client address the relay opens its own upstream socket to the
server, so one relay serves any number of clients and the server sees them as distinct peers.

Every datagram, in each direction, is dropped with probability --loss, otherwise delivered
after --delay-ms plus a uniform extra of up to --jitter-ms. The extra delay is drawn per
datagram, so a jitter larger than the gap between datagrams reorders them, as on a real path.
The random generator is seeded (--seed): a run's drop and delay sequence is reproducible.

When it is listening it prints one JSON line, {"listen_port": N}, and flushes. It exits on
SIGTERM or SIGINT, or after --max-seconds (so a relay a crashed test forgot never outlives it
by much), and then writes its counts to --stats as JSON.

    udp_relay.py --server 127.0.0.1:7000 [--listen-port 0] [--delay-ms 50] [--jitter-ms 10]
                 [--loss 0.05] [--seed 1] [--max-seconds 120] [--stats stats.json]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import random
import signal
import sys
from dataclasses import asdict, dataclass, field
from typing import Callable, cast

Address = tuple[str, int]


@dataclass
class DirectionStats:
    """What happened to the datagrams travelling one way."""

    received: int = 0
    dropped: int = 0
    delivered: int = 0
    # Delivered after a datagram that was sent later (same client, same direction).
    reordered: int = 0
    bytes_delivered: int = 0


@dataclass
class RelayStats:
    up: DirectionStats = field(default_factory=DirectionStats)  # client -> server
    down: DirectionStats = field(default_factory=DirectionStats)  # server -> client
    clients: int = 0


@dataclass
class Impairment:
    """The path's behaviour, the same each way."""

    delay_s: float
    jitter_s: float
    loss: float


class _Lane:
    """One direction of one client's path: decides each datagram's fate and counts it."""

    def __init__(self, p_stats: DirectionStats, p_rng: random.Random) -> None:
        self._stats = p_stats
        self._rng = p_rng
        self._sent = 0
        self._newest_delivered = -1

    def admit(self, p_path: Impairment) -> tuple[int, float] | None:
        """Returns (sequence, delay in seconds), or None when the datagram is lost."""
        self._stats.received += 1
        sequence = self._sent
        self._sent += 1
        if self._rng.random() < p_path.loss:
            self._stats.dropped += 1
            return None
        return sequence, p_path.delay_s + self._rng.uniform(0.0, p_path.jitter_s)

    def delivered(self, p_sequence: int, p_size: int) -> None:
        self._stats.delivered += 1
        self._stats.bytes_delivered += p_size
        if p_sequence < self._newest_delivered:
            self._stats.reordered += 1
        self._newest_delivered = max(self._newest_delivered, p_sequence)


class _Upstream(asyncio.DatagramProtocol):
    """The relay's socket toward the server on behalf of one client."""

    def __init__(self, p_on_reply: Callable[[bytes], None]) -> None:
        self._on_reply = p_on_reply
        self.transport: asyncio.DatagramTransport | None = None

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        self.transport = cast(asyncio.DatagramTransport, transport)

    def datagram_received(self, data: bytes, addr: Address) -> None:
        self._on_reply(data)

    def error_received(self, exc: Exception) -> None:
        # The server's port is closed (ICMP unreachable): a datagram is lost, the path stays.
        pass


class Relay(asyncio.DatagramProtocol):
    """The relay's front socket, where clients send."""

    def __init__(
        self, p_server: Address, p_path: Impairment, p_seed: int, p_stats: RelayStats
    ) -> None:
        self._server = p_server
        self._path = p_path
        self._seed = p_seed
        self._client_numbers: dict[Address, int] = {}
        self._stats = p_stats
        self._front: asyncio.DatagramTransport | None = None
        self._upstreams: dict[Address, _Upstream] = {}
        self._pending: dict[Address, list[bytes]] = {}
        self._lanes: dict[tuple[Address, str], _Lane] = {}

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        self._front = cast(asyncio.DatagramTransport, transport)

    def error_received(self, exc: Exception) -> None:
        pass

    def datagram_received(self, data: bytes, addr: Address) -> None:
        upstream = self._upstreams.get(addr)
        if upstream is None:
            self._open_upstream(addr, data)
            return
        self._send_later(addr, "up", data)

    def close(self) -> None:
        for upstream in self._upstreams.values():
            if upstream.transport is not None:
                upstream.transport.close()
        if self._front is not None:
            self._front.close()

    def _lane(self, p_client: Address, p_direction: str) -> _Lane:
        key = (p_client, p_direction)
        if key not in self._lanes:
            stats = self._stats.up if p_direction == "up" else self._stats.down
            # A generator per lane: a datagram's fate depends on its place in its own lane,
            # not on how the two directions happened to interleave, so a seed reproduces a run.
            number = self._client_numbers.setdefault(p_client, len(self._client_numbers))
            rng = random.Random(f"{self._seed}/{number}/{p_direction}")
            self._lanes[key] = _Lane(stats, rng)
        return self._lanes[key]

    def _open_upstream(self, p_client: Address, p_first: bytes) -> None:
        if p_client in self._pending:
            self._pending[p_client].append(p_first)
            return
        self._pending[p_client] = [p_first]
        self._stats.clients += 1
        upstream = _Upstream(lambda data: self._send_later(p_client, "down", data))
        loop = asyncio.get_running_loop()

        async def connect() -> None:
            await loop.create_datagram_endpoint(lambda: upstream, remote_addr=self._server)
            self._upstreams[p_client] = upstream
            for data in self._pending.pop(p_client):
                self._send_later(p_client, "up", data)

        loop.create_task(connect())

    def _send_later(self, p_client: Address, p_direction: str, p_data: bytes) -> None:
        lane = self._lane(p_client, p_direction)
        fate = lane.admit(self._path)
        if fate is None:
            return
        sequence, delay = fate
        asyncio.get_running_loop().call_later(
            delay, self._deliver, p_client, p_direction, p_data, lane, sequence
        )

    def _deliver(
        self, p_client: Address, p_direction: str, p_data: bytes, p_lane: _Lane, p_sequence: int
    ) -> None:
        if p_direction == "up":
            transport = self._upstreams[p_client].transport
            if transport is None or transport.is_closing():
                return
            transport.sendto(p_data)
        else:
            if self._front is None or self._front.is_closing():
                return
            self._front.sendto(p_data, p_client)
        p_lane.delivered(p_sequence, len(p_data))


def _address(p_text: str) -> Address:
    host, _, port = p_text.rpartition(":")
    if not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise argparse.ArgumentTypeError(f"expected HOST:PORT, got {p_text!r}")
    return host, int(port)


def _probability(p_text: str) -> float:
    value = float(p_text)
    if not 0.0 <= value < 1.0:
        raise argparse.ArgumentTypeError(f"expected a probability in [0, 1), got {p_text}")
    return value


def _milliseconds(p_text: str) -> float:
    value = float(p_text)
    if not 0.0 <= value <= 10_000.0:
        raise argparse.ArgumentTypeError(f"expected 0..10000 ms, got {p_text}")
    return value


def parse_arguments(p_argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--server", type=_address, required=True, help="HOST:PORT to relay to")
    parser.add_argument("--listen-host", default="127.0.0.1")
    parser.add_argument("--listen-port", type=int, default=0, help="0 picks a free port")
    parser.add_argument("--delay-ms", type=_milliseconds, default=0.0, help="each way")
    parser.add_argument("--jitter-ms", type=_milliseconds, default=0.0, help="uniform extra")
    parser.add_argument("--loss", type=_probability, default=0.0, help="each way, 0..1")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-seconds", type=float, default=600.0)
    parser.add_argument("--stats", help="write the counts here as JSON at exit")
    return parser.parse_args(p_argv)


async def run(p_args: argparse.Namespace) -> RelayStats:
    stats = RelayStats()
    path = Impairment(p_args.delay_ms / 1000.0, p_args.jitter_ms / 1000.0, p_args.loss)
    relay = Relay(p_args.server, path, p_args.seed, stats)
    loop = asyncio.get_running_loop()
    transport, _ = await loop.create_datagram_endpoint(
        lambda: relay, local_addr=(p_args.listen_host, p_args.listen_port)
    )
    stop = asyncio.Event()
    for signum in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(signum, stop.set)
    port = transport.get_extra_info("sockname")[1]
    print(json.dumps({"listen_port": port}), flush=True)
    try:
        await asyncio.wait_for(stop.wait(), timeout=p_args.max_seconds)
    except asyncio.TimeoutError:
        pass
    relay.close()
    return stats


def main(p_argv: list[str]) -> int:
    args = parse_arguments(p_argv)
    stats = asyncio.run(run(args))
    if args.stats:
        with open(args.stats, "w", encoding="utf-8") as out:
            json.dump(asdict(stats), out, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
