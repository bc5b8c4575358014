"""What a person sees of the side-scroller on a screenshot, and the keys they steer it with.

The sub is the one saturated orange body on the screen (its hull keeps that colour under the
water's tint; sand and crates are paler). Where the sub is in the level a person judges from
the scenery going by: here, how far the picture scrolled between two looks (phase
correlation of the two screenshots, the HUD and the sub left out, its few best guesses judged
by how well the two pictures then agree), added up from the start,
plus the sub's own move on the screen. The way to the goal is the route a person who has
played the level learnt (given in the level's pixels from its start)."""

from __future__ import annotations

import math

import numpy as np
from PIL import Image
from scipy import ndimage

# The HUD's bar at the top of the screen is not scenery.
HUD_BOTTOM = 100
# Looks are compared at half size: enough for a scroll of a few pixels, four times cheaper.
SCALE = 2


def _pixels(shot) -> np.ndarray:
    return np.asarray(Image.open(shot).convert("RGB")).astype(int)


def sub_at(pixels: np.ndarray) -> tuple[float, float] | None:
    """The sub's centre on the screen, None when it is not seen."""
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    orange = (r > 150) & ((r - b) > 0.7 * r) & (g > 0.4 * r) & (g < 0.85 * r)
    orange[:HUD_BOTTOM] = False
    labels, count = ndimage.label(ndimage.binary_closing(orange, iterations=2))
    if count == 0:
        return None
    sizes = ndimage.sum(orange, labels, range(1, count + 1))
    best = int(np.argmax(sizes)) + 1
    if sizes[best - 1] < 60:
        return None
    ys, xs = np.nonzero(labels == best)
    return (float(xs.mean()), float(ys.mean()))


def goal_at(pixels: np.ndarray) -> tuple[float, float] | None:
    """The goal's buoy on the screen (the only red and white stripes in the level), None when
    it is not in view."""
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    red = (r > 170) & (g < 90) & (b < 110) & (r - g > 110)
    red[:HUD_BOTTOM] = False
    ys, xs = np.nonzero(red)
    if len(xs) < 150:
        return None
    return (float(np.median(xs)), float(np.median(ys)))


# Phase correlation proposes this many scrolls; the one under which the two looks agree best
# wins. The rock is one texture tiled about every 246 screen pixels, so a long scroll (the
# sub leaping out of the water: 210 px between two looks) can correlate best one tile off,
# where only the texture agrees, not the outlines, the water line or the light.
CANDIDATES = 5


class Scenery:
    """One look's scenery at half size: the HUD's bar cut off and the sub left out."""

    def __init__(self, pixels: np.ndarray, sub: tuple[float, float] | None) -> None:
        gray = pixels.mean(axis=2)[HUD_BOTTOM:, :]
        seen = np.ones(gray.shape, dtype=bool)
        if sub is not None:
            x, y = int(sub[0]), int(sub[1]) - HUD_BOTTOM
            seen[max(0, y - 40):max(0, y + 40), max(0, x - 50):x + 50] = False
        self.gray = gray[::SCALE, ::SCALE]
        self.seen = seen[::SCALE, ::SCALE]
        # What phase correlation compares: the sub's box filled with the mean, tapered edges.
        small = np.where(self.seen, self.gray, self.gray[self.seen].mean())
        small = small - small.mean()
        self.spectrum = np.fft.fft2(small * np.outer(np.hanning(small.shape[0]),
                                                     np.hanning(small.shape[1])))

    def agreement(self, after: "Scenery", dx: int, dy: int) -> float:
        """How alike the two looks are where they overlap when `after` is this look moved by
        (dx, dy) half-size pixels: the correlation coefficient of the pixels both saw."""
        h, w = self.gray.shape
        y0, y1, x0, x1 = max(0, -dy), min(h, h - dy), max(0, -dx), min(w, w - dx)
        if y1 - y0 < 20 or x1 - x0 < 20:
            return -1.0
        both = self.seen[y0:y1, x0:x1] & after.seen[y0 + dy:y1 + dy, x0 + dx:x1 + dx]
        a = self.gray[y0:y1, x0:x1][both]
        b = after.gray[y0 + dy:y1 + dy, x0 + dx:x1 + dx][both]
        a, b = a - a.mean(), b - b.mean()
        return float((a * b).sum() / math.sqrt((a * a).sum() * (b * b).sum() + 1e-9))


