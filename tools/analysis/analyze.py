#!/usr/bin/env python3
"""Analyse a maze-study folder (format: tools/analysis/FORMAT.md).

    analyze.py STUDY_DIR [--out OUT_DIR] [--skip-invalid]

Writes into OUT_DIR (default STUDY_DIR/analysis): fig6_criteria.png, fig7_total.png,
trial_metrics.png, report.md and summary.json.

Exit status: 0 done; 1 the data has problems (each printed as FILE:LINE: what) and nothing
was written, or no valid participant is left; 2 bad usage. With --skip-invalid, invalid
participants are excluded and listed in the report (and on stderr) instead of aborting.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import studydata

EXIT_OK, EXIT_DATA, EXIT_USAGE = 0, 1, 2


def load_checked(study_dir: Path, skip_invalid: bool, tool: str, skip_dirs=()) -> studydata.Study | None:
    """Loads and validates; prints every problem. None when the caller must exit EXIT_DATA."""
    study = studydata.load_study(study_dir, skip_dirs=skip_dirs)
    for w in study.all_warnings():
        print(f"{tool}: warning: {w}", file=sys.stderr)
    if study.errors:
        for e in study.errors:
            print(f"{tool}: error: {e}", file=sys.stderr)
        return None
    invalid = study.invalid_participants
    for p in invalid:
        for e in p.errors:
            print(f"{tool}: error: {e}", file=sys.stderr)
    if invalid and not skip_invalid:
        n = sum(len(p.errors) for p in invalid)
        print(
            f"{tool}: {n} problem(s) in {len(invalid)} participant folder(s): "
            f"{', '.join(p.id for p in invalid)}. Nothing written. Fix the data, or pass "
            "--skip-invalid to exclude these participants (they are listed in the output).",
            file=sys.stderr,
        )
        return None
    if invalid:
        print(f"{tool}: excluding invalid participant(s): {', '.join(p.id for p in invalid)}", file=sys.stderr)
    if not study.valid_participants:
        print(f"{tool}: no valid participant left", file=sys.stderr)
        return None
    return study


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("study_dir", type=Path, metavar="STUDY_DIR")
    parser.add_argument("--out", type=Path, metavar="OUT_DIR", help="default: STUDY_DIR/analysis")
    parser.add_argument("--skip-invalid", action="store_true",
                        help="exclude (and list) invalid participants instead of failing")
    args = parser.parse_args(argv)
    if not args.study_dir.is_dir():
        print(f"analyze.py: {args.study_dir}: not a directory", file=sys.stderr)
        return EXIT_USAGE
    out = args.out or args.study_dir / "analysis"
    study = load_checked(args.study_dir, args.skip_invalid, "analyze.py", skip_dirs=(out,))
    if study is None:
        return EXIT_DATA

    # Heavy imports only once the data is known to be usable.
    import figures
    import report
    import results

    res = results.compute(study)
    out.mkdir(parents=True, exist_ok=True)
    names = {"fig6": "fig6_criteria.png", "fig7": "fig7_total.png", "trials": "trial_metrics.png"}
    figures.fig6_criteria(res, out / names["fig6"])
    figures.fig7_total(res, out / names["fig7"])
    figures.trial_metrics(res, results.trials_frame(study.valid_participants), out / names["trials"])
    (out / "report.md").write_text(report.render(res, names), encoding="utf-8")
    summary = results.json_ready(res)
    (out / "summary.json").write_text(json.dumps(summary, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")

    t = res["tests"]
    from stats import fmt_f

    print(f"analyze.py: {len(res['participants']['valid'])} valid participant(s) "
          f"({len(res['participants']['complete'])} complete); wrote {out}/")
    print(f"  one-way ANOVA (paper style): {fmt_f(t['oneway_anova_pooled_ratings'], 'df_between', 'df_within')}")
    print(f"  repeated-measures ANOVA:     {fmt_f(t['rm_anova_total'], 'df_conditions', 'df_error')}")
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
