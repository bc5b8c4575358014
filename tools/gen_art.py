#!/usr/bin/env python3
"""Generates the side-scroller's SVG art into assets/art/ (deterministic: fixed seeds).

Run from the project root: python3 tools/gen_art.py
Textures that tile (terrain fills, parallax layers) are made seamless by drawing every
element again one period to the left/right (and up/down) and letting the view box clip.
"""
import math
import os
import random

OUT = os.path.join(os.path.dirname(__file__), "..", "assets", "art")


def write(name, width, height, body, defs=""):
    path = os.path.join(OUT, name)
    with open(path, "w") as f:
        f.write(
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}">\n<defs>{defs}</defs>\n{body}\n</svg>\n'
        )


def pts(points):
    return " ".join(f"{x:.1f},{y:.1f}" for x, y in points)


def blob(cx, cy, r, rng, n=9, jitter=0.3):
    out = []
    for i in range(n):
        a = 2 * math.pi * i / n + rng.uniform(-0.2, 0.2)
        rr = r * (1 + rng.uniform(-jitter, jitter))
        out.append((cx + math.cos(a) * rr, cy + math.sin(a) * rr * 0.8))
    return out


def wrapped(size, x, y, draw):
    """Calls draw(x, y) for the element and its copies one tile away."""
    s = ""
    for dx in (-size, 0, size):
        for dy in (-size, 0, size):
            s += draw(x + dx, y + dy)
    return s


# ---------------------------------------------------------------------------------------
# Terrain fills (256 px tiles)


def rock_tile():
    rng = random.Random(7)
    size = 256
    body = f'<rect width="{size}" height="{size}" fill="#4b5868"/>'
    palette = ["#556477", "#5d6d80", "#46525f", "#516073", "#62728a"]
    for _ in range(26):
        x, y, r = rng.uniform(0, size), rng.uniform(0, size), rng.uniform(16, 38)
        poly = blob(0, 0, r, rng, n=7, jitter=0.25)
        colour = rng.choice(palette)

        def stone(px, py, poly=poly, colour=colour):
            moved = [(px + a, py + b) for a, b in poly]
            hi = [(px + a * 0.7 - 3, py + b * 0.7 - 4) for a, b in poly]
            return (
                f'<polygon points="{pts(moved)}" fill="{colour}" stroke="#3a4552" '
                f'stroke-width="2.5" stroke-linejoin="round"/>'
                f'<polygon points="{pts(hi)}" fill="#ffffff" opacity="0.05"/>'
            )

        body += wrapped(size, x, y, stone)
    for _ in range(70):
        x, y = rng.uniform(0, size), rng.uniform(0, size)
        r = rng.uniform(0.8, 2.2)
        c = rng.choice(["#2f3944", "#7d8ca0", "#394552"])
        body += wrapped(size, x, y, lambda px, py, r=r, c=c: f'<circle cx="{px:.1f}" cy="{py:.1f}" r="{r:.1f}" fill="{c}"/>')
    return write("rock_hard.svg", size, size, body)


def sponge_tile():
    rng = random.Random(11)
    size = 256
    body = f'<rect width="{size}" height="{size}" fill="#d0894e"/>'
    for _ in range(40):
        x, y, r = rng.uniform(0, size), rng.uniform(0, size), rng.uniform(18, 40)
        c = rng.choice(["#d99a5c", "#c97f45", "#dca266", "#c47a42"])
        body += wrapped(size, x, y, lambda px, py, r=r, c=c: f'<circle cx="{px:.1f}" cy="{py:.1f}" r="{r:.1f}" fill="{c}" opacity="0.7"/>')
    for _ in range(55):
        x, y, r = rng.uniform(0, size), rng.uniform(0, size), rng.uniform(3, 9)
        body += wrapped(
            size, x, y,
            lambda px, py, r=r: (
                f'<ellipse cx="{px:.1f}" cy="{py + 1.5:.1f}" rx="{r + 2:.1f}" ry="{r * 0.8 + 2:.1f}" fill="#efc08a"/>'
                f'<ellipse cx="{px:.1f}" cy="{py:.1f}" rx="{r:.1f}" ry="{r * 0.8:.1f}" fill="#7a3e22"/>'
            ),
        )
    for _ in range(90):
        x, y = rng.uniform(0, size), rng.uniform(0, size)
        body += wrapped(size, x, y, lambda px, py: f'<circle cx="{px:.1f}" cy="{py:.1f}" r="1.3" fill="#f6d6a8" opacity="0.8"/>')
    return write("sponge_soft.svg", size, size, body)


