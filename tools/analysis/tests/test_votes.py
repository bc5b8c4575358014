"""(b) Favourite votes: k favourites give each 1/k vote (the paper split votes by halves)."""

from __future__ import annotations

import pytest

import results
import stats
import studydata
import studywriter as w

C = ("none", "movement", "constraint")


def test_paper_split_by_halves(tmp_path):
    # The paper: "No feedback was preferred by one subject, and three and four votes were given
    # to the movement and constraint methods ... others voted for two methods, each method was
    # given half a point." Ten participants reproducing 1 / 3 / 4 with two split votes and two
    # abstentions.
    favourites = [["none"], ["movement"], ["movement"], ["constraint"], ["constraint"], ["constraint"],
                  ["movement", "constraint"], ["constraint", "movement"], [], []]
    for i, fav in enumerate(favourites):
        w.make_participant(tmp_path, f"P{i:02d}", {c: 5 for c in C}, favourite=fav)
    res = results.compute(studydata.load_study(tmp_path))
    fav = res["favourite"]
    assert fav["votes"] == {"none": 1.0, "movement": 3.0, "constraint": 4.0}
    assert (fav["voters"], fav["abstained"], fav["answered"]) == (8, 2, 10)
    assert fav["no_final_json"] == []


def test_split_by_thirds_and_missing_final(tmp_path):
    w.make_participant(tmp_path, "A", {c: 5 for c in C}, favourite=["none", "movement", "constraint"])
    w.make_participant(tmp_path, "B", {c: 5 for c in C}, favourite=["movement"])
    w.make_participant(tmp_path, "C", {c: 5 for c in C}, favourite=["none", "constraint"])
    w.make_participant(tmp_path, "D", {c: 5 for c in C}, favourite=None)  # no final.json
    res = results.compute(studydata.load_study(tmp_path))
    votes = res["favourite"]["votes"]
    assert votes["none"] == pytest.approx(1 / 3 + 1 / 2)
    assert votes["movement"] == pytest.approx(1 / 3 + 1)
    assert votes["constraint"] == pytest.approx(1 / 3 + 1 / 2)
    assert sum(votes.values()) == pytest.approx(3.0)  # one vote per voter in total
    assert res["favourite"]["no_final_json"] == ["D"]
    assert res["favourite"]["answered"] == 3


def test_vote_function_directly():
    v = stats.favourite_votes([["none", "movement"], [], ["movement"]], C)
    assert v["votes"] == {"none": 0.5, "movement": 1.5, "constraint": 0.0}
    assert (v["voters"], v["abstained"]) == (2, 1)
