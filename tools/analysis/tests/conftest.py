"""Shared helpers: the hand-computed dataset and a runner for the command-line tools."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import studywriter as w

ANALYSIS_DIR = Path(__file__).resolve().parent.parent

# Total rating (= every criterion's offset cancels) per participant and condition.
#            none movement constraint
HAND_TOTALS = {
    "S1": (3, 5, 6),
    "S2": (5, 6, 8),
    "S3": (4, 4, 5),
    "S4": (6, 7, 9),
}
# Each cell's six criteria are total + these offsets (mean offset 0, within-cell SS 4).
OFFSETS = (-1, +1, 0, 0, -1, +1)


def hand_criteria(total: int) -> list[int]:
    return [total + o for o in OFFSETS]


def write_hand_study(root: Path) -> Path:
    """Four complete participants with the totals above; orders rotate (Latin square)."""
    orders = [
        ("none", "movement", "constraint"),
        ("movement", "constraint", "none"),
        ("constraint", "none", "movement"),
        ("none", "movement", "constraint"),
    ]
    for (pid, totals), order in zip(HAND_TOTALS.items(), orders):
        ratings = {c: hand_criteria(t) for c, t in zip(("none", "movement", "constraint"), totals)}
        w.make_participant(root, pid, ratings, favourite=["constraint"], condition_order=order,
                           counterbalancing="latin_square")
    return root


def run_tool(script: str, *args, cwd: Path | None = None) -> subprocess.CompletedProcess:
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, str(ANALYSIS_DIR / script), *map(str, args)],
                          capture_output=True, text=True, env=env, cwd=cwd)


@pytest.fixture
def hand_study(tmp_path: Path) -> Path:
    return write_hand_study(tmp_path / "study")
