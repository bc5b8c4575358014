#!/usr/bin/env python3
"""Gather every participant of a maze-study folder into one long CSV.

    export_csv.py STUDY_DIR OUT.csv [--skip-invalid]

One row per participant x condition (every condition the participant rated or has trials
for), sorted by participant then condition order none, movement, constraint. Columns:
EXPORT_COLUMNS below (documented in FORMAT.md). Same validation and exit status as
analyze.py: 1 when the data has problems and --skip-invalid is not given (nothing written).
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from statistics import fmean
from pathlib import Path

from analyze import EXIT_DATA, EXIT_OK, EXIT_USAGE, load_checked
from schema import CONDITIONS, CRITERIA, DEMOGRAPHICS
from studydata import Participant, contact_models_of

TRIAL_AGGREGATES = ("time_to_goal_s", "wall_collisions", "contact_time_s", "path_length_px", "mean_force_n", "max_force_n")
EXPORT_COLUMNS = (
    "participant_id",
    *DEMOGRAPHICS,
    "seed",
    "counterbalancing",
    "condition_order",
    "app_version",
    "extension_version",
    "started",
    "finished",
    "complete",
    "condition",
    "order_index",
    *CRITERIA,
    "total",
    "rating_timestamp",
    "favourite_vote",
    "trials",
    "trials_completed",
    "contact_model",
    *(f"{m}_mean" for m in TRIAL_AGGREGATES),
)


def _num(x: float) -> str:
    return repr(float(x)) if math.isfinite(x) else ""


def rows_for(p: Participant) -> list[dict]:
    meta = p.meta
    fav = p.final["favourite"] if p.final is not None else None
    conditions = [c for c in CONDITIONS if any(r["condition"] == c for r in p.ratings)
                  or any(t["condition"] == c for t in p.trials)]
    rows = []
    for c in conditions:
        rating = next((r for r in p.ratings if r["condition"] == c), None)
        trials = [t for t in p.trials if t["condition"] == c]
        row = {
            "participant_id": p.id,
            **{k: meta["demographics"][k] for k in DEMOGRAPHICS},
            "seed": meta["seed"],
            "counterbalancing": meta["counterbalancing"],
            "condition_order": ";".join(meta["condition_order"]),
            "app_version": meta["app_version"],
            "extension_version": meta["extension_version"],
            "started": meta["started"],
            "finished": meta["finished"] or "",
            "complete": int(p.complete),
            "condition": c,
            "order_index": meta["condition_order"].index(c),
            "favourite_vote": "" if fav is None else _num(1.0 / len(fav) if c in fav else 0.0),
            "trials": len(trials),
            "trials_completed": sum(t["completed"] for t in trials),
            "contact_model": ";".join(sorted(contact_models_of(trials))),
        }
        for k in CRITERIA:
            row[k] = rating[k] if rating else ""
        row["total"] = _num(fmean([rating[k] for k in CRITERIA])) if rating else ""
        row["rating_timestamp"] = rating["timestamp"] if rating else ""
        for m in TRIAL_AGGREGATES:
            pool = [t[m] for t in trials if t["completed"] == 1] if m == "time_to_goal_s" else [t[m] for t in trials]
            row[f"{m}_mean"] = _num(fmean(pool)) if pool else ""
        rows.append(row)
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("study_dir", type=Path, metavar="STUDY_DIR")
    parser.add_argument("out_csv", type=Path, metavar="OUT.csv")
    parser.add_argument("--skip-invalid", action="store_true",
                        help="exclude (and list on stderr) invalid participants instead of failing")
    args = parser.parse_args(argv)
    if not args.study_dir.is_dir():
        print(f"export_csv.py: {args.study_dir}: not a directory", file=sys.stderr)
        return EXIT_USAGE
    study = load_checked(args.study_dir, args.skip_invalid, "export_csv.py")
    if study is None:
        return EXIT_DATA
    rows = [row for p in study.valid_participants for row in rows_for(p)]
    args.out_csv.parent.mkdir(parents=True, exist_ok=True)
    with open(args.out_csv, "w", encoding="utf-8", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(EXPORT_COLUMNS), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    print(f"export_csv.py: {len(rows)} row(s) from {len(study.valid_participants)} participant(s) -> {args.out_csv}")
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
