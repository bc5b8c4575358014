"""Headless Godot peers and the UDP relay for the networked-Pong process tests and bench.

Every process is started here and killed by its PID in a finally (never by name); every
file goes into a temporary directory that is removed afterwards. Wall times in the peers'
reports are this machine's clock: the protocol never uses them, the tests use them to line
the peers up (they all run on one machine).
"""

from __future__ import annotations

import bisect
import json
import math
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from net_relay import ROUGH, Network, Relay, udp_ports  # noqa: F401 (the tests' one import)

ROOT = Path(__file__).resolve().parents[2]
GODOT = ROOT / "tools" / "godot"
# Every peer of the source tree runs the game's networked-Pong command line under the test
# driver (tests/net/driver/net_peer.gd: autopilot, match seconds, scripts, the JSON report),
# which an exported game does not have.
DRIVER_SCENE = "res://tests/net/driver/net_peer.tscn"
FAILURES = ROOT / ".build" / "net-failures"
# Generous bounds for a loaded 2-core machine (never timing assertions).
START_PATIENCE_S = 30.0
EXIT_PATIENCE_S = 40.0


def protocol_seconds(name: str) -> float:
    """PongNetProtocol's constant [name] (a float, seconds), read from its script: the tests
    bound what the game promises by the game's own figure."""
    text = (ROOT / "game" / "pong" / "net" / "pong_net_protocol.gd").read_text()
    found = re.search(rf"^const {name}: float = ([0-9.]+)$", text, re.MULTILINE)
    assert found, f"PongNetProtocol.{name} is not a float constant"
    return float(found.group(1))


def free_udp_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


