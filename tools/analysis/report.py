"""report.md: every number of summary.json as Markdown tables."""

from __future__ import annotations

import math

from results import TRIAL_METRICS
from stats import fmt_df, fmt_f, fmt_num, fmt_p
from schema import CONDITION_LABELS, CONDITIONS, CRITERIA, CRITERION_TITLES, CRITERION_WORDING, RATING_MAX, RATING_MIN

L = CONDITION_LABELS


def _table(header: list[str], rows: list[list[str]], align: list[str] | None = None) -> list[str]:
    align = align or ["l"] + ["r"] * (len(header) - 1)
    sep = ["---:" if a == "r" else ":---" for a in align]
    out = ["| " + " | ".join(header) + " |", "| " + " | ".join(sep) + " |"]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return out + [""]


def _msd(d: dict) -> str:
    if d["n"] == 0:
        return "n/a"
    return f"{fmt_num(d['mean'])} ({fmt_num(d['sd'])})"


def _votes(v: float) -> str:
    return f"{v:.2f}".rstrip("0").rstrip(".") if v else "0"


def render(res: dict, figures: dict[str, str]) -> str:
    md: list[str] = []
    parts = res["participants"]
    tests = res["tests"]
    md += [f"# Study analysis: `{res['study_dir']}`", ""]
    md += [
        f"- Participant folders found: {len(parts['found'])}",
        f"- Valid: {len(parts['valid'])}; complete (all three conditions rated): {len(parts['complete'])}",
        f"- Excluded as invalid: {len(parts['excluded_invalid'])}"
        + (" (see *Data problems*)" if parts["excluded_invalid"] else ""),
        f"- Incomplete (excluded from the within-subjects tests): {len(parts['incomplete'])}"
        + "".join(f"\n  - `{i['id']}` rated: {', '.join(i['rated']) or 'nothing'}" for i in parts["incomplete"]),
        "",
        "Descriptive statistics and the one-way ANOVAs use every rating of every valid participant; "
        "the repeated-measures ANOVA, the Friedman test and the post-hoc tests use the complete "
        "participants only. A participant's *total* rating for a condition is the mean of its six "
        "criteria; SE = SD / sqrt(n).",
        "",
    ]

    md += ["## Participants", ""]
    rows = []
    for key, counts in res["demographics"].items():
        rows.append([key, ", ".join(f"{v}: {n}" for v, n in counts.items()) or "n/a"])
    md += _table(["Demographic", "Counts"], rows, ["l", "l"])
    rows = [[order, str(n)] for order, n in res["condition_orders"].items()]
    rows += [[f"*counterbalancing: {mode}*", str(n)] for mode, n in res["counterbalancing"].items()]
    md += _table(["Condition order", "Participants"], rows)

    md += ["## Ratings per criterion (Figure 6)", "", f"Mean (SD) on the {RATING_MIN}-{RATING_MAX} scale.", ""]
    header = ["Criterion"] + [f"{L[c]} (n = {res['ratings'][c]['n']})" for c in CONDITIONS]
    rows = [[f"{CRITERION_TITLES[k]} ({CRITERION_WORDING[k]})"] + [_msd(res["ratings"][c]["criteria"][k]) for c in CONDITIONS]
            for k in CRITERIA]
    rows.append(["**Total** (mean of the six)"] + [_msd(res["ratings"][c]["total"]) for c in CONDITIONS])
    md += _table(header, rows)
    md += [f"![Figure 6]({figures['fig6']})", ""]

    md += ["## Total mean rating (Figure 7)", ""]
    rows = []
    for c in CONDITIONS:
        t = res["ratings"][c]["total"]
        rows.append([L[c], str(t["n"]), fmt_num(t["mean"]), fmt_num(t["sd"]), fmt_num(t["se"])])
    md += _table(["Condition", "n", "Mean", "SD", "SE"], rows)
    md += [f"![Figure 7]({figures['fig7']})", ""]

    md += ["## Tests", ""]
    ow = tests["oneway_anova_pooled_ratings"]
    md += [
        "### One-way ANOVA across conditions, as reported in the paper",
        "",
        "The paper reports F(2, 163) for 10 participants, which is only possible if every single "
        "criterion rating is an observation (up to 6 × 10 per condition). This test repeats that: "
        "it ignores that ratings come from the same participants, so it is shown for comparison "
        "with the paper; the within-subjects tests below are the ones the design calls for.",
        "",
        f"**{fmt_f(ow, 'df_between', 'df_within')}** (η² = {fmt_num(ow['eta_squared'], 3)}; "
        f"{ow['n']} ratings)" + (f" — {ow['note']}" if ow["note"] else ""),
        "",
    ]
    md += _anova_table(ow)
    ot = tests["oneway_anova_participant_totals"]
    md += [
        "One-way ANOVA on the participants' total ratings (one value per participant and condition): "
        f"**{fmt_f(ot, 'df_between', 'df_within')}**" + (f" — {ot['note']}" if ot["note"] else ""),
        "",
    ]
    md += _anova_table(ot)

    rm = tests["rm_anova_total"]
    md += [
        "### Repeated-measures ANOVA on the total rating",
        "",
        f"**{fmt_f(rm, 'df_conditions', 'df_error')}**, partial η² = {fmt_num(rm['partial_eta_squared'], 3)}; "
        f"Greenhouse-Geisser ε = {fmt_num(rm['gg_epsilon'], 3)}, corrected "
        f"{fmt_p(rm['p_gg'])} ({rm['n']} complete participants)" + (f" — {rm['note']}" if rm["note"] else ""),
        "",
    ]
    md += _table(
        ["Source", "SS", "df", "MS", "F", "p"],
        [
            ["Conditions", fmt_num(rm["ss_conditions"], 3), fmt_df(rm["df_conditions"]), fmt_num(rm["ms_conditions"], 3),
             fmt_num(rm["F"]), _bare_p(rm["p"])],
            ["Subjects", fmt_num(rm["ss_subjects"], 3), fmt_df(rm["df_subjects"]), "", "", ""],
            ["Error", fmt_num(rm["ss_error"], 3), fmt_df(rm["df_error"]), fmt_num(rm["ms_error"], 3), "", ""],
            ["Total", fmt_num(rm["ss_total"], 3), fmt_df(rm["n"] * rm["k"] - 1), "", "", ""],
        ],
    )

    fr = tests["friedman_total"]
    ranks = ", ".join(f"{L[c]} {fmt_num(r)}" for c, r in fr["mean_ranks"].items()) if fr["mean_ranks"] else "n/a"
    md += [
        "### Friedman test on the total rating",
        "",
        f"**χ²({fmt_df(fr['df'])}) = {fmt_num(fr['chi2'])}, {fmt_p(fr['p'])}**, Kendall's W = "
        f"{fmt_num(fr['kendalls_w'], 3)} ({fr['n']} complete participants; mean ranks: {ranks})"
        + (f" — {fr['note']}" if fr["note"] else ""),
        "",
        "### Post-hoc: pairwise Wilcoxon signed-rank tests, Holm-corrected",
        "",
    ]
    rows = []
    for r in tests["posthoc_wilcoxon_total"]:
        rows.append([f"{L[r['a']]} vs {L[r['b']]}", str(r["n"]), str(r["n_nonzero"]), fmt_num(r["median_difference"]),
                     fmt_num(r["W"], 1), _bare_p(r["p"]), _bare_p(r["p_holm"]) + (f" ({r['note']})" if r["note"] else "")])
    md += _table(["Pair (b - a)", "n", "non-zero", "Median difference", "W", "p", "p (Holm)"], rows)

    fav = res["favourite"]
    md += [
        "## Favourite",
        "",
        "A participant naming k favourites gives each 1/k vote (the paper split votes by halves). "
        f"{fav['answered']} participants answered: {fav['voters']} voted, {fav['abstained']} named no favourite"
        + (f"; no final.json (did not reach the end): {', '.join(fav['no_final_json'])}" if fav["no_final_json"] else "")
        + ".",
        "",
    ]
    md += _table(["Condition", "Votes"], [[L[c], _votes(fav["votes"][c])] for c in CONDITIONS])

    md += ["## Trial metrics by condition", "", "Mean (SD), n trials. Time to goal counts completed trials only.", ""]
    tm = res["trial_metrics"]
    header = ["Metric"] + [L[c] for c in CONDITIONS]
    rows = [["Trials (completed) / participants"] + [f"{tm[c]['trials']} ({tm[c]['completed']}) / {tm[c]['participants']}" for c in CONDITIONS]]
    rows.append(["Contact model (trials)"] + [_models(tm[c]["contact_models"]) for c in CONDITIONS])
    for col, label, _ in TRIAL_METRICS:
        rows.append([label] + [f"{_msd(tm[c][col])}, n = {tm[c][col]['n']}" for c in CONDITIONS])
    md += _table(header, rows)
    md += [f"![Trial metrics]({figures['trials']})", ""]

    if parts["excluded_invalid"] or res["warnings"]:
        md += ["## Data problems", ""]
        for ex in parts["excluded_invalid"]:
            md += [f"- **`{ex['id']}` excluded** (invalid):"] + [f"  - `{pr}`" for pr in ex["problems"]]
        if res["warnings"]:
            md += ["- Warnings (data kept):"] + [f"  - `{w}`" for w in res["warnings"]]
        md += [""]
    return "\n".join(md)


def _models(counts: dict[str, int]) -> str:
    """"paper_sum" or "paper_sum: 8, per_contact: 2"; "n/a" without any (position control)."""
    if len(counts) == 1:
        return f"`{next(iter(counts))}`"
    return ", ".join(f"`{m}`: {n}" for m, n in counts.items()) or "n/a"


def _bare_p(p: float) -> str:
    if not math.isfinite(p):
        return "n/a"
    return "< .001" if p < 0.001 else fmt_p(p)[4:]


def _anova_table(t: dict) -> list[str]:
    return _table(
        ["Source", "SS", "df", "MS", "F", "p"],
        [
            ["Between conditions", fmt_num(t["ss_between"], 3), fmt_df(t["df_between"]), fmt_num(t["ms_between"], 3),
             fmt_num(t["F"]), _bare_p(t["p"])],
            ["Within", fmt_num(t["ss_within"], 3), fmt_df(t["df_within"]), fmt_num(t["ms_within"], 3), "", ""],
        ],
    )