def crystal_tile():
    rng = random.Random(5)
    size = 256
    body = f'<rect width="{size}" height="{size}" fill="#7fc6da"/>'
    palette = ["#93d5e6", "#6fb6cf", "#a9e3ef", "#86cde0", "#5fa9c5"]
    for _ in range(30):
        x, y = rng.uniform(0, size), rng.uniform(0, size)
        w, h = rng.uniform(14, 34), rng.uniform(40, 90)
        ang = rng.uniform(-35, 35)
        c = rng.choice(palette)

        def shard(px, py, w=w, h=h, ang=ang, c=c):
            p = [(0, -h / 2), (w / 2, -h / 4), (w / 2, h / 2), (-w / 2, h / 2), (-w / 2, -h / 4)]
            return (
                f'<g transform="translate({px:.1f},{py:.1f}) rotate({ang:.1f})">'
                f'<polygon points="{pts(p)}" fill="{c}" stroke="#d8f6fc" stroke-width="1.5" stroke-linejoin="round"/>'
                f'<polygon points="{pts([(0, -h / 2), (w / 2, -h / 4), (0, h / 2)])}" fill="#ffffff" opacity="0.18"/>'
                f"</g>"
            )

        body += wrapped(size, x, y, shard)
    for _ in range(14):
        x, y = rng.uniform(0, size), rng.uniform(0, size)
        body += wrapped(
            size, x, y,
            lambda px, py: f'<line x1="{px:.1f}" y1="{py:.1f}" x2="{px + 26:.1f}" y2="{py - 26:.1f}" stroke="#ffffff" stroke-width="2" opacity="0.45" stroke-linecap="round"/>',
        )
    return write("crystal_slippery.svg", size, size, body)


def backwall_tile():
    """Dark rock seen behind the cave (drawn far darker than the terrain)."""
    rng = random.Random(23)
    size = 256
    body = f'<rect width="{size}" height="{size}" fill="#1b2a38"/>'
    for _ in range(22):
        x, y, r = rng.uniform(0, size), rng.uniform(0, size), rng.uniform(20, 48)
        poly = blob(0, 0, r, rng, n=8, jitter=0.3)
        c = rng.choice(["#1f3040", "#223547", "#192734", "#24394b"])
        body += wrapped(size, x, y, lambda px, py, poly=poly, c=c: f'<polygon points="{pts([(px + a, py + b) for a, b in poly])}" fill="{c}" stroke="#142029" stroke-width="3" stroke-linejoin="round"/>')
    return write("backwall.svg", size, size, body)


# ---------------------------------------------------------------------------------------
# Props (drawn at 2x, shown at scale 0.5)


def crate(name, heavy):
    s = 96
    wood = "#6b5a4e" if heavy else "#c0843f"
    dark = "#3e332c" if heavy else "#8a5524"
    light = "#857366" if heavy else "#dda35c"
    body = f'<rect x="2" y="2" width="92" height="92" rx="6" fill="{dark}"/>'
    # planks
    for i in range(4):
        y = 8 + i * 20.5
        body += f'<rect x="8" y="{y:.1f}" width="80" height="18" rx="2" fill="{wood}"/>'
        body += f'<rect x="8" y="{y:.1f}" width="80" height="4" rx="2" fill="{light}" opacity="0.7"/>'
        body += f'<line x1="{20 + i * 17}" y1="{y + 9:.1f}" x2="{36 + i * 17}" y2="{y + 10:.1f}" stroke="{dark}" stroke-width="1.5" opacity="0.6"/>'
    # frame and diagonal brace
    body += f'<rect x="2" y="2" width="92" height="92" rx="6" fill="none" stroke="{dark}" stroke-width="5"/>'
    body += f'<rect x="6" y="6" width="84" height="84" rx="4" fill="none" stroke="{light}" stroke-width="8" opacity="0.9"/>'
    body += f'<rect x="6" y="6" width="84" height="84" rx="4" fill="none" stroke="{dark}" stroke-width="1.5" opacity="0.7"/>'
    body += f'<line x1="14" y1="82" x2="82" y2="14" stroke="{light}" stroke-width="11" stroke-linecap="round"/>'
    body += f'<line x1="14" y1="82" x2="82" y2="14" stroke="{dark}" stroke-width="1.5" opacity="0.5" transform="translate(0,5)"/>'
    if heavy:
        for y in (20, 76):
            body += f'<rect x="2" y="{y - 6}" width="92" height="12" fill="#59636e" stroke="#2c3238" stroke-width="2"/>'
            for x in (12, 48, 84):
                body += f'<circle cx="{x}" cy="{y}" r="3.2" fill="#a9b4bf" stroke="#2c3238" stroke-width="1"/>'
    else:
        for x, y in ((12, 12), (84, 12), (12, 84), (84, 84)):
            body += f'<circle cx="{x}" cy="{y}" r="2.6" fill="#4a3524"/>'
    write(name, s, s, body)


