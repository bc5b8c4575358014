"""Parsers of single CSV fields, and of whole records by their schema columns.

Each parser returns the parsed value or raises ValueError with what is wrong; the caller
adds the file, line and column.
"""

from __future__ import annotations

import math
import re
from datetime import datetime

from schema import CONDITIONS, CONTACT_MODELS, PATTERNS, RATING_MAX, RATING_MIN, columns

ID_RE = re.compile(PATTERNS["id"])
LEVEL_RE = re.compile(PATTERNS["level"])
INT_RE = re.compile(PATTERNS["integer"])
FLOAT_RE = re.compile(PATTERNS["number"])
TIMESTAMP_RE = re.compile(PATTERNS["timestamp"])


def parse_int(value: str, lo: int | None = None, hi: int | None = None) -> int:
    if not INT_RE.match(value):
        raise ValueError(f"{value!r} is not an integer")
    number = int(value)
    if lo is not None and number < lo or hi is not None and number > hi:
        lo_s = "" if lo is None else str(lo)
        hi_s = "" if hi is None else str(hi)
        raise ValueError(f"{number} outside {lo_s}..{hi_s}")
    return number


def parse_float(value: str, lo: float | None = None) -> float:
    if not FLOAT_RE.match(value):
        raise ValueError(f"{value!r} is not a decimal number")
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(f"{value!r} is not finite")
    if lo is not None and number < lo:
        raise ValueError(f"{number} is below {lo}")
    return number


def parse_condition(value: str) -> str:
    if value not in CONDITIONS:
        raise ValueError(f"unknown condition {value!r} (expected one of {', '.join(CONDITIONS)})")
    return value


def parse_contact_model(value: str) -> str:
    if value != "" and value not in CONTACT_MODELS:
        raise ValueError(f"unknown contact model {value!r} (expected empty or one of {', '.join(CONTACT_MODELS)})")
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
        raise ValueError(f"{value!r} is not a valid participant id ({PATTERNS['id'][1:-1]})")
    return value


def parse_level(value: str) -> str:
    if not LEVEL_RE.match(value):
        raise ValueError(f"{value!r} is not a valid level id ({PATTERNS['level'][1:-1]})")
    return value


def parser_for(column: dict):
    """The parser of one schema column."""
    kind = column["type"]
    if kind == "integer":
        return lambda v: parse_int(v, column.get("min"), column.get("max"))
    if kind == "number":
        return lambda v: parse_float(v, column.get("min"))
    if kind == "rating":
        return lambda v: parse_int(v, RATING_MIN, RATING_MAX)
    if kind == "telemetry_file":
        return lambda v: v  # checked against the record's condition and trial_index
    return {"id": parse_id, "level": parse_level, "condition": parse_condition, "contact_model": parse_contact_model,
            "timestamp": parse_timestamp}[kind]


def parsers_of(table: str) -> dict:
    """Column name -> parser for the CSV table `table` of the schema."""
    return {c["name"]: parser_for(c) for c in columns(table)}


def fast_row_re(table: str) -> re.Pattern | None:
    """One regular expression matching a record of `table` whose every field is valid, for
    tables of plain numbers and 0/1 flags (telemetry: thousands of rows per trial); None when
    the table has other columns. A row it does not match is diagnosed field by field."""
    number = "(?:" + PATTERNS["number"][1:-1] + ")"
    parts = []
    for c in columns(table):
        if c["type"] == "number" and "min" not in c and "max" not in c:
            parts.append(number)
        elif c["type"] == "integer" and (c.get("min"), c.get("max")) == (0, 1):
            parts.append("[01]")
        else:
            return None
    return re.compile("^" + ",".join(parts) + "$")
