#!/usr/bin/env python3
"""Prints the Makefile's documented targets (`make help`): for each `## name: summary` block
above a rule, the name and its one-line summary (the block's other lines say the rest)."""

import re
import sys

START = re.compile(r"^## ([a-z][a-z0-9-]*): (.*)$")


def blocks(path):
    for line in open(path, encoding="utf-8"):
        start = START.match(line.rstrip("\n"))
        if start:
            yield start.group(1), start.group(2)


def main(path):
    rows = list(blocks(path))
    width = max(len(name) for name, _ in rows)
    print("Usage: make <target>. Two matter: make play and make test; make check is the quick")
    print("loop before a commit. Each target's comment in the Makefile says what it does.\n")
    for name, text in rows:
        print(f"  {name:<{width}}  {text}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "Makefile"))
    except BrokenPipeError:
        sys.exit(0)
