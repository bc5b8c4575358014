"""Reading the study's files strictly: CSV tables (header, complete records, fields parsed
by column) and JSON objects. Every problem is collected as an `Issue` naming the file
(relative to the study folder), the line (1-based, the header is line 1; JSON errors carry
the parser's line) and what is wrong.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from fields import fast_row_re, parsers_of
from schema import columns as schema_columns


@dataclass
class Issue:
    path: str
    line: int | None
    message: str

    def __str__(self) -> str:
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        return f"{where}: {self.message}"


def read_lines(path: Path, rel: str, errors: list[Issue]) -> list[str] | None:
    """The file's complete records (header first), or None when nothing usable is there.

    A last line without its terminating newline is a truncated record: reported, dropped.
    """
    text = _read_text(path, rel, errors)
    if text is None:
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


def read_table(path: Path, rel: str, table: str, errors: list[Issue]) -> list[tuple[int, dict]] | None:
    """The records of a file of the schema's CSV table `table` as (line number, {column:
    parsed value}); None if the header is unusable. Invalid records are reported, left out."""
    columns = tuple(c["name"] for c in schema_columns(table))
    parsers = parsers_of(table)
    fast_re = fast_row_re(table)
    lines = read_lines(path, rel, errors)
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
        if fast_re is not None and fast_re.match(line):
            try:
                rows.append((lineno, {c: parsers[c](v) for c, v in zip(columns, line.split(","))}))
                continue
            except ValueError:
                pass  # e.g. 1e999: diagnosed below
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
    """The JSON object in the file, or None (reported) when it is not one."""
    text = _read_text(path, rel, errors)
    if text is None:
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


def _read_text(path: Path, rel: str, errors: list[Issue]) -> str | None:
    """The file's text, or None (reported) when it cannot be read or is not UTF-8."""
    try:
        raw = path.read_bytes()
    except OSError as exc:
        errors.append(Issue(rel, None, f"cannot read file ({exc.strerror})"))
        return None
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        errors.append(Issue(rel, line, f"not valid UTF-8 (byte {exc.start})"))
        return None


def _reject_constant(name: str):
    raise ValueError(f"{name} is not allowed")


def json_line(path: Path, key: str) -> int | None:
    """Best-effort line of `"key"` in a JSON file, for messages."""
    try:
        for i, line in enumerate(path.read_text("utf-8").split("\n"), start=1):
            if f'"{key}"' in line:
                return i
    except (OSError, UnicodeDecodeError):
        pass
    return None