def sub():
    w, h = 128, 88
    defs = (
        '<linearGradient id="hull" x1="0" y1="0" x2="0" y2="1">'
        '<stop offset="0" stop-color="#ffd25e"/><stop offset="0.55" stop-color="#f59b2e"/>'
        '<stop offset="1" stop-color="#c4601e"/></linearGradient>'
        '<radialGradient id="glass" cx="0.35" cy="0.35" r="0.7">'
        '<stop offset="0" stop-color="#e9fbff"/><stop offset="0.45" stop-color="#7fd3ee"/>'
        '<stop offset="1" stop-color="#2b7fa6"/></radialGradient>'
    )
    cx, cy = 64, 46
    b = ""
    # tail fin and keel
    b += f'<polygon points="{pts([(22, 40), (6, 18), (18, 18), (36, 36)])}" fill="#d9712a" stroke="#5a2a10" stroke-width="3" stroke-linejoin="round"/>'
    b += f'<polygon points="{pts([(24, 56), (8, 74), (20, 74), (38, 58)])}" fill="#d9712a" stroke="#5a2a10" stroke-width="3" stroke-linejoin="round"/>'
    # conning tower
    b += '<rect x="50" y="14" width="30" height="20" rx="7" fill="url(#hull)" stroke="#5a2a10" stroke-width="3"/>'
    b += '<rect x="62" y="6" width="4" height="10" fill="#5a2a10"/><rect x="62" y="4" width="12" height="4" rx="2" fill="#5a2a10"/>'
    # hull
    b += f'<ellipse cx="{cx}" cy="{cy}" rx="44" ry="24" fill="url(#hull)" stroke="#5a2a10" stroke-width="3.5"/>'
    b += f'<ellipse cx="{cx - 4}" cy="{cy - 12}" rx="30" ry="6" fill="#fff3c4" opacity="0.55"/>'
    b += f'<path d="M 26 {cy + 8} Q 64 {cy + 24} 102 {cy + 8}" fill="none" stroke="#a34a14" stroke-width="3" opacity="0.6"/>'
    # portholes
    for x in (44, 58):
        b += f'<circle cx="{x}" cy="{cy + 2}" r="4.5" fill="#1d4d66" stroke="#5a2a10" stroke-width="2.5"/>'
        b += f'<circle cx="{x - 1.5}" cy="{cy + 0.5}" r="1.5" fill="#bff0ff"/>'
    # cockpit dome
    b += f'<circle cx="88" cy="{cy - 2}" r="15" fill="url(#glass)" stroke="#5a2a10" stroke-width="3.5"/>'
    b += f'<path d="M 80 {cy - 10} Q 86 {cy - 15} 93 {cy - 12}" fill="none" stroke="#ffffff" stroke-width="3" stroke-linecap="round" opacity="0.85"/>'
    # headlamp
    b += f'<rect x="104" y="{cy + 4}" width="10" height="10" rx="3" fill="#fff8d8" stroke="#5a2a10" stroke-width="2.5"/>'
    # stern hub
    b += f'<rect x="14" y="{cy - 6}" width="10" height="12" rx="3" fill="#7a8794" stroke="#2a3138" stroke-width="2.5"/>'
    write("sub.svg", w, h, b, defs)


def propeller():
    w, h = 16, 48
    b = '<ellipse cx="8" cy="12" rx="6" ry="11" fill="#c7d3de" stroke="#2a3138" stroke-width="2.5"/>'
    b += '<ellipse cx="8" cy="36" rx="6" ry="11" fill="#9fb0bf" stroke="#2a3138" stroke-width="2.5"/>'
    b += '<circle cx="8" cy="24" r="4" fill="#5b6671" stroke="#2a3138" stroke-width="2"/>'
    write("propeller.svg", w, h, b)