def scroll_between(before: Scenery, after: Scenery) -> tuple[float, float, float]:
    """How far the scenery moved on the screen from `before` to `after` (screen pixels), and
    how alike the two looks are under that move (1: the same picture moved)."""
    cross = after.spectrum * np.conj(before.spectrum)
    cross /= np.abs(cross) + 1e-9
    corr = np.fft.ifft2(cross).real
    h, w = corr.shape
    peaks = np.flatnonzero(corr == ndimage.maximum_filter(corr, size=5, mode="wrap"))
    best = (-2.0, 0, 0)
    for flat in peaks[np.argsort(corr.flat[peaks])[::-1][:CANDIDATES]]:
        peak_y, peak_x = divmod(int(flat), w)
        dy = peak_y - h if peak_y > h // 2 else peak_y
        dx = peak_x - w if peak_x > w // 2 else peak_x
        best = max(best, (before.agreement(after, dx, dy), dx, dy))
    return (float(best[1] * SCALE), float(best[2] * SCALE), best[0])


class Whereabouts:
    """The sub's place in the level as a person keeps track of it, from one look to the next."""

    def __init__(self, start: tuple[float, float]) -> None:
        self.start = start
        self.camera = None  # the level point at the screen's top-left corner
        self._scenery: Scenery | None = None
        self.position: tuple[float, float] | None = None
        # What the last look saw on the screen: the sub and the goal (None: not seen).
        self.sub: tuple[float, float] | None = None
        self.goal: tuple[float, float] | None = None
        # The last look's scroll of the scenery and how sure it was (for the trail).
        self.scroll: tuple[float, float, float] = (0.0, 0.0, 1.0)

    def look(self, shot) -> tuple[float, float] | None:
        pixels = _pixels(shot)
        sub = sub_at(pixels)
        self.sub, self.goal = sub, goal_at(pixels)
        scenery = Scenery(pixels, sub)
        if self._scenery is None:
            if sub is None:
                return None
            self.camera = (self.start[0] - sub[0], self.start[1] - sub[1])
        else:
            self.scroll = scroll_between(self._scenery, scenery)
            dx, dy = self.scroll[0], self.scroll[1]
            # The scenery moving left on the screen is the camera moving right in the level.
            self.camera = (self.camera[0] - dx, self.camera[1] - dy)
        self._scenery = scenery
        if sub is not None:
            self.position = (self.camera[0] + sub[0], self.camera[1] + sub[1])
        return self.position


# The keys held for each of the eight directions (angles in degrees, screen y down).
CHORDS = {0: ["Right"], 45: ["Right", "Down"], 90: ["Down"], 135: ["Left", "Down"],
          180: ["Left"], -135: ["Left", "Up"], -90: ["Up"], -45: ["Right", "Up"]}


def chord_toward(here: tuple[float, float], there: tuple[float, float], lift: int = 0) -> list[str]:
    """The arrow keys a person holds to go from here toward there (the nearest of eight),
    turned `lift` eighths of a turn further up (further down when negative): a person stuck
    against the sand tries over it, and under a ledge they are pressed against."""
    angle = math.degrees(math.atan2(there[1] - here[1], there[0] - here[0]))
    nearest = min(CHORDS, key=lambda a: abs((angle - a + 180) % 360 - 180))
    toward = -90 if lift > 0 else 90
    for _ in range(abs(lift)):
        if nearest == toward:
            break
        # Turn the short way round toward straight up (or down).
        step = 45 if (toward - nearest) % 360 < 180 else -45
        nearest = (nearest + step + 180) % 360 - 180
        nearest = 180 if nearest == -180 else nearest
    return CHORDS[nearest]


