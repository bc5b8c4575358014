#!/usr/bin/env python3
"""Writes game/levels/level_1.tscn, the "Sea Cave" level, from the layout below.

Run from the project root: python3 tools/gen_level_1.py

Coordinates are world pixels, y down. The world is 8960 x 1440 (7 x 2 screens). Terrain is
one Terrain body per look (rock = hard, sponge/sand = soft, crystal = slippery) whose
CollisionPolygon2D children are also drawn by game/props/terrain.gd. Notable surfaces
(angle of the surface from horizontal; "overhang" = faces down):
  beach slope 30 deg           (480,640)-(1520,1240)          soft
  curtain overhang 45 deg      (1760,520)-(2100,860)           hard, normal down-left (135 deg wall)
  curtain back face 60 deg     (2260,905)-(2420,628)           hard, overhang facing down-right
  cave-mouth wall 60 deg       (2600,1200)-(2890,700)          hard
  crystal ridge 45 deg up      (4300,700)-(4600,400)           slippery
  crystal ridge 60 deg down    (4760,400)-(4960,746)           slippery
  chamber wall overhang        (4300,600)-(4360,420)           hard, leans over the ridge foot
  pool dive face ~62 deg       (6000,520)-(6200,900)           hard, overhang
  pool back face 45 deg        (6320,920)-(6600,640)           hard, overhang
  pool exit slope 45 deg       (6800,1120)-(7280,640)          soft
"""
import math
import os

ROOT = os.path.join(os.path.dirname(__file__), "..")
OUT = os.path.join(ROOT, "game", "levels", "level_1.tscn")

WORLD_W, WORLD_H = 8960, 1440

# ---------------------------------------------------------------------------------------
# Layout

ROCK = [
    # cliff over the beach, cave-mouth ceiling and the rock curtain dipping into the sea
    [(1060, -40), (3420, -40), (3400, 360), (3200, 380), (2900, 440), (2600, 520),
     (2420, 628), (2260, 905), (2180, 900), (2100, 860), (1760, 520), (1500, 470),
     (1180, 440), (1110, 400), (1130, 300), (1100, 150)],
    # sea floor, cave-mouth wall and the crate-hall / tunnel floor
    [(1880, 1250), (2050, 1190), (2200, 1230), (2400, 1180), (2600, 1200), (2890, 700),
     (4300, 700), (4420, WORLD_H + 40), (1760, WORLD_H + 40)],
    # gallery ceiling
    [(3380, -40), (4140, -40), (4110, 320), (3900, 280), (3600, 300), (3400, 360)],
    # tunnel roof left of the drop hole (the crate stack stands on it)
    [(3440, 600), (3470, 520), (3700, 520), (3700, 600)],
    # tunnel roof right of the hole, gallery end wall and the chamber's left wall
    [(3820, 600), (3820, 520), (4100, 520), (4140, 420), (4110, 320), (4120, -40),
     (4580, -40), (4500, 140), (4330, 260), (4360, 420), (4300, 600)],
    # ceiling over the crystal chamber and the second pool, with the dive curtain
    [(4560, -40), (7460, -40), (7420, 120), (7380, 260), (7100, 300), (6900, 420),
     (6700, 560), (6600, 640), (6320, 920), (6200, 900), (6000, 520), (5900, 300),
     (5600, 240), (5300, 230), (5000, 200), (4800, 150), (4620, 110)],
    # far cliff closing the lagoon
    [(8760, -40), (WORLD_W + 40, -40), (WORLD_W + 40, WORLD_H + 40), (8700, WORLD_H + 40),
     (8740, 1000), (8800, 760), (8780, 520), (8830, 300), (8790, 120)],
]

SAND = [
    # beach and the sandy slope into the sea
    [(-40, 600), (140, 590), (300, 610), (480, 640), (1520, 1240), (1900, 1250),
     (1780, WORLD_H + 40), (-40, WORLD_H + 40)],
    # pool floor, exit slope and the lagoon bed
    [(5300, 932), (5600, 1120), (6000, 1180), (6400, 1170), (6800, 1120), (7280, 640),
     (7300, 620), (7400, 620), (7700, 900), (8100, 960), (8500, 940), (8760, 980),
     (8760, WORLD_H + 40), (5480, WORLD_H + 40)],
]