def pearl():
    defs = (
        '<radialGradient id="p" cx="0.35" cy="0.3" r="0.75">'
        '<stop offset="0" stop-color="#ffffff"/><stop offset="0.5" stop-color="#f4ecff"/>'
        '<stop offset="1" stop-color="#b9a6d8"/></radialGradient>'
    )
    b = '<circle cx="16" cy="16" r="13" fill="url(#p)" stroke="#6d5a8c" stroke-width="2.5"/>'
    b += '<ellipse cx="11" cy="10" rx="4" ry="3" fill="#ffffff"/>'
    write("pearl.svg", 32, 32, b, defs)
    # open clam (drawn 2x: 96x64)
    defs2 = (
        '<linearGradient id="c" x1="0" y1="0" x2="0" y2="1">'
        '<stop offset="0" stop-color="#f39bb0"/><stop offset="1" stop-color="#b8496a"/></linearGradient>'
    )
    b2 = ""
    # upper shell (open, tilted back)
    b2 += '<path d="M 10 34 Q 48 -6 86 34 Z" fill="url(#c)" stroke="#5e1d33" stroke-width="3.5" stroke-linejoin="round"/>'
    for i in range(5):
        x = 22 + i * 13
        b2 += f'<path d="M 48 32 L {x} {12 + abs(i - 2) * 5}" stroke="#ffd0dc" stroke-width="2.5" opacity="0.7"/>'
    # lower shell
    b2 += '<path d="M 8 38 Q 48 70 88 38 Q 48 48 8 38 Z" fill="#d86a87" stroke="#5e1d33" stroke-width="3.5" stroke-linejoin="round"/>'
    b2 += '<path d="M 14 40 Q 48 50 82 40" fill="none" stroke="#ffe0e8" stroke-width="3" opacity="0.8"/>'
    write("clam.svg", 96, 64, b2, defs2)


def buoy():
    """Goal beacon: a striped buoy with a lamp cage and a flag (drawn 2x: 128x224)."""
    w, h = 128, 224
    b = ""
    b += '<line x1="64" y1="8" x2="64" y2="96" stroke="#2b2f36" stroke-width="5"/>'
    b += f'<polygon points="{pts([(66, 10), (112, 22), (66, 36)])}" fill="#3fd08a" stroke="#1b5e3e" stroke-width="3" stroke-linejoin="round"/>'
    b += '<rect x="46" y="52" width="36" height="44" rx="8" fill="#fff1b0" stroke="#2b2f36" stroke-width="4"/>'
    b += '<line x1="58" y1="54" x2="58" y2="94" stroke="#2b2f36" stroke-width="3"/><line x1="70" y1="54" x2="70" y2="94" stroke="#2b2f36" stroke-width="3"/>'
    b += '<rect x="40" y="44" width="48" height="10" rx="4" fill="#c6303e" stroke="#2b2f36" stroke-width="3"/>'
    # body: cone with red/white stripes
    body = [(36, 100), (92, 100), (112, 190), (16, 190)]
    b += f'<polygon points="{pts(body)}" fill="#f5f1e8" stroke="#2b2f36" stroke-width="4" stroke-linejoin="round"/>'
    b += f'<polygon points="{pts([(33, 114), (95, 114), (101, 140), (27, 140)])}" fill="#d63b4a"/>'
    b += f'<polygon points="{pts([(24, 162), (104, 162), (109, 184), (19, 184)])}" fill="#d63b4a"/>'
    b += f'<polygon points="{pts(body)}" fill="none" stroke="#2b2f36" stroke-width="4" stroke-linejoin="round"/>'
    b += '<rect x="8" y="188" width="112" height="18" rx="8" fill="#414a57" stroke="#1d2229" stroke-width="4"/>'
    b += '<path d="M 40 206 Q 64 222 88 206" fill="#414a57" stroke="#1d2229" stroke-width="4"/>'
    write("buoy.svg", w, h, b)


# ---------------------------------------------------------------------------------------
# Parallax layers (2048 wide, repeat horizontally)


def ridge(rng, width, base, amp, step, period_ok=True):
    """A closed silhouette from the bottom up to a jagged ridge, seamless over width."""
    n = int(width / step)
    heights = [base - rng.uniform(0, amp) for _ in range(n)]
    heights.append(heights[0])
    return heights


