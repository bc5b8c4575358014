"""(c) Every kind of corrupt or truncated file is reported with file and line, and fails the run;
--skip-invalid excludes the participant and lists it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import analyze
import schema
import studydata
import studywriter as w
from conftest import run_tool

C = ("none", "movement", "constraint")


def make_study(root: Path) -> Path:
    """Three valid participants; P02 (the one the cases damage) has telemetry."""
    for pid in ("P01", "P02", "P03"):
        w.make_participant(root, pid, {c: [5, 6, 7, 8, 9, 10] for c in C}, favourite=["movement"],
                           telemetry=pid == "P02")
    return root


def edit_line(path: Path, lineno: int, fn) -> None:
    lines = path.read_text("utf-8").split("\n")
    lines[lineno - 1] = fn(lines[lineno - 1])
    path.write_text("\n".join(lines), "utf-8")


def set_field(path: Path, lineno: int, column: str, value: str) -> None:
    header = path.read_text("utf-8").split("\n")[0].split(",")
    i = header.index(column)

    def fn(line):
        fields = line.split(",")
        fields[i] = value
        return ",".join(fields)

    edit_line(path, lineno, fn)


def append_raw(path: Path, text: str) -> None:
    with open(path, "a", encoding="utf-8", newline="") as fh:
        fh.write(text)


def append_bytes(path: Path, data: bytes) -> None:
    with open(path, "ab") as fh:
        fh.write(data)


# (id, mutation of the P02 folder, expected "file:line" prefix, expected fragment)
CASES = [
    ("bad_header", lambda d: edit_line(d / "ratings.csv", 1, lambda s: s.replace("realism", "realsim")),
     "P02/ratings.csv:1:", "bad header"),
    ("bad_header_order", lambda d: edit_line(d / "trials.csv", 1, lambda s: s.replace("level,trial_index", "trial_index,level")),
     "P02/trials.csv:1:", "columns out of order"),
    ("wrong_column_count", lambda d: edit_line(d / "ratings.csv", 3, lambda s: s + ",7"),
     "P02/ratings.csv:3:", "expected 10 columns, found 11"),
    ("too_few_columns", lambda d: edit_line(d / "trials.csv", 2, lambda s: s.rsplit(",", 1)[0]),
     "P02/trials.csv:2:", "expected 14 columns, found 13"),
    ("non_numeric_rating", lambda d: set_field(d / "ratings.csv", 2, "ease", "x"),
     "P02/ratings.csv:2:", "column 'ease': 'x' is not an integer"),
    ("non_numeric_trial", lambda d: set_field(d / "trials.csv", 3, "time_to_goal_s", "12s"),
     "P02/trials.csv:3:", "column 'time_to_goal_s': '12s' is not a decimal number"),
    ("nan_in_trial", lambda d: set_field(d / "trials.csv", 2, "mean_force_n", "nan"),
     "P02/trials.csv:2:", "column 'mean_force_n'"),
    ("rating_above_10", lambda d: set_field(d / "ratings.csv", 4, "partiality", "11"),
     "P02/ratings.csv:4:", "column 'partiality': 11 outside 1..10"),
    ("rating_zero", lambda d: set_field(d / "ratings.csv", 2, "realism", "0"),
     "P02/ratings.csv:2:", "column 'realism': 0 outside 1..10"),
    ("rating_not_integer", lambda d: set_field(d / "ratings.csv", 2, "realism", "7.5"),
     "P02/ratings.csv:2:", "'7.5' is not an integer"),
    ("unknown_condition", lambda d: set_field(d / "ratings.csv", 3, "condition", "haptic"),
     "P02/ratings.csv:3:", "unknown condition 'haptic'"),
    ("unknown_contact_model", lambda d: set_field(d / "trials.csv", 3, "contact_model", "sum"),
     "P02/trials.csv:3:", "column 'contact_model': unknown contact model 'sum'"),
    ("old_format_version", lambda d: (d / "participant.json").write_text(
        (d / "participant.json").read_text().replace('"format_version": 2', '"format_version": 1')),
     "P02/participant.json:", "unsupported version 1 (this tool reads 2)"),
    ("unknown_condition_trial", lambda d: set_field(d / "trials.csv", 2, "condition", "None"),
     "P02/trials.csv:2:", "unknown condition 'None'"),
    ("duplicate_condition", lambda d: append_raw(d / "ratings.csv", "P02,none,0,1,1,1,1,1,1,2025-05-01T10:09:00Z\n"),
     "P02/ratings.csv:5:", "duplicate condition 'none' (already rated on line 2)"),
    ("duplicate_trial", lambda d: append_raw(d / "trials.csv", (d / "trials.csv").read_text().split("\n")[1].replace("telemetry/none_0.csv", "") + "\n"),
     "P02/trials.csv:5:", "duplicate trial 'none' #0 (already on line 2)"),
    ("truncated_ratings", lambda d: append_raw(d / "ratings.csv", "P02,none,0,5,5"),
     "P02/ratings.csv:5:", "truncated record"),
    ("truncated_trials", lambda d: (d / "trials.csv").write_bytes((d / "trials.csv").read_bytes()[:-1]),
     "P02/trials.csv:4:", "truncated record"),
    ("truncated_telemetry", lambda d: (d / "telemetry/movement_0.csv").write_bytes((d / "telemetry/movement_0.csv").read_bytes()[:-9]),
     "P02/telemetry/movement_0.csv:101:", "truncated record"),
    ("telemetry_time_backwards", lambda d: set_field(d / "telemetry/none_0.csv", 50, "time_s", "0.001"),
     "P02/telemetry/none_0.csv:50:", "time_s decreases (0.001 after 0.047)"),
    ("telemetry_missing", lambda d: (d / "telemetry/constraint_0.csv").unlink(),
     "P02/trials.csv:4:", "telemetry file 'telemetry/constraint_0.csv' does not exist"),
    ("invalid_json_participant", lambda d: (d / "participant.json").write_text((d / "participant.json").read_text()[:80]),
     "P02/participant.json:", "invalid JSON"),
    ("invalid_json_final", lambda d: (d / "final.json").write_text('{\n  "favourite": ["movement",]\n}\n'),
     "P02/final.json:2:", "invalid JSON"),
    ("unknown_favourite", lambda d: (d / "final.json").write_text(json.dumps(
        {"participant_id": "P02", "favourite": ["haptic"], "differences_text": "", "timestamp": w.TIMESTAMP}, indent=1)),
     "P02/final.json:3:", "unknown condition \"haptic\""),
    ("missing_participant_json", lambda d: (d / "participant.json").unlink(),
     "P02/participant.json:", "missing"),
    ("id_mismatch", lambda d: set_field(d / "ratings.csv", 3, "participant_id", "P03"),
     "P02/ratings.csv:3:", "participant_id 'P03' is not 'P02'"),
    ("order_index_mismatch", lambda d: set_field(d / "ratings.csv", 3, "order_index", "2"),
     "P02/ratings.csv:3:", "order_index 2 is 'constraint'"),
    ("bad_timestamp", lambda d: set_field(d / "ratings.csv", 2, "timestamp", "2025-05-01 10:00:00"),
     "P02/ratings.csv:2:", "not an RFC 3339 timestamp"),
    ("empty_file", lambda d: (d / "ratings.csv").write_bytes(b""),
     "P02/ratings.csv:1:", "empty file"),
    ("empty_line", lambda d: append_raw(d / "ratings.csv", "\n"),
     "P02/ratings.csv:5:", "empty line"),
    ("not_utf8", lambda d: append_bytes(d / "trials.csv", b"P02,none,maze\xff,1\n"),
     "P02/trials.csv:5:", "not valid UTF-8"),
    ("bad_demographic", lambda d: (d / "participant.json").write_text(
        (d / "participant.json").read_text().replace('"gaming_experience": "some"', '"gaming_experience": "lots"')),
     "P02/participant.json:", "'gaming_experience': \"lots\" is not one of"),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_corruption_is_reported_and_fails(tmp_path, case):
    _id, mutate, where, fragment = case
    study = make_study(tmp_path / "study")
    mutate(study / "P02")
    out = tmp_path / "out"
    proc = run_tool("analyze.py", study, "--out", out)
    assert proc.returncode == 1, proc.stderr
    errors = [line for line in proc.stderr.splitlines() if "error:" in line]
    assert any(where in line and fragment in line for line in errors), proc.stderr
    assert all("P02/" in line for line in errors), proc.stderr  # only P02 is blamed
    assert "--skip-invalid" in proc.stderr
    assert not out.exists(), "nothing may be written when the data is invalid"
    # The export refuses the same data.
    proc = run_tool("export_csv.py", study, tmp_path / "all.csv")
    assert proc.returncode == 1 and where in proc.stderr
    assert not (tmp_path / "all.csv").exists()


def test_skip_invalid_excludes_and_lists(tmp_path, capsys):
    study = make_study(tmp_path / "study")
    set_field(study / "P02" / "ratings.csv", 4, "partiality", "11")
    assert analyze.main([str(study), "--skip-invalid"]) == 0
    assert "excluding invalid participant(s): P02" in capsys.readouterr().err
    out = study / "analysis"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["participants"]["valid"] == ["P01", "P03"]
    assert summary["participants"]["excluded_invalid"] == [
        {"id": "P02", "problems": ["P02/ratings.csv:4: column 'partiality': 11 outside 1..10"]}
    ]
    assert summary["ratings"]["none"]["n"] == 2
    report = (out / "report.md").read_text()
    assert "Excluded as invalid: 1" in report
    assert "**`P02` excluded** (invalid)" in report
    assert "P02/ratings.csv:4: column 'partiality': 11 outside 1..10" in report
    # The export with --skip-invalid leaves P02 out too.
    proc = run_tool("export_csv.py", study, tmp_path / "all.csv", "--skip-invalid")
    assert proc.returncode == 0, proc.stderr
    rows = (tmp_path / "all.csv").read_text().splitlines()[1:]
    assert {r.split(",")[0] for r in rows} == {"P01", "P03"}


def test_all_problems_of_a_file_are_listed(tmp_path):
    study = make_study(tmp_path / "study")
    set_field(study / "P02" / "ratings.csv", 2, "ease", "0")
    set_field(study / "P02" / "ratings.csv", 3, "aptness", "abc")
    errors = studydata.load_study(study).all_errors()
    assert [str(e) for e in errors] == [
        "P02/ratings.csv:2: column 'ease': 0 outside 1..10",
        "P02/ratings.csv:3: column 'aptness': 'abc' is not an integer",
    ]


def test_valid_variants_are_accepted(tmp_path, capsys):
    """Header-only files, CRLF line ends, no trials, and orphaned telemetry are not errors."""
    study = make_study(tmp_path / "study")
    p = study / "P03"
    (p / "ratings.csv").write_bytes((p / "ratings.csv").read_bytes().replace(b"\n", b"\r\n"))
    (p / "trials.csv").write_text(",".join(schema.TRIALS_COLUMNS) + "\n")
    (p / "telemetry").mkdir()
    (p / "telemetry" / "none_7.csv").write_text("time_s,inp")  # interrupted trial: ignored
    loaded = studydata.load_study(study)
    assert loaded.all_errors() == []
    warnings = [str(x) for x in loaded.all_warnings()]
    assert any("P03/telemetry/none_7.csv" in x and "not referenced" in x for x in warnings)
    assert analyze.main([str(study), "--out", str(tmp_path / "out")]) == 0
    assert "warning: P03/telemetry/none_7.csv" in capsys.readouterr().err


def test_low_telemetry_rate_is_a_warning(tmp_path):
    folder = w.write_participant_json(tmp_path, "P01")
    w.append_trial(folder, "P01", "none", 0, telemetry=w.telemetry_rows(seconds=1.0, rate_hz=100.0))
    loaded = studydata.load_study(tmp_path)
    assert loaded.all_errors() == []
    assert [str(x) for x in loaded.all_warnings()] == [
        "P01/telemetry/none_0.csv: effective sample rate 100 Hz is below 250 Hz"
    ]


def test_trials_of_one_condition_with_several_contact_models_earn_a_warning(tmp_path, capsys):
    study = make_study(tmp_path / "study")
    set_field(study / "P03" / "trials.csv", 3, "contact_model", "per_contact")  # P03's movement trial
    loaded = studydata.load_study(study)
    assert loaded.all_errors() == []
    assert [str(x) for x in loaded.all_warnings()] == [
        f"{study}: condition 'movement': trials ran several contact models (paper_sum: 2, per_contact: 1); "
        "its trial metrics mix them"
    ]
    assert analyze.main([str(study), "--out", str(tmp_path / "out")]) == 0
    assert "trials ran several contact models" in capsys.readouterr().err
    report = (tmp_path / "out" / "report.md").read_text()
    assert "| Contact model (trials) | `paper_sum` | `paper_sum`: 2, `per_contact`: 1 | n/a |" in report


def test_empty_study_fails(tmp_path):
    (tmp_path / "study").mkdir()
    proc = run_tool("analyze.py", tmp_path / "study")
    assert proc.returncode == 1
    assert "no participant folders found" in proc.stderr


def test_missing_study_dir_is_usage_error(tmp_path):
    proc = run_tool("analyze.py", tmp_path / "nope")
    assert proc.returncode == 2
