"""The study schema (assets/study/study_schema.json) as the analysis reads it, and that the
game reads the same file."""

from __future__ import annotations

import re
import tomllib

import pytest

import fields
import schema
import studywriter as w


def test_the_ratings_have_a_column_per_criterion():
    cols = schema.columns("ratings")
    assert schema.RATINGS_COLUMNS == ("participant_id", "condition", "order_index", *schema.CRITERIA, "timestamp")
    assert [c["type"] for c in cols[3:-1]] == ["rating"] * len(schema.CRITERIA)
    assert schema.CRITERION_WORDING["realism"] == "how realistic is the control scheme"  # Table I
    assert schema.telemetry_name("constraint", 2) == "telemetry/constraint_2.csv"
    assert schema.TELEMETRY_DIR == "telemetry"


@pytest.mark.parametrize("table", ["ratings", "trials", "telemetry"])
def test_every_column_has_a_parser(table):
    assert set(fields.parsers_of(table)) == {c["name"] for c in schema.columns(table)}


def test_columns_are_parsed_with_their_ranges():
    ratings = fields.parsers_of("ratings")
    trials = fields.parsers_of("trials")
    assert ratings["partiality"]("10") == 10
    with pytest.raises(ValueError, match="11 outside 1..10"):
        ratings["partiality"]("11")
    with pytest.raises(ValueError, match="3 outside 0..2"):
        ratings["order_index"]("3")
    assert trials["time_to_goal_s"]("1.5e-3") == pytest.approx(0.0015)
    with pytest.raises(ValueError, match="is below 0"):
        trials["contact_time_s"]("-1")
    assert trials["telemetry_file"]("") == ""
    assert trials["contact_model"]("paper_sum") == "paper_sum"
    assert trials["contact_model"]("") == ""  # position control
    with pytest.raises(ValueError, match="unknown contact model 'sum'"):
        trials["contact_model"]("sum")


def test_the_fast_telemetry_pattern_matches_valid_rows_only():
    pattern = fields.fast_row_re("telemetry")
    row = ",".join(str(v) for v in w.telemetry_rows()[7])
    assert pattern.match(row)
    assert not pattern.match(row[:-1] + "2")  # in_contact is 0 or 1
    assert fields.fast_row_re("trials") is None  # bounded numbers, ids, timestamps


def test_the_contact_models_are_the_servers_names():
    # The names are defined once, in the movement renderer's schema (the C++ enum and its
    # names are generated from it); the study schema lists them for the data.
    project = schema.SCHEMA_PATH.parents[2]
    renderer_schema = project / "gdextension" / "src" / "renderers" / "movement" / "movement.schema.toml"
    names = tomllib.loads(renderer_schema.read_text("utf-8"))["enums"]["ContactModel"]["values"]
    assert tuple(names) == schema.CONTACT_MODELS


def test_the_game_reads_the_same_schema():
    project = schema.SCHEMA_PATH.parents[2]
    gd = (project / "game" / "study" / "data" / "study_format.gd").read_text("utf-8")
    path = re.search(r'const SCHEMA_PATH: String = "res://([^"]+)"', gd).group(1)
    assert project / path == schema.SCHEMA_PATH
