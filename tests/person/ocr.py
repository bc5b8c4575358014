"""The person's reading: words and their boxes on a screenshot (tesseract), and phrases found
among them."""

from __future__ import annotations

import os
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path


@dataclass
class Word:
    text: str
    left: int
    top: int
    width: int
    height: int
    conf: float

    @property
    def right(self) -> int:
        return self.left + self.width


@dataclass
class Box:
    text: str
    left: int
    top: int
    right: int
    bottom: int

    @property
    def center(self) -> tuple[int, int]:
        return ((self.left + self.right) // 2, (self.top + self.bottom) // 2)


def norm(word: str) -> str:
    return re.sub(r"[^0-9a-z/]", "", word.lower())


def phrase_boxes(words: list[Word], phrase: str, alone: bool = False) -> list[Box]:
    """Every place where the phrase's words stand in a row on one line; with `alone`, only
    where no other word stands right before or after them on that line (a button's caption,
    not the same word in a label or a sentence beside it: "Host" but not "Host address")."""
    wanted = [norm(w) for w in phrase.split() if norm(w)]
    usable = [w for w in words if norm(w.text)]
    rows = sorted(usable, key=lambda w: (w.top + w.height // 2, w.left))
    found = []
    for i, first in enumerate(rows):
        if norm(first.text) != wanted[0]:
            continue
        chain = [first]
        for want in wanted[1:]:
            last = chain[-1]
            mid = last.top + last.height / 2
            nxt = [w for w in usable
                   if norm(w.text) == want and abs(w.top + w.height / 2 - mid) < last.height * 0.7
                   and 0 <= w.left - last.right < 3 * last.height]
            if not nxt:
                break
            chain.append(min(nxt, key=lambda w: w.left))
        if len(chain) == len(wanted) and not (alone and _neighboured(usable, chain)):
            found.append(Box(phrase, min(w.left for w in chain), min(w.top for w in chain),
                             max(w.right for w in chain), max(w.top + w.height for w in chain)))
    return found


def _neighboured(words: list[Word], chain: list[Word]) -> bool:
    """Whether another word stands on the chain's line within a word gap of either end."""
    first, last = chain[0], chain[-1]
    mid = first.top + first.height / 2
    gap = 3 * first.height
    for w in words:
        if w in chain or abs(w.top + w.height / 2 - mid) >= first.height * 0.7:
            continue
        if 0 <= w.left - last.right < gap or 0 <= first.left - w.right < gap:
            return True
    return False


# Two looks at a screenshot: the light text alone (a gray threshold, black on white: the
# game's buttons, whose borders and focus rings otherwise hide a short word such as "Play"),
# then the whole picture in gray, negated, at twice its size (the orange titles, the HUD's
# small text). Tesseract's sparse-text mode finds words anywhere on a screen that is not a page.
OCR_VARIANTS = (("light", ["-colorspace", "Gray", "-threshold", "65%", "-negate"], 1),
                ("gray2x", ["-colorspace", "Gray", "-negate", "-resize", "200%"], 2),
                # Small pale captions over a bright level (the HUD's): larger still.
                ("gray3x", ["-colorspace", "Gray", "-negate", "-resize", "300%"], 3))


@dataclass
class Region:
    """A part of the screen a person glances at (where a text stood a moment ago)."""

    left: int
    top: int
    width: int
    height: int

    @staticmethod
    def around(box: Box, pad_x: int = 60, pad_y: int = 16) -> "Region":
        left, top = max(0, box.left - pad_x), max(0, box.top - pad_y)
        return Region(left, top, box.right + pad_x - left, box.bottom + pad_y - top)


def read_words(shot: Path, variant: tuple[str, list[str], int], scratch: Path,
               region: Region | None = None) -> list[Word]:
    """The words one look finds on a screenshot (or on a region of it), with their boxes in
    screen pixels."""
    label, args, scale = variant
    # An uncompressed picture: writing a PNG three times the screen's size took 1.5-3 s.
    prepared = scratch / f"ocr-{label}.pgm"
    crop = [] if region is None else [
        "-crop", f"{region.width}x{region.height}+{region.left}+{region.top}", "+repage"]
    subprocess.run(["convert", str(shot), *crop, *args, str(prepared)], check=True, timeout=60)
    # One thread: the machine is shared, and tesseract's threads gain nothing on a screen.
    out = subprocess.run(["tesseract", str(prepared), "-", "--psm", "11", "tsv"],
                         env={**os.environ, "OMP_THREAD_LIMIT": "1"}, check=True,
                         capture_output=True, text=True, timeout=120).stdout
    words = []
    for line in out.splitlines()[1:]:
        cols = line.split("\t")
        if len(cols) < 12 or not cols[11].strip() or float(cols[10]) < 40:
            continue
        left, top, width, height = (int(int(c) / scale) for c in cols[6:10])
        if region is not None:
            left, top = left + region.left, top + region.top
        words.append(Word(cols[11], left, top, width, height, float(cols[10])))
    return words
