"""The statistics of the study analysis, computed from sums of squares with NumPy.

SciPy supplies only distribution tails (F, chi-square) and the rank tests (Friedman,
Wilcoxon signed-rank). Every function returns plain dicts of floats so the numbers go
straight into summary.json and the report; a statistic that cannot be computed for the data
at hand is NaN with a `note` saying why.
"""

from __future__ import annotations

import math
import warnings
from itertools import combinations

import numpy as np
from scipy import stats as sps

NAN = float("nan")


def describe(values) -> dict:
    """Mean, SD (n-1), SE = SD/sqrt(n) and n of a sample."""
    x = np.asarray(values, dtype=float)
    n = int(x.size)
    mean = float(x.mean()) if n else NAN
    sd = float(x.std(ddof=1)) if n > 1 else NAN
    se = sd / math.sqrt(n) if n > 1 else NAN
    return {"mean": mean, "sd": sd, "se": se, "n": n}


def oneway_anova(groups: dict[str, list[float]]) -> dict:
    """One-way between-groups ANOVA over the non-empty groups.

    SS_between = sum_g n_g (mean_g - grand)^2, SS_within = sum_g sum_i (x_gi - mean_g)^2,
    df = (k - 1, N - k), F = MS_between / MS_within, p = P(F(df1, df2) > F).
    """
    data = {g: np.asarray(v, dtype=float) for g, v in groups.items() if len(v) > 0}
    k = len(data)
    n_total = sum(v.size for v in data.values())
    out = {
        "groups": {g: {"n": int(v.size), "mean": float(v.mean())} for g, v in data.items()},
        "k": k,
        "n": int(n_total),
        "ss_between": NAN,
        "ss_within": NAN,
        "df_between": k - 1,
        "df_within": n_total - k,
        "ms_between": NAN,
        "ms_within": NAN,
        "F": NAN,
        "p": NAN,
        "eta_squared": NAN,
        "note": "",
    }
    if k < 2 or n_total <= k:
        out["note"] = "needs at least two groups and more observations than groups"
        return out
    grand = np.concatenate(list(data.values())).mean()
    ss_b = float(sum(v.size * (v.mean() - grand) ** 2 for v in data.values()))
    ss_w = float(sum(((v - v.mean()) ** 2).sum() for v in data.values()))
    df_b, df_w = k - 1, n_total - k
    ms_b, ms_w = ss_b / df_b, ss_w / df_w
    out.update(ss_between=ss_b, ss_within=ss_w, ms_between=ms_b, ms_within=ms_w)
    out["eta_squared"] = ss_b / (ss_b + ss_w) if ss_b + ss_w > 0 else NAN
    out.update(_f_and_p(ms_b, ms_w, df_b, df_w))
    if out["note"] == "" and not math.isfinite(out["F"]):
        out["note"] = "no variance within groups"
    return out


def _f_and_p(ms_effect: float, ms_error: float, df1: float, df2: float) -> dict:
    if ms_error > 0:
        f = ms_effect / ms_error
        return {"F": f, "p": float(sps.f.sf(f, df1, df2))}
    if ms_effect > 0:
        return {"F": math.inf, "p": 0.0, "note": "zero error variance: F is infinite"}
    return {"F": NAN, "p": NAN, "note": "no variance at all"}


def rm_anova(matrix) -> dict:
    """One-way repeated-measures ANOVA: rows are subjects, columns are conditions.

    SS_total = sum (x - grand)^2, SS_conditions = n sum_j (mean_j - grand)^2,
    SS_subjects = k sum_i (mean_i - grand)^2, SS_error = SS_total - SS_conditions - SS_subjects;
    df = (k - 1, (k - 1)(n - 1)), F = MS_conditions / MS_error. Also the Greenhouse-Geisser
    epsilon (from the double-centred covariance matrix) and the p corrected with it.
    """
    x = np.asarray(matrix, dtype=float)
    n, k = x.shape if x.ndim == 2 else (0, 0)
    out = {
        "n": int(n),
        "k": int(k),
        "ss_total": NAN,
        "ss_subjects": NAN,
        "ss_conditions": NAN,
        "ss_error": NAN,
        "df_conditions": k - 1,
        "df_subjects": n - 1,
        "df_error": (k - 1) * (n - 1),
        "ms_conditions": NAN,
        "ms_error": NAN,
        "F": NAN,
        "p": NAN,
        "partial_eta_squared": NAN,
        "gg_epsilon": NAN,
        "p_gg": NAN,
        "note": "",
    }
    if n < 2 or k < 2:
        out["note"] = "needs at least two complete participants"
        return out
    grand = x.mean()
    ss_total = float(((x - grand) ** 2).sum())
    ss_cond = float(n * ((x.mean(axis=0) - grand) ** 2).sum())
    ss_subj = float(k * ((x.mean(axis=1) - grand) ** 2).sum())
    ss_err = ss_total - ss_cond - ss_subj
    if ss_err < 1e-12 * max(ss_total, 1.0):  # rounding residue of a perfect additive fit
        ss_err = 0.0
    df_c, df_e = k - 1, (k - 1) * (n - 1)
    ms_c, ms_e = ss_cond / df_c, ss_err / df_e
    out.update(ss_total=ss_total, ss_subjects=ss_subj, ss_conditions=ss_cond, ss_error=ss_err,
               ms_conditions=ms_c, ms_error=ms_e)
    out["partial_eta_squared"] = ss_cond / (ss_cond + ss_err) if ss_cond + ss_err > 0 else NAN
    out.update(_f_and_p(ms_c, ms_e, df_c, df_e))
    # Greenhouse-Geisser epsilon.
    cov = np.cov(x, rowvar=False, ddof=1)
    centre = np.eye(k) - np.ones((k, k)) / k
    dc = centre @ cov @ centre
    denom = (k - 1) * np.trace(dc @ dc)
    if denom > 0:
        eps = float(np.trace(dc) ** 2 / denom)
        eps = min(max(eps, 1.0 / (k - 1)), 1.0)
        out["gg_epsilon"] = eps
        if math.isfinite(out["F"]):
            out["p_gg"] = float(sps.f.sf(out["F"], eps * df_c, eps * df_e))
        else:
            out["p_gg"] = out["p"]
    return out


