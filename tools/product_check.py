#!/usr/bin/env python3
"""What a player gets holds none of our drivers: the pack and folder checks of
tools/check-product.sh, and a writer of Godot packs for its own test
(tools/test-check-product.sh).

Every test, benchmark, trial and demonstration driver lives under tests/ or tools/
(docs/testing.md, "Drivers"), so a driver is a file there; its names are derived from the
repository: every class_name that a .gd file under tests/ or tools/ declares.

  python3 tools/product_check.py drivers        the drivers' class names, one a line
  python3 tools/product_check.py pack PCK...     check Godot packs (exit 1 on a find)
  python3 tools/product_check.py tree DIR...     check the text files of unpacked folders

A pack fails when
  - its index holds a file under tests/ or tools/ (a script is packed as .gdc and
    .gd.remap, a scene as .remap beside .godot/exported/...);
  - a packed file names a driver: a driver's class name as a whole word, or the path of a
    file under res://tests/ or res://tools/ (project settings, scenes, resources, scripts
    exported as text);
  - the global class cache lists a driver's class name with a path outside tests/ and
    tools/ (a product script declares it).
The export packs the whole class cache and the whole uid cache, which list every class and
file the editor scanned, tests/ included, whether packed or not: they are read only for
the rule above. A product script that merely names a driver class cannot be seen in a
pack whose scripts are compressed tokens (the presets' script_export_mode=2); it would not
even parse in the export, and tools/check-gd-layers.py refuses a product file that depends
on tests/.
"""

import os
import re
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DRIVER_FOLDERS = ("tests", "tools")
CLASS_CACHE = ".godot/global_script_class_cache.cfg"
UID_CACHE = ".godot/uid_cache.bin"
CLASS_NAME = re.compile(r"^class_name\s+([A-Za-z_]\w*)", re.M)
DRIVER_PATH = re.compile(
    rb"res://(?:tests|tools)/[\w./-]*\.(?:gd|gdc|tscn|scn|tres|res|gdshader)"
)
CACHE_ENTRY = re.compile(r'"class":\s*&"(\w+)".*?"path":\s*"([^"]*)"', re.S)
TEXT_SUFFIXES = (".gd", ".tscn", ".tres", ".cfg", ".gdextension", ".godot", ".json", ".md", ".txt")

PACK_MAGIC = b"GDPC"
PACK_DIR_ENCRYPTED = 1
PACK_REL_FILEBASE = 2
PACK_FILE_ENCRYPTED = 1
PACK_FILE_REMOVAL = 2


def driver_classes(root=ROOT):
    """Every class_name declared by a .gd file under tests/ or tools/, sorted."""
    names = set()
    for folder in DRIVER_FOLDERS:
        for base, _dirs, files in os.walk(os.path.join(root, folder)):
            for name in files:
                if name.endswith(".gd"):
                    with open(os.path.join(base, name), encoding="utf-8", errors="replace") as f:
                        names.update(CLASS_NAME.findall(f.read()))
    return sorted(names)


def is_driver_path(path):
    """Whether a project path (with or without res://) lies under tests/ or tools/."""
    path = path.removeprefix("res://")
    return path.split("/", 1)[0] in DRIVER_FOLDERS


