"""A reference writer of the study format (FORMAT.md), used by the tests and synth_study.py.

It shows, in a few lines each, exactly what the game's study runner writes: CSV records are
appended as complete lines (header written when the file is created), flushed and fsynced;
JSON files are written whole. It is not used by the analysis itself.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from schema import (
    CONDITIONS,
    CRITERIA,
    FINAL_FILE,
    FORMAT_VERSION,
    PARTICIPANT_FILE,
    RATINGS_COLUMNS,
    RATINGS_FILE,
    TELEMETRY_COLUMNS,
    TRIALS_COLUMNS,
    TRIALS_FILE,
    telemetry_name,
)

TIMESTAMP = "2025-05-01T10:00:00Z"
DEFAULT_DEMOGRAPHICS = {
    "age_band": "20-29",
    "gender": "male",
    "handedness": "right",
    "hand_used": "left",
    "gaming_experience": "some",
}


def _fmt(value) -> str:
    if isinstance(value, float):
        return repr(value)
    return str(value)


def append_records(path: Path, columns, records) -> None:
    """Appends complete '\\n'-terminated records, creating the file with its header first,
    then flushes and fsyncs."""
    path.parent.mkdir(parents=True, exist_ok=True)
    new = not path.exists()
    with open(path, "a", encoding="utf-8", newline="") as fh:
        if new:
            fh.write(",".join(columns) + "\n")
        for values in records:
            fh.write(",".join(_fmt(v) for v in values) + "\n")
        fh.flush()
        os.fsync(fh.fileno())


def append_record(path: Path, columns, values) -> None:
    append_records(path, columns, [values])


def write_json(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w", encoding="utf-8") as fh:
        json.dump(data, fh, indent=2, ensure_ascii=False)
        fh.write("\n")
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)


def write_participant_json(study: Path, pid: str, condition_order=CONDITIONS, **overrides) -> Path:
    folder = Path(study) / pid
    data = {
        "format_version": FORMAT_VERSION,
        "participant_id": pid,
        "demographics": dict(DEFAULT_DEMOGRAPHICS),
        "seed": 12345,
        "condition_order": list(condition_order),
        "counterbalancing": "random",
        "app_version": "0.1.0",
        "extension_version": "0.1.0",
        "started": TIMESTAMP,
        "finished": None,
    }
    data.update(overrides)
    write_json(folder / PARTICIPANT_FILE, data)
    return folder


def append_rating(folder: Path, pid: str, condition: str, order_index: int, values, timestamp=TIMESTAMP) -> None:
    if isinstance(values, dict):
        values = [values[k] for k in CRITERIA]
    append_record(folder / RATINGS_FILE, RATINGS_COLUMNS, [pid, condition, order_index, *values, timestamp])


def append_trial(folder: Path, pid: str, condition: str, trial_index: int, *, level="maze", contact_model=None,
                 time_to_goal_s=30.0, completed=1, wall_collisions=3, contact_time_s=2.5, path_length_px=1500.0,
                 mean_force_n=0.4, max_force_n=1.2, telemetry: list | None = None, timestamp=TIMESTAMP) -> None:
    """contact_model None writes what the game writes by default: the study's paper_sum in
    acceleration control, empty in position control (the constraint condition)."""
    if contact_model is None:
        contact_model = "" if condition == "constraint" else "paper_sum"
    tel = ""
    if telemetry is not None:
        tel = telemetry_name(condition, trial_index)
        append_records(folder / tel, TELEMETRY_COLUMNS, telemetry)
    append_record(folder / TRIALS_FILE, TRIALS_COLUMNS,
                  [pid, condition, level, trial_index, contact_model, time_to_goal_s, completed, wall_collisions,
                   contact_time_s,
                   path_length_px, mean_force_n, max_force_n, tel, timestamp])


def telemetry_rows(seconds: float = 0.1, rate_hz: float = 1000.0, contact_every: int = 7) -> list[list]:
    n = int(seconds * rate_hz)
    return [[round(i / rate_hz, 6), 0.5, -0.25, 100.0 + i, 200.0 - i, 0.1 if i % contact_every == 0 else 0.0, 0.0,
             1 if i % contact_every == 0 else 0] for i in range(n)]


def write_final(folder: Path, pid: str, favourite, text: str = "", timestamp=TIMESTAMP) -> None:
    write_json(folder / FINAL_FILE, {"participant_id": pid, "favourite": list(favourite), "differences_text": text,
                                     "timestamp": timestamp})


def make_participant(study: Path, pid: str, ratings: dict, favourite=None, condition_order=CONDITIONS,
                     trials: dict | None = None, telemetry: bool = False, **meta) -> Path:
    """A participant who rated the conditions in `ratings` ({condition: six ints or one int}),
    in condition_order; `trials` maps condition -> list of append_trial keyword dicts (default
    one default trial per rated condition); favourite None means no final.json."""
    folder = write_participant_json(study, pid, condition_order, **meta)
    for i, c in enumerate(condition_order):
        if c not in ratings:
            continue
        for j, kw in enumerate((trials or {}).get(c, [{}])):
            append_trial(folder, pid, c, j, telemetry=telemetry_rows() if telemetry else None, **kw)
        v = ratings[c]
        append_rating(folder, pid, c, i, [v] * len(CRITERIA) if isinstance(v, int) else v)
    if favourite is not None:
        write_final(folder, pid, favourite)
    return folder
