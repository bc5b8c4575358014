"""The PNG figures. Fixed pixel sizes (no tight bounding box) so the output is predictable."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stats  # noqa: E402
from results import TRIAL_METRICS  # noqa: E402
from schema import CONDITION_LABELS, CONDITIONS, CRITERIA  # noqa: E402

DPI = 100
FIG6_SIZE = (11.0, 5.5)  # inches -> 1100 x 550 px
FIG7_SIZE = (6.0, 5.0)  # 600 x 500 px
TRIALS_SIZE = (10.0, 7.5)  # 1000 x 750 px
COLOURS = {"none": "#9e9e9e", "movement": "#1f77b4", "constraint": "#d62728"}


def _nan0(x: float) -> float:
    return 0.0 if x is None or not math.isfinite(x) else x


def fig6_criteria(res: dict, path: Path) -> None:
    fig, ax = plt.subplots(figsize=FIG6_SIZE, dpi=DPI)
    x = np.arange(len(CRITERIA))
    width = 0.8 / len(CONDITIONS)
    for i, c in enumerate(CONDITIONS):
        r = res["ratings"][c]
        means = [_nan0(r["criteria"][k]["mean"]) for k in CRITERIA]
        ax.bar(x + (i - 1) * width, means, width, label=f"{CONDITION_LABELS[c]} (n = {r['n']})",
               color=COLOURS[c], edgecolor="black", linewidth=0.5)
        total = r["total"]["mean"]
        if math.isfinite(total):  # the paper's dashed total-mean lines
            ax.axhline(total, color=COLOURS[c], linestyle="--", linewidth=1.2)
    ax.set_xticks(x, [k.capitalize() for k in CRITERIA])
    ax.set_ylim(0, 10.5)
    ax.set_yticks(range(0, 11))
    ax.set_ylabel("Mean rating (1-10)")
    ax.set_title("Average rating for each criterion for each interface (dashed: total mean rating)")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    ax.grid(axis="y", alpha=0.3)
    ax.set_axisbelow(True)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def fig7_total(res: dict, path: Path) -> None:
    fig, ax = plt.subplots(figsize=FIG7_SIZE, dpi=DPI)
    x = np.arange(len(CONDITIONS))
    means = [_nan0(res["ratings"][c]["total"]["mean"]) for c in CONDITIONS]
    ses = [_nan0(res["ratings"][c]["total"]["se"]) for c in CONDITIONS]
    ax.bar(x, means, 0.6, yerr=ses, capsize=8, color=[COLOURS[c] for c in CONDITIONS],
           edgecolor="black", linewidth=0.5)
    for xi, m, se, c in zip(x, means, ses, CONDITIONS):
        n = res["ratings"][c]["total"]["n"]
        ax.text(xi, m + se + 0.15, f"{m:.2f}\n(n = {n})", ha="center", va="bottom", fontsize=9)
    ax.set_xticks(x, [CONDITION_LABELS[c] for c in CONDITIONS])
    ax.set_ylim(0, 11.5)
    ax.set_yticks(range(0, 11))
    ax.set_ylabel("Total mean rating (± SE)")
    ax.set_title("\n".join(["Total mean rating and standard error", *fig7_tests(res)]), fontsize=10)
    ax.grid(axis="y", alpha=0.3)
    ax.set_axisbelow(True)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def fig7_tests(res: dict) -> list[str]:
    """Figure 7's test lines: the paper's test (a one-way ANOVA over every criterion rating,
    how it reported F(2, 163)) beside the repeated-measures ANOVA the design calls for; a
    test that cannot be computed (too few participants) says so instead of its F."""
    t = res["tests"]
    ow, rm = t["oneway_anova_pooled_ratings"], t["rm_anova_total"]

    def shown(test: dict, df1: str, df2: str) -> str:
        return stats.fmt_f(test, df1, df2) if _finite(test["F"]) else "n/a"

    return [
        "Paper's test (one-way ANOVA, every rating): " + shown(ow, "df_between", "df_within"),
        "Repeated measures (participant totals): " + shown(rm, "df_conditions", "df_error"),
    ]


def _finite(x) -> bool:
    return x is not None and math.isfinite(x)


def trial_metrics(res: dict, trials, path: Path) -> None:
    """Mean ± SD bars with every trial as a dot, for four metrics."""
    shown = [m for m in TRIAL_METRICS if m[0] in ("time_to_goal_s", "wall_collisions", "contact_time_s", "mean_force_n")]
    fig, axes = plt.subplots(2, 2, figsize=TRIALS_SIZE, dpi=DPI)
    rng = np.random.default_rng(0)
    x = np.arange(len(CONDITIONS))
    for ax, (col, label, completed_only) in zip(axes.ravel(), shown):
        means, sds = [], []
        for i, c in enumerate(CONDITIONS):
            entry = res["trial_metrics"][c][col]
            means.append(_nan0(entry["mean"]))
            sds.append(_nan0(entry["sd"]))
            sub = trials[trials["condition"] == c]
            if completed_only:
                sub = sub[sub["completed"] == 1]
            vals = sub[col].to_numpy(dtype=float)
            if vals.size:
                ax.scatter(i + rng.uniform(-0.15, 0.15, vals.size), vals, s=10, color="black",
                           alpha=0.6, zorder=3)
        ax.bar(x, means, 0.6, yerr=sds, capsize=6, color=[COLOURS[c] for c in CONDITIONS],
               edgecolor="black", linewidth=0.5, alpha=0.8)
        ax.set_xticks(x, [CONDITION_LABELS[c] for c in CONDITIONS], fontsize=9)
        ax.set_title(label + (" (completed trials)" if completed_only else ""), fontsize=10)
        ax.set_ylim(bottom=0)
        ax.grid(axis="y", alpha=0.3)
        ax.set_axisbelow(True)
        if trials.empty:
            ax.text(0.5, 0.5, "no trials", transform=ax.transAxes, ha="center", va="center")
    fig.suptitle("Trial metrics by condition (mean ± SD; dots: trials)")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
