"""(e) export_csv.py: one row per participant x condition, the documented columns."""

from __future__ import annotations

import csv

import pytest

import studywriter as w
from conftest import run_tool

EXPECTED_COLUMNS = [
    "participant_id", "age_band", "gender", "handedness", "hand_used", "gaming_experience", "seed",
    "counterbalancing", "condition_order", "app_version", "extension_version", "started", "finished",
    "complete", "condition", "order_index", "realism", "ease", "aptness", "intuitiveness", "enthusiasm",
    "partiality", "total", "rating_timestamp", "favourite_vote", "trials", "trials_completed",
    "contact_model", "time_to_goal_s_mean", "wall_collisions_mean", "contact_time_s_mean", "path_length_px_mean",
    "mean_force_n_mean", "max_force_n_mean",
]


def read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh)), path.read_text("utf-8").split("\n")[0].split(",")


def test_export_rows_and_columns(tmp_path):
    study = tmp_path / "study"
    w.make_participant(
        study, "A", {"none": [1, 2, 3, 4, 5, 6], "movement": 7, "constraint": 10},
        favourite=["movement", "constraint"], condition_order=("movement", "none", "constraint"),
        trials={"movement": [dict(time_to_goal_s=20.0, wall_collisions=2),
                             dict(time_to_goal_s=40.0, wall_collisions=5),
                             dict(time_to_goal_s=99.0, completed=0, wall_collisions=11)]},
        demographics={**w.DEFAULT_DEMOGRAPHICS, "gender": "female"}, seed=42,
    )
    # B: rated "none" only and has an unrated "movement" trial (session interrupted).
    folder = w.make_participant(study, "B", {"none": 3})
    w.append_trial(folder, "B", "movement", 0, time_to_goal_s=12.5, contact_model="per_contact")
    out = tmp_path / "export" / "all.csv"
    proc = run_tool("export_csv.py", study, out)
    assert proc.returncode == 0, proc.stderr
    assert "5 row(s) from 2 participant(s)" in proc.stdout
    rows, header = read(out)
    assert header == EXPECTED_COLUMNS
    assert [(r["participant_id"], r["condition"]) for r in rows] == [
        ("A", "none"), ("A", "movement"), ("A", "constraint"), ("B", "none"), ("B", "movement")]
    a_none, a_mov, a_con, b_none, b_mov = rows
    assert a_none["total"] == "3.5" and a_none["realism"] == "1" and a_none["partiality"] == "6"
    assert a_none["order_index"] == "1" and a_mov["order_index"] == "0"
    assert a_none["condition_order"] == "movement;none;constraint"
    assert a_none["gender"] == "female" and a_none["seed"] == "42" and a_none["complete"] == "1"
    assert (a_none["favourite_vote"], a_mov["favourite_vote"], a_con["favourite_vote"]) == ("0.0", "0.5", "0.5")
    assert a_mov["trials"] == "3" and a_mov["trials_completed"] == "2"
    assert float(a_mov["time_to_goal_s_mean"]) == pytest.approx(30.0)  # completed trials only
    assert float(a_mov["wall_collisions_mean"]) == pytest.approx(6.0)  # all three
    assert a_con["total"] == "10.0"
    assert (a_none["contact_model"], a_mov["contact_model"], a_con["contact_model"]) == ("paper_sum", "paper_sum", "")
    assert b_mov["contact_model"] == "per_contact" and b_none["contact_model"] == "paper_sum"
    assert b_none["complete"] == "0" and b_none["favourite_vote"] == "" and b_none["finished"] == ""
    assert b_mov["realism"] == "" and b_mov["total"] == "" and b_mov["trials"] == "1"
    assert float(b_mov["time_to_goal_s_mean"]) == pytest.approx(12.5)


def test_export_header_only_when_nothing_rated(tmp_path):
    w.write_participant_json(tmp_path / "s", "C")
    proc = run_tool("export_csv.py", tmp_path / "s", tmp_path / "c.csv")
    assert proc.returncode == 0, proc.stderr
    rows, header = read(tmp_path / "c.csv")
    assert rows == [] and header == EXPECTED_COLUMNS