def parallax_far():
    rng = random.Random(3)
    w, h = 2048, 1100
    defs = (
        '<linearGradient id="deep" x1="0" y1="0" x2="0" y2="1">'
        '<stop offset="0" stop-color="#1c4a62"/><stop offset="0.5" stop-color="#0f2d45"/>'
        '<stop offset="1" stop-color="#071524"/></linearGradient>'
    )
    b = f'<rect width="{w}" height="{h}" fill="url(#deep)"/>'
    # hanging formations from the top and mounds from the bottom, hazy blue
    for layer, (colour, top_base, bottom_base, amp) in enumerate(
        [("#17405a", 140, 860, 160), ("#12344b", 90, 930, 200)]
    ):
        step = 64
        n = w // step
        tops = [top_base + rng.uniform(-40, amp) for _ in range(n)] + [0]
        tops[-1] = tops[0]
        bots = [bottom_base - rng.uniform(-40, amp) for _ in range(n)] + [0]
        bots[-1] = bots[0]
        top_poly = [(0, 0)] + [(i * step, tops[i]) for i in range(n + 1)] + [(w, 0)]
        bot_poly = [(0, h)] + [(i * step, bots[i]) for i in range(n + 1)] + [(w, h)]
        b += f'<polygon points="{pts(top_poly)}" fill="{colour}"/>'
        b += f'<polygon points="{pts(bot_poly)}" fill="{colour}"/>'
        # a few columns joining top and bottom
        for _ in range(2 + layer):
            x = rng.uniform(100, w - 200)
            cw = rng.uniform(60, 130)
            col = [(x, 0), (x + cw, 0), (x + cw * 0.7, h * 0.45), (x + cw * 1.1, h), (x - cw * 0.2, h), (x + cw * 0.25, h * 0.5)]
            b += f'<polygon points="{pts(col)}" fill="{colour}"/>'
    # faint light shafts
    for _ in range(5):
        x = rng.uniform(0, w)
        b += f'<polygon points="{pts([(x, 0), (x + 90, 0), (x + 260, h), (x + 120, h)])}" fill="#9fe3ff" opacity="0.045"/>'
    write("parallax_far.svg", w, h, b, defs)


def parallax_mid():
    rng = random.Random(9)
    w, h = 2048, 1100
    b = ""
    colour = "#0f2738"
    # stalactites
    x = 0
    while x < w:
        cw = rng.uniform(40, 120)
        length = rng.uniform(60, 260)
        tip = x + cw * rng.uniform(0.3, 0.7)
        b += f'<polygon points="{pts([(x, 0), (x + cw, 0), (x + cw * 0.8, length * 0.4), (tip, length), (x + cw * 0.2, length * 0.5)])}" fill="{colour}"/>'
        x += cw * rng.uniform(0.8, 1.6)
    b += f'<rect x="0" y="0" width="{w}" height="50" fill="{colour}"/>'
    # seabed mounds
    step = 48
    n = w // step
    hs = [h - 120 - rng.uniform(0, 140) for _ in range(n)] + [0]
    hs[-1] = hs[0]
    poly = [(0, h)] + [(i * step, hs[i]) for i in range(n + 1)] + [(w, h)]
    b += f'<polygon points="{pts(poly)}" fill="{colour}"/>'
    # kelp strands and glowing dots
    for _ in range(16):
        x = rng.uniform(0, w)
        base = h - 100
        top = base - rng.uniform(150, 380)
        sway = rng.uniform(-40, 40)
        b += f'<path d="M {x:.0f} {base} Q {x + sway:.0f} {(base + top) / 2:.0f} {x + sway * 0.3:.0f} {top:.0f}" fill="none" stroke="#16384a" stroke-width="{rng.uniform(6, 12):.1f}" stroke-linecap="round"/>'
    for _ in range(60):
        x, y = rng.uniform(0, w), rng.uniform(60, h - 60)
        r = rng.uniform(1.2, 3.0)
        b += f'<circle cx="{x:.0f}" cy="{y:.0f}" r="{r:.1f}" fill="#7ff0e0" opacity="{rng.uniform(0.25, 0.6):.2f}"/>'
    write("parallax_mid.svg", w, h, b)


