"""A scripted person at the real windowed game: only the screen, the keys and the mouse.

Everything a test does goes through the X server the game draws on (desktop.py's):
screenshots (the root window through Xlib, Pillow's ImageGrab: 35 ms where ImageMagick's
`import` took 450 ms, and a look at a game in motion is only as quick as its screenshot),
words found on them by OCR (tesseract's word boxes), and input events (xdotool: mouse moves,
clicks, key presses and releases, the window manager's close shortcut). Nothing reads the
game's internals, and the game is started with a player's command line and no flag of ours.

The game is started here and stopped by its PID; every screenshot of a key moment is kept in
.build/person/<test>/NN-moment.png.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from PIL import ImageGrab

from desktop import GODOT, ROOT, Display, stop_process
from ocr import OCR_VARIANTS, Box, Region, Word, norm, phrase_boxes, read_words

EXPORTED = ROOT / ".export" / "linux" / "haptic-game"
SHOTS = ROOT / ".build" / "person"
# Generous bounds for a loaded 2-core machine: they only stop a test that hangs.
START_PATIENCE_S = 90.0
FIND_PATIENCE_S = 30.0
EXIT_PATIENCE_S = 30.0
# A window that takes no notice of Alt+F4 for this long gets a second press, as from a player.
NOTICE_S = 10.0
# Which look read each text last, for every person of this run: the same game draws a text
# the same way on every screen.
READ_BY: dict[str, str] = {}
# What fails every run when the game prints it: an engine or script error, or an X error.
ERROR_LINE = re.compile(r"^(ERROR|SCRIPT ERROR)|BadWindow|BadDrawable|X Error")


@dataclass
class Person:
    """The person: eyes (screenshots, OCR), hands (xdotool), a folder of key moments."""

    display: Display
    shots: Path
    scratch: Path
    ocr_seconds: list[float] = field(default_factory=list)
    _count: int = 0
    _last_look: str = OCR_VARIANTS[0][0]
    _held: set[str] = field(default_factory=set)
    # Where each text was last found, and by which look: a person glances back at that spot.
    _seen: dict[str, tuple[Box, tuple[str, list[str], int]]] = field(default_factory=dict)

    def _x(self, *args: str) -> None:
        subprocess.run(["xdotool", *args], env=self.display.env(), check=True, timeout=30,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    # Eyes.
    def grab(self, path: Path) -> Path:
        """The screen as it is now, saved to `path` (PNG, fast rather than small)."""
        ImageGrab.grab(xdisplay=self.display.name).save(path, compress_level=1)
        return path

    def screenshot(self, name: str) -> Path:
        """Keeps a screenshot of a key moment as NN-name.png in the test's folder."""
        self._count += 1
        return self.grab(self.shots / f"{self._count:02d}-{name}.png")

    def keep_look(self, name: str) -> Path:
        """Keeps the look the last text was found on as NN-name.png: the moment itself, which
        may be over by the time a new screenshot is taken (a card read by OCR for a second)."""
        self._count += 1
        return Path(shutil.copy(self.scratch / "look.png", self.shots / f"{self._count:02d}-{name}.png"))

    def read_words(self, shot: Path, variant: tuple[str, list[str], int],
                   region: Region | None = None) -> list[Word]:
        started = time.monotonic()
        words = read_words(shot, variant, self.scratch, region)
        self.ocr_seconds.append(time.monotonic() - started)
        return words

    def read_screen(self, shot: Path | None = None, region: Region | None = None) -> list[Word]:
        """Every word any look finds on the screen (or on a screenshot given, or in a region
        of it)."""
        shot = shot or self.grab(self.scratch / "look.png")
        return [w for v in OCR_VARIANTS for w in self.read_words(shot, v, region)]

    def find_text(self, text: str, patience: float = FIND_PATIENCE_S,
                  below: int = 0, region: Region | None = None, alone: bool = False) -> Box | None:
        """Where `text` (one or more words on a line) is on the screen, looking again until the
        deadline; None if it never shows. `below` skips what is above that screen row (the
        window's title bar names the game too); a region is the only part looked at; `alone`
        takes the text only where it stands by itself (a button, phrase_boxes)."""
        deadline = time.monotonic() + patience
        while True:
            shot = self.grab(self.scratch / "look.png")
            # The look that read this text before first (on this screen or another person's),
            # then the one that found the last text: screens come in runs of one kind.
            known = READ_BY.get(text)
            for variant in sorted(OCR_VARIANTS, key=lambda v: (v[0] != known, v[0] != self._last_look)):
                boxes = [b for b in phrase_boxes(self.read_words(shot, variant, region), text, alone)
                         if b.top >= below]
                if boxes:
                    self._last_look = variant[0]
                    self._seen[text] = (boxes[0], variant)
                    READ_BY[text] = variant[0]
                    return boxes[0]
            if time.monotonic() > deadline:
                return None
            time.sleep(0.5)

    def find_all(self, text: str) -> list[Box]:
        """Every place `text` stands on the screen now, as the first look that finds any
        reads it."""
        shot = self.grab(self.scratch / "look.png")
        for variant in OCR_VARIANTS:
            boxes = phrase_boxes(self.read_words(shot, variant), text)
            if boxes:
                return boxes
        return []

    def still_shows(self, text: str, below: int = 24) -> bool:
        """Whether `text` is on the screen now: a glance at where it was last found, read as it
        was read then; only when it is not there, a look at the whole screen."""
        if text in self._seen:
            box, variant = self._seen[text]
            shot = self.grab(self.scratch / "look.png")
            if phrase_boxes(self.read_words(shot, variant, Region.around(box)), text):
                return True
        return self.find_text(text, 0.0, below) is not None

    def wait_gone(self, text: str, patience: float = FIND_PATIENCE_S, below: int = 24) -> bool:
        """Whether `text` has left the screen (looked at again until the deadline)."""
        deadline = time.monotonic() + patience
        while self.still_shows(text, below):
            if time.monotonic() > deadline:
                return False
            time.sleep(0.3)
        return True

    def wait_text(self, text: str, patience: float = FIND_PATIENCE_S, below: int = 24,
                  region: Region | None = None, alone: bool = False) -> Box:
        box = self.find_text(text, patience, below, region, alone)
        if box is None:
            shot = self.screenshot(f"missing-{norm(text) or 'text'}")
            raise AssertionError(f"{text!r} never showed on the screen within {patience:.0f} s "
                                 f"(last screen: {shot})")
        return box

    # Hands.
    def move_mouse(self, x: int, y: int) -> None:
        self._x("mousemove", str(x), str(y))

    def click(self, x: int, y: int) -> None:
        """A person's click: the pointer comes to rest, the button is held a moment, and the
        hand stays put a moment after (a game reads a click over several frames)."""
        self._x("mousemove", str(x), str(y))
        time.sleep(0.25)
        self._x("mousedown", "1")
        time.sleep(0.1)
        self._x("mouseup", "1")
        time.sleep(0.4)

    def click_text(self, text: str, patience: float = FIND_PATIENCE_S, below: int = 24,
                   alone: bool = False) -> Box:
        box = self.wait_text(text, patience, below, alone=alone)
        self.click(*box.center)
        return box

    def type_into(self, label: Box, text: str, offset: int = 200) -> None:
        """Clicks the field right of a label, selects what it holds and types over it."""
        self.click(label.right + offset, (label.top + label.bottom) // 2)
        self._x("key", "ctrl+a")
        self._x("type", "--delay", "80", text)
        time.sleep(0.2)

    def press(self, key: str) -> None:
        """A key pressed as a person does: down, a moment, up."""
        self._x("keydown", key)
        time.sleep(0.1)
        self._x("keyup", key)
        time.sleep(0.3)

    def hold_keys(self, keys: list[str], seconds: float) -> None:
        """Holds the keys down together for `seconds`, then lets them go (even on a failure)."""
        for key in keys:
            self._x("keydown", key)
        try:
            time.sleep(seconds)
        finally:
            for key in keys:
                self._x("keyup", key)

    def hold_key(self, key: str, seconds: float) -> None:
        self.hold_keys([key], seconds)

    def hold_only(self, keys: list[str]) -> None:
        """Keeps exactly these keys held from now on: lets go of the others, presses the new."""
        for key in sorted(self._held - set(keys)):
            self._x("keyup", key)
        for key in keys:
            if key not in self._held:
                self._x("keydown", key)
        self._held = set(keys)

    def close_window(self, game: "Game") -> None:
        """Closes the game's window as a player does on this desktop: the window manager's
        close shortcut (Alt+F4 in openbox), which asks the game to close (WM_DELETE_WINDOW).
        Like a player, it first brings the game's window to the front when another has the
        keyboard (said on the output: it should not happen)."""
        windows = game.windows()
        if windows and self._focused() not in windows:
            print(f"person: the game's window had no keyboard focus ({self._focused()}): clicked it")
            self._x("windowactivate", "--sync", windows[0])
        self.press("alt+F4")

    def close_and_see_it_exit(self, game: "Game") -> float:
        """Closes the game's window and waits for the game to end by itself, with exit code 0;
        returns how long that took. A window that takes no notice in NOTICE_S gets a second
        Alt+F4, as a player would give it (said on the output). A failure says whether the
        window was still there (the close never reached the game) or gone (the game hung while
        quitting)."""
        closing = time.monotonic()
        self.close_window(game)
        code = game.wait_exit(NOTICE_S)
        if code is None and game.has_window():
            print(f"person: the window was still up {NOTICE_S:.0f} s after Alt+F4: pressed it again")
            self.close_window(game)
        if code is None:
            code = game.wait_exit(EXIT_PATIENCE_S - NOTICE_S)
        took = time.monotonic() - closing
        if code is None:
            shot = self.screenshot("still-running")
            where = "still on the screen" if game.has_window() else "gone"
            raise AssertionError(f"the game still ran {took:.0f} s after Alt+F4, its window "
                                 f"{where} (last screen: {shot})")
        assert code == 0, f"the game exited with {code} after its window closed"
        return took

    def _focused(self) -> str:
        found = subprocess.run(["xdotool", "getwindowfocus"], env=self.display.env(),
                               capture_output=True, text=True, timeout=30)
        return found.stdout.strip()


class Game:
    """The game in its window, started as a player starts it, its output in a log file."""

    def __init__(self, build: str, display: Display, log: Path) -> None:
        self.build = build
        self.display = display
        self.log = log
        self.proc: subprocess.Popen | None = None
        # Engine options a benchmark adds (--print-fps); the tests add none.
        self.engine_args: list[str] = []

    def command(self) -> list[str]:
        if self.build == "export":
            return [str(EXPORTED), *self.engine_args]
        # What `make play` runs on a display (the Makefile's play target), with the renderer
        # this machine has (tools/test-windowed.sh): no flag of the tests.
        return [str(GODOT), "--path", str(ROOT), "--rendering-driver", "opengl3", *self.engine_args]

    def start(self) -> None:
        with open(self.log, "wb") as out:
            self.proc = subprocess.Popen(self.command(), cwd=ROOT, env=self.display.env(),
                                         stdout=out, stderr=subprocess.STDOUT,
                                         start_new_session=True)

    def output(self) -> str:
        return self.log.read_text(errors="replace") if self.log.exists() else ""

    def error_lines(self) -> list[str]:
        return [line for line in self.output().splitlines() if ERROR_LINE.search(line)]

    def windows(self) -> list[str]:
        assert self.proc is not None
        found = subprocess.run(["xdotool", "search", "--onlyvisible", "--pid", str(self.proc.pid)],
                               env=self.display.env(), capture_output=True, text=True, timeout=30)
        return found.stdout.split()

    def has_window(self) -> bool:
        """Whether a window of the game's process is on the display (asked of X, as a window
        list would)."""
        return bool(self.windows())

    def window_titles(self) -> list[str]:
        """The titles of the game's windows, as the title bar and the task list show them."""
        return [subprocess.run(["xdotool", "getwindowname", w], env=self.display.env(),
                               capture_output=True, text=True, timeout=30).stdout.strip()
                for w in self.windows()]

    def running(self) -> bool:
        return self.proc is not None and self.proc.poll() is None

    def wait_exit(self, patience: float = EXIT_PATIENCE_S) -> int | None:
        assert self.proc is not None
        try:
            return self.proc.wait(timeout=patience)
        except subprocess.TimeoutExpired:
            return None

    def stop(self) -> None:
        # tools/godot execs the engine, so this PID is the game itself.
        stop_process(self.proc)


class Session:
    """One test's display, game and person; `close()` stops all of them."""

    def __init__(self, test_name: str, build: str) -> None:
        self.scratch = Path(tempfile.mkdtemp(prefix="person-"))
        self.shots = SHOTS / test_name
        shutil.rmtree(self.shots, ignore_errors=True)
        self.shots.mkdir(parents=True)
        print(f"person: screenshots of {test_name} in {self.shots}")
        self.display = Display(self.scratch)
        self.game = Game(build, self.display, self.shots / "game.log")
        self.person = Person(self.display, self.shots, self.scratch)

    def start(self) -> None:
        self.display.start()
        self.game.start()

    def close(self) -> None:
        try:
            self.game.stop()
        finally:
            self.display.stop()
            shutil.rmtree(self.scratch, ignore_errors=True)
