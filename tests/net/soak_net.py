"""A long networked match between two live headless peers (issue 36: "a 10-minute match on the
rough path with both peers alive has 0 false disconnects"). Not a test: it takes ten minutes.
It prints what a player would have met: silences noticed (each one a "connection trouble" on
a screen), seats the computer took, a server lost, refused messages by reason, the share of
the master's ball states each follower used, and whether both ended with the same health.
JSON into .bench/net-soak.json (or --json FILE); the exit code is 1 when anything was
disconnected or refused.

    python tests/net/soak_net.py [--seconds 600] [--network rough] [--json .bench/net-soak.json]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from bench_net import SETTINGS
from net_harness import ROOT, check_health, engine_errors, misbehaviour, run_match, workspace
from net_measure import ball_state_use

# Enough health for ten minutes of autopilots (about 0.5-0.8 points a second are lost).
HEALTH = 999


def soak(seconds: float, label: str) -> dict:
    with workspace() as work:
        peers, relay = run_match(work, 2, SETTINGS[label], seconds, force_relay=True,
                                 host_args=(f"--pong-net-health={HEALTH}",),
                                 client_args=((f"--pong-net-health={HEALTH}",),))
        reports = {p.name: p.report for p in peers}
        errors = {p.name: engine_errors(p)[:5] for p in peers}
    row: dict = {"seconds": seconds, "network": label, "relay": relay, "peers": {}}
    for name, report in reports.items():
        extra = report.get("extra", {})
        row["peers"][name] = {
            "exit": report.get("exit"), "exit_code": report.get("exit_code"),
            "silences": extra.get("absent", []), "seats_taken": extra.get("peers_left", []),
            "server_lost": extra.get("server_lost"),
            "refused": misbehaviour(report),
            "health": report.get("health"), "errors": errors[name],
            "said": [f"from peer {p}: {what}: {why}"
                     for p, what, why in report.get("refusal_reasons", [])],
        }
    row["ball_states"] = ball_state_use(list(reports.values()))
    try:
        check_health(list(reports.values()))
        row["health_agrees"] = True
    except AssertionError as error:
        row["health_agrees"] = str(error)[:400]
    return row


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=600.0)
    parser.add_argument("--network", choices=list(SETTINGS), default="rough")
    parser.add_argument("--json", type=Path, default=ROOT / ".bench" / "net-soak.json")
    args = parser.parse_args()
    row = soak(args.seconds, args.network)
    bad = False
    for name, peer in row["peers"].items():
        silences = len(peer["silences"])
        taken = len(peer["seats_taken"])
        bad = bad or taken > 0 or peer["server_lost"] is not None or bool(peer["refused"])
        bad = bad or peer["exit"] != "time" or bool(peer["errors"])
        print(f"{name}: exit {peer['exit']} ({peer['exit_code']}), silences noticed {silences}, "
              f"seats taken over {taken}, server lost {peer['server_lost']}, refused "
              f"{peer['refused'] or 'nothing'}, health {peer['health']}, error lines "
              f"{len(peer['errors'])}")
        for line in peer["said"]:
            print(f"  {name} refused {line}")
    use = row["ball_states"]
    shares = ", ".join(f"{100 * p['used_share']:.1f} %" for p in use["per_peer"]
                       if p["used_share"] is not None)
    print(f"{args.seconds:.0f} s on {args.network}: ball states used of those that reached each "
          f"peer {shares}; health agrees: {row['health_agrees']}")
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(row, indent=1))
    return 1 if bad or row["health_agrees"] is not True else 0


if __name__ == "__main__":
    sys.exit(main())
