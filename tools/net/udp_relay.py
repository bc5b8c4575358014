#!/usr/bin/env python3
"""A UDP relay that puts the networks players have between ENet peers.

Latency, jitter that reorders, loss (independent and in bursts), duplicates, paths that die.

Godot's ENet has no network emulation and netem is unavailable here, so the network tests put
this relay between the clients and the server (docs/networking.md, "Latency and loss"). Clients connect to
the relay's port; for each client address the relay opens its own upstream socket to the
server, so one relay serves any number of clients and the server sees them as distinct peers.
Clients are numbered from 0 in the order their first datagram arrived.

Each direction of each client's path decides every datagram's fate (path_model.py): lost
with probability --loss, and/or in Gilbert-Elliott bursts (--burst-loss L --burst-length B:
the two-state chain that loses L of the datagrams in bursts of B on average); otherwise
delivered after --delay-ms plus a uniform 0..--jitter-ms (or, with --jitter-centred, delay
+- jitter; --up-delay-ms and --down-delay-ms set one direction's delay apart, an asymmetric
path), drawn per datagram and released at its own time, so a jitter larger than the
gap between datagrams reorders them as on a real path (--in-order: each waits for the one
before it instead); with probability --duplicate a second copy goes too, with its own delay.
Every lane has its own generator seeded from --seed: a run's fates are reproducible.

With --control it reads commands from stdin, one a line, and answers each with one JSON
line on stdout: `blackhole CLIENT` drops everything on that client's path from now on, both
ways, datagrams on their way included (a dead path; the other clients play on), `restore
CLIENT` lets it through again, `rebind CLIENT` sends that client's datagrams to the server
from a new port from now on (a NAT that rebound it, a laptop on another network: the server
sees a new address, and what it sends to the old one goes nowhere); CLIENT is its number or
its HOST:PORT as the relay sees it. `blackhole new` cuts every client first seen from then
on, until `restore new` restores them (a machine whose network is down: the new connection a
game opens meanwhile from another port is as dead as its old one).
--answers-lost-first-ms N drops everything the server sends for N ms from the first datagram
any client sends (a join through a loss burst: the server's first answers never arrive, and a
client that tries again from a new port meets the same burst).

When it is listening it prints one JSON line, {"listen_port": N}, and flushes; then one line
{"client": N, "address": "HOST:PORT"} for each new client. It exits on SIGTERM or SIGINT, or
after --max-seconds (so a relay a crashed test forgot never outlives it by much), and then
writes its counts to --stats as JSON: per direction in total ("up", "down") and per client
("paths"), the fields of path_model.DirectionStats.

    udp_relay.py --server 127.0.0.1:7000 [--listen-port 0] [--delay-ms 50] [--jitter-ms 10]
                 [--up-delay-ms 50 --down-delay-ms 250]
                 [--jitter-centred] [--in-order] [--loss 0.05] [--burst-loss 0.1
                 --burst-length 6.5] [--duplicate 0.01] [--answers-lost-first-ms 3000]
                 [--control] [--seed 1]
                 [--max-seconds 120] [--stats stats.json]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import random
import signal
import socket
import sys
from dataclasses import asdict
from typing import Callable, cast

from path_model import BurstLoss, DirectionStats, Lane, PathModel

Address = tuple[str, int]
DIRECTIONS = ("up", "down")  # client -> server, server -> client
# A command line longer than this is refused (and the relay reads on).
MAX_COMMAND_BYTES = 1024
# Asked of the kernel for each socket's receive buffer (it grants up to net.core.rmem_max):
# a datagram the kernel drops while this process waits for a core on a loaded machine is a
# loss nobody asked for; the default buffer holds about 200 small ones.
RECEIVE_BUFFER_BYTES = 4 << 20


class UsageError(Exception):
    """The relay cannot run as asked (found only once it starts)."""


def say(p_message: dict) -> None:
    """One JSON line on stdout for whoever drives the relay; a reader that went away is no
    reason to stop relaying."""
    try:
        print(json.dumps(p_message), flush=True)
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)


def _enlarge_receive_buffer(p_transport: asyncio.BaseTransport) -> None:
    sock = p_transport.get_extra_info("socket")
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RECEIVE_BUFFER_BYTES)


def _text(p_address: Address) -> str:
    return f"{p_address[0]}:{p_address[1]}"


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

    def __init__(self, p_server: Address, p_models: dict[str, PathModel], p_seed: int,
                 p_answers_lost_s: float = 0.0) -> None:
        self._server = p_server
        self._answers_lost_s = p_answers_lost_s
        # The loop time before which the server's answers are dropped (set by the first client).
        self._answers_from: float | None = None
        # Each direction's path (DIRECTIONS), the same one unless the path is asymmetric.
        self._models = p_models
        self._seed = p_seed
        self._clients: list[Address] = []
        self._front: asyncio.DatagramTransport | None = None
        self._upstreams: dict[Address, _Upstream] = {}
        self._pending: dict[Address, list[bytes]] = {}
        self._lanes: dict[tuple[Address, str], Lane] = {}
        # `blackhole new`: clients first seen from then on start cut (those cut so, in order).
        self._cut_new = False
        self._cut_as_new: list[Address] = []

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
        for lane in self._lanes.values():
            lane.abandon()
        for upstream in self._upstreams.values():
            if upstream.transport is not None:
                upstream.transport.close()
        if self._front is not None:
            self._front.close()

    def stats(self) -> dict:
        """The counts: per direction in total, and per client path."""
        totals = {direction: DirectionStats() for direction in DIRECTIONS}
        paths = []
        for number, client in enumerate(self._clients):
            path: dict = {"client": number, "address": _text(client)}
            for direction in DIRECTIONS:
                lane = self._lanes.get((client, direction))
                counts = lane.stats if lane is not None else DirectionStats()
                totals[direction].add(counts)
                path[direction] = asdict(counts)
            paths.append(path)
        return {
            **{direction: asdict(counts) for direction, counts in totals.items()},
            "clients": len(self._clients),
            "paths": paths,
        }

    def command(self, p_text: str) -> dict:
        """Carries out one control line; the answer, an error that changed nothing included."""
        words = p_text.split()
        if len(words) != 2 or words[0] not in ("blackhole", "restore", "rebind"):
            return {"error": f"unknown command {p_text[:80]!r}: expected 'blackhole CLIENT', "
                             "'restore CLIENT' or 'rebind CLIENT'"}
        if words[1] == "new" and words[0] != "rebind":
            self._cut_new = words[0] == "blackhole"
            restored = [] if self._cut_new else self._cut_as_new
            for cut_client in restored:
                for direction in DIRECTIONS:
                    self._lane(cut_client, direction).cut = False
            self._cut_as_new = [] if not self._cut_new else self._cut_as_new
            return {words[0]: "new", "clients": [self._clients.index(c) for c in restored]}
        client = self._find_client(words[1])
        if client is None:
            return {"error": f"no client {words[1][:80]!r} (clients: "
                             f"{[_text(c) for c in self._clients]})"}
        if words[0] == "rebind":
            old = self._upstreams.pop(client, None)
            if old is None:
                return {"error": f"client {words[1][:80]!r} has no port to the server yet"}
            if old.transport is not None:
                old.transport.close()
            self._pending[client] = []
            self._connect_upstream(client)
            return {"rebind": self._clients.index(client), "address": _text(client)}
        for direction in DIRECTIONS:
            self._lane(client, direction).cut = words[0] == "blackhole"
        return {words[0]: self._clients.index(client), "address": _text(client)}

    def _find_client(self, p_word: str) -> Address | None:
        if p_word.isdigit():
            number = int(p_word)
            return self._clients[number] if number < len(self._clients) else None
        for client in self._clients:
            if _text(client) == p_word:
                return client
        return None

    def _lane(self, p_client: Address, p_direction: str) -> Lane:
        key = (p_client, p_direction)
        if key not in self._lanes:
            # A generator per lane: a datagram's fate depends on its place in its own lane,
            # not on how the two directions happened to interleave, so a seed reproduces a run.
            number = self._clients.index(p_client)
            rng = random.Random(f"{self._seed}/{number}/{p_direction}")
            self._lanes[key] = Lane(self._models[p_direction], rng)
        return self._lanes[key]

    def _open_upstream(self, p_client: Address, p_first: bytes) -> None:
        if p_client in self._pending:
            self._pending[p_client].append(p_first)
            return
        self._pending[p_client] = [p_first]
        self._clients.append(p_client)
        if self._answers_from is None:
            self._answers_from = asyncio.get_running_loop().time() + self._answers_lost_s
        say({"client": len(self._clients) - 1, "address": _text(p_client)})
        if self._cut_new:
            for direction in DIRECTIONS:
                self._lane(p_client, direction).cut = True
            self._cut_as_new.append(p_client)
        self._connect_upstream(p_client)

    def _connect_upstream(self, p_client: Address) -> None:
        """A new socket toward the server for [p_client]; what it sends meanwhile waits in
        _pending."""
        upstream = _Upstream(lambda data: self._send_later(p_client, "down", data))
        loop = asyncio.get_running_loop()

        async def connect() -> None:
            transport, _ = await loop.create_datagram_endpoint(
                lambda: upstream, remote_addr=self._server)
            _enlarge_receive_buffer(transport)
            self._upstreams[p_client] = upstream
            for data in self._pending.pop(p_client):
                self._send_later(p_client, "up", data)

        loop.create_task(connect())

    def _send_later(self, p_client: Address, p_direction: str, p_data: bytes) -> None:
        lane = self._lane(p_client, p_direction)
        loop = asyncio.get_running_loop()
        if p_direction == "down" and loop.time() < (self._answers_from or 0.0):
            lane.stats.received += 1
            lane.stats.blackholed += 1
            return
        for sequence, release_s in lane.admit(loop.time()):
            loop.call_at(release_s, self._deliver, p_client, p_direction, p_data, lane, sequence)

    def _deliver(
        self, p_client: Address, p_direction: str, p_data: bytes, p_lane: Lane, p_sequence: int
    ) -> None:
        if p_direction == "up":
            upstream = self._upstreams.get(p_client)  # None while a rebind connects
            transport = upstream.transport if upstream is not None else None
        else:
            transport = self._front
        if transport is None or transport.is_closing():
            p_lane.lost_on_way(p_sequence)
            return
        if p_lane.release(p_sequence, len(p_data)):
            if p_direction == "up":
                transport.sendto(p_data)
            else:
                transport.sendto(p_data, p_client)


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
    """The options, and in .models each direction's path (an impossible one is refused)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--server", type=_address, required=True, help="HOST:PORT to relay to")
    parser.add_argument("--listen-host", default="127.0.0.1")
    parser.add_argument("--listen-port", type=int, default=0, help="0 picks a free port")
    parser.add_argument("--delay-ms", type=_milliseconds, default=0.0, help="each way")
    for direction, towards in zip(DIRECTIONS, ("server", "client")):
        parser.add_argument(f"--{direction}-delay-ms", type=_milliseconds, default=None,
                            help=f"towards the {towards} only, instead of --delay-ms")
    parser.add_argument("--jitter-ms", type=_milliseconds, default=0.0,
                        help="uniform extra 0..J per datagram (+-J with --jitter-centred)")
    parser.add_argument("--jitter-centred", action="store_true",
                        help="delay +- jitter (needs jitter <= delay) instead of delay + 0..jitter")
    parser.add_argument("--in-order", action="store_true",
                        help="jitter never reorders: each datagram waits for the one before it")
    parser.add_argument("--loss", type=_probability, default=0.0, help="each way, 0..1")
    parser.add_argument("--burst-loss", type=_probability, default=0.0,
                        help="average loss in Gilbert-Elliott bursts (with --burst-length)")
    parser.add_argument("--burst-length", type=float, default=0.0,
                        help="mean burst length in datagrams, >= 1")
    parser.add_argument("--duplicate", type=_probability, default=0.0,
                        help="probability that a datagram goes twice")
    parser.add_argument("--answers-lost-first-ms", type=_milliseconds, default=0.0,
                        help="drop the server's datagrams for this long from the first "
                             "client's first datagram")
    parser.add_argument("--control", action="store_true",
                        help="read blackhole/restore commands from stdin (a pipe)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-seconds", type=float, default=600.0)
    parser.add_argument("--stats", help="write the counts here as JSON at exit")
    args = parser.parse_args(p_argv)
    if (args.burst_loss > 0.0) != (args.burst_length != 0.0):
        parser.error("--burst-loss and --burst-length go together")
    try:
        bursts = (BurstLoss.from_mean(args.burst_loss, args.burst_length)
                  if args.burst_loss > 0.0 else None)
        args.models = {}
        for direction in DIRECTIONS:
            delay_ms = getattr(args, f"{direction}_delay_ms")
            args.models[direction] = PathModel(
                delay_s=(args.delay_ms if delay_ms is None else delay_ms) / 1000.0,
                jitter_s=args.jitter_ms / 1000.0, centred=args.jitter_centred,
                reorder=not args.in_order, loss=args.loss, bursts=bursts,
                duplicate=args.duplicate,
            )
    except ValueError as error:
        parser.error(str(error))
    return args


