"""Scenario 4: a participant and a researcher go through the maze study at the screen: the
start screen (an ID typed, every question of the demographics chosen from its list, consent
ticked), a look at the practice, then each of the three methods: the "hold still at the
start" card (the handle's dot brought into the ring that is drawn, with the arrow keys, and
held still), the maze steered to the flag with the arrow keys by what the screen shows, and
the six ratings; then the favourite, Finish, the thank-you and back to the menu."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from scipy import ndimage

from maze_eyes import Way, goal_at, pixels_of
from ocr import Region
from person import Person
from sub_eyes import chord_toward, sub_at

METHODS = 3
# Generous bounds for a loaded machine: a person takes about 20-40 s through a maze.
MAZE_PATIENCE_S = 150.0
HOLD_PATIENCE_S = 60.0
# The gauge's colours (game/study/screens/centre_gauge.gd): the zone's green ring and the
# handle's dot, orange outside the zone and white inside.
ZONE_GREEN = (102, 217, 140)
DOT_OUTSIDE = (247, 130, 84)
# How far from its ring's centre the gauge draws the dot, at most (its disc's radius).
GAUGE_REACH_PX = 60


def _near(pixels: np.ndarray, colour: tuple[int, int, int], tolerance: int) -> np.ndarray:
    return np.abs(pixels - np.array(colour)).max(axis=2) <= tolerance


def choose_every_demographic(person: Person) -> int:
    """Opens each list still saying "Choose…" and clicks the first answer under it."""
    chosen = 0
    for _ in range(10):
        button = person.find_text("Choose", patience=2.0)
        if button is None:
            break
        person.click(*button.center)
        # The open list: its rows start under the button, their words where the button's
        # text starts; the first row repeats "Choose…", the second is the first answer.
        under = Region(max(0, button.left - 40), button.bottom, 480, 320)
        rows = sorted((w for w in person.read_screen(region=under)
                       if w.top > button.bottom + 4 and abs(w.left - button.left) < 30),
                      key=lambda w: w.top)
        tops: list[int] = []
        for word in rows:
            if not tops or word.top - tops[-1] > 10:
                tops.append(word.top)
        assert len(tops) >= 2, f"the list under {button} did not open"
        answer = min((w for w in rows if abs(w.top - tops[1]) <= 10), key=lambda w: w.left)
        person.click(answer.left + answer.width // 2, answer.top + answer.height // 2)
        chosen += 1
    return chosen


def hold_still_at_the_start(person: Person, scratch) -> float:
    """Brings the gauge's dot into its ring with short taps of the arrow keys, then holds
    still until the card goes; returns how long it took."""
    started = time.monotonic()
    while time.monotonic() - started < HOLD_PATIENCE_S:
        if not person.still_shows("Hold still"):
            return time.monotonic() - started
        pixels = pixels_of(person.grab(scratch / "gauge.png"))
        ring = np.argwhere(_near(pixels, ZONE_GREEN, 40))
        if len(ring):
            centre = ring.mean(axis=0)
            # The dot is on the gauge's disc, near its ring (the card's heading and the
            # flag are orange too).
            dot = np.argwhere(_near(pixels, DOT_OUTSIDE, 30))
            dot = dot[np.abs(dot - centre).max(axis=1) < GAUGE_REACH_PX]
        if len(ring) and len(dot):
            where = dot.mean(axis=0)
            keys = chord_toward((where[1], where[0]), (centre[1], centre[0]))
            person.hold_keys(keys, 0.08)
        time.sleep(0.3)
    raise AssertionError(f"the hold-still card stayed {HOLD_PATIENCE_S:.0f} s")


def steer_through_the_maze(person: Person, scratch) -> float:
    """Holds the arrow keys toward a point a little ahead on the way to the flag, looking
    again after each move, until "Goal!" shows; returns the time it took."""
    first = pixels_of(person.grab(scratch / "maze.png"))
    goal = goal_at(first)
    assert goal is not None, "no flag seen in the maze"
    way = Way(first, goal)
    started = time.monotonic()
    try:
        looks = 0
        while time.monotonic() - started < MAZE_PATIENCE_S:
            pixels = pixels_of(person.grab(scratch / "maze.png"))
            looks += 1
            sub = sub_at(pixels)
            if sub is not None:
                ahead = way.ahead(sub, 48.0)
                if ahead is not None:
                    person.hold_only(chord_toward(sub, ahead))
            # The goal card shows a moment, then the ratings: a person reads the screen
            # when the sub is gone from it, and now and then.
            if sub is None or looks % 20 == 0:
                person.hold_only([])
                if person.find_text("Rate the method", patience=0.0) is not None:
                    return time.monotonic() - started
    finally:
        person.hold_only([])
    shot = person.screenshot("maze-not-solved")
    raise AssertionError(f"the flag was not reached within {MAZE_PATIENCE_S:.0f} s ({shot})")


# The rating buttons' fill (the study theme's buttons): a person sees ten boxes a row.
BUTTON_FILL = (23, 59, 92)


def rating_boxes(pixels: np.ndarray) -> list[list[tuple[float, float]]]:
    """The centres of the rating screen's number boxes, a list of rows top to bottom, each
    row left to right (1 to 10)."""
    labels, count = ndimage.label(_near(pixels, BUTTON_FILL, 6))
    boxes = []
    for i, found in enumerate(ndimage.find_objects(labels), 1):
        h, w = found[0].stop - found[0].start, found[1].stop - found[1].start
        if 30 <= w <= 70 and 30 <= h <= 70 and abs(w - h) < 12:
            boxes.append(((found[1].start + found[1].stop) / 2, (found[0].start + found[0].stop) / 2))
    rows: list[list[tuple[float, float]]] = []
    for box in sorted(boxes, key=lambda b: b[1]):
        if rows and abs(rows[-1][0][1] - box[1]) < 15:
            rows[-1].append(box)
        else:
            rows.append([box])
    return [sorted(row) for row in rows if len(row) == 10]


def rate_everything(person: Person, scratch) -> None:
    """Clicks the 7 of each criterion's row of ten, then Submit ratings."""
    person.wait_text("Rate the method", patience=60.0)
    rows = rating_boxes(pixels_of(person.grab(scratch / "ratings.png")))
    assert len(rows) == 6, f"{len(rows)} rows of ten rating boxes seen, not six"
    for row in rows:
        person.click(round(row[6][0]), round(row[6][1]))
    person.click_text("Submit ratings")


