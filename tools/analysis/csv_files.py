"""The CSV files of a participant folder: ratings.csv, trials.csv and the telemetry files
trials.csv references (FORMAT.md, columns in the schema).

Each check reads its file strictly and records the valid records on the participant and
every problem as an error (or, for doubtful but valid data, a warning).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from schema import CONDITIONS, RATINGS_FILE, TELEMETRY_MIN_RATE_HZ, TRIALS_FILE, telemetry_name
from tables import Issue, read_table
from trial_metrics import mismatches

if TYPE_CHECKING:
    from studydata import Participant


def check_ratings(p: Participant) -> None:
    path = p.folder / RATINGS_FILE
    rel = f"{p.id}/{RATINGS_FILE}"
    if not path.is_file():
        return  # nothing rated yet: an incomplete participant, not a corrupt one
    rows = read_table(path, rel, "ratings", p.errors)
    if rows is None:
        return
    seen: dict[str, int] = {}
    order = (p.meta or {}).get("condition_order")
    order_ok = isinstance(order, list) and sorted(map(str, order)) == sorted(CONDITIONS)
    for lineno, row in rows:
        if row["participant_id"] != p.id:
            p.errors.append(Issue(rel, lineno, f"participant_id {row['participant_id']!r} is not {p.id!r}"))
            continue
        cond = row["condition"]
        if cond in seen:
            p.errors.append(Issue(rel, lineno, f"duplicate condition {cond!r} (already rated on line {seen[cond]})"))
            continue
        seen[cond] = lineno
        if order_ok and order[row["order_index"]] != cond:
            p.errors.append(
                Issue(
                    rel,
                    lineno,
                    f"order_index {row['order_index']} is {order[row['order_index']]!r} in "
                    f"participant.json condition_order, not {cond!r}",
                )
            )
            continue
        p.ratings.append(row)


def check_trials(p: Participant) -> set[str]:
    """Validates trials.csv and the telemetry files it references; returns those names."""
    path = p.folder / TRIALS_FILE
    rel = f"{p.id}/{TRIALS_FILE}"
    referenced: set[str] = set()
    if not path.is_file():
        return referenced
    rows = read_table(path, rel, "trials", p.errors)
    if rows is None:
        return referenced
    seen: dict[tuple[str, int], int] = {}
    for lineno, row in rows:
        if row["participant_id"] != p.id:
            p.errors.append(Issue(rel, lineno, f"participant_id {row['participant_id']!r} is not {p.id!r}"))
            continue
        key = (row["condition"], row["trial_index"])
        if key in seen:
            p.errors.append(
                Issue(rel, lineno, f"duplicate trial {key[0]!r} #{key[1]} (already on line {seen[key]})")
            )
            continue
        seen[key] = lineno
        tel = row["telemetry_file"]
        if tel != "":
            expected = telemetry_name(row["condition"], row["trial_index"])
            if tel != expected:
                p.errors.append(Issue(rel, lineno, f"column 'telemetry_file': {tel!r} (expected {expected!r} or empty)"))
                continue
            referenced.add(tel)
            tel_path = p.folder / tel
            tel_rel = f"{p.id}/{tel}"
            if not tel_path.is_file():
                p.errors.append(Issue(rel, lineno, f"telemetry file {tel!r} does not exist"))
                continue
            tel_rows = check_telemetry(p, tel_path, tel_rel)
            if tel_rows is None:
                continue
            gap = (p.meta or {}).get("contact_gap_s")
            if isinstance(gap, (int, float)) and not isinstance(gap, bool):
                for problem in mismatches(row, tel_rows, float(gap)):
                    p.warnings.append(Issue(rel, lineno, problem))
        if row["contact_time_s"] > row["time_to_goal_s"] + 1e-6:
            p.warnings.append(Issue(rel, lineno, "contact_time_s exceeds time_to_goal_s"))
        if row["max_force_n"] + 1e-9 < row["mean_force_n"]:
            p.warnings.append(Issue(rel, lineno, "max_force_n is below mean_force_n"))
        p.trials.append(row)
    return referenced


def check_telemetry(p: Participant, path: Path, rel: str) -> list[dict] | None:
    """Validates a telemetry file; returns its records, or None when it has errors."""
    before = len(p.errors)
    rows = read_table(path, rel, "telemetry", p.errors)
    if rows is None:
        return None
    prev_t = None
    for lineno, row in rows:
        t = row["time_s"]
        if prev_t is not None and t < prev_t:
            p.errors.append(Issue(rel, lineno, f"time_s decreases ({t} after {prev_t})"))
            break
        prev_t = t
    if len(p.errors) == before and len(rows) >= 2:
        span = rows[-1][1]["time_s"] - rows[0][1]["time_s"]
        if span > 0:
            rate = (len(rows) - 1) / span
            if rate < TELEMETRY_MIN_RATE_HZ:
                p.warnings.append(
                    Issue(rel, None, f"effective sample rate {rate:.0f} Hz is below {TELEMETRY_MIN_RATE_HZ:.0f} Hz")
                )
    return [row for _, row in rows] if len(p.errors) == before else None
