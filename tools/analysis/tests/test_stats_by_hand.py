"""(a) The statistics checked against arithmetic done by hand on the conftest dataset.

Data (total rating per participant; each cell's six criteria are total + (-1, +1, 0, 0, -1, +1)):

         none movement constraint   subject mean
    S1     3      5       6           14/3
    S2     5      6       8           19/3
    S3     4      4       5           13/3
    S4     6      7       9           22/3
    mean  4.5    5.5     7.0          grand 17/3

For an F distribution with df1 = 2 the tail has a closed form:
    P(F(2, d) > f) = (1 + 2 f / d) ** (-d / 2)
and a chi-square with 2 degrees of freedom: P(chi2(2) > x) = exp(-x / 2).
"""

from __future__ import annotations

import math

import pytest
from scipy import stats as sps

import results
import stats
import studydata
import studywriter as w
from conftest import HAND_TOTALS, hand_criteria, write_hand_study


def f2_tail(f: float, d: int) -> float:
    """Closed form of P(F(2, d) > f), independent of SciPy."""
    return (1 + 2 * f / d) ** (-d / 2)


def test_closed_form_f_tail_is_right():
    # Sanity of the closed form itself against a value tabulated in every F table:
    # the 5 % critical value of F(2, 10) is 4.10 (4.102821).
    assert f2_tail(4.102821, 10) == pytest.approx(0.05, abs=1e-6)


@pytest.fixture
def res(tmp_path):
    return results.compute(studydata.load_study(write_hand_study(tmp_path / "study")))


def test_oneway_anova_as_the_paper_pooled_ratings(res):
    t = res["tests"]["oneway_anova_pooled_ratings"]
    # 4 participants x 6 criteria = 24 ratings per condition, 72 in all.
    grand = (4.5 + 5.5 + 7.0) / 3  # equal group sizes: 17/3
    ss_between = 24 * ((4.5 - grand) ** 2 + (5.5 - grand) ** 2 + (7.0 - grand) ** 2)  # 24 * 114/36 = 76
    assert ss_between == pytest.approx(76.0)
    # Within: participant totals around the group means, 6 ratings each ...
    ss_within_totals = 6 * ((1.5**2 + 0.5**2 + 0.5**2 + 1.5**2)  # none: 5
                            + (0.5**2 + 0.5**2 + 1.5**2 + 1.5**2)  # movement: 5
                            + (1.0**2 + 1.0**2 + 2.0**2 + 2.0**2))  # constraint: 10
    # ... plus the criteria around each cell's total: 12 cells x (1+1+0+0+1+1).
    ss_within = ss_within_totals + 12 * 4  # 120 + 48 = 168
    assert ss_within == 168
    df1, df2 = 3 - 1, 72 - 3  # (2, 69)
    f = (ss_between / df1) / (ss_within / df2)  # 38 / (168/69) = 15.607142857...
    assert f == pytest.approx(38 * 69 / 168)
    assert t["df_between"] == 2 and t["df_within"] == 69 and t["n"] == 72
    assert t["ss_between"] == pytest.approx(76.0)
    assert t["ss_within"] == pytest.approx(168.0)
    assert t["F"] == pytest.approx(15.607142857142858)
    assert t["p"] == pytest.approx(f2_tail(f, 69), rel=1e-9)
    assert t["p"] == pytest.approx(2.56e-6, rel=0.02)  # (69/(69+31.214))**34.5, by hand
    # The paper's way of writing it.
    assert stats.fmt_f(t, "df_between", "df_within") == "F(2, 69) = 15.61, p < .001"
    # Additionally (not instead): SciPy agrees.
    groups = [[x for totals in HAND_TOTALS.values() for x in hand_criteria(totals[j])] for j in range(3)]
    assert sps.f_oneway(*groups).statistic == pytest.approx(t["F"])


def test_oneway_anova_on_participant_totals(res):
    t = res["tests"]["oneway_anova_participant_totals"]
    ss_between = 4 * ((4.5 - 17 / 3) ** 2 + (5.5 - 17 / 3) ** 2 + (7.0 - 17 / 3) ** 2)  # 38/3
    ss_within = 5 + 5 + 10  # squared deviations listed in the pooled test
    f = (ss_between / 2) / (ss_within / 9)  # (19/3) / (20/9) = 2.85
    assert f == pytest.approx(2.85)
    assert (t["df_between"], t["df_within"]) == (2, 9)
    assert t["F"] == pytest.approx(2.85)
    assert t["p"] == pytest.approx((9 / (9 + 5.7)) ** 4.5, rel=1e-9)  # = 0.10994...
    assert t["p"] == pytest.approx(0.10994, abs=1e-5)
    assert stats.fmt_f(t, "df_between", "df_within") == "F(2, 9) = 2.85, p = .110"


