"""Scenario 1: a person plays the side-scroller's level 1 with the keyboard, from the main menu
through the pause menu and its Settings to the goal, and quits by closing the window."""

from __future__ import annotations

import math
import re
import time

import pytest

from person import SCREEN, Box, Person

# Level 1's way to the goal as a person who has played it learns it: where the sub goes, in
# the level's pixels, from the start to the goal (the level's own path, game/levels/
# level_1.tscn, AutopilotPath, read once by a developer; the test never reads the game).
ROUTE = [(240, 520), (560, 565), (700, 640), (1100, 840), (1500, 1010), (1900, 1060),
         (2200, 1060), (2460, 1000), (2650, 800), (2720, 660), (2900, 640), (3340, 650),
         (3500, 650), (4290, 650), (4370, 590), (4540, 410), (4690, 335), (4850, 470),
         (5060, 740), (5320, 860), (5800, 1010), (6260, 1050), (6620, 1010), (6900, 720),
         (7150, 560), (7350, 550), (7700, 600), (8100, 600), (8420, 650)]
# The level's water (left, top, width, height), where the sub is slower.
WATER = [(660, 760, 2300, 680), (4860, 640, 2440, 800), (7330, 660, 1520, 780)]
AIR_SPEED = 320.0  # px/s, the sub's top speed (game/player/player.gd), and 0.7 of it in water
WATER_SPEED = 224.0
# The keys held for each of the eight directions a keyboard gives (angles in degrees, y down).
OCTANTS = {-90: ["Up"], -45: ["Right", "Up"], 0: ["Right"], 45: ["Right", "Down"],
           90: ["Down"]}
CYCLE_S = 0.3  # a person alternates two key chords this often to steer between octants
# Generous: a person with keys may be slower than the sub's top speed; the goal screen ends it.
PLAY_PATIENCE_S = 90.0


def _unit(deg: float) -> tuple[float, float]:
    return (math.cos(math.radians(deg)), math.sin(math.radians(deg)))


def key_moves() -> list[tuple[list[str], float]]:
    """The route as key chords and how long to hold each: a direction between two octants is
    held as a mix of the two, alternated every CYCLE_S."""
    moves = []
    for (x0, y0), (x1, y1) in zip(ROUTE, ROUTE[1:]):
        angle = math.degrees(math.atan2(y1 - y0, x1 - x0))
        low = max(a for a in OCTANTS if a <= angle)
        high = min(a for a in OCTANTS if a >= angle)
        # The share f of `high` whose mean direction is the segment's.
        f = 0.0
        if high != low:
            ua, ub = _unit(low), _unit(high)
            t = math.tan(math.radians(angle - low))
            # Direction of (1-f) ua + f ub, measured from ua, has tangent t.
            perp = (-ua[1], ua[0])
            along = lambda f_: (1 - f_) + f_ * (ub[0] * ua[0] + ub[1] * ua[1])  # noqa: E731
            across = lambda f_: f_ * (ub[0] * perp[0] + ub[1] * perp[1])  # noqa: E731
            lo_f, hi_f = 0.0, 1.0
            for _ in range(30):
                f = (lo_f + hi_f) / 2
                if across(f) / along(f) < t:
                    lo_f = f
                else:
                    hi_f = f
        mid = ((x0 + x1) / 2, (y0 + y1) / 2)
        wet = any(a <= mid[0] <= a + w and b <= mid[1] <= b + h for a, b, w, h in WATER)
        ua, ub = _unit(low), _unit(high)
        mean = math.hypot((1 - f) * ua[0] + f * ub[0], (1 - f) * ua[1] + f * ub[1])
        seconds = math.hypot(x1 - x0, y1 - y0) / ((WATER_SPEED if wet else AIR_SPEED) * mean)
        cycles = max(1, round(seconds / CYCLE_S))
        for _ in range(cycles):
            if f < 0.999:
                moves.append((OCTANTS[low], seconds / cycles * (1 - f)))
            if f > 0.001:
                moves.append((OCTANTS[high], seconds / cycles * f))
    return [(keys, s) for keys, s in moves if s >= 0.02]


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


def park_mouse(person: Person) -> None:
    """The mouse moves the simulated hand when no key is held: a person rests it mid-window."""
    person.move_mouse(SCREEN[0] // 2, (20 + SCREEN[1]) // 2)


def test_a_person_plays_level_1_with_keys(session) -> None:
    person = session.person
    game = session.game
    timings: dict[str, float] = {}
    started = time.monotonic()

    # The main menu, then its Play button: level 1.
    play: Box = person.wait_text("Play", patience=90.0)
    person.screenshot("main-menu")
    timings["menu shown"] = time.monotonic() - started
    person.click(*play.center)
    # The mouse is the hand while no key is held: left on the Play button it steers the sub
    # upward, so it goes to the middle of the window at once.
    park_mouse(person)
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
    park_mouse(person)
    if not person.wait_gone("Resume", patience=10.0):
        shot = person.screenshot("still-paused")
        raise AssertionError(f"Resume was clicked and the pause menu stayed ({shot})")
    timings["menus"] = time.monotonic() - started

    # Play toward the goal with the keys, the route as a person learned it.
    play_started = time.monotonic()
    reached = None
    moves = key_moves()
    shot_every = max(1, len(moves) // 6)
    for n, (keys, seconds) in enumerate(moves):
        person.hold_keys(keys, seconds)
        if n % shot_every == shot_every - 1:
            person.screenshot(f"playing-{n:03d}")
    # Then hold right toward the goal until the goal screen shows or the patience runs out.
    deadline = play_started + PLAY_PATIENCE_S
    while reached is None and time.monotonic() < deadline:
        reached = person.find_text("Goal reached", patience=0.0)
        if reached is None:
            person.hold_keys(["Right"], 2.0)
    timings["playing"] = time.monotonic() - play_started
    person.screenshot("goal" if reached else "where-the-person-got")
    items = "goal screen" if reached else items_collected(person)
    print(f"person: level 1 with keys: {'goal reached' if reached else 'goal not reached'} "
          f"after {timings['playing']:.0f} s; items {items}")

    # Quit by closing the window: the game must exit by itself, with 0.
    closing = time.monotonic()
    person.close_window()
    code = game.wait_exit()
    timings["quit"] = time.monotonic() - closing
    assert code is not None, "the game did not exit within the bound after its window closed"
    assert code == 0, f"the game exited with {code}"
    assert not game.error_lines(), game.error_lines()
    timings["total"] = time.monotonic() - started
    print("person: timings " + ", ".join(f"{k} {v:.1f} s" for k, v in timings.items()))
    if not reached:
        pytest.xfail(f"a person holding the keys along the level's route did not reach the goal "
                     f"within {PLAY_PATIENCE_S:.0f} s (items: {items}; screenshots: "
                     f"{session.shots})")
