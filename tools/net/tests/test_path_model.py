"""The path model's decisions without sockets: the burst chain's parameters and what it
loses over many datagrams, duplicates, release order and the counts."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from path_model import BurstLoss, Lane, PathModel  # noqa: E402

DATAGRAMS = 200_000


def loss_runs(p_lost: list[bool]) -> list[int]:
    """Lengths of the runs of consecutive losses."""
    runs, length = [], 0
    for lost in p_lost:
        if lost:
            length += 1
        elif length:
            runs.append(length)
            length = 0
    if length:
        runs.append(length)
    return runs


@pytest.mark.parametrize("loss, burst", [(0.10, 6.5), (0.02, 1.5), (0.30, 3.0), (0.5, 1.0)])
def test_chain_from_mean_has_that_mean(loss, burst):
    chain = BurstLoss.from_mean(loss, burst)
    assert chain.average_loss == pytest.approx(loss, rel=1e-12)
    assert chain.mean_burst == pytest.approx(burst, rel=1e-12)
    assert 0.0 < chain.enter_bad <= 1.0 and 0.0 < chain.leave_bad <= 1.0


@pytest.mark.parametrize("loss, burst, why", [
    (0.0, 5.0, "burst loss"), (1.0, 5.0, "burst loss"), (0.1, 0.9, "at least 1"),
    (0.6, 1.0, "at most 0.500"), (0.9, 5.0, "at most 0.833"),
])
def test_impossible_chains_are_refused(loss, burst, why):
    with pytest.raises(ValueError, match=why):
        BurstLoss.from_mean(loss, burst)


def run_lane(p_model: PathModel, p_count: int, p_seed: str = "7") -> tuple[Lane, list[bool]]:
    """Admits [p_count] datagrams one per millisecond and releases every copy at once."""
    lane = Lane(p_model, random.Random(p_seed))
    lost = []
    for i in range(p_count):
        copies = lane.admit(i / 1000.0)
        lost.append(not copies)
        for sequence, _ in copies:
            lane.release(sequence, 10)
    return lane, lost


def test_bursts_lose_the_asked_share_in_runs_of_the_asked_mean():
    lane, lost = run_lane(PathModel(bursts=BurstLoss.from_mean(0.10, 6.5)), DATAGRAMS)
    runs = loss_runs(lost)
    # About 3000 bursts: the share and the mean are within a few per cent; 10 % is > 4 sd.
    assert sum(lost) / DATAGRAMS == pytest.approx(0.10, rel=0.10)
    assert sum(runs) / len(runs) == pytest.approx(6.5, rel=0.10)
    assert lane.stats.dropped == sum(lost) and lane.stats.loss_runs == len(runs)
    # A Markov chain's bursts are geometric: one in 6.5 is a single datagram, whatever the
    # mean (a chain cannot keep bursts within 3..10).
    assert sum(1 for r in runs if r == 1) / len(runs) == pytest.approx(1 / 6.5, abs=0.03)


def test_independent_loss_is_not_bursty():
    _, lost = run_lane(PathModel(loss=0.10), DATAGRAMS)
    runs = loss_runs(lost)
    assert sum(lost) / DATAGRAMS == pytest.approx(0.10, rel=0.05)
    assert sum(runs) / len(runs) == pytest.approx(1 / 0.9, rel=0.05)


def test_default_options_draw_what_the_relay_drew_before():
    """A seed gives the drops and delays it gave before the path model: the lane draws the
    loss, then the delay, nothing else (the network tests' seeds stay meaningful)."""
    model = PathModel(delay_s=0.05, jitter_s=0.01, loss=0.2)
    lane, old = Lane(model, random.Random("1/0/up")), random.Random("1/0/up")
    for _ in range(2000):
        expected = None if old.random() < 0.2 else 0.05 + old.uniform(0.0, 0.01)
        copies = lane.admit(0.0)
        assert (copies[0][1] if copies else None) == expected


def test_duplicates_about_the_asked_share_each_with_its_own_delay():
    model = PathModel(delay_s=0.2, jitter_s=0.06, centred=True, duplicate=0.01)
    lane = Lane(model, random.Random("3"))
    twins = [copies for copies in (lane.admit(0.0) for _ in range(DATAGRAMS))
             if len(copies) == 2]
    # Binomial(200000, 0.01): mean 2000, sd 44.
    assert 1800 <= len(twins) <= 2200 and lane.stats.duplicated == len(twins)
    assert all(a[0] == b[0] for a, b in twins)
    assert sum(1 for a, b in twins if a[1] != b[1]) == len(twins)
    assert all(0.14 <= t <= 0.26 for copies in twins for _, t in copies)


def test_centred_jitter_spans_delay_plus_minus_jitter():
    lane = Lane(PathModel(delay_s=0.2, jitter_s=0.06, centred=True), random.Random("4"))
    delays = [lane.admit(0.0)[0][1] for _ in range(10_000)]
    assert 0.14 <= min(delays) < 0.142 and 0.258 < max(delays) <= 0.26
    assert sum(delays) / len(delays) == pytest.approx(0.2, abs=0.002)


def test_in_order_lane_never_releases_a_later_datagram_first():
    lane = Lane(PathModel(delay_s=0.2, jitter_s=0.06, centred=True, reorder=False,
                          duplicate=0.05), random.Random("5"))
    releases = [t for i in range(5000) for _, t in lane.admit(i / 1000.0)]
    assert all(b > a for a, b in zip(releases, releases[1:]))
    # Still delayed by the path: never sooner than the shortest draw after arrival.
    assert releases[0] >= 0.14


def test_reordered_and_overtaking_count_both_sides_of_an_overtake():
    lane = Lane(PathModel(), random.Random("6"))
    for _ in range(4):
        lane.admit(0.0)
    for sequence in (2, 0, 3, 1):
        assert lane.release(sequence, 1)
    # 2 overtook 0 and 1, 3 overtook 1: two overtakers; 0 and 1 came after a newer one.
    assert lane.stats.overtaking == 2
    assert lane.stats.reordered == 2
    assert lane.stats.delivered == 4 and lane.stats.bytes_delivered == 4


def test_a_cut_drops_arrivals_and_what_is_on_its_way_and_every_datagram_is_counted_once():
    model = PathModel(delay_s=0.1, jitter_s=0.05, loss=0.05,
                      bursts=BurstLoss.from_mean(0.1, 4.0), duplicate=0.1)
    lane = Lane(model, random.Random("8"))
    on_way = [copy for i in range(500) for copy in lane.admit(i / 1000.0)]
    for sequence, _ in on_way[:100]:
        lane.release(sequence, 1)
    lane.cut = True
    assert lane.admit(1.0) == []
    for sequence, _ in on_way[100:200]:
        assert not lane.release(sequence, 1)
    lane.cut = False
    lane.lost_on_way(on_way[200][0])
    lane.abandon()
    s = lane.stats
    assert s.blackholed == 101 and s.undelivered == len(on_way) - 200 and s.delivered == 100
    assert s.received + s.duplicated == s.dropped + s.blackholed + s.delivered + s.undelivered


@pytest.mark.parametrize("fields", [
    {"delay_s": -0.1}, {"jitter_s": -0.1}, {"loss": 1.0}, {"duplicate": -0.1},
    {"delay_s": 0.05, "jitter_s": 0.06, "centred": True},
])
def test_impossible_paths_are_refused(fields):
    with pytest.raises(ValueError):
        PathModel(**fields)
