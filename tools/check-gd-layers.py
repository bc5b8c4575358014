#!/usr/bin/env python3
"""Checks that the GDScript folders form layers: each depends only on floors below it.

Run: python3 tools/check-gd-layers.py [--graph]   (--graph also prints every module edge)
Exit 0 when every dependency runs downward, 1 with one line per offending edge otherwise.

A module is a folder of game/ (its scenes and scripts together, e.g. "pong/net"), and
an addon is one module with its subfolders. A file depends on another
when it names the other's class_name or autoload, or names its path (preload, load, a
res:// or uid:// string, a scene's ext_resource). Tests (tests/) and tools (tools/) sit above
everything and are not checked, but a class they declare counts as theirs: game code that
names one depends on them; assets/ holds data and is below everything.

Reported: an edge from a module to one on the same or a higher floor (with the class or
path that makes it), a module that is in no floor, a dependency on tests/ or tools/ (where
every test, benchmark and trial driver lives: never the product's), and a game script that
names a native class (HapticsSystem, DurableFile) in its code outside the one script
allowed to (the door's native backend, the study's durable writer).
"""

import configparser
import os
import re
import sys

# The floors, lowest first. A module may use modules on floors below its own, never one on
# its own floor or above. Subfolders are listed: a folder is no floor of its subfolders.
FLOORS = [
    # The haptics addon: the Haptics door and its rooms, the probe, materials, water.
    ["addons/haptics"],
    # What every game shares: the Settings and CleanExit autoloads, then UI pieces (focus,
    # the force plot, the pause menu and the settings screen).
    ["common"],
    ["common/ui"],
    # The platformer the side-scroller and the maze study share: the avatar, the props
    # (and the effects they set off), the level base and level 1.
    ["player"],
    ["props"],
    ["levels"],
    # The maze study, bottom up: records and settings, the maze levels, the screens, the
    # conditions and trials, the session that runs it all.
    ["study/data", "study/levels"],
    ["study/screens"],
    ["study/trials"],
    ["study/session"],
    # Haptic Battle Pong: the match, its 3D view, its screens, then the network game.
    ["pong/servo"],
    ["pong"],
    ["pong/view"],
    ["pong/ui"],
    ["pong/net/messages"],
    ["pong/net"],
    ["pong/net/ui"],
    # The 3D room: its avatar, its builder and the room; the driving scene beside it.
    ["level3d", "level3d/drive"],
    # The side-scroller's HUD and goal screen, the main menu; then the main scene (the
    # menu and one run of a level): the top.
    ["ui"],
    ["main"],
]

ROOTS = ["addons", "game"]
# Above every floor: their classes are known only so that a dependency on them is reported.
ABOVE = ["tests", "tools"]
# Prefixes that name a module by the rest of the path.
MODULE_PREFIXES = ["game/"]
# The native classes, each named by one script only: the typed door to it. Every other
# script then parses where the library cannot load.
NATIVE_DOORS = {
    "HapticsSystem": "addons/haptics/door/haptics_native_backend.gd",
    "DurableFile": "game/study/data/durable_native_writer.gd",
}

STRING = re.compile(r'(?:[&^r]?)("""|\'\'\'|"|\')')
IDENT = re.compile(r"(?<![\w.$@%])[A-Z][A-Za-z0-9_]*\b")
CLASS_NAME = re.compile(r"^class_name\s+([A-Za-z_][A-Za-z0-9_]*)", re.M)
EXT_RESOURCE = re.compile(r'^\[ext_resource\b[^\]]*?\bpath="([^"]+)"', re.M)
RESOURCE_UID = re.compile(r'^\[gd_(?:scene|resource)\b[^\]]*?\buid="(uid://[^"]+)"', re.M)
# A file's path (a folder prefix such as "res://tests/" names no file); without a scheme, a
# resource path relative to the script (preload("helper.gd")).
PATH_LITERAL = re.compile(r"^(?:res://(?:.*/)?[^/]+\.\w+|uid://\w+)$")
RELATIVE_PATH = re.compile(r"^[\w.][\w./-]*\.(?:gd|tscn|scn|tres|res|gdshader)$")


def module_of(path):
    """The module a project file belongs to, or None outside addons/, game/, game/."""
    if path.startswith("addons/"):
        return "/".join(path.split("/")[:2])
    for prefix in MODULE_PREFIXES:
        if path.startswith(prefix):
            return os.path.dirname(path[len(prefix) :]) or "."
    return None


def split_code(text):
    """GDScript source as (code with strings and comments blanked, string literals)."""
    code = []
    strings = []
    i = 0
    n = len(text)
    while i < n:
        c = text[i]
        if c == "#":
            end = text.find("\n", i)
            i = n if end < 0 else end
            continue
        m = STRING.match(text, i)
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            quote = m.group(1)
            j = m.end()
            body = []
            while j < n and not text.startswith(quote, j):
                if text[j] == "\\" and j + 1 < n:
                    body.append(text[j : j + 2])
                    j += 2
                    continue
                body.append(text[j])
                j += 1
            strings.append("".join(body))
            code.append(" \"\" ")
            i = j + len(quote)
            continue
        code.append(c)
        i += 1
    return "".join(code), strings