CRYSTAL = [
    # crystal ridge between the tunnel and the second pool
    [(4300, 700), (4600, 400), (4760, 400), (4960, 746), (5300, 932),
     (5500, WORLD_H + 40), (4400, WORLD_H + 40)],
    # crystal stalactites under the chamber ceiling
    [(4640, 105), (4700, 250), (4760, 130)],
    [(5080, 215), (5130, 330), (5190, 220)],
]

# Invisible walls around the world (left, top, right; the floor is terrain).
BOUNDS = [
    [(-200, -200), (0, -200), (0, WORLD_H + 200), (-200, WORLD_H + 200)],
    [(-200, -200), (WORLD_W + 200, -200), (WORLD_W + 200, 0), (-200, 0)],
]

# name, x, y (top-left corner = surface), width, height
WATER = [
    ("Sea", 660, 760, 2300, 680),
    ("Pool", 4860, 640, 2440, 800),
    ("Lagoon", 7330, 660, 1520, 780),
]

# scene ("light"/"heavy"), x, y (centre), optional mass
CRATES = [
    # stack on the tunnel roof, next to the drop hole
    ("light", 3492, 496), ("light", 3542, 496), ("light", 3592, 496),
    ("light", 3517, 448), ("light", 3567, 448),
    ("light", 3542, 400),
    # on the slippery crystal ridge: a nudge sends them sliding down into the pool
    ("light", 4735, 376), ("light", 4680, 376),
    # floating in the sea and the pool
    ("light", 1320, 745), ("light", 1660, 745), ("light", 2500, 745),
    ("light", 5250, 625), ("light", 5520, 625), ("light", 5770, 625),
    ("light", 7900, 645),
    # sunk
    ("heavy", 2060, 1178), ("heavy", 5700, 1112), ("heavy", 5752, 1118),
    ("heavy", 6700, 1110),
]

# Each pearl sits in its clam on the floor below the given point.
PEARLS = [
    (560, 600), (1250, 1000), (2130, 1180), (2980, 690), (3200, 690), (3760, 690),
    (4040, 510), (4625, 390), (5480, 1100), (6260, 1160), (7080, 760), (8000, 940),
]

# kind, x, y near the surface it grows on (snapped to the floor, or ceiling for roots),
# scale. Kelp and grass sway.
DECOR = [
    ("seagrass", 820, 800, 0.6), ("starfish", 1050, 940, 0.5), ("kelp", 1180, 1000, 0.7),
    ("kelp", 1230, 1020, 0.55), ("coral", 1420, 1180, 0.6), ("seagrass", 1640, 1240, 0.6),
    ("kelp", 1960, 1230, 0.8), ("kelp", 2010, 1210, 0.6), ("coral", 2300, 1200, 0.7),
    ("seagrass", 2460, 1180, 0.6), ("starfish", 2540, 1200, 0.45),
    ("roots", 1350, 460, 0.7), ("roots", 2750, 470, 0.6), ("roots", 3050, 400, 0.7),
    ("roots", 3750, 290, 0.6), ("roots", 5450, 235, 0.7), ("roots", 6820, 480, 0.6),
    ("coral", 5480, 1100, 0.6), ("kelp", 5820, 1160, 0.8), ("kelp", 5870, 1170, 0.6),
    ("seagrass", 6100, 1180, 0.6), ("kelp", 6450, 1170, 0.75), ("coral", 6640, 1130, 0.7),
    ("starfish", 6380, 1170, 0.45), ("seagrass", 6950, 970, 0.6),
    ("seagrass", 7800, 930, 0.6), ("kelp", 7950, 955, 0.7), ("coral", 8250, 950, 0.6),
    ("kelp", 8550, 950, 0.8), ("starfish", 8400, 945, 0.45),
]

START = (240, 520)
GOAL = (8420, 690)

AUTOPILOT = [
    START, (560, 565), (700, 640), (1100, 840), (1500, 1010), (1900, 1060), (2200, 1060),
    (2460, 1000), (2650, 800), (2720, 660), (2900, 640), (3340, 650), (3500, 650),
    (4290, 650), (4370, 590), (4540, 410), (4690, 335), (4850, 470), (5060, 740),
    (5320, 860), (5800, 1010), (6260, 1050), (6620, 1010), (6900, 720), (7150, 560),
    (7350, 550), (7700, 600), (8100, 600), (GOAL[0], GOAL[1] - 40),
]