def test_repeated_measures_anova(res):
    t = res["tests"]["rm_anova_total"]
    # sum x^2 = (9+25+36) + (25+36+64) + (16+16+25) + (36+49+81) = 418; N grand^2 = 12 * 289/9
    ss_total = 418 - 12 * (17 / 3) ** 2  # 98/3
    ss_conditions = 4 * ((4.5 - 17 / 3) ** 2 + (5.5 - 17 / 3) ** 2 + (7 - 17 / 3) ** 2)  # 38/3
    ss_subjects = 3 * ((14 / 3 - 17 / 3) ** 2 + (19 / 3 - 17 / 3) ** 2 + (13 / 3 - 17 / 3) ** 2
                       + (22 / 3 - 17 / 3) ** 2)  # 3 * 54/9 = 18
    ss_error = ss_total - ss_conditions - ss_subjects  # 98/3 - 38/3 - 18 = 2
    assert ss_error == pytest.approx(2.0)
    df_c, df_e = 2, 2 * 3  # (k-1), (k-1)(n-1)
    f = (ss_conditions / df_c) / (ss_error / df_e)  # (19/3) / (1/3) = 19
    assert f == pytest.approx(19.0)
    p = (1 + 2 * 19 / 6) ** (-3)  # = (6/44)^3 = 27/10648
    assert p == pytest.approx(27 / 10648)
    assert t["ss_total"] == pytest.approx(98 / 3)
    assert t["ss_conditions"] == pytest.approx(38 / 3)
    assert t["ss_subjects"] == pytest.approx(18.0)
    assert t["ss_error"] == pytest.approx(2.0)
    assert (t["df_conditions"], t["df_error"], t["n"]) == (2, 6, 4)
    assert t["F"] == pytest.approx(19.0)
    assert t["p"] == pytest.approx(27 / 10648, rel=1e-9)
    assert t["partial_eta_squared"] == pytest.approx((38 / 3) / (38 / 3 + 2))
    assert 0.5 <= t["gg_epsilon"] <= 1.0
    assert stats.fmt_f(t, "df_conditions", "df_error") == "F(2, 6) = 19.00, p = .003"


def test_friedman_from_ranks(res):
    t = res["tests"]["friedman_total"]
    # Ranks within each subject: S1 1,2,3  S2 1,2,3  S3 1.5,1.5,3 (tie)  S4 1,2,3
    rank_sums = (1 + 1 + 1.5 + 1, 2 + 2 + 1.5 + 2, 3 + 3 + 3 + 3)  # 4.5, 7.5, 12
    n, k = 4, 3
    chi2 = 12 / (n * k * (k + 1)) * sum(r**2 for r in rank_sums) - 3 * n * (k + 1)  # 55.125 - 48
    assert chi2 == pytest.approx(7.125)
    # Tie correction: one tie of size 2 -> 1 - (2^3 - 2) / (n k (k^2 - 1)) = 1 - 6/96
    chi2_corrected = chi2 / (1 - (2**3 - 2) / (n * k * (k**2 - 1)))
    assert chi2_corrected == pytest.approx(7.6)
    assert t["chi2"] == pytest.approx(7.6)
    assert t["df"] == 2
    assert t["p"] == pytest.approx(math.exp(-7.6 / 2), rel=1e-9)  # 0.022371
    assert t["kendalls_w"] == pytest.approx(7.6 / (4 * 2))
    assert t["mean_ranks"] == pytest.approx({"none": 4.5 / 4, "movement": 7.5 / 4, "constraint": 12 / 4})


