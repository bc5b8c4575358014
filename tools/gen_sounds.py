#!/usr/bin/env python3
"""Synthesises the side-scroller's sounds into assets/sounds/ (16-bit mono WAV, 22 050 Hz).

Run from the project root: python3 tools/gen_sounds.py. Deterministic (fixed seeds); pure
Python, no dependencies. Looping sounds carry a RIFF 'smpl' chunk with their loop points,
which Godot's WAV importer reads ("Detect From WAV", the default loop mode).
"""
import math
import os
import random
import struct

RATE = 22050
OUT = os.path.join(os.path.dirname(__file__), "..", "assets", "sounds")


def write_wav(name, samples, loop=False):
    peak = max(1e-9, max(abs(s) for s in samples))
    scale = 0.89 / peak
    data = b"".join(struct.pack("<h", int(max(-1.0, min(1.0, s * scale)) * 32767)) for s in samples)
    chunks = b"fmt " + struct.pack("<IHHIIHH", 16, 1, 1, RATE, RATE * 2, 2, 16)
    chunks += b"data" + struct.pack("<I", len(data)) + data
    if loop:
        smpl = struct.pack("<IIIIIIIII", 0, 0, int(1e9 / RATE), 60, 0, 0, 0, 1, 0)
        smpl += struct.pack("<IIIIII", 0, 0, 0, len(samples) - 1, 0, 0)
        chunks += b"smpl" + struct.pack("<I", len(smpl)) + smpl
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(b"RIFF" + struct.pack("<I", 4 + len(chunks)) + b"WAVE" + chunks)


def lowpass(samples, cutoff):
    a = 1.0 - math.exp(-2.0 * math.pi * cutoff / RATE)
    out, y = [], 0.0
    for s in samples:
        y += a * (s - y)
        out.append(y)
    return out


def highpass(samples, cutoff):
    low = lowpass(samples, cutoff)
    return [s - l for s, l in zip(samples, low)]


def noise(n, seed):
    rng = random.Random(seed)
    return [rng.uniform(-1.0, 1.0) for _ in range(n)]


def modes(duration, partials, seed=0, noise_amount=0.0, noise_decay=0.01, noise_cut=3000.0):
    """Decaying sinusoids (frequency, amplitude, decay seconds) plus a filtered noise click."""
    n = int(duration * RATE)
    out = [0.0] * n
    for freq, amp, decay in partials:
        for i in range(n):
            t = i / RATE
            out[i] += amp * math.exp(-t / decay) * math.sin(2 * math.pi * freq * t)
    if noise_amount > 0.0:
        burst = lowpass(noise(n, seed), noise_cut)
        for i in range(n):
            out[i] += noise_amount * burst[i] * math.exp(-(i / RATE) / noise_decay)
    fade = int(0.005 * RATE)
    for i in range(fade):
        out[n - 1 - i] *= i / fade
    return out


def impact_wood():
    return modes(0.35, [(190, 1.0, 0.06), (410, 0.6, 0.04), (780, 0.3, 0.02), (1240, 0.15, 0.012)],
                 seed=1, noise_amount=0.8, noise_decay=0.008, noise_cut=2500)


def impact_rock():
    return modes(0.4, [(140, 0.7, 0.05), (620, 0.5, 0.025), (1630, 0.35, 0.015), (2870, 0.2, 0.008)],
                 seed=2, noise_amount=1.2, noise_decay=0.012, noise_cut=5000)


def impact_soft():
    return modes(0.4, [(70, 1.0, 0.09), (140, 0.4, 0.05)],
                 seed=3, noise_amount=0.5, noise_decay=0.03, noise_cut=700)


def impact_ice():
    return modes(0.7, [(1180, 0.6, 0.18), (2310, 0.45, 0.12), (3470, 0.3, 0.08), (520, 0.4, 0.05)],
                 seed=4, noise_amount=0.4, noise_decay=0.004, noise_cut=6000)


