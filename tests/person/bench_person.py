"""A player's numbers beside the autopilot's (make bench): level 1's time to the goal and the
frame time in a 1280x720 window under Xvfb (the probe on the sub, software rendering), for
the level's autopilot and for the scripted person steering by the screen with the keys; and
Pong against the computer with the person's clumsy mouse hand: paddle contacts and the
longest rally in a minute. One run each: numbers to compare, not bounds."""

from __future__ import annotations

import argparse
import contextlib
import json
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.dont_write_bytecode = True

from desktop import GODOT, ROOT, SCREEN, Display, tools_missing  # noqa: E402
from person import Session  # noqa: E402
from pong_eyes import ClumsyMouseHand, RallyWatch, ball_at, paddle_at  # noqa: E402
from test_side_scroller import steer_to_the_goal  # noqa: E402

FPS_LINE = re.compile(r"Project FPS: \d+ \(([\d.]+) mspf\)")
PONG_SECONDS = 60.0


def frame_ms(log: str) -> dict[str, float]:
    """Godot's once-a-second frame times (--print-fps), the first two (loading) left out."""
    times = [float(m) for m in FPS_LINE.findall(log)][2:]
    if not times:
        return {"median_ms": float("nan"), "worst_ms": float("nan"), "seconds": 0}
    return {"median_ms": statistics.median(times), "worst_ms": max(times), "seconds": len(times)}


def autopilot(scratch: Path) -> dict:
    display = Display(scratch)
    display.start()
    log = scratch / "autopilot.log"
    try:
        with open(log, "wb") as out:
            code = subprocess.run(
                [str(GODOT), "--path", str(ROOT), "--rendering-driver", "opengl3", "--print-fps",
                 "res://tests/drivers/game_autopilot.tscn", "--", "--autopilot-seconds=0"],
                env=display.env(), stdout=out, stderr=subprocess.STDOUT, timeout=300).returncode
    finally:
        display.stop()
    text = log.read_text(errors="replace")
    goal = re.search(r"goal reached at t=([\d.]+)s", text)
    return {"exit": code, "goal_s": float(goal.group(1)) if goal else None, **frame_ms(text)}


@contextlib.contextmanager
def playing(name: str):
    """The game from source in its window, printing its frame times, stopped at the end."""
    session = Session(name, "source")
    session.game.engine_args = ["--print-fps"]
    try:
        session.start()
        yield session
    finally:
        session.close()


def person_level(name: str) -> dict:
    with playing(name) as session:
        person = session.person
        person.click_text("Play", patience=90.0)
        person.wait_text("ITEMS", patience=60.0)
        started = time.monotonic()
        reached, looks = steer_to_the_goal(person, session.scratch)
        goal_s = time.monotonic() - started if reached else None
        person.close_and_see_it_exit(session.game)
        return {"goal_s": goal_s, "looks": looks, **frame_ms(session.game.output())}


def person_pong(name: str) -> dict:
    with playing(name) as session:
        person = session.person
        person.click_text("Haptic Battle Pong", patience=90.0)
        person.click_text("Play against the computer")
        rest = (SCREEN[0] // 2, (20 + SCREEN[1]) // 2)
        person.move_mouse(*rest)
        hand = ClumsyMouseHand(rest, seed=7)
        watch = RallyWatch()
        started = time.monotonic()
        while time.monotonic() - started < PONG_SECONDS:
            look = person.grab(session.scratch / "pong.png")
            ball, paddle = ball_at(look), paddle_at(look)
            watch.see(time.monotonic() - started, ball, paddle)
            hand.play(person, ball, paddle)
        person.close_and_see_it_exit(session.game)
        return {"contacts": watch.contacts, "longest_rally": watch.longest, "misses": watch.misses,
                "seconds": PONG_SECONDS, **frame_ms(session.game.output())}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    missing = tools_missing()
    if missing:
        print(f"bench-person: skipped, missing {', '.join(missing)} (make deps installs them)")
        return 0
    scratch = Path(subprocess.run(["mktemp", "-d"], capture_output=True, text=True).stdout.strip())
    result = {"autopilot": autopilot(scratch), "person": person_level("bench-person-level"),
              "pong": person_pong("bench-person-pong")}
    a, p, g = result["autopilot"], result["person"], result["pong"]
    ratio = (p["goal_s"] / a["goal_s"]) if a["goal_s"] and p["goal_s"] else float("nan")
    print("bench-person: level 1 at 1280x720 under Xvfb (software rendering, probe on the sub)")
    print(f"  time to the goal    autopilot {a['goal_s']} s   person {p['goal_s'] and round(p['goal_s'], 1)} s"
          f"   ratio {ratio:.2f}")
    print(f"  frame time median   autopilot {a['median_ms']:.1f} ms   person {p['median_ms']:.1f} ms"
          f"   (worst second {a['worst_ms']:.1f} / {p['worst_ms']:.1f} ms)")
    print(f"bench-person: Pong vs the computer, clumsy mouse hand, {g['seconds']:.0f} s: "
          f"{g['contacts']} paddle contacts, longest rally {g['longest_rally']}, "
          f"{g['misses']} balls past a paddle; frame time median {g['median_ms']:.1f} ms")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
