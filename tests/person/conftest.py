"""The person's fixtures: one display, game and person per test, for each build a player can
start (the source tree as `make play` runs it; the exported game when .export/linux has one).
A SIGTERM to pytest unwinds like Ctrl-C, so every test's finally stops what it started."""

from __future__ import annotations

import signal
import sys

import pytest

from desktop import tools_missing
from person import EXPORTED, Session


def _unwind(_signum, _frame):
    raise KeyboardInterrupt


signal.signal(signal.SIGTERM, _unwind)
sys.dont_write_bytecode = True


def skip_unless_playable(build: str) -> None:
    """Skips the test where the tools or the build it needs are not here."""
    missing = tools_missing()
    if missing:
        pytest.skip(f"missing {', '.join(missing)} (make deps installs them)")
    if build == "export" and not EXPORTED.exists():
        pytest.skip(f"no exported game at {EXPORTED.relative_to(EXPORTED.parents[2])} "
                    "(make export builds it)")


def _played(name: str, build: str):
    skip_unless_playable(build)
    s = Session(name, build)
    try:
        s.start()
        yield s
    finally:
        s.close()
        # Every run fails on an error line or an X error, whatever else it checked.
        errors = s.game.error_lines()
        print(f"person: {len(s.person.ocr_seconds)} OCR passes, "
              f"{sum(s.person.ocr_seconds) / max(1, len(s.person.ocr_seconds)):.2f} s each "
              f"on average; screenshots in {s.shots}")
        assert not errors, "the game printed errors:\n" + "\n".join(errors[:20])


@pytest.fixture(params=["source", "export"])
def session(request):
    """The game in each build a player starts: from source (make play) and exported."""
    yield from _played(request.node.name.replace("[", "-").replace("]", ""), request.param)


@pytest.fixture
def shipped_session(request):
    """The game as it ships (the exported build; from source where none is exported), for
    a scenario too long to play twice."""
    build = "export" if EXPORTED.exists() else "source"
    yield from _played(f"{request.node.name}-{build}", build)
