"""The study's data format as the analysis reads it: assets/study/study_schema.json.

The schema is the one machine-readable description of the format, shared with the game
(StudyFormat reads the same file); FORMAT.md explains it. This module exposes its parts as
constants, in the shapes the analysis uses.
"""

from __future__ import annotations

import json
from pathlib import Path, PurePosixPath

SCHEMA_PATH = Path(__file__).resolve().parents[2] / "assets" / "study" / "study_schema.json"
SCHEMA: dict = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))

FORMAT_VERSION: int = SCHEMA["format_version"]
CONDITIONS = tuple(c["id"] for c in SCHEMA["conditions"])
# The conditions' names for people (participants only ever see "Method N").
CONDITION_LABELS = {c["id"]: c["name"] for c in SCHEMA["conditions"]}
COUNTERBALANCING = tuple(SCHEMA["counterbalancing"])
# The movement renderer's contact models a trial may record (force_model.contact_model).
CONTACT_MODELS = tuple(SCHEMA["contact_models"])
CRITERIA = tuple(c["id"] for c in SCHEMA["criteria"])
CRITERION_TITLES = {c["id"]: c["title"] for c in SCHEMA["criteria"]}
# The paper's wording of each criterion (Table I).
CRITERION_WORDING = {c["id"]: c["wording"] for c in SCHEMA["criteria"]}
RATING_MIN: int = SCHEMA["rating"]["min"]
RATING_MAX: int = SCHEMA["rating"]["max"]
DEMOGRAPHICS = {d["key"]: tuple(d["values"]) for d in SCHEMA["demographics"]}
PATTERNS: dict[str, str] = SCHEMA["patterns"]

_FILES = SCHEMA["files"]
PARTICIPANT_FILE: str = _FILES["participant"]
RATINGS_FILE: str = _FILES["ratings"]
TRIALS_FILE: str = _FILES["trials"]
FINAL_FILE: str = _FILES["final"]
TELEMETRY_DIR = PurePosixPath(_FILES["telemetry"]).parent.as_posix()
# Folder names in a study folder that are not participants.
RESERVED_DIR_NAMES = tuple(_FILES["reserved_folders"])
# Below this effective sample rate a telemetry file earns a warning.
TELEMETRY_MIN_RATE_HZ = float(SCHEMA["telemetry_min_rate_hz"])
# The longest time between two telemetry rows that contact_time_s counts (FORMAT.md, "Trial
# metrics").
METRIC_MAX_ROW_STEP_S = float(SCHEMA["metric_max_row_step_s"])


def columns(table: str) -> tuple[dict, ...]:
    """The columns of the CSV table `table` in file order: dicts with name, type and, for
    numbers, min/max where bounded (an {"each": "criteria"} entry is one column per criterion)."""
    out = []
    for column in SCHEMA["tables"][table]:
        each = column.get("each")
        if each is None:
            out.append(column)
        else:
            spec = {k: v for k, v in column.items() if k != "each"}
            out.extend({**spec, "name": entry["id"]} for entry in SCHEMA[each])
    return tuple(out)


RATINGS_COLUMNS = tuple(c["name"] for c in columns("ratings"))
TRIALS_COLUMNS = tuple(c["name"] for c in columns("trials"))
TELEMETRY_COLUMNS = tuple(c["name"] for c in columns("telemetry"))


def telemetry_name(condition: str, trial_index: int) -> str:
    """The telemetry file of a trial, relative to the participant folder."""
    return _FILES["telemetry"].format(condition=condition, trial_index=trial_index)
