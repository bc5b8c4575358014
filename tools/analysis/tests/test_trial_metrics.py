"""Trial metrics are recomputed from the telemetry rows a trial keeps (FORMAT.md, "Trial
metrics"): by hand on a few rows, and as the check that warns when trials.csv holds
something else (only for data whose participant.json records contact_gap_s)."""

from __future__ import annotations

import pytest

import studydata
import studywriter as w
import trial_metrics

# time_s, input_x, input_y, avatar_x, avatar_y, force_x, force_y, in_contact
ROWS = [
    [0.000, 0.5, 0.0, 100.0, 100.0, 0.0, 0.0, 0],
    [0.002, 0.5, 0.0, 103.0, 104.0, 3.0, 4.0, 1],  # |f| = 5, contact begins
    [0.004, 0.5, 0.0, 103.0, 104.0, 0.6, 0.8, 1],  # |f| = 1
    [0.006, 0.5, 0.0, 103.0, 104.0, 0.0, 0.0, 0],
    [0.030, 0.5, 0.0, 103.0, 104.0, 0.0, 0.0, 1],  # 24 ms step: counts 10; 26 ms after the last contact: the same one
    [0.100, 0.5, 0.0, 103.0, 110.0, 0.0, 0.0, 1],  # 70 ms step: counts 10; 70 ms after: a new collision
]
GAP_S = 0.04


def as_records(rows):
    names = ("time_s", "input_x", "input_y", "avatar_x", "avatar_y", "force_x", "force_y", "in_contact")
    return [dict(zip(names, row)) for row in rows]


def test_metrics_by_hand():
    got = trial_metrics.recompute(as_records(ROWS), GAP_S, time_to_goal_s=10.0)
    assert got["mean_force_n"] == pytest.approx(6.0 / 6)
    assert got["max_force_n"] == pytest.approx(5.0)
    # Rows 1, 2, 4 and 5 in contact: 2 + 2 + min(24, 10) + min(70, 10) ms.
    assert got["contact_time_s"] == pytest.approx(0.024)
    assert got["wall_collisions"] == 2
    assert got["path_length_px"] == pytest.approx(5.0 + 6.0)
    assert trial_metrics.recompute(as_records(ROWS), GAP_S, time_to_goal_s=0.01)["contact_time_s"] == 0.01


def participant(tmp_path, trial: dict, **meta):
    folder = w.write_participant_json(tmp_path / "study", "P01", **meta)
    w.append_trial(folder, "P01", "movement", 0, telemetry=ROWS, **trial)
    return studydata.load_participant(folder)


def trial_warnings(p) -> list[str]:
    # The few rows are far below the telemetry rate the format asks for: that warning aside.
    return [str(x) for x in p.warnings if "trials.csv" in str(x)]


MATCHING = {"mean_force_n": 1.0, "max_force_n": 5.0, "contact_time_s": 0.024, "wall_collisions": 2,
            "path_length_px": 11.0, "time_to_goal_s": 10.0}


def test_a_trial_whose_metrics_match_its_telemetry_earns_no_warning(tmp_path):
    p = participant(tmp_path, MATCHING, contact_gap_s=GAP_S)
    assert p.valid and trial_warnings(p) == []


@pytest.mark.parametrize("metric, value", [("max_force_n", 5.01), ("wall_collisions", 1),
                                           ("contact_time_s", 0.04), ("path_length_px", 11.2)])
def test_a_metric_the_telemetry_does_not_give_is_a_warning(tmp_path, metric, value):
    p = participant(tmp_path, {**MATCHING, metric: value}, contact_gap_s=GAP_S)
    assert p.valid
    assert trial_warnings(p) == [
        f"P01/trials.csv:2: {metric} {value} is not what its telemetry gives "
        f"({trial_metrics.recompute(as_records(ROWS), GAP_S, 10.0)[metric]:.4f})"
    ]


def test_data_without_the_contact_gap_is_not_checked(tmp_path):
    # Written before the metrics were defined on the rows kept (over every 1 kHz sample).
    p = participant(tmp_path, {**MATCHING, "max_force_n": 9.0})
    assert p.valid and trial_warnings(p) == []
