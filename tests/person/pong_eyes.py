"""What a person sees of a Pong match on a screenshot, and the hand that follows it.

The ball is the one small, round, pure-white disc on the court; the person's paddle is the
blue disc with the near-white (cyan-tinted) rim on their side of the net. The hand is a
first-time player's (tests/pong/pong_clumsy_player.gd's limits): it sees the ball once per
look (about a third of a second: a newcomer's reaction), moves the mouse by part of the gap
between its paddle and the ball, and wobbles."""

from __future__ import annotations

import random
import time
from dataclasses import dataclass, field

import numpy as np
from PIL import Image
from scipy import ndimage

# The court, inside the HUD's corners (the players' panels above, the force graph below right).
COURT = (320, 180, 960, 700)
# Movement smaller than this (px, screen y) between looks is not a change of direction.
TURN_PX = 12.0
# Past the person's paddle by this much (screen y), the ball went by them; above this row it
# went by the computer.
PAST_PADDLE_PX = 60.0
PAST_COMPUTER_Y = 250.0


def _court_pixels(shot) -> np.ndarray:
    pixels = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    mask = np.zeros(pixels.shape[:2], dtype=bool)
    left, top, right, bottom = COURT
    mask[top:bottom, left:right] = True
    return pixels, mask


def ball_at(shot) -> tuple[float, float] | None:
    """The ball's centre on the screen, None when it is not seen (behind a paddle)."""
    pixels, court = _court_pixels(shot)
    white = court & (pixels.min(axis=2) > 235)
    labels, _count = ndimage.label(white)
    for i, box in enumerate(ndimage.find_objects(labels), 1):
        h, w = box[0].stop - box[0].start, box[1].stop - box[1].start
        area = int((labels[box] == i).sum())
        if 6 <= w <= 48 and 6 <= h <= 48 and abs(w - h) <= max(w, h) * 0.4 and area >= 0.6 * w * h:
            return ((box[1].start + box[1].stop) / 2, (box[0].start + box[0].stop) / 2)
    return None


# Where the person's own paddle is drawn: a band about the net line (the paddle is held up
# near the net; the ball rolling behind it on the floor is lower on the screen).
NEAR_TOP = 330
NEAR_BOTTOM = 430
# More light pixels than this in one screen row is the net line, wider than any paddle.
NET_ROW_PX = 120


def paddle_at(shot, colour: str = "blue") -> tuple[float, float] | None:
    """The centre of the person's paddle's rim on the screen, None when it is not seen. The
    rim is near-white, tinted with the seat's colour: blue (seat 1) or orange (seat 2)."""
    ys, xs = np.nonzero(paddle_rim(shot, colour))
    if len(xs) < 20:
        return None
    return (float(xs.mean()), float(ys.mean()))


def paddle_rim(shot, colour: str = "blue") -> np.ndarray:
    """The pixels of the paddle's rim's tint about the net line (the avatar's head, in the
    same tint, has a few at its edge)."""
    pixels, court = _court_pixels(shot)
    court[:NEAR_TOP] = False
    court[NEAR_BOTTOM:] = False
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    if colour == "blue":
        rim = court & (g > 235) & (b > 235) & (r > 150) & (r < 245)
    else:
        rim = court & (r > 225) & (g > 225) & (b > 130) & (b < 215)
    # The net line is drawn in the same light tint: rows the rim alone could not fill are it.
    rim[rim.sum(axis=1) > NET_ROW_PX] = False
    return rim


