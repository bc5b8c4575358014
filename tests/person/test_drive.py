"""Scenario: a person opens Drive from the main menu with the mouse and drives the car with the
arrow keys (no wheel: the keys turn the simulated one). Up drives and the speed readout climbs;
Left at speed turns the wheel, and the readout shows it pulling back; Down brakes the car to a
stop and then backs it away slowly; Esc goes back to the menu. The person reads the status line
at the top, as a player does."""

from __future__ import annotations

import re
import time

from ocr import OCR_VARIANTS
from person import Person

# Up held this long takes the car past this speed on the readout (it makes about 40 km/h).
UP_S = 2.0
UNDER_WAY_KMH = 15
# Down brings it under this speed within this long, and held on backs it away no faster
# than this.
STOP_PATIENCE_S = 6.0
STOPPED_KMH = 5
REVERSE_S = 3.0
REVERSE_MOST_KMH = 20
# Left held at speed: the wheel pulls back toward straight, at least this hard on the readout.
LEFT_S = 0.8
PULL_LEAST_N = 0.2


def readout(person: Person) -> tuple[int | None, float | None, bool]:
    """The status line's speed (the number before km/h), wheel pull (the number after pull,
    in N) and whether it says reverse, as the first look that reads the numbers gives them;
    None for what none reads. Words may run together ("40km/h", "pull+1.69N"), and a lone
    zero reads as an O."""
    shot = person.grab(person.scratch / "look.png")
    speed: int | None = None
    pull: float | None = None
    reverse = False
    for variant in OCR_VARIANTS:
        line = " ".join(w.text for w in person.read_words(shot, variant))
        reverse = reverse or "reverse" in line
        found = re.search(r"(\d{1,3}|O)\s*km", line)
        if speed is None and found:
            speed = int(found.group(1).replace("O", "0"))
        # The pull's sign is read unreliably: its size is what is checked.
        found = re.search(r"pull\s*[+-]?\s*(\d+[.,]\d+)", line)
        if pull is None and found:
            pull = float(found.group(1).replace(",", "."))
        if speed is not None and pull is not None:
            break
    return speed, pull, reverse


def test_a_person_drives_the_car_with_the_arrow_keys(shipped_session) -> None:
    person = shipped_session.person
    game = shipped_session.game
    started = time.monotonic()
    person.click_text("Drive", patience=90.0)
    person.wait_text("restart")
    person.screenshot("drive")
    standing, _, _ = readout(person)
    person.hold_key("Up", UP_S)
    moving, _, _ = readout(person)
    person.screenshot("under-way")
    assert moving is not None and moving > UNDER_WAY_KMH, (
        f"Up for {UP_S} s: the readout says {moving} km/h (standing {standing}) "
        f"({shipped_session.shots})")
    # Read while the keys are held: let go, the wheel is straight again within frames.
    person.hold_only(["Up", "Left"])
    try:
        time.sleep(LEFT_S)
        turning_speed, pull, _ = readout(person)
        person.screenshot("turning")
    finally:
        person.hold_only([])
    assert pull is not None and pull >= PULL_LEAST_N, (
        f"Left at {turning_speed} km/h: the wheel pull reads {pull} N ({shipped_session.shots})")
    # Down held until the readout says it has stopped (or already backs: the moment at 0 is
    # short), then on: it backs away, slowly.
    person.hold_only(["Down"])
    try:
        braking = time.monotonic()
        braked: int | None = None
        backs = False
        while time.monotonic() - braking < STOP_PATIENCE_S and not backs:
            braked, _, backs = readout(person)
            backs = backs or (braked is not None and braked < STOPPED_KMH)
        stopped_s = time.monotonic() - braking
        person.screenshot("stopped")
        assert backs, f"Down for {STOP_PATIENCE_S} s: still {braked} km/h ({shipped_session.shots})"
        time.sleep(REVERSE_S)
        backing, _, says_reverse = readout(person)
        person.screenshot("reversing")
    finally:
        person.hold_only([])
    assert says_reverse and backing is not None and 0 < backing <= REVERSE_MOST_KMH, (
        f"Down held {REVERSE_S} s more: {backing} km/h, 'reverse' shown: {says_reverse} "
        f"({shipped_session.shots})")
    print(f"person: drive: {standing} km/h standing, {moving} after {UP_S} s of Up, "
          f"pull {pull} N turning at {turning_speed}, {braked} after {stopped_s:.1f} s of Down, "
          f"{backing} backward {REVERSE_S} s later")
    person.press("Escape")
    person.wait_text("Haptic Battle Pong")
    quit_s = person.close_and_see_it_exit(game)
    print(f"person: drive scenario {time.monotonic() - started:.1f} s; the game ended "
          f"{quit_s:.1f} s after its window closed")