def project_files(roots=ROOTS):
    out = []
    for root in roots:
        for folder, dirs, files in os.walk(root):
            if os.path.exists(os.path.join(folder, ".gdignore")):
                dirs[:] = []
                continue
            dirs.sort()
            for name in sorted(files):
                if name.endswith((".gd", ".tscn", ".tres")):
                    out.append(os.path.join(folder, name).replace(os.sep, "/"))
    return out


def uid_table():
    """uid:// → res-relative path, from .uid files and the uid of each scene and resource."""
    table = {}
    for root in ROOTS + ["assets"]:
        for folder, _dirs, files in os.walk(root):
            for name in files:
                path = os.path.join(folder, name).replace(os.sep, "/")
                if name.endswith(".uid"):
                    with open(path, encoding="utf-8") as f:
                        table[f.read().strip()] = path[: -len(".uid")]
                elif name.endswith((".tscn", ".tres")):
                    with open(path, encoding="utf-8") as f:
                        m = RESOURCE_UID.search(f.read(4096))
                    if m:
                        table[m.group(1)] = path
    return table


def autoloads():
    parser = configparser.ConfigParser(interpolation=None, strict=False)
    parser.optionxform = str
    with open("project.godot", encoding="utf-8") as f:
        text = f.read()
    # Only the [autoload] section: the rest is not ini-compatible.
    m = re.search(r"^\[autoload\]\n(.*?)(?=^\[|\Z)", text, re.M | re.S)
    parser.read_string("[autoload]\n" + (m.group(1) if m else ""))
    out = {}
    for name, value in parser.items("autoload"):
        out[name] = value.strip('"').lstrip("*")[len("res://") :]
    return out


def resolve(target, uids, folder=""):
    if target.startswith("uid://"):
        return uids.get(target)
    if target.startswith("res://"):
        return target[len("res://") :]
    if RELATIVE_PATH.match(target):
        return os.path.normpath(os.path.join(folder, target)).replace(os.sep, "/")
    return None


def scan(files):
    """Every dependency of [files] as (from file, to file, why), and door bypasses as
    (file, why)."""
    uids = uid_table()
    sources = {}
    classes = {}
    for path in files:
        with open(path, encoding="utf-8") as f:
            sources[path] = f.read()
        if path.endswith(".gd"):
            for name in CLASS_NAME.findall(sources[path]):
                classes[name] = path
    for name, path in autoloads().items():
        classes.setdefault(name, path)
    for path in project_files(ABOVE):
        if path.endswith(".gd"):
            with open(path, encoding="utf-8") as f:
                for name in CLASS_NAME.findall(f.read()):
                    classes.setdefault(name, path)
    edges = []
    bypasses = []
    for path, text in sources.items():
        targets = []
        if path.endswith(".gd"):
            code, strings = split_code(text)
            for name in sorted(set(IDENT.findall(code))):
                if name in classes:
                    targets.append((classes[name], name))
            for literal in strings:
                if PATH_LITERAL.match(literal) or RELATIVE_PATH.match(literal):
                    targets.append((resolve(literal, uids, os.path.dirname(path)), literal))
            for native, door in NATIVE_DOORS.items():
                # In code only: a name in a string (ClassDB.class_exists) still parses.
                if path != door and re.search(rf"\b{native}\b", code):
                    bypasses.append((path, f"names {native} (only {door} may)"))
        else:
            for target in EXT_RESOURCE.findall(text):
                targets.append((resolve(target, uids), target))
        for target, why in targets:
            if target is not None and target != path:
                edges.append((path, target, why))
    return edges, bypasses


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    floor_of = {}
    for level, modules in enumerate(FLOORS):
        for module in modules:
            floor_of[module] = level
    files = project_files()
    edges, bypasses = scan(files)
    problems = []
    unplaced = {module_of(path) for path in files} - set(floor_of)
    module_edges = {}
    for source, target, why in edges:
        a = module_of(source)
        above = target.split("/", 1)[0]
        if above in ABOVE:
            problems.append(f"{source} -> {target} ({why}): {above}/ is above every floor")
            continue
        b = module_of(target)
        if b is None or a == b:
            continue
        module_edges.setdefault((a, b), []).append((source, target, why))
    for module in sorted(unplaced):
        problems.append(f"{module}: in no floor (add it to FLOORS in tools/check-gd-layers.py)")
    for (a, b), uses in sorted(module_edges.items()):
        if a not in floor_of or b not in floor_of:
            continue
        if floor_of[a] > floor_of[b]:
            continue
        pair = " (two-way)" if (b, a) in module_edges else ""
        where = "same floor" if floor_of[a] == floor_of[b] else "higher floor"
        for source, target, why in uses:
            problems.append(f"{source} -> {target} ({why}): {a} uses {b}, {where}{pair}")
    for path, why in bypasses:
        problems.append(f"{path}: {why}: the script would not parse without the library")
    if "--graph" in sys.argv:
        for (a, b), uses in sorted(module_edges.items()):
            print(f"{a} -> {b}: {len(uses)}")
    for line in problems:
        print(line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
