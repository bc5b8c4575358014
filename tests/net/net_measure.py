"""What the peers cost and what the followers made of the ball stream, for make bench-net
(numbers, not assertions)."""

from __future__ import annotations

import os
import threading
import time
from dataclasses import dataclass
from pathlib import Path

CLOCK_TICKS_PER_S = os.sysconf("SC_CLK_TCK")
# Often enough that the last sample before a peer's exit misses little of its match.
SAMPLE_PERIOD_S = 0.2


@dataclass
class _Sample:
    wall_s: float
    cpu_s: float
    peak_kib: int


def read_process(pid: int) -> tuple[float, int] | None:
    """(user + system CPU seconds, peak resident KiB) of a live process; None once it has
    exited (a zombie has no memory left to report)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
        status = Path(f"/proc/{pid}/status").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    # The command name may hold spaces and parentheses: the fields start after the last ')'.
    fields = stat[stat.rindex(")") + 2:].split()
    if fields[0] == "Z":
        return None
    # Fields 14 and 15 of proc(5), utime and stime; fields[0] is field 3.
    cpu_s = (int(fields[11]) + int(fields[12])) / CLOCK_TICKS_PER_S
    for line in status.splitlines():
        if line.startswith("VmHWM:"):
            return cpu_s, int(line.split()[1])
    return None


class ProcessMeter:
    """Samples processes' CPU time and peak resident memory on a thread, from start() until
    they have all exited or stop() is called; result() gives each one's share of a core over
    the wall time between its first and last samples."""

    def __init__(self) -> None:
        self._pids: dict[str, int] = {}
        self._first: dict[str, _Sample] = {}
        self._last: dict[str, _Sample] = {}
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def start(self, pids: dict[str, int]) -> None:
        self._pids = dict(pids)
        self._sample()
        self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        if self._thread.is_alive():
            self._thread.join()

    def result(self) -> dict[str, dict]:
        out = {}
        for name, first in self._first.items():
            last = self._last[name]
            wall_s = last.wall_s - first.wall_s
            cpu_s = last.cpu_s - first.cpu_s
            out[name] = {
                "wall_s": wall_s,
                "cpu_s": cpu_s,
                "cpu_share": cpu_s / wall_s if wall_s > 0 else None,
                "peak_rss_kib": last.peak_kib,
            }
        return out

    def _run(self) -> None:
        while not self._stop.wait(SAMPLE_PERIOD_S):
            if not self._sample():
                return

    def _sample(self) -> bool:
        """One sample of each live process; whether any was alive."""
        alive = False
        for name, pid in self._pids.items():
            now = time.monotonic()
            read = read_process(pid)
            if read is None:
                continue
            alive = True
            sample = _Sample(now, read[0], read[1])
            self._first.setdefault(name, sample)
            self._last[name] = sample
        return alive


def ball_state_use(reports: list[dict]) -> dict:
    """Of the ball states the masters sent, the share each follower took (its handler kept:
    neither a copy nor late), and of those that reached it, the share its jitter buffer used
    (played in sequence order; the rest arrived after the play had passed them). A master
    sends every state to every other peer, so a peer was offered what all the others sent."""
    sent = sum(r["sent"] for r in reports)
    per_peer = []
    for r in reports:
        offered = sent - r["sent"]
        stream = r.get("extra", {}).get("ball_stream", {})
        reached = stream.get("received", 0) + stream.get("late", 0)
        per_peer.append({
            "peer": r["peer"],
            "offered": offered,
            "taken": r["states"],
            "taken_share": r["states"] / offered if offered else None,
            "reached": reached,
            "used": stream.get("used", 0),
            "used_share": stream.get("used", 0) / reached if reached else None,
            # Why the rest went unused: the buffer's own counts.
            **{k: stream[k] for k in ("late", "late_after_news", "news", "gaps_given_up", "delay_s")
               if k in stream},
        })
    offered_all = sum(p["offered"] for p in per_peer)
    reached_all = sum(p["reached"] for p in per_peer)
    return {
        "per_peer": per_peer,
        "taken_share": sum(r["states"] for r in reports) / offered_all if offered_all else None,
        "used_share": sum(p["used"] for p in per_peer) / reached_all if reached_all else None,
    }
