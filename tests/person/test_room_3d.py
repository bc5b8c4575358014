"""Scenario: a person opens the 3D room from the main menu with the mouse, walks it with the
arrow keys (no device: the keys move the simulated hand, the probe feeds it to the explorer),
and leaves with Esc back to the menu. The camera follows the explorer, so walking shows as the
gold ring ahead coming down the screen toward the player."""

from __future__ import annotations

import time

import numpy as np
from PIL import Image

# The ring must come at least this far down the screen after 1.5 s of walking toward it.
RING_CLOSER_PX = 20.0


def ring_at(shot) -> tuple[float, float] | None:
    """The gold ring's centre on the screen (the only bright yellow there), None unseen."""
    pixels = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    yellow = (r > 200) & (g > 170) & (b < 110)
    if yellow.sum() < 30:
        return None
    ys, xs = np.nonzero(yellow)
    return (float(np.median(xs)), float(np.median(ys)))


def test_a_person_walks_the_3d_room_with_the_arrow_keys(session) -> None:
    person = session.person
    game = session.game
    started = time.monotonic()
    person.click_text("3D room", patience=90.0)
    person.wait_text("gold ring")
    before = ring_at(person.screenshot("room"))
    assert before is not None, f"no gold ring on the screen ({session.shots})"
    person.hold_key("Up", 1.5)
    after = ring_at(person.screenshot("walked"))
    assert after is not None, f"the ring went out of sight ({session.shots})"
    print(f"person: room 3D: the ring at y {before[1]:.0f} px, after walking {after[1]:.0f} px")
    assert after[1] - before[1] > RING_CLOSER_PX, (
        f"the Up key did not walk the explorer toward the ring: {before} -> {after} "
        f"({session.shots})")
    person.press("Escape")
    person.wait_text("Haptic Battle Pong")
    person.screenshot("menu-again")
    quit_s = person.close_and_see_it_exit(game)
    print(f"person: room 3D scenario {time.monotonic() - started:.1f} s; the game ended "
          f"{quit_s:.1f} s after its window closed")
