"""Everything analyze.py reports, as one JSON-ready dict computed from the valid participants."""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pandas as pd

import stats
from schema import CONDITIONS, CRITERIA, DEMOGRAPHICS, RATINGS_COLUMNS, TRIALS_COLUMNS
from studydata import Participant, Study, contact_models_of

# (column, label, completed trials only)
TRIAL_METRICS = (
    ("time_to_goal_s", "Time to goal (s)", True),
    ("wall_collisions", "Wall collisions", False),
    ("contact_time_s", "Time in contact (s)", False),
    ("path_length_px", "Path length (px)", False),
    ("mean_force_n", "Mean force (N)", False),
    ("max_force_n", "Max force (N)", False),
)


def ratings_frame(participants: list[Participant]) -> pd.DataFrame:
    rows = [r for p in participants for r in p.ratings]
    df = pd.DataFrame(rows, columns=list(RATINGS_COLUMNS))
    for c in ("order_index", *CRITERIA):
        df[c] = df[c].astype(int)
    # "Total" rating of one participant in one condition: the mean of its six criteria.
    df["total"] = df[list(CRITERIA)].mean(axis=1).astype(float)
    return df


def trials_frame(participants: list[Participant]) -> pd.DataFrame:
    rows = [t for p in participants for t in p.trials]
    df = pd.DataFrame(rows, columns=list(TRIALS_COLUMNS))
    for c in ("trial_index", "completed", "wall_collisions"):
        df[c] = df[c].astype(int)
    for c in ("time_to_goal_s", "contact_time_s", "path_length_px", "mean_force_n", "max_force_n"):
        df[c] = df[c].astype(float)
    return df


def totals_matrix(ratings: pd.DataFrame, complete_ids: list[str]) -> np.ndarray:
    """Rows: complete participants (sorted), columns: CONDITIONS; cells: total rating."""
    sub = ratings[ratings["participant_id"].isin(complete_ids)]
    wide = sub.pivot(index="participant_id", columns="condition", values="total")
    wide = wide.reindex(index=sorted(complete_ids), columns=list(CONDITIONS))
    return wide.to_numpy(dtype=float).reshape(len(complete_ids), len(CONDITIONS))


def compute(study: Study) -> dict:
    valid = study.valid_participants
    complete = [p for p in valid if p.complete]
    complete_ids = [p.id for p in complete]
    ratings = ratings_frame(valid)
    trials = trials_frame(valid)

    # Figure 6 and 7: every rating of every valid participant (incomplete ones included).
    per_condition = {}
    for c in CONDITIONS:
        sub = ratings[ratings["condition"] == c]
        per_condition[c] = {
            "n": int(len(sub)),
            "criteria": {k: stats.describe(sub[k]) for k in CRITERIA},
            "total": stats.describe(sub["total"]),
        }

    # As the paper: one-way ANOVA treating every single criterion rating as an observation
    # (that is the only reading under which 10 participants give F(2, 163)); and the same
    # test on per-participant totals, for comparison.
    pooled = {c: ratings.loc[ratings["condition"] == c, list(CRITERIA)].to_numpy().ravel().tolist()
              for c in CONDITIONS}
    by_total = {c: ratings.loc[ratings["condition"] == c, "total"].tolist() for c in CONDITIONS}
    matrix = totals_matrix(ratings, complete_ids)
    columns = {c: matrix[:, j].tolist() for j, c in enumerate(CONDITIONS)}

    tests = {
        "oneway_anova_pooled_ratings": stats.oneway_anova(pooled),
        "oneway_anova_participant_totals": stats.oneway_anova(by_total),
        "rm_anova_total": stats.rm_anova(matrix),
        "friedman_total": stats.friedman(matrix),
        "posthoc_wilcoxon_total": stats.pairwise_wilcoxon(columns) if len(complete) >= 1 else [],
    }
    if tests["friedman_total"]["mean_ranks"]:
        tests["friedman_total"]["mean_ranks"] = dict(zip(CONDITIONS, tests["friedman_total"]["mean_ranks"]))

    answered = [p for p in valid if p.final is not None]
    votes = stats.favourite_votes([p.final["favourite"] for p in answered], CONDITIONS)
    votes["no_final_json"] = [p.id for p in valid if p.final is None]

    trial_metrics = {}
    for c in CONDITIONS:
        sub = trials[trials["condition"] == c]
        entry = {
            "trials": int(len(sub)),
            "participants": int(sub["participant_id"].nunique()),
            "completed": int(sub["completed"].sum()),
            "levels": sorted(sub["level"].unique().tolist()),
            "contact_models": dict(sorted(contact_models_of(sub.to_dict("records")).items())),
        }
        for col, _label, completed_only in TRIAL_METRICS:
            values = sub.loc[sub["completed"] == 1, col] if completed_only else sub[col]
            d = stats.describe(values)
            entry[col] = {"mean": d["mean"], "sd": d["sd"], "n": d["n"]}
        trial_metrics[c] = entry

    demographics = {}
    for key in DEMOGRAPHICS:
        counts = Counter(p.meta["demographics"][key] for p in valid)
        demographics[key] = {v: counts[v] for v in DEMOGRAPHICS[key] if counts[v]}
    orders = Counter(" > ".join(p.meta["condition_order"]) for p in valid)
    counterbalancing = Counter(p.meta["counterbalancing"] for p in valid)

    return {
        "study_dir": str(study.folder),
        "conditions": list(CONDITIONS),
        "criteria": list(CRITERIA),
        "participants": {
            "found": [p.id for p in study.participants],
            "valid": [p.id for p in valid],
            "excluded_invalid": [
                {"id": p.id, "problems": [str(e) for e in p.errors]} for p in study.invalid_participants
            ],
            "complete": complete_ids,
            "incomplete": [{"id": p.id, "rated": p.rated_conditions} for p in valid if not p.complete],
        },
        "warnings": [str(w) for w in study.all_warnings()],
        "demographics": demographics,
        "condition_orders": dict(sorted(orders.items())),
        "counterbalancing": dict(sorted(counterbalancing.items())),
        "ratings": per_condition,
        "totals_complete": {pid: dict(zip(CONDITIONS, row.tolist())) for pid, row in zip(sorted(complete_ids), matrix)},
        "tests": tests,
        "favourite": votes,
        "trial_metrics": trial_metrics,
    }


def json_ready(obj):
    """NaN and infinities become null (JSON has neither)."""
    if isinstance(obj, dict):
        return {k: json_ready(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_ready(v) for v in obj]
    if isinstance(obj, (np.floating, float)):
        f = float(obj)
        return f if math.isfinite(f) else None
    if isinstance(obj, np.integer):
        return int(obj)
    return obj