# x range of the sky backdrops and the y of their painted horizon (just above the sea)
SKY_WEST = (0, 1300, 745)
SKY_EAST = (7250, 8800, 645)

# ---------------------------------------------------------------------------------------
# Scene writer


class Scene:
    def __init__(self):
        self.ext = []
        self.sub = []
        self.nodes = []

    def ext_resource(self, kind, path):
        rid = f"{len(self.ext) + 1}_r"
        self.ext.append(f'[ext_resource type="{kind}" path="{path}" id="{rid}"]')
        return f'ExtResource("{rid}")'

    def sub_resource(self, kind, rid, props):
        body = "\n".join(f"{k} = {v}" for k, v in props.items())
        self.sub.append(f'[sub_resource type="{kind}" id="{rid}"]\n{body}')
        return f'SubResource("{rid}")'

    def node(self, name, kind=None, parent=None, instance=None, props=None):
        head = f'[node name="{name}"'
        if kind:
            head += f' type="{kind}"'
        if parent is not None:
            head += f' parent="{parent}"'
        if instance:
            head += f" instance={instance}"
        head += "]"
        body = "\n".join(f"{k} = {v}" for k, v in (props or {}).items())
        self.nodes.append(head + ("\n" + body if body else ""))

    def text(self):
        steps = len(self.ext) + len(self.sub) + 1
        parts = [f"[gd_scene load_steps={steps} format=3]"]
        parts += self.ext + self.sub + self.nodes
        return "\n\n".join(parts) + "\n"


def v2(p):
    return f"Vector2({p[0]:g}, {p[1]:g})"


def packed(points):
    return "PackedVector2Array(" + ", ".join(f"{x:g}, {y:g}" for x, y in points) + ")"


def colour(r, g, b, a=1.0):
    return f"Color({r:g}, {g:g}, {b:g}, {a:g})"


def _inside(poly, x, y):
    inside = False
    n = len(poly)
    for i in range(n):
        (x1, y1), (x2, y2) = poly[i], poly[(i + 1) % n]
        if (y1 > y) != (y2 > y):
            cross = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
            if x < cross:
                inside = not inside
    return inside


def snap(x, y, up):
    """The y of the nearest ground surface at x: a floor (solid below) or, with up, a
    ceiling (solid above), searched from y."""
    solids = ROCK + SAND + CRYSTAL
    solid = lambda py: any(_inside(p, x, py) for p in solids)
    best = None
    for step in range(0, 400):
        for py in (y - step, y + step):
            below, above = solid(py + 1), solid(py - 1)
            if (not up and below and not above) or (up and above and not below):
                best = py
                break
        if best is not None:
            return best
    raise ValueError(f"no surface near {(x, y)}")


def angle_report():
    """Prints the slope of every terrain edge steeper than 20 degrees, to check the notes."""
    for group, polys in (("rock", ROCK), ("sand", SAND), ("crystal", CRYSTAL)):
        for poly in polys:
            for a, b in zip(poly, poly[1:] + poly[:1]):
                dx, dy = b[0] - a[0], b[1] - a[1]
                if math.hypot(dx, dy) < 150:
                    continue
                ang = math.degrees(math.atan2(abs(dy), abs(dx)))
                if 20 < ang < 80:
                    print(f"  {group:8s} {a} -> {b}: {ang:.1f} deg")