def read_pack(path):
    """The files of a Godot 4 pack (format 2 or 3) as (path without res://, bytes or None
    for an encrypted or removed file)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != PACK_MAGIC:
        raise ValueError(f"{path}: not a Godot pack")
    version, _major, _minor, _patch, flags = struct.unpack_from("<5I", data, 4)
    if version not in (2, 3):
        raise ValueError(f"{path}: pack format {version} is not known here")
    if flags & PACK_DIR_ENCRYPTED:
        raise ValueError(f"{path}: its index is encrypted and cannot be checked")
    (file_base,) = struct.unpack_from("<Q", data, 24)
    if version == 3:
        (position,) = struct.unpack_from("<Q", data, 32)
    else:
        position = 32 + 16 * 4
    (count,) = struct.unpack_from("<I", data, position)
    position += 4
    files = []
    for _ in range(count):
        (length,) = struct.unpack_from("<I", data, position)
        position += 4
        name = data[position : position + length].rstrip(b"\0").decode("utf-8")
        position += length
        offset, size = struct.unpack_from("<QQ", data, position)
        position += 16 + 16  # offset and size, then the MD5
        (file_flags,) = struct.unpack_from("<I", data, position)
        position += 4
        if flags & PACK_REL_FILEBASE:
            offset += file_base
        content = None
        if not file_flags & (PACK_FILE_ENCRYPTED | PACK_FILE_REMOVAL):
            content = data[offset : offset + size]
        files.append((name.removeprefix("res://"), content))
    return files


def write_pack(path, files):
    """Writes [(path without res://, bytes)] as a format 3 pack, as Godot 4.6 does."""
    header_size = 4 + 5 * 4 + 8 + 8 + 16 * 4
    file_base = (header_size + 15) // 16 * 16
    body = b""
    index = b""
    for name, content in files:
        encoded = name.encode("utf-8")
        padded = encoded + b"\0" * (4 - len(encoded) % 4)
        index += struct.pack("<I", len(padded)) + padded
        index += struct.pack("<QQ", len(body), len(content)) + b"\0" * 16 + struct.pack("<I", 0)
        body += content
    directory = file_base + len(body)
    header = PACK_MAGIC + struct.pack("<5I", 3, 4, 6, 0, PACK_REL_FILEBASE)
    header += struct.pack("<QQ", file_base, directory) + b"\0" * (16 * 4)
    with open(path, "wb") as f:
        f.write(header.ljust(file_base, b"\0") + body + struct.pack("<I", len(files)) + index)


def _word_pattern(classes):
    if not classes:
        return None
    names = b"|".join(re.escape(name.encode()) for name in classes)
    return re.compile(rb"(?<![A-Za-z0-9_])(" + names + rb")(?![A-Za-z0-9_])")


def names_in(content, words):
    """The driver class names and driver paths that [content] (bytes) names."""
    found = set()
    if words is not None:
        found.update(m.group(1).decode() for m in words.finditer(content))
    found.update(m.group(0).decode() for m in DRIVER_PATH.finditer(content))
    return found


def check_class_cache(text, classes):
    """Problems of a global class cache: driver classes declared outside tests/ and tools/."""
    drivers = set(classes)
    return [
        f"the class cache declares the driver class {name} at {path}"
        for name, path in CACHE_ENTRY.findall(text)
        if name in drivers and not is_driver_path(path)
    ]


def check_pack(path, classes):
    """The problems found in one pack (an empty list when it is clean)."""
    problems = []
    words = _word_pattern(classes)
    for name, content in read_pack(path):
        if is_driver_path(name):
            problems.append(f"packs {name}")
            continue
        if content is None:
            continue
        if name == CLASS_CACHE:
            problems += check_class_cache(content.decode("utf-8", "replace"), classes)
        elif name != UID_CACHE:
            problems += [f"{name} names {found}" for found in sorted(names_in(content, words))]
    return problems


def check_tree(folder, classes):
    """The problems found in the text files of an unpacked folder (an addon)."""
    problems = []
    words = _word_pattern(classes)
    for base, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            if not name.endswith(TEXT_SUFFIXES):
                continue
            file = os.path.join(base, name)
            with open(file, "rb") as f:
                found = names_in(f.read(), words)
            problems += [f"{os.path.relpath(file, folder)} names {n}" for n in sorted(found)]
    return problems


def main(argv):
    if len(argv) < 2 or argv[1] not in ("drivers", "pack", "tree"):
        print(__doc__.split("\n\n")[2], file=sys.stderr)
        return 2
    classes = driver_classes()
    if argv[1] == "drivers":
        print("\n".join(classes))
        return 0
    failed = False
    for target in argv[2:]:
        check = check_pack if argv[1] == "pack" else check_tree
        try:
            problems = check(target, classes)
        except (OSError, ValueError, struct.error) as error:
            problems = [f"cannot be read: {error}"]
        for problem in problems:
            print(f"check-product: FAIL: {target}: {problem}", file=sys.stderr)
        failed = failed or bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
