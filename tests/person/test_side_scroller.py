"""Scenario 1: a person plays the side-scroller's level 1 with the keyboard, from the main menu
through the pause menu and its Settings to the goal, steering by what they see; then the goal
screen's Menu button, and they quit by closing the window. Played once, in the build a player
starts (the exported game; from source where none is exported): the longest scenario, and the
source tree's level is played by the autopilot suites."""

from __future__ import annotations

import math
import os
import re
import shutil
import time
from pathlib import Path

from person import Person
from sub_eyes import Approach, Route, Whereabouts, chord_toward

# Level 1's way to the goal as a person who has played it learns it: where the sub goes, in
# the level's pixels, from the start to the goal (the level's own path, game/levels/
# level_1.tscn, AutopilotPath, read once by a developer; the test never reads the game).
ROUTE = [(240, 520), (560, 565), (700, 640), (1100, 840), (1500, 1010), (1900, 1060),
         (2200, 1060), (2460, 1000), (2650, 800), (2720, 660), (2900, 640), (3340, 650),
         (3500, 650), (4290, 650), (4370, 590), (4540, 410), (4690, 335), (4850, 470),
         (5060, 740), (5320, 860), (5800, 1010), (6260, 1050), (6620, 1010), (6900, 720),
         (7150, 560), (7350, 550), (7700, 600), (8100, 600), (8420, 650)]
# Generous for a loaded machine: the sub's top speed covers the route in about 30 s.
PLAY_PATIENCE_S = 120.0
# A person reads the screen when the sub has not moved for this many looks: the goal screen
# stops the level (or the sub is stuck, and they look at what happened).
STILL_LOOKS = 6
# No further along the route than this in this long, a person is stuck: they try another
# way, an eighth of a turn up, then down, then two up, two down... until they get on.
STUCK_S = 5.0
PROGRESS_PX = 60.0
LIFTS = [1, -1, 2, -2, 3, -3]
# A folder to keep every look in, numbered as the trail's rows (PERSON_KEEP_LOOKS; about
# 1 MB a look): what the person saw when the way they went needs explaining.
KEEP_LOOKS = os.environ.get("PERSON_KEEP_LOOKS", "")


def items_collected(person: Person) -> str:
    """The HUD's items count as a person reads it (the number after ITEMS)."""
    words = person.read_screen()
    for i, w in enumerate(words):
        if w.text.upper() == "ITEMS":
            # The HUD's zero reads as a Q or an O.
            rest = " ".join(x.text for x in words[i + 1:i + 4]).translate(str.maketrans("QOo", "000"))
            m = re.match(r"(\d+)\s*/\s*(\d*)", rest)
            if m:
                return f"{m.group(1)} / {m.group(2) or '?'}"
    return "unread"