def build():
    s = Scene()
    script = s.ext_resource("Script", "res://game/levels/level_1.gd")
    terrain_script = s.ext_resource("Script", "res://game/props/terrain.gd")
    player = s.ext_resource("PackedScene", "res://game/player/player.tscn")
    crate_light = s.ext_resource("PackedScene", "res://game/props/crate.tscn")
    crate_heavy = s.ext_resource("PackedScene", "res://game/props/crate_heavy.tscn")
    water = s.ext_resource("PackedScene", "res://game/props/water.tscn")
    pearl = s.ext_resource("PackedScene", "res://game/props/pearl.tscn")
    goal = s.ext_resource("PackedScene", "res://game/props/goal.tscn")
    effects = s.ext_resource("PackedScene", "res://game/props/effects.tscn")
    mat = {k: s.ext_resource("Resource", f"res://addons/haptics/materials/{k}.tres")
           for k in ("hard", "soft", "slippery")}
    tex = {k: s.ext_resource("Texture2D", f"res://assets/art/{k}.svg")
           for k in ("rock_hard", "sponge_soft", "crystal_slippery", "parallax_far",
                     "parallax_mid", "sky")}
    ambience = s.ext_resource("AudioStream", "res://assets/sounds/ambience.wav")

    s.node("Level1", "Node2D", props={"script": script})

    # Background: two parallax layers of cave depths, and the sky where the coast is open.
    s.node("Background", "Node2D", ".", props={"z_index": -20})
    for name, key, scale in (("Far", "parallax_far", 0.25), ("Mid", "parallax_mid", 0.5)):
        s.node(name, "Parallax2D", "Background", props={
            "scroll_scale": f"Vector2({scale}, {scale})",
            "repeat_size": "Vector2(2048, 0)",
            "repeat_times": 2,
        })
        s.node("Sprite", "Sprite2D", f"Background/{name}", props={
            "texture": tex[key], "centered": "false",
        })
    for name, (x0, x1, horizon), fade_left in (("SkyWest", SKY_WEST, False),
                                               ("SkyEast", SKY_EAST, True)):
        w = x1 - x0
        fade = 220
        inner = x0 + fade if fade_left else x1 - fade
        solid = (inner, x1) if fade_left else (x0, inner)
        faded = (x0, inner) if fade_left else (inner, x1)
        for part, (a, b), alphas in ((name, solid, (1, 1, 1, 1)),
                                     (name + "Fade", faded, (0, 1, 1, 0) if fade_left else (1, 0, 0, 1))):
            pts = [(a, 0), (b, 0), (b, 960), (a, 960)]
            # Texels per pixel that put the painted horizon (texel row 580) at the horizon.
            k = 580 / horizon
            uv = [((px - x0) * k, py * k) for px, py in pts]
            s.node(part, "Polygon2D", "Background", props={
                "texture": tex["sky"],
                "polygon": packed(pts),
                "uv": packed(uv),
                "vertex_colors": "PackedColorArray(" + ", ".join(
                    f"1, 1, 1, {al}" for al in alphas) + ")",
            })

    # Terrain
    s.node("Terrain", "Node2D", ".", props={"z_index": 10})
    styles = [
        ("Rock", ROCK, "hard", "rock_hard", colour(0.72, 0.76, 0.84), colour(0.08, 0.1, 0.14),
         colour(0.7, 0.8, 0.9, 0.45), colour(0.02, 0.04, 0.08, 0.45)),
        ("Sand", SAND, "soft", "sponge_soft", colour(0.95, 0.92, 0.9), colour(0.3, 0.15, 0.07),
         colour(1, 0.9, 0.62, 0.85), colour(0.25, 0.1, 0.04, 0.4)),
        ("Crystal", CRYSTAL, "slippery", "crystal_slippery", colour(0.9, 0.95, 1),
         colour(0.08, 0.26, 0.36), colour(0.92, 1, 1, 0.9), colour(0.05, 0.2, 0.3, 0.4)),
    ]
    friction = {"hard": 0.8, "soft": 1.0, "slippery": 0.03}
    for name, polys, material, texture, fill, edge, shine, shade in styles:
        physics = s.sub_resource("PhysicsMaterial", f"PhysicsMaterial_{material}", {
            "friction": friction[material],
            "bounce": 0.0,
        })
        s.node(name, "StaticBody2D", "Terrain", props={
            "collision_mask": 0,
            "physics_material_override": physics,
            "script": terrain_script,
            "haptic_material": mat[material],
            "fill_texture": tex[texture],
            "fill_color": fill,
            "edge_color": edge,
            "edge_width": 7.0,
            "highlight_color": shine,
            "shade_color": shade,
            "metadata/haptic_material": mat[material],
        })
        for i, poly in enumerate(polys):
            s.node(f"Polygon{i}", "CollisionPolygon2D", f"Terrain/{name}", props={
                "polygon": packed(poly),
            })
    s.node("Bounds", "StaticBody2D", "Terrain", props={
        "collision_mask": 0,
        "metadata/haptic_material": mat["hard"],
    })
    for i, poly in enumerate(BOUNDS):
        s.node(f"Polygon{i}", "CollisionPolygon2D", "Terrain/Bounds", props={
            "polygon": packed(poly),
        })

    # Water
    s.node("Water", "Node2D", ".")
    for name, x, y, w, h in WATER:
        s.node(name, None, "Water", instance=water, props={
            "position": v2((x, y)),
            "size": v2((w, h)),
        })

    # Decoration: plants on the floors (sway), roots under the ceilings.
    decor_tex = {k: s.ext_resource("Texture2D", f"res://assets/art/{k}.svg")
                 for k in ("kelp", "coral", "seagrass", "starfish", "roots")}
    sway_shader = s.ext_resource("Shader", "res://game/props/sway.gdshader")
    sway = s.sub_resource("ShaderMaterial", "ShaderMaterial_sway", {
        "shader": sway_shader, "shader_parameter/amplitude": 12.0,
    })
    hang = s.sub_resource("ShaderMaterial", "ShaderMaterial_hang", {
        "shader": sway_shader, "shader_parameter/amplitude": 6.0,
        "shader_parameter/anchor_top": "true", "shader_parameter/speed": 0.7,
    })
    s.node("Decor", "Node2D", ".", props={"z_index": 4})
    for i, (kind, x, y, scale) in enumerate(DECOR):
        up = kind == "roots"
        surface = snap(x, y, up)
        size = {"kelp": (64, 320), "coral": (160, 128), "seagrass": (96, 80),
                "starfish": (64, 64), "roots": (96, 160)}[kind]
        scale *= 1.5
        for _, wx, wy, ww, wh in WATER:
            # plants in water stay below its surface
            if not up and wx <= x <= wx + ww and surface > wy:
                scale = min(scale, (surface - wy - 40) / size[1])
        props = {
            "position": v2((x, surface + (-4 if up else 6))),
            "scale": f"Vector2({scale * (-1 if i % 3 == 0 else 1):.3g}, {scale:.3g})",
            "texture": decor_tex[kind],
            "centered": "false",
        }
        # anchor: bottom centre (top centre for roots)
        props["offset"] = v2((-size[0] / 2, 0 if up else -size[1]))
        if kind in ("kelp", "seagrass"):
            props["material"] = sway
        elif kind == "roots":
            props["material"] = hang
        s.node(f"{kind.capitalize()}{i}", "Sprite2D", "Decor", props=props)

    # Props
    s.node("Crates", "Node2D", ".")
    counts = {"light": 0, "heavy": 0}
    for kind, x, y in CRATES:
        counts[kind] += 1
        name = ("Crate" if kind == "light" else "HeavyCrate") + str(counts[kind])
        s.node(name, None, "Crates", instance=crate_light if kind == "light" else crate_heavy,
               props={"position": v2((x, y))})
    s.node("Pearls", "Node2D", ".")
    for i, (x, y) in enumerate(PEARLS):
        s.node(f"Pearl{i + 1}", None, "Pearls", instance=pearl,
               props={"position": v2((x, snap(x, y, False) - 12))})
    s.node("Goal", None, ".", instance=goal, props={"position": v2(GOAL)})

    s.node("Start", "Marker2D", ".", props={"position": v2(START)})
    s.node("AutopilotPath", "Line2D", ".", props={
        "visible": "false",
        "points": packed(AUTOPILOT),
        "width": 4.0,
    })
    s.node("Player", None, ".", instance=player, props={"position": v2(START), "z_index": 11})
    s.node("Effects", None, ".", instance=effects)
    s.node("Ambience", "AudioStreamPlayer", ".", props={
        "stream": ambience, "volume_db": -14.0,
    })
    return s.text()


def main():
    with open(OUT, "w") as f:
        f.write(build())
    print(f"wrote {os.path.relpath(OUT, ROOT)}")
    angle_report()


if __name__ == "__main__":
    main()