def sky():
    w, h = 1600, 720
    defs = (
        '<linearGradient id="s" x1="0" y1="0" x2="0" y2="1">'
        '<stop offset="0" stop-color="#3b6aa8"/><stop offset="0.55" stop-color="#8fb8d8"/>'
        '<stop offset="0.8" stop-color="#f2c894"/><stop offset="1" stop-color="#f7a86b"/></linearGradient>'
        '<radialGradient id="sun" cx="0.5" cy="0.5" r="0.5">'
        '<stop offset="0" stop-color="#fff7d6"/><stop offset="0.35" stop-color="#ffe3a0" stop-opacity="0.8"/>'
        '<stop offset="1" stop-color="#ffc78a" stop-opacity="0"/></radialGradient>'
    )
    b = f'<rect width="{w}" height="{h}" fill="url(#s)"/>'
    b += '<circle cx="620" cy="470" r="170" fill="url(#sun)"/>'
    b += '<circle cx="620" cy="470" r="46" fill="#fff6da"/>'
    rng = random.Random(2)
    for _ in range(7):
        x, y = rng.uniform(0, w), rng.uniform(60, 380)
        for k in range(4):
            b += f'<ellipse cx="{x + k * 34:.0f}" cy="{y + rng.uniform(-8, 8):.0f}" rx="{rng.uniform(40, 70):.0f}" ry="{rng.uniform(14, 22):.0f}" fill="#ffffff" opacity="0.55"/>'
    # distant headland and sea horizon
    b += f'<rect x="0" y="580" width="{w}" height="{h - 580}" fill="#2d6f93"/>'
    b += f'<rect x="0" y="580" width="{w}" height="4" fill="#cfe9f5" opacity="0.7"/>'
    for _ in range(30):
        x, y = rng.uniform(0, w), rng.uniform(590, 700)
        b += f'<rect x="{x:.0f}" y="{y:.0f}" width="{rng.uniform(20, 60):.0f}" height="2" fill="#bfe6f7" opacity="0.5"/>'
    write("sky.svg", w, h, b, defs)


def particles():
    b = '<circle cx="8" cy="8" r="6" fill="#d8f4ff" fill-opacity="0.25" stroke="#ffffff" stroke-width="1.6"/>'
    b += '<circle cx="5.5" cy="5.5" r="1.8" fill="#ffffff"/>'
    write("bubble.svg", 16, 16, b)
    defs = (
        '<radialGradient id="g" cx="0.5" cy="0.5" r="0.5">'
        '<stop offset="0" stop-color="#ffffff"/><stop offset="0.5" stop-color="#ffffff" stop-opacity="0.6"/>'
        '<stop offset="1" stop-color="#ffffff" stop-opacity="0"/></radialGradient>'
    )
    write("puff.svg", 32, 32, '<circle cx="16" cy="16" r="16" fill="url(#g)"/>', defs)
    write("droplet.svg", 12, 16, '<path d="M 6 1 Q 11 9 10 11 A 4.2 4.2 0 0 1 2 11 Q 1 9 6 1 Z" fill="#e8fbff"/>')
    write("glow.svg", 64, 64, '<circle cx="32" cy="32" r="32" fill="url(#g)"/>', defs)