def splash():
    n = int(0.9 * RATE)
    raw = noise(n, 5)
    out = [0.0] * n
    # a burst whose brightness falls: two low-passed copies crossfaded
    bright = lowpass(raw, 4000)
    dull = lowpass(raw, 900)
    for i in range(n):
        t = i / RATE
        env = (1 - math.exp(-t / 0.006)) * math.exp(-t / 0.22)
        mix = min(1.0, t / 0.3)
        out[i] = env * (bright[i] * (1 - mix) + dull[i] * mix * 1.6)
    # bubbles: short rising chirps
    rng = random.Random(6)
    for _ in range(14):
        start = rng.uniform(0.05, 0.7)
        f0 = rng.uniform(500, 1300)
        length = rng.uniform(0.03, 0.07)
        amp = rng.uniform(0.15, 0.35) * math.exp(-start / 0.4)
        s0 = int(start * RATE)
        for k in range(int(length * RATE)):
            if s0 + k >= n:
                break
            t = k / RATE
            f = f0 * (1 + 3.0 * t / length)
            out[s0 + k] += amp * math.sin(2 * math.pi * f * t) * math.sin(math.pi * t / length)
    return highpass(out, 120)


def chime(notes, duration, decay=0.35, spacing=0.09):
    n = int(duration * RATE)
    out = [0.0] * n
    for k, freq in enumerate(notes):
        s0 = int(k * spacing * RATE)
        for i in range(s0, n):
            t = (i - s0) / RATE
            env = math.exp(-t / decay) * min(1.0, t / 0.004)
            out[i] += env * (math.sin(2 * math.pi * freq * t) + 0.35 * math.sin(2 * math.pi * 2 * freq * t)
                             + 0.12 * math.sin(2 * math.pi * 3.01 * freq * t))
    return out


def ambience():
    """An 8 s seamless loop: low rumble of surf, slow swell, a few drips."""
    seconds = 8.0
    n = int(seconds * RATE)
    base = noise(n, 8)
    rumble = lowpass(lowpass(base, 220), 220)
    hiss = lowpass(highpass(noise(n, 9), 600), 2500)
    out = [0.0] * n
    for i in range(n):
        t = i / RATE
        swell = 0.6 + 0.4 * math.sin(2 * math.pi * t / seconds) ** 2
        out[i] = 2.5 * rumble[i] * swell + 0.08 * hiss[i] * swell
    rng = random.Random(10)
    for _ in range(5):
        start = rng.uniform(0.3, seconds - 0.5)
        f = rng.uniform(900, 1600)
        s0 = int(start * RATE)
        for k in range(int(0.25 * RATE)):
            t = k / RATE
            out[s0 + k] += 0.12 * math.exp(-t / 0.05) * math.sin(2 * math.pi * f * (1 + 0.6 * t) * t)
    # seamless: crossfade the last 0.5 s into the first
    fade = int(0.5 * RATE)
    for i in range(fade):
        w = i / fade
        out[i] = out[i] * w + out[n - fade + i] * (1 - w)
    return out[: n - fade]


def hum():
    """A 1 s seamless motor hum (whole number of cycles of every partial)."""
    n = RATE
    out = [0.0] * n
    buzz = lowpass(noise(n, 12), 400)
    for i in range(n):
        t = i / RATE
        out[i] = (0.6 * math.sin(2 * math.pi * 60 * t) + 0.3 * math.sin(2 * math.pi * 120 * t)
                  + 0.15 * math.sin(2 * math.pi * 181 * t) + 0.5 * buzz[i])
    fade = int(0.1 * RATE)
    for i in range(fade):
        w = i / fade
        out[i] = out[i] * w + out[n - fade + i] * (1 - w)
    return out[: n - fade]


def main():
    os.makedirs(OUT, exist_ok=True)
    write_wav("impact_wood.wav", impact_wood())
    write_wav("impact_rock.wav", impact_rock())
    write_wav("impact_soft.wav", impact_soft())
    write_wav("impact_ice.wav", impact_ice())
    write_wav("splash.wav", splash())
    write_wav("pearl.wav", chime([1046.5, 1318.5, 1568.0], 0.9))
    write_wav("goal.wav", chime([523.25, 659.25, 783.99, 1046.5, 1318.5], 2.0, decay=0.6, spacing=0.13))
    write_wav("ambience.wav", ambience(), loop=True)
    write_wav("hum.wav", hum(), loop=True)


if __name__ == "__main__":
    main()
