"""The ball stream on issue 24's path, with real peers (numbers, not a test): a two-peer
match through tools/net/udp_relay.py at 140 + U(0, 120) ms each way (200 +- 60 ms) and 10 %
loss (the relay's losses are independent, not the issue's bursts, and it copies nothing).
Prints, per follower, the share of the states that reached it which it used, how many it
dropped as late or copies, the buffer's wait; the ball's divergence between the peers
(p50/p99/max, serves left out) and the hand-off corrections (how many over 1 m, the largest).

    tools/analysis/run.sh tests/net/bench_ball_path.py [--seconds 20] [--seed 1] [--json F]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from net_harness import Network, divergences, quantile, run_match, workspace

ISSUE_PATH = Network(140, 120, 0.10)


def measure(seconds: float, seed: int) -> dict:
    with workspace() as work:
        peers, relay = run_match(work, 2, ISSUE_PATH, seconds, force_relay=True, seed=seed)
    reports = [p.report for p in peers]
    followers = []
    for report in reports:
        stream = report.get("extra", {}).get("ball_stream", {})
        reached = stream.get("received", 0) + stream.get("late", 0)
        used = stream.get("used", 0)
        if not stream:
            # A build before the buffer: what the handler took, of what the relay let through.
            sent = sum(r["sent"] for r in reports if r is not report)
            reached = round(sent * (1.0 - ISSUE_PATH.loss))
            used = report["states"]
        followers.append({
            "peer": report["peer"],
            "states_reached": reached,
            "states_used": used,
            "used_share": used / reached if reached else 0.0,
            "late": stream.get("late", 0),
            "duplicates": stream.get("duplicates", 0),
            "wait_s": stream.get("delay_s", 0.0),
            "ignored_after_touch": stream.get("ignored_after_touch", 0),
        })
    spread = divergences(reports, ISSUE_PATH.path_s + 0.1)
    handoffs = [c for r in reports for c in r["handoff_corrections_m"]]
    return {
        "network": ISSUE_PATH.label,
        "seconds": seconds,
        "sent": [r["sent"] for r in reports],
        "followers": followers,
        "divergence_p50_m": quantile(spread, 0.5),
        "divergence_p99_m": quantile(spread, 0.99),
        "divergence_max_m": quantile(spread, 1.0),
        "handoff_corrections": len(handoffs),
        "handoff_corrections_over_1m": sum(1 for c in handoffs if c > 1.0),
        "handoff_correction_max_m": max(handoffs, default=0.0),
        "relay": relay,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    row = measure(args.seconds, args.seed)
    for f in row["followers"]:
        print(f"peer {f['peer']}: used {f['states_used']} of {f['states_reached']} states that "
              f"reached it ({100 * f['used_share']:.1f} %), {f['late']} late, "
              f"{f['duplicates']} copies, wait {1000 * f['wait_s']:.0f} ms, "
              f"{f['ignored_after_touch']} not applied after a touch")
    print(f"divergence p50 {row['divergence_p50_m']:.3f} m, p99 {row['divergence_p99_m']:.3f} m, "
          f"max {row['divergence_max_m']:.3f} m; hand-off corrections: "
          f"{row['handoff_corrections_over_1m']} of {row['handoff_corrections']} over 1 m, "
          f"largest {row['handoff_correction_max_m']:.2f} m")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(row, indent=2))


if __name__ == "__main__":
    main()