async def _read_commands(p_relay: Relay, p_reader: asyncio.StreamReader) -> None:
    while True:
        try:
            line = await p_reader.readline()
        except ValueError:
            say({"error": f"command longer than {MAX_COMMAND_BYTES} bytes"})
            continue
        if not line:
            return  # the driver closed its end: no more commands, the relay goes on
        text = line.decode("utf-8", "replace").strip()
        if text:
            say(p_relay.command(text))


async def run(p_args: argparse.Namespace) -> Relay:
    relay = Relay(p_args.server, p_args.models, p_args.seed, p_args.answers_lost_first_ms / 1000.0)
    loop = asyncio.get_running_loop()
    transport, _ = await loop.create_datagram_endpoint(
        lambda: relay, local_addr=(p_args.listen_host, p_args.listen_port)
    )
    _enlarge_receive_buffer(transport)
    stop = asyncio.Event()
    for signum in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(signum, stop.set)
    commands = None
    if p_args.control:
        reader = asyncio.StreamReader(limit=MAX_COMMAND_BYTES)
        try:
            await loop.connect_read_pipe(lambda: asyncio.StreamReaderProtocol(reader), sys.stdin)
        except (ValueError, OSError) as error:
            transport.close()
            raise UsageError(f"--control needs stdin to be a pipe: {error}") from error
        commands = loop.create_task(_read_commands(relay, reader))
    say({"listen_port": transport.get_extra_info("sockname")[1]})
    try:
        await asyncio.wait_for(stop.wait(), timeout=p_args.max_seconds)
    except asyncio.TimeoutError:
        pass
    if commands is not None:
        commands.cancel()
    relay.close()
    return relay


def main(p_argv: list[str]) -> int:
    args = parse_arguments(p_argv)
    try:
        relay = asyncio.run(run(args))
    except UsageError as error:
        print(f"udp_relay.py: error: {error}", file=sys.stderr)
        return 2
    if args.stats:
        with open(args.stats, "w", encoding="utf-8") as out:
            json.dump(relay.stats(), out, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