def test_a_participant_goes_through_the_maze_study(shipped_session) -> None:
    session = shipped_session
    person = session.person
    started = time.monotonic()
    person.click_text("Maze study", patience=90.0)
    participant = f"P{int(time.time()) % 100000}"
    person.type_into(person.wait_text("Participant ID"), participant)
    chosen = choose_every_demographic(person)
    person.click_text("The participant has read this")
    person.screenshot("start-screen")
    person.click_text("Start", below=500)
    person.wait_text("I'm ready", patience=60.0)
    person.screenshot("practice")
    # The button, at the right of the bar (the line under the title names it too).
    ready = max(person.find_all("I'm ready"), key=lambda b: b.left)
    person.click(*ready.center)
    for method in range(1, METHODS + 1):
        person.wait_text(f"Method {method} of 3", patience=60.0)
        start = person.find_text("Start", patience=10.0, below=200)
        if start is not None:
            person.click(*start.center)
        person.wait_text("Hold still", patience=30.0)
        person.keep_look(f"method-{method}-hold-still")
        held = hold_still_at_the_start(person, session.scratch)
        person.screenshot(f"method-{method}-maze")
        took = steer_through_the_maze(person, session.scratch)
        person.screenshot(f"method-{method}-goal")
        print(f"person: study: method {method}: held still in {held:.1f} s, the maze in {took:.0f} s "
              f"({len(person.ocr_seconds)} OCR passes so far)")
        rate_everything(person, session.scratch)
    person.wait_text("Finish", patience=60.0)
    person.click_text("Method 1")
    person.screenshot("favourite")
    person.click_text("Finish")
    person.wait_text("Thank you", patience=30.0)
    person.screenshot("thank-you")
    person.click_text("Back to menu")
    person.wait_text("Haptic Battle Pong", patience=30.0)
    took = person.close_and_see_it_exit(session.game)
    # What the researcher takes home: the participant's folder in the study's data folder
    # (the start screen names it: the game's user data, in the player's XDG data folder).
    data_home = Path(session.display.env()["XDG_DATA_HOME"])
    folders = list(data_home.glob(f"godot/app_userdata/*/study/{participant}"))
    assert folders, f"no study folder for {participant} under {data_home}"
    written = sorted(f.name for f in folders[0].iterdir())
    for name in ("participant.json", "trials.csv", "ratings.csv", "final.json"):
        assert name in written, f"{name} missing from {folders[0]}: {written}"
    print(f"person: study: {participant}'s folder holds {', '.join(written)}")
    print(f"person: study: {chosen} demographics chosen; the whole study "
          f"{time.monotonic() - started:.0f} s; the game ended {took:.1f} s after its window closed")
