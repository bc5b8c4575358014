#!/usr/bin/env python3
"""The extension's include directions and file sizes.

Reads every #include "..." under gdextension/src, tests, bench and vm_tests,
resolves it the way the build does, and checks that the including file's folder may include
the included file's folder (LAYERS below). Also checks that no C++ file under gdextension/ is
over MAX_LINES lines. Prints one line per problem and exits 1 if there is any.

Usage: tools/check-includes.py [path/to/gdextension]   (default: next to tools/)
"""

import re
import sys
from pathlib import Path

# Who may include whom, bottom to top. A key is a folder under gdextension/; its files may
# include files of their own folder and of the folders listed. A key ending in /* makes each
# subfolder a layer of its own (a renderer may not include another renderer). The most
# specific key holding a file is its layer. The core's floors may include only lower floors.
CORE = ["src/core"]
LAYERS = {
    "src/core/base": [],
    "src/core/wire": ["src/core/base"],
    "src/core/config": ["src/core/base", "src/core/wire"],
    "src/core/device": ["src/core/base", "src/core/wire"],
    "src/core/render": ["src/core/base", "src/core/wire", "src/core/config", "src/core/device"],
    "src/core/servo": ["src/core/base", "src/core/wire", "src/core/config", "src/core/device", "src/core/render"],
    "src/renderers/*": CORE,
    "src/devices": ["src/core/base", "src/core/wire", "src/core/device"],
    "src/storage": ["src/core/base"],
    "src/system": CORE + ["src/renderers", "src/devices"],
    "src/dev_tools": CORE + ["src/devices", "src/system"],
    "src/binding": CORE + ["src/renderers", "src/devices", "src/storage", "src/system", "src/dev_tools"],
    "tests_support": [],
    "tests": ["src", "tests_support"],
    "bench": ["src", "tests", "tests_support"],
    "vm_tests": ["src"],
    "rt_probe": ["src"],
}
# Where a quoted include is looked for after the including file's own folder (as the build's
# include paths do), and headers from outside the tree.
ROOTS = ["src", "tests", "tests_support", "bench"]
# The build writes renderer_headers.gen.h (cmake/libraries.cmake): the renderers' headers.
EXTERNAL = {"gdextension_interface.h", "renderer_headers.gen.h"}
MAX_LINES = 400
SOURCES = ("src", "tests", "bench", "vm_tests", "rt_probe")
CPP = (".h", ".cpp")

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def layer_of(p_path):
    """The LAYERS key (with a /* key, the subfolder itself) holding p_path, or None."""
    best = None
    for key in LAYERS:
        if key.endswith("/*"):
            base = key[:-2]
            parts = p_path.split("/")
            depth = len(base.split("/"))
            if p_path.startswith(base + "/") and len(parts) > depth + 1:
                candidate = "/".join(parts[: depth + 1])
            else:
                continue
        elif p_path == key or p_path.startswith(key + "/"):
            candidate = key
        else:
            continue
        if best is None or len(candidate) > len(best[1]):
            best = (key, candidate)
    return best


def allowed(p_from, p_to):
    """Whether a file of layer p_from may include p_to (a path under gdextension/)."""
    key, own = p_from
    if p_to == own or p_to.startswith(own + "/"):
        return True
    return any(p_to == folder or p_to.startswith(folder + "/") for folder in LAYERS[key])


def resolve(p_root, p_file, p_include):
    """The included file as a path under gdextension/, or None."""
    candidates = [p_file.parent / p_include] + [p_root / root / p_include for root in ROOTS]
    for candidate in candidates:
        if candidate.is_file():
            return candidate.resolve().relative_to(p_root.resolve()).as_posix()
    return None


def short(p_path):
    """How the code names a file: relative to src/ for the library's own."""
    return p_path[len("src/"):] if p_path.startswith("src/") else p_path


def main():
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "gdextension"
    shown = root.name if len(sys.argv) > 1 else "gdextension"
    problems = []
    checked = 0
    for path in sorted(p for p in root.rglob("*") if p.suffix in CPP and p.is_file()):
        relative = path.relative_to(root).as_posix()
        lines = path.read_text(encoding="utf-8").splitlines()
        if len(lines) > MAX_LINES:
            problems.append(f"{shown}/{relative}: {len(lines)} lines: over the {MAX_LINES}-line limit; split it by job")
        if not relative.startswith(SOURCES):
            continue
        layer = layer_of(relative)
        for number, line in enumerate(lines, 1):
            match = INCLUDE.match(line)
            if not match or match.group(1) in EXTERNAL:
                continue
            checked += 1
            where = f"{shown}/{relative}:{number}"
            target = resolve(root, path, match.group(1))
            if target is None:
                problems.append(f'{where}: includes "{match.group(1)}", which is not in the tree')
            elif layer is None:
                problems.append(f"{where}: {short(relative)} is in no layer of tools/check-includes.py")
            elif not allowed(layer, target):
                own = short(layer[1])
                to = layer_of(target)
                to_name = short(to[1]) if to else short(target)
                problems.append(f"{where}: {short(relative)} includes {short(target)}: {own} may not include {to_name}")
    for problem in problems:
        print(problem)
    if problems:
        print(f"check-includes: {len(problems)} problem(s)", file=sys.stderr)
        return 1
    print(f"check-includes: {checked} includes follow the layers; no C++ file over {MAX_LINES} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
