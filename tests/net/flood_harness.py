"""A network namespace for the sustained connect-flood test (tests/net/test_net_guard.py): its
own loopback, where the test applies the kernel's guard (tools/net/flood-guard.sh) without
touching this machine's firewall, runs the peers and the flood (tests/net/connect_flood.py),
and is deleted afterwards. Needs root and iproute2, and nftables for the guard.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from contextlib import contextmanager
from pathlib import Path

from guard_harness import LogWatch
from net_harness import DRIVER_SCENE, GODOT, ROOT, Peer

GUARD = ROOT / "tools" / "net" / "flood-guard.sh"
FLOOD = Path(__file__).resolve().parent / "connect_flood.py"


def missing_tools(guard: bool) -> str:
    """Why the namespace (with the kernel's guard: [guard]) cannot be made here, or ""."""
    if os.geteuid() != 0:
        return "a network namespace needs root"
    for tool in ("ip", "nft") if guard else ("ip",):
        if shutil.which(tool) is None:
            return f"{tool} is not installed (Debian: iproute2, nftables)"
    return ""


class Namespace:
    """A network namespace with its loopback up; [guard_port] > 0: the kernel's guard
    installed for that port."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.prefix = ("ip", "netns", "exec", name)

    def run(self, *command: str) -> None:
        subprocess.run([*self.prefix, *command], check=True, capture_output=True, text=True)

    def peer(self, workdir: Path, name: str, args: list[str]) -> Peer:
        """A peer of the source tree started now inside the namespace (the caller kills it)."""
        peer = Peer(name, args, workdir, scene=DRIVER_SCENE,
                    command=(*self.prefix, str(GODOT), "--headless", "--path", str(ROOT)))
        peer.start()
        return peer

    def flood(self, port: int, rate: float, seconds: float, source: str) -> subprocess.Popen:
        """tests/net/connect_flood.py started now inside the namespace: RATE CONNECTs a second
        from SOURCE's fresh ports to PORT for at most SECONDS (stop_flood ends it sooner)."""
        return subprocess.Popen(
            [*self.prefix, sys.executable, str(FLOOD), f"--port={port}", f"--rate={rate}",
             f"--seconds={seconds}", f"--source={source}"],
            stdout=subprocess.PIPE, text=True, cwd=ROOT)

    def guard_counters(self) -> str:
        out = subprocess.run([*self.prefix, "nft", "list", "chain", "inet", "pong_flood_guard",
                              "connection_request"], capture_output=True, text=True)
        return " | ".join(line.strip() for line in out.stdout.splitlines() if "counter" in line)


@contextmanager
def namespace(guard_port: int = 0):
    name = f"pong-flood-{os.getpid()}"
    subprocess.run(["ip", "netns", "add", name], check=True, capture_output=True)
    try:
        space = Namespace(name)
        space.run("ip", "link", "set", "lo", "up")
        if guard_port > 0:
            space.run(str(GUARD), str(guard_port))
        yield space
    finally:
        subprocess.run(["ip", "netns", "delete", name], capture_output=True)


def flood_started_at(flood: subprocess.Popen) -> float:
    """The wall time the flood's first datagram left (its first line)."""
    assert flood.stdout is not None
    return json.loads(flood.stdout.readline())["started"]


def stop_flood(flood: subprocess.Popen) -> dict:
    """Ends the flood (SIGTERM to its PID) and returns what it sent."""
    if flood.poll() is None:
        os.kill(flood.pid, signal.SIGTERM)
    out, _ = flood.communicate(timeout=30)
    lines = [json.loads(line) for line in out.splitlines() if line.strip()]
    return lines[-1] if lines else {}


def flood_joins(work: Path, server_args: list[str], guard: bool, joins_at_s: tuple[float, ...],
                rate: float, flood_s: float, source: str, watch_for: str,
                launch_lead_s: float = 1.0, join_patience_s: float = 6.0) -> dict:
    """A server (SERVER_ARGS: the dedicated one or a player's host, on port 7420) in a fresh
    namespace, with the kernel's guard or without; a flood of RATE CONNECTs a second from
    SOURCE's fresh ports; and a player launched LAUNCH_LEAD_S before each of JOINS_AT_S
    (seconds into the flood) who joins, stays a few seconds in the lobby and leaves. The
    flood lasts FLOOD_S and until the last player is in (or gave up). Returns the peers (the
    server first), each join's start into the flood and its time to connect (None: it never
    did), when the server first logged WATCH_FOR, what the flood sent, the guard's counters;
    every process is ended."""
    port = 7420
    peers: list[Peer] = []
    result: dict = {"peers": peers, "joins": [], "flood": {}, "counters": ""}
    with namespace(guard_port=port if guard else 0) as space:
        flood = None
        try:
            server = space.peer(work, "server", [
                *server_args, f"--port={port}", f"--pong-net-max-seconds={flood_s + 90}"])
            peers.append(server)
            assert server.wait_for_log("Hosting on port"), server.log()
            server_watch = LogWatch(server)
            watching = threading.Thread(target=server_watch.wait,
                                        args=([watch_for], flood_s + 60), daemon=True)
            flood = space.flood(port, rate, flood_s + 60, source)
            started = flood_started_at(flood)
            watching.start()
            result["started"] = started
            for index, at_s in enumerate(joins_at_s):
                time.sleep(max(0.0, started + at_s - launch_lead_s - time.time()))
                client = space.peer(work, f"join{index}", [
                    "--pong-net=join", f"--port={port}", f"--name=join{index}",
                    f"--pong-net-max-seconds={join_patience_s}"])
                peers.append(client)
                watch = LogWatch(client)
                watch.wait(["Connecting to", "Connected;"], 30.0)
                began = watch.seen.get("Connecting to")
                joined = watch.seen.get("Connected;")
                result["joins"].append({
                    "at_s": None if began is None else began - started,
                    "join_s": None if began is None or joined is None else joined - began})
            time.sleep(max(0.0, started + flood_s - time.time()))
            result["flood"] = stop_flood(flood)
            result["flood"]["stopped_s"] = time.time() - started
            result["counters"] = space.guard_counters() if guard else ""
            for client in peers[1:]:
                client.wait()
            seen = server_watch.seen.get(watch_for)
            result["logged_s"] = None if seen is None else seen - started
        finally:
            if flood is not None and flood.poll() is None:
                stop_flood(flood)
            for peer in peers:
                peer.kill()
    return result
