"""(d) analyze.py writes the three figures (PNG, right size, not blank), report.md and
summary.json with the hand-computed numbers."""

from __future__ import annotations

import contextlib
import io
import json

import matplotlib.image as mpimg
import numpy as np
import pytest

import analyze
import figures
import studywriter as w
from conftest import run_tool, write_hand_study

FIGURES = {  # name -> (height, width) in pixels
    "fig6_criteria.png": (550, 1100),
    "fig7_total.png": (500, 600),
    "trial_metrics.png": (750, 1000),
}


@pytest.fixture(scope="module")
def analysed(tmp_path_factory):
    """The hand-computed study analysed once (in-process) for the tests of this module."""
    study = write_hand_study(tmp_path_factory.mktemp("outputs") / "study")
    # An abandoned trial with telemetry for one participant, so the metrics have some spread.
    w.append_trial(study / "S1", "S1", "movement", 1, time_to_goal_s=50.0, completed=0, wall_collisions=9,
                   telemetry=w.telemetry_rows(0.2))
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        assert analyze.main([str(study)]) == 0
    return study / "analysis", stdout.getvalue()


def test_figures_exist_with_the_right_size(analysed):
    out, _ = analysed
    for name, (h, wd) in FIGURES.items():
        path = out / name
        assert path.is_file(), name
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
        assert path.stat().st_size > 15_000, f"{name} is suspiciously small"
        img = mpimg.imread(path)
        assert img.shape[:2] == (h, wd), name
        # Not blank: many distinct colours (bars in three condition colours, text, axes).
        flat = img[..., :3].reshape(-1, 3)
        assert flat.std() > 0.05, name
        assert len(np.unique((flat * 255).astype(np.uint8), axis=0)) > 50, name


def test_condition_colours_are_drawn(analysed):
    """The three condition colours appear in Figure 7 (i.e. three bars were drawn)."""
    out, _ = analysed
    img = (mpimg.imread(out / "fig7_total.png")[..., :3] * 255).round().astype(int)
    for hex_colour in ("#9e9e9e", "#1f77b4", "#d62728"):
        rgb = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)])
        hits = (np.abs(img - rgb).sum(axis=-1) <= 3).sum()
        assert hits > 2000, f"{hex_colour}: {hits} pixels"


def test_report_and_summary(analysed):
    out, stdout = analysed
    report = (out / "report.md").read_text()
    # The paper's one-way ANOVA and the within-subject tests, with the hand-computed values.
    assert "**F(2, 69) = 15.61, p < .001**" in report
    assert "**F(2, 9) = 2.85, p = .110**" in report
    assert "**F(2, 6) = 19.00, p = .003**" in report
    assert "**χ²(2) = 7.60, p = .022**" in report
    assert "| No feedback | 4 | 4.50 | 1.29 | 0.65 |" in report  # Figure 7 table
    assert "| Constraint-based | 4 |" in report and "Holm" in report
    for name in FIGURES:
        assert f"]({name})" in report
    summary = json.loads((out / "summary.json").read_text())
    assert summary["tests"]["rm_anova_total"]["F"] == pytest.approx(19.0)
    assert summary["tests"]["oneway_anova_pooled_ratings"]["df_within"] == 69
    assert summary["ratings"]["movement"]["criteria"]["ease"]["mean"] == pytest.approx(6.5)
    assert summary["favourite"]["votes"] == {"none": 0.0, "movement": 0.0, "constraint": 4.0}
    tm = summary["trial_metrics"]["movement"]
    # S1..S4 one default trial (30 s, 3 collisions) + S1's abandoned trial (50 s, 9 collisions).
    assert tm["trials"] == 5 and tm["completed"] == 4
    assert tm["time_to_goal_s"] == {"mean": 30.0, "sd": 0.0, "n": 4}  # completed trials only
    assert tm["wall_collisions"]["mean"] == pytest.approx((4 * 3 + 9) / 5)
    assert tm["wall_collisions"]["n"] == 5
    assert "F(2, 6) = 19.00, p = .003" in stdout


def test_figure_7_shows_the_papers_test_beside_the_repeated_measures_one(analysed):
    out, _ = analysed
    res = json.loads((out / "summary.json").read_text())
    assert figures.fig7_tests(res) == [
        "Paper's test (one-way ANOVA, every rating): F(2, 69) = 15.61, p < .001",
        "Repeated measures (participant totals): F(2, 6) = 19.00, p = .003",
    ]


def test_figure_7_says_when_a_test_cannot_be_computed():
    nothing = {"F": None, "p": None, "df_between": 2, "df_within": 0, "df_conditions": 2, "df_error": 0}
    res = {"tests": {"oneway_anova_pooled_ratings": nothing, "rm_anova_total": nothing}}
    assert [line.split(": ")[1] for line in figures.fig7_tests(res)] == ["n/a", "n/a"]


def test_script_second_run_ignores_its_own_output_folder(analysed):
    """The real script (a subprocess) exits 0 and does not take analysis/ for a participant."""
    out, _ = analysed
    study = out.parent
    before = (out / "summary.json").stat().st_mtime_ns
    proc = run_tool("analyze.py", study)
    assert proc.returncode == 0, proc.stderr
    assert (out / "summary.json").stat().st_mtime_ns != before
    summary = json.loads((out / "summary.json").read_text())
    assert summary["participants"]["found"] == ["S1", "S2", "S3", "S4"]
    assert "wrote" in proc.stdout


def test_figures_with_sparse_data(tmp_path):
    """One participant, one condition rated, no trials: the figures are still produced."""
    w.make_participant(tmp_path / "s", "X", {"none": 4}, trials={"none": []})
    assert analyze.main([str(tmp_path / "s"), "--out", str(tmp_path / "o")]) == 0
    for name, (h, wd) in FIGURES.items():
        assert mpimg.imread(tmp_path / "o" / name).shape[:2] == (h, wd)
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["tests"]["rm_anova_total"]["F"] is None
    assert summary["participants"]["incomplete"] == [{"id": "X", "rated": ["none"]}]
