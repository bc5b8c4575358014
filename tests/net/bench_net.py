"""make bench-net: networked Pong's numbers for each network setting and player count (not
tests: nothing here passes or fails). Bytes per second per client through the relay, the
hand-off gap (no master while the transfer travels), the ball's divergence between peers
p50/p99 (serves left out, see net_harness.divergences), the followers' correction sizes,
the share of the masters' ball states the followers took and of those that reached them the
share they used, the most a correction moved a servo's ball in one tick, the hand-off
corrections over 1 m, what the relay did (losses, bursts, duplicates, reordering) and each
headless peer's share of a core and peak resident memory from all connected to its exit
(net_measure), and how soon a killed client is noticed. JSON into .bench/net.json (or --json FILE).

    python tests/net/bench_net.py [--seconds 12] [--peers 2] [--networks rough ...]
        [--json .bench/net.json]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from net_harness import (ROOT, ROUGH, Network, detection_s, divergences, handoff_gaps, killer,
                         quantile, run_match, transfers, workspace)
from net_measure import ProcessMeter, ball_state_use

SETTINGS = {
    "0ms": Network(0, 0, 0.0),
    "50ms+10j": Network(50, 10, 0.0),
    "50ms+10j/5%": Network(50, 10, 0.05),
    "150ms+20j/5%": Network(150, 20, 0.05),
    # 200 +- 60 ms, 10 % lost in bursts of 6.5 on average, 1 % twice (issue 24).
    "rough": ROUGH,
}


def measure(peers: int, label: str, network: Network, seconds: float) -> dict:
    meter = ProcessMeter()
    with workspace() as work:
        try:
            started, relay = run_match(
                work, peers, network, seconds, force_relay=True,
                on_running=lambda running, _relay: meter.start({p.name: p.proc.pid for p in running}))
        finally:
            meter.stop()
    reports = [p.report for p in started]
    clients = max(1, relay.get("clients", 1))
    spread = divergences(reports, network.path_s + 0.1)
    corrections = [r["corrections"] for r in reports]
    gaps = handoff_gaps(reports)
    row = {
        "peers": peers,
        "network": label,
        "seconds": seconds,
        "client_up_bytes_per_s": relay["up"]["bytes_delivered"] / clients / seconds,
        "client_down_bytes_per_s": relay["down"]["bytes_delivered"] / clients / seconds,
        "relay": relay,
        "handoffs": sum(1 for t in transfers(reports[0]) if t[1] == 1),
        "handoff_gap_p50_s": quantile(gaps, 0.5),
        "handoff_gap_max_s": quantile(gaps, 1.0),
        "divergence_p50_m": quantile(spread, 0.5),
        "divergence_p99_m": quantile(spread, 0.99),
        "correction_p50_m": max(c["p50_m"] for c in corrections),
        "correction_p99_m": max(c["p99_m"] for c in corrections),
        "correction_max_m": max(c["max_m"] for c in corrections),
        "snaps": sum(c["snaps"] for c in corrections),
        "states_per_peer": [r["states"] for r in reports],
        "ball_states": ball_state_use(reports),
        "correction_step_max_m": max(r["correction_step_max_m"] for r in reports),
        "handoff_corrections_over_1m": sum(
            1 for r in reports for c in r["handoff_corrections_m"] if c > 1.0),
        "handoff_corrections": sum(len(r["handoff_corrections_m"]) for r in reports),
        "processes": meter.result(),
        "conditions": network.label,
    }
    return row


def describe(row: dict) -> str:
    """The second line of a row: the peers' cost, the ball states taken and used, the
    corrections, the relay's doing."""
    costs = ", ".join(
        f"{name} {p['cpu_share'] * 100:.0f} % {p['peak_rss_kib'] / 1024:.0f} MiB"
        for name, p in row["processes"].items() if p["cpu_share"] is not None)
    shares = row["ball_states"]
    used = ", ".join("-" if p["used_share"] is None else f"{p['used_share'] * 100:.1f} %"
                     for p in shares["per_peer"])
    taken = shares["taken_share"]
    up = row["relay"]["up"]
    runs = max(1, up["loss_runs"])
    return (f"    CPU of a core and peak memory: {costs}; ball states taken of those sent "
            f"{'-' if taken is None else f'{taken * 100:.0f} %'}, used of those that reached "
            f"each peer {used}; largest correction step {row['correction_step_max_m'] * 1000:.1f}"
            f" mm; hand-off corrections over 1 m {row['handoff_corrections_over_1m']} of "
            f"{row['handoff_corrections']}; relay up: lost "
            f"{up['dropped'] / max(1, up['received']) * 100:.1f} % in runs of "
            f"{up['dropped'] / runs:.1f}, {up['duplicated']} twice, {up['reordered']} after a "
            f"newer one")


def detection(label: str, network: Network) -> dict:
    """Seconds from a client's SIGKILL to the host's notice (ENet's timeouts)."""
    killed_at: list[float] = []
    with workspace() as work:
        started, _ = run_match(work, 2, network, 10, on_running=killer(4.0, 1, killed_at),
                               force_relay=True)
    return {"network": label, "detection_s": detection_s(started[0].report, killed_at[0])}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=12.0)
    parser.add_argument("--peers", type=int, nargs="+", default=[2])
    parser.add_argument("--networks", nargs="+", choices=list(SETTINGS), default=list(SETTINGS))
    parser.add_argument("--json", type=Path, default=ROOT / ".bench" / "net.json")
    args = parser.parse_args()
    rows = []
    for peers in args.peers:
        for label in args.networks:
            row = measure(peers, label, SETTINGS[label], args.seconds)
            rows.append(row)
            print(f"{peers} peers {label:>13}: up {row['client_up_bytes_per_s']:7.0f} B/s "
                  f"down {row['client_down_bytes_per_s']:7.0f} B/s, {row['handoffs']:2d} hand-offs "
                  f"gap p50 {row['handoff_gap_p50_s'] * 1000:5.0f} ms, divergence p50/p99 "
                  f"{row['divergence_p50_m']:.3f}/{row['divergence_p99_m']:.3f} m, corrections "
                  f"p50/p99/max {row['correction_p50_m']:.3f}/{row['correction_p99_m']:.3f}/"
                  f"{row['correction_max_m']:.3f} m, snaps {row['snaps']}", flush=True)
            print(describe(row), flush=True)
    kills = []
    for label in [n for n in ("0ms", "50ms+10j/5%", "rough") if n in args.networks]:
        kills.append(detection(label, SETTINGS[label]))
        seconds = kills[-1]["detection_s"]
        shown = "not noticed" if seconds is None else f"{seconds:.2f} s"
        print(f"a killed client noticed by the host, {label:>13}: {shown}", flush=True)
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps({"runs": rows, "dead_peer": kills}, indent=1))


if __name__ == "__main__":
    main()
