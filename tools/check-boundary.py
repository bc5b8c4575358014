#!/usr/bin/env python3
"""Checks that GDScript and the native library meet at one typed boundary, and prints the
counts that show it:

- the native methods (HapticsSystem's, as its header declares them) that take or return a
  Dictionary or an untyped Array: at most MAX_MAPS, each a documented diagnostic report;
- calls by name (`call(&"...")`, `callv(`, `rpc(&"...")`) in the addon and the games: none, but in the
  editor plugin (Godot's own editor classes it drives have no typed API);
- game or addon scripts that read a Dictionary the server returned: none can, since none
  is returned, so this is the first count;
- @rpc functions whose parameters are variadic or untyped: none;
- citations of files outside the repository (the fact sheets and notes beside it): none.

Exit 1 when a rule is broken. Run by make lint.
"""

import os
import re
import sys

MAX_MAPS = 2
HEADER = "gdextension/src/binding/system_object.h"
# Where a call by name may be: the editor plugin's glue to Godot's editor classes.
CALLS_BY_NAME_ALLOWED = "addons/haptics/editor/"
SCRIPT_ROOTS = ("addons", "game")
METHOD = re.compile(r"^\t(?:static )?([\w:<>]+) (\w+)\((.*?)\)(?: const)?;", re.M)
MAP_TYPES = re.compile(r"\bgd::(Dictionary|Array)\b")
CALL_BY_NAME = re.compile(r"\bcall\(\s*&?\"|\bcallv\(|\brpc(?:_id)?\(\s*(?:\w+\s*,\s*)?&?\"")
RPC = re.compile(r"^@rpc\([^)]*\)\s*\n\s*func\s+\w+\((.*?)\)", re.M | re.S)
# [F] keeps this pattern out of a plain grep for such citations.
OUTSIDE = re.compile(r"[F]ACTS §|\.\./shared|shared/(?:pong|devices)/|KERNEL\.md|\bRT\.md|DESIGN\.md")


def scripts():
    for root in SCRIPT_ROOTS:
        for folder, dirs, files in os.walk(root):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(".gd"):
                    yield os.path.join(folder, name)


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    problems = []
    header = open(HEADER, encoding="utf-8").read()
    public = header[header.index("public:") : header.index("private:")]
    methods = METHOD.findall(public)
    maps = [name for ret, name, args in methods if MAP_TYPES.search(ret) or MAP_TYPES.search(args)]
    print(f"check-boundary: {len(methods)} native methods; {len(maps)} take or return a Dictionary or Array"
          + (f" ({', '.join(maps)})" if maps else ""))
    if len(maps) > MAX_MAPS:
        problems.append(f"{HEADER}: {len(maps)} methods take or return maps, at most {MAX_MAPS}")
    by_name = []
    rpcs = 0
    for path in scripts():
        text = open(path, encoding="utf-8").read()
        for number, line in enumerate(text.split("\n"), 1):
            if CALL_BY_NAME.search(line):
                by_name.append(f"{path}:{number}")
        for params in RPC.findall(text):
            rpcs += 1
            for param in filter(None, (p.strip() for p in params.split(","))):
                if param.startswith("...") or ":" not in param or param.split(":")[1].strip() in ("Variant", "Array"):
                    problems.append(f"{path}: @rpc parameter '{param}' is variadic or untyped")
    stray = [place for place in by_name if not place.startswith(CALLS_BY_NAME_ALLOWED)]
    print(f"check-boundary: {len(by_name)} calls by name in addons/ and game/, {len(stray)} outside "
          f"the editor plugin; {rpcs} @rpc functions")
    problems += [f"{place}: a call by name (call a typed method instead)" for place in stray]
    outside = []
    for folder, dirs, files in os.walk("."):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") or d == ".ci")
        for name in files:
            if name.endswith((".gd", ".cpp", ".h", ".py", ".sh", ".md", ".cmake")) or name == "Makefile":
                path = os.path.join(folder, name)[2:]
                if path == "tools/check-boundary.py":
                    continue
                for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
                    if OUTSIDE.search(line):
                        outside.append(f"{path}:{number}")
    print(f"check-boundary: {len(outside)} citations of files outside the repository")
    problems += [f"{place}: cites a file outside the repository" for place in outside]
    for line in problems:
        print(f"check-boundary: {line}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
