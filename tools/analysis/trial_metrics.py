"""A trial's metrics recomputed from its telemetry rows, as FORMAT.md ("Trial metrics")
defines them, and the check that trials.csv holds those values.

The game writes `contact_gap_s` into participant.json since it computes the metrics from
the rows it keeps; data without that key was measured over every 1 kHz sample, so its
metrics cannot be recomputed and are not checked.
"""

from __future__ import annotations

import math

from schema import METRIC_MAX_ROW_STEP_S

# How far a recorded metric may lie from the recomputed one: half a unit of the last
# decimal trials.csv is written with (forces 4, contact time 3, path 1 decimals), plus the
# summation's rounding.
TOLERANCES = {
    "mean_force_n": 1.5e-4,
    "max_force_n": 1.5e-4,
    "contact_time_s": 1.5e-3,
    "path_length_px": 0.06,
    "wall_collisions": 0,
}


def recompute(rows: list[dict], contact_gap_s: float, time_to_goal_s: float) -> dict:
    """The metrics of the telemetry records `rows` (dicts by column name, in file order)."""
    force_sum = largest = contact = path = 0.0
    collisions = 0
    last_contact = -math.inf
    prev = None
    for row in rows:
        force = math.hypot(row["force_x"], row["force_y"])
        force_sum += force
        largest = max(largest, force)
        if prev is not None:
            path += math.hypot(row["avatar_x"] - prev["avatar_x"], row["avatar_y"] - prev["avatar_y"])
        if row["in_contact"] == 1:
            if prev is not None:
                contact += min(max(row["time_s"] - prev["time_s"], 0.0), METRIC_MAX_ROW_STEP_S)
            if row["time_s"] - last_contact > contact_gap_s:
                collisions += 1
            last_contact = row["time_s"]
        prev = row
    return {
        "mean_force_n": force_sum / len(rows) if rows else 0.0,
        "max_force_n": largest,
        "contact_time_s": min(contact, time_to_goal_s),
        "wall_collisions": collisions,
        "path_length_px": path,
    }


def mismatches(trial: dict, rows: list[dict], contact_gap_s: float) -> list[str]:
    """What in the trials.csv record `trial` differs from its telemetry `rows`, one line per
    metric (empty when everything agrees)."""
    expected = recompute(rows, contact_gap_s, trial["time_to_goal_s"])
    out = []
    for metric, tolerance in TOLERANCES.items():
        if abs(trial[metric] - expected[metric]) > tolerance:
            out.append(f"{metric} {trial[metric]} is not what its telemetry gives ({expected[metric]:.4f})")
    return out
