"""Reading and strict validation of a study folder (the format is defined in FORMAT.md).

Every problem is collected as an `Issue` naming the file (relative to the study folder), the
line (1-based, the header is line 1; JSON errors carry the parser's line) and what is wrong.
A participant with at least one error is invalid; the caller decides whether that aborts the
run or excludes the participant. Warnings never invalidate a participant but are always
reported.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path

FORMAT_VERSION = 1

CONDITIONS = ("none", "movement", "constraint")
CONDITION_LABELS = {
    "none": "No feedback",
    "movement": "Movement-based",
    "constraint": "Constraint-based",
}
CRITERIA = ("realism", "ease", "aptness", "intuitiveness", "enthusiasm", "partiality")
CRITERION_WORDING = {
    "realism": "how realistic is the control scheme",
    "ease": "how easy is it to control the character",
    "aptness": "how appropriate does the control feel",
    "intuitiveness": "how natural is the control",
    "enthusiasm": "how much did you enjoy this method",
    "partiality": "how much do you prefer this method",
}
RATING_MIN, RATING_MAX = 1, 10

DEMOGRAPHICS = {
    "age_band": ("under_20", "20-29", "30-39", "40-49", "50-59", "60+", "undisclosed"),
    "gender": ("female", "male", "non_binary", "other", "undisclosed"),
    "handedness": ("left", "right", "ambidextrous", "undisclosed"),
    "hand_used": ("left", "right"),
    "gaming_experience": ("none", "little", "some", "extensive"),
}
COUNTERBALANCING = ("random", "latin_square")

RATINGS_FILE = "ratings.csv"
TRIALS_FILE = "trials.csv"
PARTICIPANT_FILE = "participant.json"
FINAL_FILE = "final.json"
TELEMETRY_DIR = "telemetry"

RATINGS_COLUMNS = ("participant_id", "condition", "order_index", *CRITERIA, "timestamp")
TRIALS_COLUMNS = (
    "participant_id",
    "condition",
    "level",
    "trial_index",
    "time_to_goal_s",
    "completed",
    "wall_collisions",
    "contact_time_s",
    "path_length_px",
    "mean_force_n",
    "max_force_n",
    "telemetry_file",
    "timestamp",
)
TELEMETRY_COLUMNS = (
    "time_s",
    "input_x",
    "input_y",
    "avatar_x",
    "avatar_y",
    "force_x",
    "force_y",
    "in_contact",
)
# Below this effective sample rate a telemetry file earns a warning (the study asks >= 250 Hz).
TELEMETRY_MIN_RATE_HZ = 250.0

# Folder names in a study folder that are not participants.
RESERVED_DIR_NAMES = ("analysis",)
ID_RE = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_-]*$")
LEVEL_RE = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.-]*$")
INT_RE = re.compile(r"^[+-]?[0-9]+$")
FLOAT_RE = re.compile(r"^[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?$")
TIMESTAMP_RE = re.compile(
    r"^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}(\.[0-9]{1,9})?(Z|[+-][0-9]{2}:[0-9]{2})$"
)
_NUM = r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
# Fast path for telemetry rows (thousands per trial): one match per line, diagnosis on failure.
TELEMETRY_ROW_RE = re.compile(r"^(?:" + _NUM + r",){7}[01]$")


@dataclass
class Issue:
    path: str
    line: int | None
    message: str

    def __str__(self) -> str:
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        return f"{where}: {self.message}"


@dataclass
class Participant:
    id: str
    folder: Path
    meta: dict | None = None
    ratings: list[dict] = field(default_factory=list)
    trials: list[dict] = field(default_factory=list)
    final: dict | None = None
    errors: list[Issue] = field(default_factory=list)
    warnings: list[Issue] = field(default_factory=list)

    @property
    def valid(self) -> bool:
        return not self.errors

    @property
    def rated_conditions(self) -> list[str]:
        return [c for c in CONDITIONS if any(r["condition"] == c for r in self.ratings)]

    @property
    def complete(self) -> bool:
        return len(self.rated_conditions) == len(CONDITIONS)


@dataclass
class Study:
    folder: Path
    participants: list[Participant]
    errors: list[Issue] = field(default_factory=list)  # study-level problems

    @property
    def valid_participants(self) -> list[Participant]:
        return [p for p in self.participants if p.valid]

    @property
    def invalid_participants(self) -> list[Participant]:
        return [p for p in self.participants if not p.valid]

    def all_errors(self) -> list[Issue]:
        out = list(self.errors)
        for p in self.participants:
            out.extend(p.errors)
        return out

    def all_warnings(self) -> list[Issue]:
        return [w for p in self.participants for w in p.warnings]


# ----------------------------------------------------------------------------- field parsers


def parse_int(value: str, lo: int | None = None, hi: int | None = None) -> int:
    if not INT_RE.match(value):
        raise ValueError(f"{value!r} is not an integer")
    number = int(value)
    if lo is not None and number < lo or hi is not None and number > hi:
        lo_s = "" if lo is None else str(lo)
        hi_s = "" if hi is None else str(hi)
        raise ValueError(f"{number} outside {lo_s}..{hi_s}")
    return number


def parse_float(value: str, nonnegative: bool = False) -> float:
    if not FLOAT_RE.match(value):
        raise ValueError(f"{value!r} is not a decimal number")
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(f"{value!r} is not finite")
    if nonnegative and number < 0:
        raise ValueError(f"{number} is negative")
    return number


def parse_condition(value: str) -> str:
    if value not in CONDITIONS:
        raise ValueError(f"unknown condition {value!r} (expected one of {', '.join(CONDITIONS)})")
    return value


def parse_timestamp(value: str) -> str:
    if not TIMESTAMP_RE.match(value):
        raise ValueError(f"{value!r} is not an RFC 3339 timestamp like 2025-05-01T10:31:07.123Z")
    try:
        datetime.fromisoformat(value.replace("Z", "+00:00"))
    except ValueError as exc:
        raise ValueError(f"{value!r} is not a valid date/time ({exc})") from None
    return value


def parse_id(value: str) -> str:
    if not ID_RE.match(value):
        raise ValueError(f"{value!r} is not a valid participant id ([A-Za-z0-9][A-Za-z0-9_-]*)")
    return value


def parse_level(value: str) -> str:
    if not LEVEL_RE.match(value):
        raise ValueError(f"{value!r} is not a valid level id ([A-Za-z0-9][A-Za-z0-9_.-]*)")
    return value


def parse_rating(value: str) -> int:
    return parse_int(value, RATING_MIN, RATING_MAX)


RATINGS_PARSERS = {
    "participant_id": parse_id,
    "condition": parse_condition,
    "order_index": lambda v: parse_int(v, 0, len(CONDITIONS) - 1),
    **{c: parse_rating for c in CRITERIA},
    "timestamp": parse_timestamp,
}
TRIALS_PARSERS = {
    "participant_id": parse_id,
    "condition": parse_condition,
    "level": parse_level,
    "trial_index": lambda v: parse_int(v, 0),
    "time_to_goal_s": lambda v: parse_float(v, True),
    "completed": lambda v: parse_int(v, 0, 1),
    "wall_collisions": lambda v: parse_int(v, 0),
    "contact_time_s": lambda v: parse_float(v, True),
    "path_length_px": lambda v: parse_float(v, True),
    "mean_force_n": lambda v: parse_float(v, True),
    "max_force_n": lambda v: parse_float(v, True),
    "telemetry_file": lambda v: v,  # checked against condition/trial_index afterwards
    "timestamp": parse_timestamp,
}
TELEMETRY_PARSERS = {
    **{c: parse_float for c in TELEMETRY_COLUMNS if c != "in_contact"},
    "in_contact": lambda v: parse_int(v, 0, 1),
}


# ----------------------------------------------------------------------------- file readers


def _read_lines(path: Path, rel: str, errors: list[Issue]) -> list[str] | None:
    """The file's complete records (header first), or None when nothing usable is there.

    A last line without its terminating newline is a truncated record: reported, dropped.
    """
    try:
        raw = path.read_bytes()
    except OSError as exc:
        errors.append(Issue(rel, None, f"cannot read file ({exc.strerror})"))
        return None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        errors.append(Issue(rel, line, f"not valid UTF-8 (byte {exc.start})"))
        return None
    if text.startswith("\ufeff"):
        errors.append(Issue(rel, 1, "starts with a byte-order mark (UTF-8 without BOM expected)"))
        text = text[1:]
    if text == "":
        errors.append(Issue(rel, 1, "empty file (the header row is missing)"))
        return None
    lines = text.split("\n")
    last = lines.pop()  # "" when the file ends with '\n'
    if last != "":
        shown = last if len(last) <= 60 else last[:57] + "..."
        errors.append(
            Issue(rel, len(lines) + 1, f"truncated record: last line has no terminating newline ({shown!r})")
        )
    # A '\r' before the '\n' (CRLF) is tolerated.
    return [line[:-1] if line.endswith("\r") else line for line in lines]


def read_table(
    path: Path,
    rel: str,
    columns: tuple[str, ...],
    parsers: dict,
    errors: list[Issue],
    fast_row_re: re.Pattern | None = None,
) -> list[tuple[int, dict]] | None:
    """Rows as (line number, {column: parsed value}); None if the header is unusable."""
    lines = _read_lines(path, rel, errors)
    if lines is None:
        return None
    if not lines:
        errors.append(Issue(rel, 1, "the header row is missing (file holds only a truncated line)"))
        return None
    header = lines[0].split(",")
    if tuple(header) != columns:
        missing = [c for c in columns if c not in header]
        extra = [c for c in header if c not in columns]
        detail = []
        if missing:
            detail.append("missing " + ", ".join(missing))
        if extra:
            detail.append("unexpected " + ", ".join(repr(c) for c in extra))
        if not detail:
            detail.append("columns out of order")
        errors.append(
            Issue(rel, 1, f"bad header ({'; '.join(detail)}): expected {','.join(columns)!r}, found {lines[0]!r}")
        )
        return None
    rows: list[tuple[int, dict]] = []
    ncol = len(columns)
    for lineno, line in enumerate(lines[1:], start=2):
        if fast_row_re is not None and fast_row_re.match(line):
            fields = line.split(",")
            rows.append((lineno, {c: parsers[c](v) for c, v in zip(columns, fields)}))
            continue
        if line == "":
            errors.append(Issue(rel, lineno, "empty line"))
            continue
        fields = line.split(",")
        if len(fields) != ncol:
            errors.append(Issue(rel, lineno, f"expected {ncol} columns, found {len(fields)}"))
            continue
        row, ok = {}, True
        for name, value in zip(columns, fields):
            try:
                row[name] = parsers[name](value)
            except ValueError as exc:
                errors.append(Issue(rel, lineno, f"column '{name}': {exc}"))
                ok = False
        if ok:
            rows.append((lineno, row))
    return rows


def read_json(path: Path, rel: str, errors: list[Issue]) -> dict | None:
    try:
        raw = path.read_bytes()
    except OSError as exc:
        errors.append(Issue(rel, None, f"cannot read file ({exc.strerror})"))
        return None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        errors.append(Issue(rel, raw[: exc.start].count(b"\n") + 1, f"not valid UTF-8 (byte {exc.start})"))
        return None
    try:
        data = json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as exc:
        errors.append(Issue(rel, exc.lineno, f"invalid JSON: {exc.msg} (column {exc.colno})"))
        return None
    except ValueError as exc:
        errors.append(Issue(rel, None, f"invalid JSON: {exc}"))
        return None
    if not isinstance(data, dict):
        errors.append(Issue(rel, 1, f"expected a JSON object, found {type(data).__name__}"))
        return None
    return data


def _reject_constant(name: str):
    raise ValueError(f"{name} is not allowed")


# ----------------------------------------------------------------------------- per file checks


def _json_line(path: Path, key: str) -> int | None:
    """Best-effort line of `"key"` in a JSON file, for messages."""
    try:
        for i, line in enumerate(path.read_text("utf-8").split("\n"), start=1):
            if f'"{key}"' in line:
                return i
    except (OSError, UnicodeDecodeError):
        pass
    return None


def _check_participant_json(p: Participant) -> None:
    path = p.folder / PARTICIPANT_FILE
    rel = f"{p.id}/{PARTICIPANT_FILE}"
    if not path.is_file():
        p.errors.append(Issue(rel, None, "missing (every participant folder needs participant.json)"))
        return
    data = read_json(path, rel, p.errors)
    if data is None:
        return

    def bad(key: str, message: str) -> None:
        p.errors.append(Issue(rel, _json_line(path, key), f"'{key}': {message}"))

    def need(key: str, kind, kind_name: str) -> bool:
        if key not in data:
            p.errors.append(Issue(rel, None, f"missing key '{key}'"))
            return False
        value = data[key]
        if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
            bad(key, f"expected {kind_name}, found {json.dumps(value)}")
            return False
        return True

    if need("format_version", int, "an integer") and data["format_version"] != FORMAT_VERSION:
        bad("format_version", f"unsupported version {data['format_version']} (this tool reads {FORMAT_VERSION})")
    if need("participant_id", str, "a string") and data["participant_id"] != p.id:
        bad("participant_id", f"{data['participant_id']!r} does not match the folder name {p.id!r}")
    if need("demographics", dict, "an object"):
        demo = data["demographics"]
        for key, allowed in DEMOGRAPHICS.items():
            if key not in demo:
                p.errors.append(Issue(rel, _json_line(path, "demographics"), f"'demographics': missing key '{key}'"))
            elif demo[key] not in allowed:
                bad(key, f"{json.dumps(demo[key])} is not one of {', '.join(allowed)}")
    need("seed", int, "an integer")
    if need("condition_order", list, "a list"):
        order = data["condition_order"]
        if sorted(map(str, order)) != sorted(CONDITIONS) or not all(isinstance(c, str) for c in order):
            bad("condition_order", f"{json.dumps(order)} is not an ordering of {', '.join(CONDITIONS)}")
    if need("counterbalancing", str, "a string") and data["counterbalancing"] not in COUNTERBALANCING:
        bad("counterbalancing", f"{data['counterbalancing']!r} is not one of {', '.join(COUNTERBALANCING)}")
    need("app_version", str, "a string")
    need("extension_version", str, "a string")
    for key, nullable in (("started", False), ("finished", True)):
        if key not in data:
            p.errors.append(Issue(rel, None, f"missing key '{key}'"))
        elif data[key] is None and nullable:
            pass
        elif not isinstance(data[key], str):
            bad(key, f"expected a timestamp string{' or null' if nullable else ''}, found {json.dumps(data[key])}")
        else:
            try:
                parse_timestamp(data[key])
            except ValueError as exc:
                bad(key, str(exc))
    p.meta = data


def _check_ratings(p: Participant) -> None:
    path = p.folder / RATINGS_FILE
    rel = f"{p.id}/{RATINGS_FILE}"
    if not path.is_file():
        return  # nothing rated yet: an incomplete participant, not a corrupt one
    rows = read_table(path, rel, RATINGS_COLUMNS, RATINGS_PARSERS, p.errors)
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


def _check_trials(p: Participant) -> set[str]:
    """Validates trials.csv and the telemetry files it references; returns those names."""
    path = p.folder / TRIALS_FILE
    rel = f"{p.id}/{TRIALS_FILE}"
    referenced: set[str] = set()
    if not path.is_file():
        return referenced
    rows = read_table(path, rel, TRIALS_COLUMNS, TRIALS_PARSERS, p.errors)
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
            expected = f"{TELEMETRY_DIR}/{row['condition']}_{row['trial_index']}.csv"
            if tel != expected:
                p.errors.append(Issue(rel, lineno, f"column 'telemetry_file': {tel!r} (expected {expected!r} or empty)"))
                continue
            referenced.add(tel)
            tel_path = p.folder / tel
            tel_rel = f"{p.id}/{tel}"
            if not tel_path.is_file():
                p.errors.append(Issue(rel, lineno, f"telemetry file {tel!r} does not exist"))
                continue
            if not _check_telemetry(p, tel_path, tel_rel):
                continue
        if row["contact_time_s"] > row["time_to_goal_s"] + 1e-6:
            p.warnings.append(Issue(rel, lineno, "contact_time_s exceeds time_to_goal_s"))
        if row["max_force_n"] + 1e-9 < row["mean_force_n"]:
            p.warnings.append(Issue(rel, lineno, "max_force_n is below mean_force_n"))
        p.trials.append(row)
    return referenced


def _check_telemetry(p: Participant, path: Path, rel: str) -> bool:
    before = len(p.errors)
    rows = read_table(path, rel, TELEMETRY_COLUMNS, TELEMETRY_PARSERS, p.errors, TELEMETRY_ROW_RE)
    if rows is None:
        return False
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
    return len(p.errors) == before


def _check_final(p: Participant) -> None:
    path = p.folder / FINAL_FILE
    rel = f"{p.id}/{FINAL_FILE}"
    if not path.is_file():
        return  # not reached the end (yet)
    data = read_json(path, rel, p.errors)
    if data is None:
        return
    ok = True
    for key in ("participant_id", "favourite", "differences_text", "timestamp"):
        if key not in data:
            p.errors.append(Issue(rel, None, f"missing key '{key}'"))
            ok = False
    if not ok:
        return
    if data["participant_id"] != p.id:
        p.errors.append(Issue(rel, _json_line(path, "participant_id"),
                              f"'participant_id': {data['participant_id']!r} does not match the folder name {p.id!r}"))
        ok = False
    fav = data["favourite"]
    if not isinstance(fav, list):
        p.errors.append(Issue(rel, _json_line(path, "favourite"), f"'favourite': expected a list, found {json.dumps(fav)}"))
        ok = False
    else:
        for c in fav:
            if c not in CONDITIONS:
                p.errors.append(Issue(rel, _json_line(path, "favourite"),
                                      f"'favourite': unknown condition {json.dumps(c)} (expected one of {', '.join(CONDITIONS)})"))
                ok = False
        if ok and len(set(fav)) != len(fav):
            p.errors.append(Issue(rel, _json_line(path, "favourite"), f"'favourite': duplicate entries in {json.dumps(fav)}"))
            ok = False
    if not isinstance(data["differences_text"], str):
        p.errors.append(Issue(rel, _json_line(path, "differences_text"), "'differences_text': expected a string"))
        ok = False
    try:
        if not isinstance(data["timestamp"], str):
            raise ValueError(f"expected a timestamp string, found {json.dumps(data['timestamp'])}")
        parse_timestamp(data["timestamp"])
    except ValueError as exc:
        p.errors.append(Issue(rel, _json_line(path, "timestamp"), f"'timestamp': {exc}"))
        ok = False
    if ok:
        p.final = data


def load_participant(folder: Path) -> Participant:
    p = Participant(id=folder.name, folder=folder)
    if not ID_RE.match(p.id):
        p.errors.append(Issue(p.id, None, "folder name is not a valid participant id ([A-Za-z0-9][A-Za-z0-9_-]*)"))
        return p
    _check_participant_json(p)
    _check_ratings(p)
    referenced = _check_trials(p)
    _check_final(p)
    known = {PARTICIPANT_FILE, RATINGS_FILE, TRIALS_FILE, FINAL_FILE, TELEMETRY_DIR}
    for entry in sorted(folder.iterdir()):
        if entry.name not in known and not entry.name.startswith("."):
            p.warnings.append(Issue(f"{p.id}/{entry.name}", None, "unexpected file, ignored"))
    tel_dir = folder / TELEMETRY_DIR
    if tel_dir.is_dir():
        for entry in sorted(tel_dir.iterdir()):
            name = f"{TELEMETRY_DIR}/{entry.name}"
            if name not in referenced:
                p.warnings.append(
                    Issue(f"{p.id}/{name}", None,
                          "not referenced by trials.csv (an interrupted trial?): not validated, not analysed")
                )
    return p


def load_study(folder: Path, skip_dirs: tuple[Path, ...] = ()) -> Study:
    folder = Path(folder)
    study = Study(folder=folder, participants=[])
    if not folder.is_dir():
        study.errors.append(Issue(str(folder), None, "study folder does not exist"))
        return study
    skip = {d.resolve() for d in skip_dirs}
    for entry in sorted(folder.iterdir()):
        if not entry.is_dir() or entry.name.startswith((".", "_")) or entry.name in RESERVED_DIR_NAMES:
            continue
        if entry.resolve() in skip:
            continue
        study.participants.append(load_participant(entry))
    if not study.participants:
        study.errors.append(Issue(str(folder), None, "no participant folders found"))
    return study