class Route:
    """A learnt way through the level, followed as a person follows a path they know: toward a
    point a little ahead along it of where they are now, never turning back along it."""

    LOOKAHEAD_PX = 160.0
    # Only this far along the route ahead of the furthest point reached is a place a person
    # can believe they are (the level folds back on itself: the route passes near itself).
    WINDOW_PX = 600.0
    # Further from the route than this, a person has left it (into a pocket beside the way,
    # over a ledge that walls it): being level with a place further on is not being there.
    OFF_ROUTE_PX = 120.0

    def __init__(self, points: list[tuple[float, float]]) -> None:
        self.points = points
        self.lengths = [0.0]
        for a, b in zip(points, points[1:]):
            self.lengths.append(self.lengths[-1] + math.dist(a, b))
        self.reached = 0.0
        self.off = 0.0  # how far from the route the last look was

    @property
    def length(self) -> float:
        return self.lengths[-1]

    def _point_at(self, along: float) -> tuple[float, float]:
        along = min(max(along, 0.0), self.length)
        for k in range(len(self.points) - 1):
            if along <= self.lengths[k + 1]:
                a, b = self.points[k], self.points[k + 1]
                f = (along - self.lengths[k]) / max(1e-9, self.lengths[k + 1] - self.lengths[k])
                return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))
        return self.points[-1]

    def _nearest(self, here: tuple[float, float]) -> tuple[float, float]:
        """How far along the route its nearest point to `here` is (within the window ahead of
        the furthest point reached), and how far `here` is from that point."""
        best, best_d = self.reached, math.inf
        for k in range(len(self.points) - 1):
            if self.lengths[k] > self.reached + self.WINDOW_PX or self.lengths[k + 1] < self.reached:
                continue
            a, b = self.points[k], self.points[k + 1]
            seg = (b[0] - a[0], b[1] - a[1])
            f = ((here[0] - a[0]) * seg[0] + (here[1] - a[1]) * seg[1]) / max(1e-9, seg[0] ** 2 + seg[1] ** 2)
            f = min(max(f, 0.0), 1.0)
            d = math.dist(here, (a[0] + f * seg[0], a[1] + f * seg[1]))
            along = self.lengths[k] + f * (self.lengths[k + 1] - self.lengths[k])
            if d < best_d and along <= self.reached + self.WINDOW_PX:
                best, best_d = along, d
        return best, best_d

    def aim(self, here: tuple[float, float]) -> tuple[float, float]:
        """Where to head from `here`; moves the furthest point reached on while `here` is on
        the route. Off it, a person heads back to where they left it."""
        along, self.off = self._nearest(here)
        if self.off > self.OFF_ROUTE_PX:
            return self._point_at(self.reached)
        self.reached = max(self.reached, along)
        return self._point_at(self.reached + self.LOOKAHEAD_PX)


class Approach:
    """Closing in on something seen on the screen, as a person does with a floaty sub: they
    aim where it will be a moment from now (the sub drifts on while they look again), let go
    when that is on the target, and tap the keys rather than hold them once close."""

    # How far ahead the person judges the drift: about one look and the sub's slowing.
    LEAD_S = 0.8
    ON_TARGET_PX = 40.0
    CLOSE_PX = 260.0
    TAP_S = 0.2

    def __init__(self) -> None:
        self._rel: tuple[float, float] | None = None
        self._at = 0.0

    def forget(self) -> None:
        """The target is out of sight: the next sighting starts afresh."""
        self._rel = None

    def keys(self, sub: tuple[float, float], target: tuple[float, float],
             now: float) -> tuple[list[str], float | None]:
        """The keys to hold, and for how long (None: until the next look)."""
        rel = (target[0] - sub[0], target[1] - sub[1])
        rate = (0.0, 0.0)
        if self._rel is not None and now > self._at:
            dt = now - self._at
            rate = ((rel[0] - self._rel[0]) / dt, (rel[1] - self._rel[1]) / dt)
        self._rel, self._at = rel, now
        aim = (rel[0] + rate[0] * self.LEAD_S, rel[1] + rate[1] * self.LEAD_S)
        if math.hypot(*aim) < self.ON_TARGET_PX:
            return [], None
        tap = self.TAP_S if math.hypot(*rel) < self.CLOSE_PX else None
        return chord_toward((0.0, 0.0), aim), tap