def friedman(matrix) -> dict:
    """Friedman test (scipy.stats.friedmanchisquare, tie-corrected) plus Kendall's W."""
    x = np.asarray(matrix, dtype=float)
    n, k = x.shape if x.ndim == 2 else (0, 0)
    out = {"n": int(n), "k": int(k), "df": k - 1, "chi2": NAN, "p": NAN, "kendalls_w": NAN,
           "mean_ranks": {}, "note": ""}
    if n < 2 or k < 3:
        out["note"] = "needs at least two complete participants and three conditions"
        return out
    ranks = np.apply_along_axis(sps.rankdata, 1, x)
    out["mean_ranks"] = [float(r) for r in ranks.mean(axis=0)]
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        res = sps.friedmanchisquare(*[x[:, j] for j in range(k)])
    chi2, p = float(res.statistic), float(res.pvalue)
    if not math.isfinite(chi2):
        out["note"] = "every participant gave all conditions the same total"
        return out
    out.update(chi2=chi2, p=p, kendalls_w=chi2 / (n * (k - 1)))
    return out


def holm(pvalues: list[float]) -> list[float]:
    """Holm-Bonferroni adjusted p values (NaN entries stay NaN and do not count)."""
    idx = [i for i, p in enumerate(pvalues) if math.isfinite(p)]
    m = len(idx)
    adjusted = [NAN] * len(pvalues)
    running = 0.0
    for rank, i in enumerate(sorted(idx, key=lambda i: pvalues[i])):
        running = max(running, min(1.0, (m - rank) * pvalues[i]))
        adjusted[i] = running
    return adjusted


def pairwise_wilcoxon(columns: dict[str, list[float]]) -> list[dict]:
    """Wilcoxon signed-rank test for every pair of conditions, Holm-corrected."""
    results = []
    for a, b in combinations(columns, 2):
        xa, xb = np.asarray(columns[a], float), np.asarray(columns[b], float)
        diff = xb - xa
        row = {"a": a, "b": b, "n": int(diff.size), "n_nonzero": int((diff != 0).sum()),
               "median_difference": float(np.median(diff)) if diff.size else NAN,
               "W": NAN, "p": NAN, "p_holm": NAN, "note": ""}
        if row["n_nonzero"] == 0:
            row["note"] = "no non-zero differences"
        else:
            with warnings.catch_warnings(), np.errstate(all="ignore"):
                warnings.simplefilter("ignore")
                res = sps.wilcoxon(xa, xb)
            row["W"], row["p"] = float(res.statistic), float(res.pvalue)
        results.append(row)
    for row, adj in zip(results, holm([r["p"] for r in results])):
        row["p_holm"] = adj
    return results


def favourite_votes(lists: list[list[str]], conditions) -> dict:
    """A participant naming k favourites gives each of them 1/k vote; k = 0 abstains."""
    votes = {c: 0.0 for c in conditions}
    voters = abstained = 0
    for fav in lists:
        if not fav:
            abstained += 1
            continue
        voters += 1
        for c in fav:
            votes[c] += 1.0 / len(fav)
    return {"votes": votes, "voters": voters, "abstained": abstained, "answered": len(lists)}


# ----------------------------------------------------------------------------- formatting


def fmt_p(p: float) -> str:
    """APA style: p = .023, p < .001 (no leading zero)."""
    if not math.isfinite(p):
        return "p = n/a"
    if p < 0.001:
        return "p < .001"
    s = f"{p:.3f}"
    return "p = " + (s[1:] if s.startswith("0") else s)


def fmt_num(x: float, digits: int = 2) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "n/a"
    if isinstance(x, float) and math.isinf(x):
        return "inf"
    return f"{x:.{digits}f}"


def fmt_df(df: float) -> str:
    return str(int(df)) if float(df).is_integer() else f"{df:.2f}"


def fmt_f(test: dict, df1_key: str, df2_key: str) -> str:
    """F(df1, df2) = x.xx, p = .xxx"""
    return (f"F({fmt_df(test[df1_key])}, {fmt_df(test[df2_key])}) = {fmt_num(test['F'])}, "
            f"{fmt_p(test['p'])}")