@dataclass
class Peer:
    name: str
    args: list[str]
    workdir: Path
    # What runs it, before the "--" and the game's arguments: the source tree's engine, or an
    # exported build's launcher.
    command: tuple[str, ...] = (str(GODOT), "--headless", "--path", str(ROOT))
    # The scene of the source tree it runs: the test driver, or another test peer (the rogue,
    # tests/net/rogue/rogue_peer.tscn); empty: the game's main scene (an exported build).
    scene: str = DRIVER_SCENE
    proc: subprocess.Popen | None = None
    report: dict = field(default_factory=dict)

    @property
    def log_path(self) -> Path:
        return self.workdir / f"{self.name}.log"

    @property
    def report_path(self) -> Path:
        return self.workdir / f"{self.name}.json"

    def start(self) -> None:
        with open(self.log_path, "w") as log:
            self.proc = subprocess.Popen(
                [*self.command, *([self.scene] if self.scene else []), "--", *self.args,
                 f"--pong-net-report={self.report_path}"],
                stdout=log, stderr=subprocess.STDOUT, cwd=ROOT,
            )

    def log(self) -> str:
        return self.log_path.read_text(errors="replace") if self.log_path.exists() else ""

    def wait_for_log(self, text: str, patience_s: float = START_PATIENCE_S) -> bool:
        end = time.monotonic() + patience_s
        while time.monotonic() < end:
            if text in self.log():
                return True
            if self.proc is not None and self.proc.poll() is not None:
                return text in self.log()
            time.sleep(0.05)
        return False

    def wait(self, patience_s: float = EXIT_PATIENCE_S) -> int:
        assert self.proc is not None
        code = self.proc.wait(timeout=patience_s)
        if self.report_path.exists():
            self.report = json.loads(self.report_path.read_text())
        return code

    def kill(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            os.kill(self.proc.pid, signal.SIGKILL)
            self.proc.wait()


def engine_errors(peer: "Peer") -> list[str]:
    """The engine and script error lines of [peer]'s log: none is accepted (issue 36)."""
    return [line for line in peer.log().splitlines()
            if line.startswith(("ERROR", "SCRIPT ERROR"))]


@contextmanager
def workspace():
    """A scratch folder for one match's logs and reports, removed afterwards; when the test
    fails it is moved to .build/net-failures/ instead, since a failure seen once in several
    runs can only be understood from the peers' own logs. With NET_KEEP set, a passing
    match's folder is copied there too (as kept-<name>), to compare with a failing one."""
    path = Path(tempfile.mkdtemp(prefix="pong-net-"))
    try:
        yield path
    except BaseException:
        kept = FAILURES / path.name
        kept.parent.mkdir(parents=True, exist_ok=True)
        shutil.move(str(path), str(kept))
        print(f"the failed match's logs and reports: {kept}", file=sys.stderr)
        raise
    finally:
        if os.environ.get("NET_KEEP") and path.exists():  # A failure's was moved already.
            shutil.copytree(path, FAILURES / ("kept-" + path.name), dirs_exist_ok=True)
        shutil.rmtree(path, ignore_errors=True)


def logs(peers: list["Peer"], tail: int = 2000) -> str:
    """Each peer's exit and the end of its log, for an assertion's message."""
    return "\n".join(f"--- {p.name} ({p.report.get('exit')}):\n{p.log()[-tail:]}" for p in peers)


def run_match(workdir: Path, peers: int, network: Network, seconds: float,
              host_args: tuple[str, ...] = (), client_args: tuple[tuple[str, ...], ...] = (),
              client_scenes: tuple[str, ...] = (), dedicated: bool = False, on_running=None,
              force_relay: bool = False, seed: int = 1,
              server_command: tuple[str, ...] = ()) -> tuple[list[Peer], dict]:
    """Starts a host (or a dedicated server) and the clients, through one relay when the
    network is impaired, waits for all to exit; returns the peers (reports loaded) and the
    relay's counts. [client_scenes][i] runs client i as that scene (see Peer.scene) with the
    same arguments. [on_running](peers, relay) runs once every client is connected (relay:
    the Relay, None when there is none); [seed] picks the relay's drop and delay sequence;
    [server_command] runs the dedicated server from an exported build instead of the source
    tree: without the test driver it writes no report (its report holds "exit_code" only)
    and serves until its deadline, --pong-net-max-seconds, an option of the game's own."""
    port = free_udp_port()
    players = peers
    # A peer quits by itself after its match's seconds, and in any case after a deadline.
    common = ["--pong-net-autopilot", f"--pong-net-seconds={seconds}",
              f"--pong-net-peers={players}", f"--pong-net-max-seconds={seconds + 25}"]
    started: list[Peer] = []
    relay: Relay | None = None
    try:
        if dedicated:
            host = Peer("server", ["--server", f"--port={port}", *common, *host_args], workdir)
            if server_command:
                host.command = server_command
                host.scene = ""
        else:
            host = Peer("host", ["--pong-net=host", f"--port={port}", "--name=host", *common,
                                 *host_args], workdir)
        host.start()
        started.append(host)
        assert host.wait_for_log("Hosting on port"), host.log()
        if network.impaired or force_relay:
            relay = Relay(port, workdir, network, seed,
                          max_seconds=max(240.0, seconds + 25 + EXIT_PATIENCE_S))
        target = relay.port if relay is not None else port
        clients = players if dedicated else players - 1
        for i in range(clients):
            extra = client_args[i] if i < len(client_args) else ()
            peer = Peer(f"client{i + 1}", ["--pong-net=join", f"--port={target}",
                                           f"--name=client{i + 1}", *common, *extra], workdir,
                        scene=client_scenes[i] if i < len(client_scenes) else DRIVER_SCENE)
            peer.start()
            started.append(peer)
        if on_running is not None:
            for peer in started[1:]:
                peer.wait_for_log("Connected")
            on_running(started, relay)
        # Each peer quits after its match's seconds: patience counts from its start.
        patience = seconds + EXIT_PATIENCE_S
        codes = [peer.wait(patience) for peer in started[1:]] + [host.wait(patience)]
        for peer, code in zip(started[1:] + [host], codes):
            peer.report["exit_code"] = code
    finally:
        for peer in started:
            peer.kill()
        if relay is not None:
            relay.stop()
    return started, (relay.stats if relay is not None else {})


def killer(after_s: float, index: int, killed_at: list[float]):
    """An on_running hook for run_match: SIGKILLs peer [index] [after_s] into the match and
    appends the wall time to [killed_at]."""

    def kill(peers: list[Peer], _relay: Relay | None) -> None:
        time.sleep(after_s)
        killed_at.append(time.time())
        os.kill(peers[index].proc.pid, signal.SIGKILL)

    return kill


def detection_s(host: dict, killed_at: float) -> float | None:
    """Seconds from the kill to the server's notice (None: not noticed)."""
    left = host.get("extra", {}).get("peers_left", [])
    return left[0]["wall_s"] - killed_at if left else None


# --- analysis of the reports ---


# A peer quits at its own match clock, so a reliable message still in flight then (a hurt,
# a shot, a mine) may be missing at the end of its lists.
LAST_IN_FLIGHT = 2


def agree(lists: list[list], what: str) -> list:
    """Every two peers' lists hold the same entries (as multisets: two senders' messages may
    arrive in either order), but for at most LAST_IN_FLIGHT that one of them lacks: each
    peer may have quit before the last messages reached it, and two peers may each hold a
    different last one (a four-peer rally at 150 ms ended with one client holding a mine hurt
    and another a bullet hurt the first never saw). Returns the longest list."""
    for a, first in enumerate(lists):
        for second in lists[a + 1:]:
            for one, other in ((first, second), (second, first)):
                missing = list(other)
                for entry in one:
                    if entry in missing:
                        missing.remove(entry)
                assert len(missing) <= LAST_IN_FLIGHT, (what, missing, one, other)
    return max(lists, key=len)


def misbehaviour(report: dict) -> dict:
    """What a peer counted against the others as bad messages, by kind (not the states that
    arrived late across a transfer, which the authority counts apart)."""
    return {k: v for k, v in report["refused"].items() if not k.startswith("authority:")}


def refusal_story(report: dict) -> str:
    """A peer's refusals with their first reasons: a rare refusal is diagnosed from these."""
    reasons = "; ".join(f"from peer {p}: {what}: {why}"
                        for p, what, why in report.get("refusal_reasons", []))
    return f"refused {report['refused']} ({reasons or 'no reasons kept'})"


def floor_hurts(report: dict) -> list[tuple]:
    return [tuple(h) for h in report["hurts"]]


def weapon_hurts(report: dict) -> list[tuple]:
    return [tuple(h) for h in report.get("extra", {}).get("weapons", {}).get("hurts", [])]


def recounted_health(report: dict, start: list[int] | None = None) -> list[int]:
    """The health the peer's own hurts give, floor bounces ([epoch, seat, cause]) and weapon
    hurts ([seat, cause, weapon seat, weapon id]), by the rules its report names, from the
    start's health or each seat's [start] (a peer that joined the match as it stood)."""
    lost = [0] * len(report["health"])
    for _, seat, cause in floor_hurts(report):
        lost[seat] += report["damage"][cause]
    for seat, cause, _, _ in weapon_hurts(report):
        lost[seat] += report["damage"][cause]
    if start is None:
        start = [report["start_health"]] * len(lost)
    return [max(s - x, 0) for s, x in zip(start, lost)]


def check_health(reports: list[dict]) -> None:
    """Every peer applied the same hurts (less what was in flight when it quit), and its
    health is what its own hurts say."""
    agree([floor_hurts(r) for r in reports], "floor hurts")
    agree([weapon_hurts(r) for r in reports], "weapon hurts")
    for report in reports:
        assert report["health"] == recounted_health(report), (
            report["peer"], report["health"], recounted_health(report))


# PongNetAuthority.SERVER_ID, and PongNetFacts' transfer kind when the server takes the ball.
SERVER_PEER = 1
TRANSFER_TAKEOVER = 2


def transfers(report: dict) -> list[tuple[int, int, int, int]]:
    """A report's transfers: (epoch, kind, territory, master peer) each."""
    return [(t["epoch"], t["kind"], t["territory"], t["master"]) for t in report["transfers"]]


def transfers_missed(reports: list[dict], network: Network) -> list[str]:
    """Every peer must have applied the same transfers in the same order. One that quit first
    may have missed those the others applied in its last moments: each peer ends by its own
    clock (CI saw three hand-offs within the host's last 0.3 s, after the peer that ended
    first had 0.5 s to go), and the host takes over the ball of a client that has left. What
    a peer missed must come after its end less a leg and its jitter, and a margin for a busy
    machine. Returns what broke that, one line each (empty: nothing)."""
    lists = [transfers(r) for r in reports]
    longest = max(lists, key=len)
    applied_at: dict[int, float] = {}
    for report in reports:
        for t in report["transfers"]:
            applied_at[t["epoch"]] = min(applied_at.get(t["epoch"], t["wall_s"]), t["wall_s"])
    slack_s = max(network.legs_ms) / 1000.0 + network.jitter_ms / 1000.0 + 0.5
    problems = []
    for report, seen in zip(reports, lists):
        if seen != longest[: len(seen)]:
            problems.append(f"peer {report['peer']} applied {seen}, another {longest}")
            continue
        ended = report["samples"][-1][0]
        early = [t for t in longest[len(seen):] if applied_at[t[0]] < ended - slack_s]
        if early:
            problems.append(f"peer {report['peer']} ended at {ended:.2f} and missed transfers "
                            f"applied before {ended - slack_s:.2f}: {early}")
    return problems


def master_overlaps(reports: list[dict]) -> list[float]:
    """Every stretch (s) during which two peers both believed they were the master."""
    overlaps = []
    for i, a in enumerate(reports):
        for b in reports[i + 1:]:
            for a0, a1 in a["master_intervals"]:
                for b0, b1 in b["master_intervals"]:
                    length = min(a1, b1) - max(a0, b0)
                    if length > 0:
                        overlaps.append(length)
    return overlaps


def _interpolate(samples: list[list[float]], times: list[float], t: float):
    i = bisect.bisect_left(times, t)
    if i <= 0 or i >= len(samples):
        return None
    a, b = samples[i - 1], samples[i]
    if b[0] - a[0] > 0.05:
        return None
    u = (t - a[0]) / (b[0] - a[0])
    return [a[k] + u * (b[k] - a[k]) for k in (2, 3, 4)]


def divergences(reports: list[dict], after_serve_s: float = 0.0,
                followers: tuple[dict, ...] = ()) -> list[float]:
    """|ball(follower) - ball(master)| at the follower's samples, whoever is master then,
    on the shared wall clock of this machine (metres); [followers]: only at theirs. A serve
    puts the ball back in the middle: no follower can know it before the message arrives, so
    the [after_serve_s] after each serve (one path delay and a frame) are left out
    (served_windows counts them)."""
    out = []
    serves = [t["wall_s"] for r in reports for t in r["transfers"] if t["kind"] == 0]
    for master in reports:
        m_samples = master["samples"]
        m_times = [s[0] for s in m_samples]
        for follower in reports:
            if follower is master or (followers and follower not in followers):
                continue
            for s0, s1 in master["master_intervals"]:
                for s in follower["samples"]:
                    if not (s0 <= s[0] <= s1):
                        continue
                    if any(0.0 <= s[0] - t <= after_serve_s for t in serves):
                        continue
                    p = _interpolate(m_samples, m_times, s[0])
                    if p is not None:
                        out.append(math.dist(p, s[2:5]))
    return out


def handoff_gaps(reports: list[dict]) -> list[float]:
    """Seconds without a master at each hand-off: from the old master's stop (its ball
    crossed) to the new master's start (the server's transfer arrived)."""
    gaps = []
    starts = sorted(a for r in reports for a, _ in r["master_intervals"])
    for r in reports:
        for _, end in r["master_intervals"]:
            later = [s for s in starts if s >= end]
            if later and later[0] - end < 2.0:
                gaps.append(later[0] - end)
    return gaps


def quantile(values: list[float], q: float) -> float:
    if not values:
        return 0.0
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, math.ceil(q * len(ordered)) - 1))]
