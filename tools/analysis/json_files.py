"""The JSON files of a participant folder: participant.json and final.json (FORMAT.md).

Each check reads its file strictly and records what it finds on the participant: the parsed
content when valid, otherwise errors.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING

from fields import parse_timestamp
from schema import CONDITIONS, COUNTERBALANCING, DEMOGRAPHICS, FINAL_FILE, FORMAT_VERSION, PARTICIPANT_FILE
from tables import Issue, json_line, read_json

if TYPE_CHECKING:
    from studydata import Participant


def check_participant_json(p: Participant) -> None:
    path = p.folder / PARTICIPANT_FILE
    rel = f"{p.id}/{PARTICIPANT_FILE}"
    if not path.is_file():
        p.errors.append(Issue(rel, None, "missing (every participant folder needs participant.json)"))
        return
    data = read_json(path, rel, p.errors)
    if data is None:
        return

    def bad(key: str, message: str) -> None:
        p.errors.append(Issue(rel, json_line(path, key), f"'{key}': {message}"))

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
                p.errors.append(Issue(rel, json_line(path, "demographics"), f"'demographics': missing key '{key}'"))
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


def check_final(p: Participant) -> None:
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
        p.errors.append(Issue(rel, json_line(path, "participant_id"),
                              f"'participant_id': {data['participant_id']!r} does not match the folder name {p.id!r}"))
        ok = False
    fav = data["favourite"]
    if not isinstance(fav, list):
        p.errors.append(Issue(rel, json_line(path, "favourite"), f"'favourite': expected a list, found {json.dumps(fav)}"))
        ok = False
    else:
        for c in fav:
            if c not in CONDITIONS:
                p.errors.append(Issue(rel, json_line(path, "favourite"),
                                      f"'favourite': unknown condition {json.dumps(c)} (expected one of {', '.join(CONDITIONS)})"))
                ok = False
        if ok and len(set(fav)) != len(fav):
            p.errors.append(Issue(rel, json_line(path, "favourite"), f"'favourite': duplicate entries in {json.dumps(fav)}"))
            ok = False
    if not isinstance(data["differences_text"], str):
        p.errors.append(Issue(rel, json_line(path, "differences_text"), "'differences_text': expected a string"))
        ok = False
    try:
        if not isinstance(data["timestamp"], str):
            raise ValueError(f"expected a timestamp string, found {json.dumps(data['timestamp'])}")
        parse_timestamp(data["timestamp"])
    except ValueError as exc:
        p.errors.append(Issue(rel, json_line(path, "timestamp"), f"'timestamp': {exc}"))
        ok = False
    if ok:
        p.final = data
