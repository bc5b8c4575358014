"""Reading and strict validation of a study folder (the format is defined in FORMAT.md and
assets/study/study_schema.json).

Every problem is collected as an `Issue` (tables.py) naming the file, the line and what is
wrong. A participant with at least one error is invalid; the caller decides whether that
aborts the run or excludes the participant. Warnings never invalidate a participant but are
always reported. The files are read by json_files.py and csv_files.py.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from csv_files import check_ratings, check_trials
from fields import ID_RE
from json_files import check_final, check_participant_json
from schema import (
    CONDITIONS,
    FINAL_FILE,
    PARTICIPANT_FILE,
    PATTERNS,
    RATINGS_FILE,
    RESERVED_DIR_NAMES,
    TELEMETRY_DIR,
    TRIALS_FILE,
)
from tables import Issue


@dataclass
class Participant:
    id: str
    folder: Path
    meta: dict | None = None
    ratings: list[dict] = field(default_factory=list)
    trials: list[dict] = field(default_factory=list)
    final: dict | None = None
    errors: list[Issue] = field(default_factory=list)
    warnings: list[Issue] = field(default_factory=list)

    @property
    def valid(self) -> bool:
        return not self.errors

    @property
    def rated_conditions(self) -> list[str]:
        return [c for c in CONDITIONS if any(r["condition"] == c for r in self.ratings)]

    @property
    def complete(self) -> bool:
        return len(self.rated_conditions) == len(CONDITIONS)


@dataclass
class Study:
    folder: Path
    participants: list[Participant]
    errors: list[Issue] = field(default_factory=list)  # study-level problems
    warnings: list[Issue] = field(default_factory=list)  # study-level doubts
    @property
    def valid_participants(self) -> list[Participant]:
        return [p for p in self.participants if p.valid]

    @property
    def invalid_participants(self) -> list[Participant]:
        return [p for p in self.participants if not p.valid]

    def all_errors(self) -> list[Issue]:
        out = list(self.errors)
        for p in self.participants:
            out.extend(p.errors)
        return out

    def all_warnings(self) -> list[Issue]:
        return list(self.warnings) + [w for p in self.participants for w in p.warnings]


def load_participant(folder: Path) -> Participant:
    p = Participant(id=folder.name, folder=folder)
    if not ID_RE.match(p.id):
        p.errors.append(Issue(p.id, None, f"folder name is not a valid participant id ({PATTERNS['id'][1:-1]})"))
        return p
    check_participant_json(p)
    check_ratings(p)
    referenced = check_trials(p)
    check_final(p)
    known = {PARTICIPANT_FILE, RATINGS_FILE, TRIALS_FILE, FINAL_FILE, TELEMETRY_DIR}
    for entry in sorted(folder.iterdir()):
        if entry.name not in known and not entry.name.startswith("."):
            p.warnings.append(Issue(f"{p.id}/{entry.name}", None, "unexpected file, ignored"))
    tel_dir = folder / TELEMETRY_DIR
    if tel_dir.is_dir():
        for entry in sorted(tel_dir.iterdir()):
            name = f"{TELEMETRY_DIR}/{entry.name}"
            if name not in referenced:
                p.warnings.append(
                    Issue(f"{p.id}/{name}", None,
                          "not referenced by trials.csv (an interrupted trial?): not validated, not analysed")
                )
    return p


def load_study(folder: Path, skip_dirs: tuple[Path, ...] = ()) -> Study:
    folder = Path(folder)
    study = Study(folder=folder, participants=[])
    if not folder.is_dir():
        study.errors.append(Issue(str(folder), None, "study folder does not exist"))
        return study
    skip = {d.resolve() for d in skip_dirs}
    for entry in sorted(folder.iterdir()):
        if not entry.is_dir() or entry.name.startswith((".", "_")) or entry.name in RESERVED_DIR_NAMES:
            continue
        if entry.resolve() in skip:
            continue
        study.participants.append(load_participant(entry))
    if not study.participants:
        study.errors.append(Issue(str(folder), None, "no participant folders found"))
    study.warnings.extend(mixed_contact_models(study.valid_participants, str(folder)))
    return study


def contact_models_of(trials: list[dict]) -> Counter:
    """How many of these trials ran each contact model (trials recording none left out)."""
    return Counter(t["contact_model"] for t in trials if t["contact_model"] != "")


def mixed_contact_models(participants: list[Participant], where: str) -> list[Issue]:
    """A warning per condition whose trials ran more than one contact model: its trial
    metrics (forces above all) then mix two renderings."""
    out = []
    for c in CONDITIONS:
        models = contact_models_of([t for p in participants for t in p.trials if t["condition"] == c])
        if len(models) > 1:
            counts = ", ".join(f"{m}: {n}" for m, n in sorted(models.items()))
            out.append(Issue(where, None, f"condition {c!r}: trials ran several contact models ({counts}); "
                                          "its trial metrics mix them"))
    return out
