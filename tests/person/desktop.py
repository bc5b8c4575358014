"""The desktop a scripted person sits at: an X server (Xvfb) with a window manager (openbox) and
a sound server (PulseAudio), each started here and stopped by its PID."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GODOT = ROOT / "tools" / "godot"
SCREEN = (1280, 720)



def tools_missing() -> list[str]:
    return [t for t in ("Xvfb", "openbox", "pulseaudio", "xdotool", "convert", "tesseract")
            if not shutil.which(t)]


def stop_process(proc: subprocess.Popen | None, patience: float = 10.0) -> None:
    """Stops one process we started, by its PID: SIGTERM, then SIGKILL."""
    if proc is None or proc.poll() is not None:
        return
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(timeout=patience)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait(timeout=patience)


class Display:
    """Xvfb on a free display (-displayfd, as tools/xvfb.sh), openbox on it, and a sound
    server: a player's desktop has one, and the game's audio driver waits on it between mixes.
    This machine has no sound card, so it plays into a null sink, which keeps a card's time
    (ALSA's null device does not: Godot's audio thread then spins on a core of its own)."""

    def __init__(self, scratch: Path) -> None:
        self.scratch = scratch
        self.xvfb: subprocess.Popen | None = None
        self.wm: subprocess.Popen | None = None
        self.sound: subprocess.Popen | None = None
        self.name = ""

    def start(self) -> None:
        read_fd, write_fd = os.pipe()
        with open(self.scratch / "xvfb.log", "wb") as log:
            self.xvfb = subprocess.Popen(
                ["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{SCREEN[0]}x{SCREEN[1]}x24",
                 "-nolisten", "tcp"],
                pass_fds=(write_fd,), stdout=log, stderr=log)
        os.close(write_fd)
        number = b""
        deadline = time.monotonic() + 30.0
        with os.fdopen(read_fd, "rb", buffering=0) as pipe:
            while not number.endswith(b"\n") and time.monotonic() < deadline:
                chunk = pipe.read(16)
                if not chunk:
                    break
                number += chunk
        if not number.strip():
            raise RuntimeError(f"Xvfb did not start: {(self.scratch / 'xvfb.log').read_text()}")
        self.name = ":" + number.decode().strip()
        with open(self.scratch / "openbox.log", "wb") as log:
            self.wm = subprocess.Popen(["openbox"], env=self.env(), stdout=log, stderr=log)
        self._start_sound()

    def _start_sound(self) -> None:
        socket = self.scratch / "pulse" / "native"
        socket.parent.mkdir()
        script = self.scratch / "pulse.pa"
        script.write_text(f"load-module module-native-protocol-unix socket={socket} auth-anonymous=1\n"
                          "load-module module-null-sink sink_name=speakers\n"
                          "set-default-sink speakers\n")
        env = {**self.env(), "HOME": str(self.scratch), "XDG_RUNTIME_DIR": str(socket.parent)}
        with open(self.scratch / "pulseaudio.log", "wb") as log:
            self.sound = subprocess.Popen(
                ["pulseaudio", "-n", "-F", str(script), "--daemonize=no", "--exit-idle-time=-1",
                 "--use-pid-file=no", "--disable-shm=yes"], env=env, stdout=log, stderr=log)
        deadline = time.monotonic() + 30.0
        while not socket.exists():
            if self.sound.poll() is not None or time.monotonic() > deadline:
                raise RuntimeError("PulseAudio did not start: "
                                   + (self.scratch / "pulseaudio.log").read_text(errors="replace"))
            time.sleep(0.1)

    def env(self) -> dict[str, str]:
        env = dict(os.environ)
        env["DISPLAY"] = self.name
        env.pop("WAYLAND_DISPLAY", None)
        env["PULSE_SERVER"] = f"unix:{self.scratch / 'pulse' / 'native'}"
        # A fresh player's folders: the exported game's XDG ones, and the root of those
        # tools/godot gives the source build (make play's own). Two people are two players:
        # two copies sharing one shader cache corrupted it ("shader_file_header").
        for name in ("CONFIG", "DATA", "CACHE"):
            folder = self.scratch / "home" / name.lower()
            folder.mkdir(parents=True, exist_ok=True)
            env[f"XDG_{name}_HOME"] = str(folder)
        env["HAPTICS_XDG_ROOT"] = str(self.scratch / "home")
        return env

    def stop(self) -> None:
        stop_process(self.wm)
        stop_process(self.sound)
        stop_process(self.xvfb)