def steer_to_the_goal(person: Person, scratch) -> tuple[bool, int]:
    """Holds the arrow keys toward the route a little ahead of where the sub is seen, looking
    again after each move, until the goal screen shows or the patience runs out. Returns
    whether the goal screen showed, and how many looks it took."""
    where = Whereabouts(ROUTE[0])
    route = Route(ROUTE)
    approach = Approach()
    started = time.monotonic()
    looks = 0
    still = 0
    tries = 0
    progress = (0.0, started)
    last = None
    shot_at = 0.0
    trail = open(person.shots / "trail.csv", "w", encoding="utf-8")
    trail.write("t_s,x,y,along,off,sub_x,sub_y,goal_x,goal_y,scroll_x,scroll_y,agreement,keys\n")
    try:
        while time.monotonic() - started < PLAY_PATIENCE_S:
            look = person.grab(scratch / "level.png")
            looks += 1
            if KEEP_LOOKS:
                shutil.copy(look, Path(KEEP_LOOKS) / f"{looks:04d}.png")
            here = where.look(look)
            keys: list[str] = []
            if here is not None:
                ahead = route.aim(here)
                now = time.monotonic()
                if route.reached >= progress[0] + PROGRESS_PX:
                    progress, tries = (route.reached, now), 0
                elif now - progress[1] > STUCK_S and where.goal is None:
                    progress, tries = (progress[0], now), tries + 1
                    print(f"person: stuck at {here} ({route.reached:.0f} px along): trying "
                          f"{LIFTS[(tries - 1) % len(LIFTS)]:+d} eighth(s) of a turn up")
                lift = LIFTS[(tries - 1) % len(LIFTS)] if tries else 0
                tap = None
                # The goal in view, a person closes in on it; else they go along the route.
                if where.sub is not None and where.goal is not None:
                    keys, tap = approach.keys(where.sub, where.goal, now)
                else:
                    approach.forget()
                    keys = chord_toward(here, ahead, lift)
                person.hold_only(keys)
                if tap is not None:
                    time.sleep(tap)
                    person.hold_only([])
                still = still + 1 if last is not None and math.dist(here, last) < 2.0 else 0
                last = here
            trail.write(",".join(f"{v:.0f}" if isinstance(v, float) else str(v) for v in (
                f"{time.monotonic() - started:.2f}", *(here or ("", "")), route.reached, route.off,
                *(where.sub or ("", "")), *(where.goal or ("", "")), *where.scroll[:2],
                f"{where.scroll[2]:.3f}", "+".join(keys))) + "\n")
            if looks % 10 == 0:
                print(f"person: look {looks}: at {here}, {route.reached:.0f} px along the route")
            if route.reached >= shot_at:
                person.screenshot(f"on-the-way-{route.reached / route.length:.0%}")
                shot_at += route.length / 5
            if still >= STILL_LOOKS:
                person.hold_only([])
                if person.find_text("Goal reached", patience=0.0) is not None:
                    return True, looks
                still = 0
    finally:
        person.hold_only([])
        trail.close()
    return False, looks


def test_a_person_plays_level_1_with_keys(shipped_session) -> None:
    session = shipped_session
    person = session.person
    game = session.game
    timings: dict[str, float] = {}
    started = time.monotonic()

    # The main menu, then its Play button: level 1.
    play = person.wait_text("Play", patience=90.0)
    person.screenshot("main-menu")
    timings["menu shown"] = time.monotonic() - started
    # The title bar names the game as the menu does, and no more (debug builds add " (DEBUG)").
    titles = game.window_titles()
    assert titles and all("DEBUG" not in t for t in titles), f"window titles {titles}"
    person.click(*play.center)
    person.wait_text("ITEMS", patience=60.0)
    person.screenshot("level-1")

    # Pause, its Settings, back, resume.
    person.press("Escape")
    person.wait_text("Paused")
    person.screenshot("paused")
    person.click_text("Settings")
    person.wait_text("Force scale")
    person.screenshot("settings")
    person.click_text("Back")
    resume = person.wait_text("Resume")
    person.screenshot("paused-again")
    person.click(*resume.center)
    if not person.wait_gone("Resume", patience=10.0):
        shot = person.screenshot("still-paused")
        raise AssertionError(f"Resume was clicked and the pause menu stayed ({shot})")
    timings["menus"] = time.monotonic() - started

    # Play to the goal with the arrow keys, steering by what the screen shows.
    play_started = time.monotonic()
    reached, looks = steer_to_the_goal(person, session.scratch)
    timings["playing"] = time.monotonic() - play_started
    if not reached:
        shot = person.screenshot("where-the-person-got")
        # The CI keeps only the output: the way the person went, every 5th look.
        rows = (person.shots / "trail.csv").read_text(encoding="utf-8").splitlines()
        raise AssertionError(
            f"the goal screen did not show within {PLAY_PATIENCE_S:.0f} s of steering by the "
            f"screen ({looks} looks; items {items_collected(person)}; last screen: {shot}); "
            "the way they went:\n" + "\n".join(rows[:1] + rows[1::5]))
    person.screenshot("goal")
    print(f"person: level 1 with keys: the goal reached {timings['playing']:.0f} s after "
          f"resuming, {looks} looks ({timings['playing'] / looks:.2f} s each)")

    # The goal screen's Menu button leads back to the main menu.
    person.click_text("Menu")
    person.wait_text("Haptic Battle Pong")
    person.screenshot("back-at-the-menu")

    # Quit by closing the window: the game must exit by itself, with 0.
    timings["quit"] = person.close_and_see_it_exit(game)
    timings["total"] = time.monotonic() - started
    print("person: timings " + ", ".join(f"{k} {v:.1f} s" for k, v in timings.items()))