@dataclass
class RallyWatch:
    """Paddle contacts as a person counts them: the ball turning back toward the other side.
    A ball that goes past a paddle ends the rally."""

    contacts: int = 0
    rally: int = 0
    longest: int = 0
    misses: int = 0
    served_at: float | None = None
    _y: float | None = None
    _extreme: float | None = None
    _coming: bool | None = None
    _now: str = "nothing"
    _before: str = "nothing"
    log: list[str] = field(default_factory=list)

    def restart(self) -> None:
        """A new match: the rally so far is over."""
        self.rally = 0
        self._y = self._extreme = self._coming = None

    def see(self, t: float, ball: tuple[float, float] | None,
            paddle: tuple[float, float] | None) -> None:
        before = self._now
        self._now = f"{t:.2f} s ball {_xy(ball)} paddle {_xy(paddle)}"
        self._before = before
        if ball is None:
            return
        y = ball[1]
        if self._y is None:
            self._y = self._extreme = y
            return
        if self.served_at is None and abs(y - self._y) >= TURN_PX:
            self.served_at = t
        paddle_y = paddle[1] if paddle else None
        if (paddle_y is not None and y > paddle_y + PAST_PADDLE_PX) or y < PAST_COMPUTER_Y:
            if self.rally:
                # Where the ball and the paddle were, as the person saw them: a miss wide of
                # the paddle is the hand's, a miss through it is the game's.
                where = f"ball ({ball[0]:.0f}, {y:.0f})" + (
                    f", paddle ({paddle[0]:.0f}, {paddle_y:.0f})" if paddle else ", paddle unseen")
                side = "the computer's" if y < PAST_COMPUTER_Y else "the person's"
                self.log.append(f"{t:.1f} s: past {side} paddle, rally of {self.rally} over: "
                                f"{where}; a look before: {self._before}")
                self.misses += 1
            self.rally = 0
            self._coming = None
            self._extreme = y
            self._y = y
            return
        coming = self._coming
        if coming is None:
            if abs(y - self._extreme) >= TURN_PX:
                self._coming = y > self._extreme
                self._extreme = y
        elif (coming and y < self._extreme - TURN_PX) or (not coming and y > self._extreme + TURN_PX):
            self.contacts += 1
            self.rally += 1
            self.longest = max(self.longest, self.rally)
            self.log.append(f"{t:.1f} s: {'the person' if coming else 'the computer'} returned it"
                            f" (rally {self.rally})")
            self._coming = not coming
            self._extreme = y
        elif (coming and y > self._extreme) or (not coming and y < self._extreme):
            self._extreme = y
        self._y = y


def _xy(point: tuple[float, float] | None) -> str:
    return "unseen" if point is None else f"({point[0]:.0f}, {point[1]:.0f})"


class ClumsyMouseHand:
    """A newcomer's hand on the mouse, held to tests/pong/pong_clumsy_player.gd's limits: it
    looks at the screen every REACTION_S at the quickest (a slow machine's look takes
    longer), moves the mouse across the screen by part of the gap it sees between its paddle
    and the ball (not yet knowing that the paddle goes about 0.4 as far as the mouse), and
    wobbles. It never walks: the computer's shots in beginner mode come at its target, the
    middle of its back wall."""

    REACTION_S = 0.3  # pong_clumsy_player.gd's
    GAIN = 0.6
    WOBBLE_PX = 18.0  # about half the paddle's drawn radius

    def __init__(self, rest: tuple[int, int], seed: int) -> None:
        self.x, self.y = rest
        self.rng = random.Random(seed)
        self._looked = 0.0

    def play(self, person, ball: tuple[float, float] | None,
             paddle: tuple[float, float] | None) -> None:
        """One look's answer, then the rest of the person's reaction time if the look took
        less (a screenshot takes 35 ms here, the eyes on it about as long)."""
        if ball is not None and paddle is not None:
            self.x += self.GAIN * (ball[0] - paddle[0])
            self.x = min(max(self.x, COURT[0]), COURT[2])
        # Placed shakily: a new wobble each look about where it means to be (the clumsy
        # player's), not added up look after look.
        person.move_mouse(round(self.x + self.rng.gauss(0.0, self.WOBBLE_PX)), self.y)
        time.sleep(max(0.0, self._looked + self.REACTION_S - time.monotonic()))
        self._looked = time.monotonic()