def decor():
    """Sea-floor decoration (drawn 2x; anchored at the bottom centre in the level)."""
    rng = random.Random(31)
    # kelp: a wavy stalk with alternating blades
    w, h = 64, 320
    b = ""
    stalk = []
    for i in range(17):
        y = h - i * 19
        x = 32 + math.sin(i * 0.7) * 6
        stalk.append((x, y))
    d = "M " + " L ".join(f"{x:.1f} {y:.1f}" for x, y in stalk)
    for i, (x, y) in enumerate(stalk[2:-1]):
        side = 1 if i % 2 else -1
        tip = (x + side * rng.uniform(18, 26), y - rng.uniform(18, 30))
        blade = [(x, y), (x + side * 10, y - 6), tip, (x + side * 6, y - 14), (x, y - 10)]
        b += f'<polygon points="{pts(blade)}" fill="#4f8a3c" stroke="#23461d" stroke-width="2" stroke-linejoin="round"/>'
    b = f'<path d="{d}" fill="none" stroke="#23461d" stroke-width="8" stroke-linecap="round"/>' + \
        f'<path d="{d}" fill="none" stroke="#6aa84f" stroke-width="4" stroke-linecap="round"/>' + b
    b += f'<ellipse cx="{stalk[-1][0]:.1f}" cy="{stalk[-1][1]:.1f}" rx="7" ry="9" fill="#8cc46a" stroke="#23461d" stroke-width="2"/>'
    write("kelp.svg", w, h, b)
    # branching coral
    w, h = 160, 128

    def branch(x, y, ang, length, depth, colour):
        out = ""
        x2 = x + math.cos(ang) * length
        y2 = y + math.sin(ang) * length
        out += f'<line x1="{x:.1f}" y1="{y:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="{colour}" stroke-width="{3 + depth * 2.5:.1f}" stroke-linecap="round"/>'
        if depth > 0:
            out += branch(x2, y2, ang - rng.uniform(0.3, 0.6), length * 0.72, depth - 1, colour)
            out += branch(x2, y2, ang + rng.uniform(0.3, 0.6), length * 0.72, depth - 1, colour)
        else:
            out += f'<circle cx="{x2:.1f}" cy="{y2:.1f}" r="4" fill="#ffd1dc"/>'
        return out

    outline = branch(80, 126, -math.pi / 2, 40, 3, "#6e1f3a")
    rng.seed(31)
    fill = branch(80, 126, -math.pi / 2, 40, 3, "#e8577e")
    # the fill pass is drawn thinner over the outline pass
    fill = fill.replace('stroke-width="', 'stroke-width="-2+')
    fixed = ""
    for part in fill.split('stroke-width="-2+')[1:]:
        num, rest = part.split('"', 1)
        fixed += f'stroke-width="{max(1.5, float(num) - 3):.1f}"' + rest
    fill = fill.split('stroke-width="-2+')[0] + fixed
    write("coral.svg", w, h, outline + fill)
    # seagrass tuft
    w, h = 96, 80
    b = ""
    for i in range(9):
        x = 18 + i * 7.5
        lean = rng.uniform(-18, 18)
        top = rng.uniform(8, 30)
        b += f'<path d="M {x:.1f} 80 Q {x + lean * 0.3:.1f} 45 {x + lean:.1f} {top:.1f}" fill="none" stroke="#2f5e3a" stroke-width="6" stroke-linecap="round"/>'
        b += f'<path d="M {x:.1f} 80 Q {x + lean * 0.3:.1f} 45 {x + lean:.1f} {top:.1f}" fill="none" stroke="#5fa05a" stroke-width="3" stroke-linecap="round"/>'
    write("seagrass.svg", w, h, b)
    # starfish
    star = []
    for i in range(10):
        a = -math.pi / 2 + i * math.pi / 5
        r = 28 if i % 2 == 0 else 12
        star.append((32 + math.cos(a) * r, 34 + math.sin(a) * r))
    b = f'<polygon points="{pts(star)}" fill="#f28c38" stroke="#7a3a12" stroke-width="3" stroke-linejoin="round"/>'
    for i in range(5):
        a = -math.pi / 2 + i * 2 * math.pi / 5
        b += f'<circle cx="{32 + math.cos(a) * 14:.1f}" cy="{34 + math.sin(a) * 14:.1f}" r="2.2" fill="#ffd29a"/>'
    write("starfish.svg", 64, 64, b)
    # hanging roots/moss for cave ceilings (anchored at the top centre)
    w, h = 96, 160
    b = ""
    for i in range(7):
        x = 12 + i * 12
        length = rng.uniform(50, 150)
        sway = rng.uniform(-10, 10)
        b += f'<path d="M {x:.1f} 0 Q {x + sway:.1f} {length * 0.6:.1f} {x + sway * 0.4:.1f} {length:.1f}" fill="none" stroke="#1e3b2a" stroke-width="5" stroke-linecap="round"/>'
        b += f'<path d="M {x:.1f} 0 Q {x + sway:.1f} {length * 0.6:.1f} {x + sway * 0.4:.1f} {length:.1f}" fill="none" stroke="#3d7a4e" stroke-width="2.5" stroke-linecap="round"/>'
        b += f'<circle cx="{x + sway * 0.4:.1f}" cy="{length:.1f}" r="3.5" fill="#9ff0c8" opacity="0.8"/>'
    write("roots.svg", w, h, b)


def main():
    os.makedirs(OUT, exist_ok=True)
    rock_tile()
    sponge_tile()
    crystal_tile()
    backwall_tile()
    crate("crate.svg", heavy=False)
    crate("crate_heavy.svg", heavy=True)
    sub()
    propeller()
    pearl()
    buoy()
    parallax_far()
    parallax_mid()
    sky()
    particles()
    decor()


if __name__ == "__main__":
    main()