def test_figure_numbers_by_hand(res):
    r = res["ratings"]
    # Criterion means = condition mean + the criterion's offset.
    assert r["none"]["criteria"]["realism"]["mean"] == pytest.approx(3.5)
    assert r["none"]["criteria"]["ease"]["mean"] == pytest.approx(5.5)
    assert r["movement"]["criteria"]["aptness"]["mean"] == pytest.approx(5.5)
    assert r["constraint"]["criteria"]["partiality"]["mean"] == pytest.approx(8.0)
    assert r["constraint"]["criteria"]["enthusiasm"]["mean"] == pytest.approx(6.0)
    # Totals: none [3, 5, 4, 6] -> mean 4.5, SD sqrt(5/3), SE sqrt(5/3)/2.
    assert r["none"]["total"]["mean"] == pytest.approx(4.5)
    assert r["none"]["total"]["sd"] == pytest.approx(math.sqrt(5 / 3))
    assert r["none"]["total"]["se"] == pytest.approx(math.sqrt(5 / 3) / 2)
    # constraint [6, 8, 5, 9] -> mean 7, SD sqrt(10/3), SE sqrt(10/3)/2
    assert r["constraint"]["total"]["se"] == pytest.approx(math.sqrt(10 / 3) / 2)
    assert r["constraint"]["total"]["n"] == 4


def test_incomplete_participant_is_excluded_from_within_subject_tests(tmp_path):
    study = write_hand_study(tmp_path / "study")
    w.make_participant(study, "S5", {"none": [10] * 6})  # rated only one condition
    res = results.compute(studydata.load_study(study))
    assert res["participants"]["incomplete"] == [{"id": "S5", "rated": ["none"]}]
    assert res["participants"]["complete"] == ["S1", "S2", "S3", "S4"]
    assert res["tests"]["rm_anova_total"]["F"] == pytest.approx(19.0)  # unchanged
    assert res["tests"]["friedman_total"]["chi2"] == pytest.approx(7.6)
    # ... but its rating counts in the descriptives: none = [3, 5, 4, 6, 10] -> 5.6
    assert res["ratings"]["none"]["total"]["mean"] == pytest.approx(5.6)
    assert res["ratings"]["none"]["total"]["n"] == 5


def test_holm_by_hand():
    # sorted 0.01, 0.03, 0.04 -> 3 * 0.01 = 0.03, 2 * 0.03 = 0.06, max(0.06, 1 * 0.04) = 0.06
    assert stats.holm([0.01, 0.04, 0.03]) == pytest.approx([0.03, 0.06, 0.06])
    assert stats.holm([0.5, 0.6, 0.001]) == pytest.approx([1.0, 1.0, 0.003])
    adj = stats.holm([0.02, float("nan"), 0.04])  # NaN does not count: m = 2
    assert adj[0] == pytest.approx(0.04) and math.isnan(adj[1]) and adj[2] == pytest.approx(0.04)


def test_wilcoxon_exact_by_hand():
    # Five distinct positive differences: W- = 0; of 2^5 sign patterns only the all-positive
    # one reaches it, so the exact two-sided p = 2 / 32.
    rows = stats.pairwise_wilcoxon({"none": [1, 2, 3, 4, 5], "movement": [2, 4, 6, 8, 10], "constraint": [1, 2, 3, 4, 5]})
    by_pair = {(r["a"], r["b"]): r for r in rows}
    nm = by_pair[("none", "movement")]
    assert nm["W"] == 0 and nm["p"] == pytest.approx(2 / 32) and nm["n_nonzero"] == 5
    nc = by_pair[("none", "constraint")]
    assert nc["n_nonzero"] == 0 and math.isnan(nc["p"]) and nc["note"]
    # Holm over the two computable p values (both 2/32): 2 * 0.0625 = 0.125 each.
    assert nm["p_holm"] == pytest.approx(0.125)
    assert by_pair[("movement", "constraint")]["p_holm"] == pytest.approx(0.125)


def test_posthoc_on_hand_study_uses_holm(res):
    rows = res["tests"]["posthoc_wilcoxon_total"]
    assert [(r["a"], r["b"]) for r in rows] == [("none", "movement"), ("none", "constraint"), ("movement", "constraint")]
    assert [r["p_holm"] for r in rows] == pytest.approx(stats.holm([r["p"] for r in rows]))
    # none -> constraint: every subject improves (3, 3, 1, 3).
    assert rows[1]["n_nonzero"] == 4 and rows[1]["median_difference"] == pytest.approx(3.0)


def test_apa_p_format():
    assert stats.fmt_p(0.0004) == "p < .001"
    assert stats.fmt_p(0.0234) == "p = .023"
    assert stats.fmt_p(0.5) == "p = .500"
    assert stats.fmt_p(float("nan")) == "p = n/a"
