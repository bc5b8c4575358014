#!/usr/bin/env python3
"""Write a synthetic study folder (random but seeded) to try the analysis before real data.

    synth_study.py OUT_DIR [--participants N] [--seed S]

The ratings loosely follow the paper's means (no feedback < movement < constraint); trial
metrics and short telemetry files are made up. OUT_DIR must not exist yet.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

import studywriter as w
from schema import CONDITIONS, CRITERIA, DEMOGRAPHICS

# Per condition: mean rating per criterion (roughly the paper's Figure 6 ordering).
MEANS = {
    "none": [4.5, 7.0, 5.5, 7.0, 4.5, 4.0],
    "movement": [7.0, 6.0, 7.0, 6.5, 8.5, 6.5],
    "constraint": [9.3, 9.4, 9.2, 9.3, 9.2, 8.5],
}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--participants", type=int, default=10)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args(argv)
    if args.out.exists():
        print(f"synth_study.py: {args.out} exists", file=sys.stderr)
        return 2
    rng = np.random.default_rng(args.seed)
    for i in range(args.participants):
        pid = f"P{i + 1:02d}"
        order = list(rng.permutation(CONDITIONS))
        demo = {k: str(rng.choice(v[:4] if k != "hand_used" else v)) for k, v in DEMOGRAPHICS.items()}
        folder = w.write_participant_json(args.out, pid, order, demographics=demo, seed=int(rng.integers(1 << 31)),
                                          finished="2025-05-01T10:05:00Z")
        for oi, c in enumerate(order):
            base = {"none": 0.0, "movement": 0.3, "constraint": 0.6}[c]
            for t in range(2):
                time_s = float(np.round(rng.gamma(9, 5 - 3 * base), 3))
                contact = float(np.round(time_s * rng.uniform(0.05, 0.3), 3))
                w.append_trial(folder, pid, c, t, time_to_goal_s=time_s, completed=int(rng.random() > 0.05),
                               wall_collisions=int(rng.poisson(8 - 6 * base)), contact_time_s=contact,
                               path_length_px=float(np.round(rng.normal(2400, 300), 1)),
                               mean_force_n=0.0 if c == "none" else float(np.round(rng.uniform(0.2, 0.8), 3)),
                               max_force_n=0.0 if c == "none" else float(np.round(rng.uniform(1.0, 2.5), 3)),
                               telemetry=w.telemetry_rows(0.5))
            vals = np.clip(np.round(rng.normal(MEANS[c], 1.5)), 1, 10).astype(int).tolist()
            w.append_rating(folder, pid, c, oi, dict(zip(CRITERIA, vals)))
        k = int(rng.choice([0, 1, 1, 1, 2]))
        w.write_final(folder, pid, list(rng.choice(CONDITIONS, k, replace=False)) if k else [],
                      "synthetic participant")
    print(f"synth_study.py: wrote {args.participants} participants to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
