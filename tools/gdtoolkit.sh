#!/usr/bin/env bash
# Runs gdtoolkit's gdlint or gdformat, pinned by tools/requirements-gdtoolkit.txt, from the
# ignored virtualenv .venv/gdtoolkit. The virtualenv is (re)built only when it is missing
# or the requirements file (or $PYTHON) changed; otherwise it only execs the tool.
#
#   tools/gdtoolkit.sh gdlint game tests          lint (config: ./gdlintrc)
#   tools/gdtoolkit.sh gdformat --check game tests
#   tools/gdtoolkit.sh gdformat game tests        reformat in place
#
# gdlint and gdformat look for gdlintrc / gdformatrc from the working directory upwards:
# run from the project root (or below). Set PYTHON to choose the interpreter (default
# python3, 3.9 or newer).
set -euo pipefail

project=$(cd "$(dirname "$0")/.." && pwd)
requirements="$project/tools/requirements-gdtoolkit.txt"
# shellcheck source=tools/venv.sh
source "$project/tools/venv.sh"

tool=${1:-}
case $tool in
  gdlint | gdformat) shift ;;
  *)
    echo "usage: tools/gdtoolkit.sh gdlint|gdformat [ARGS...]" >&2
    exit 2
    ;;
esac

venv=$(ensure_venv gdtoolkit "$requirements" "$tool")
exec "$venv/bin/$tool" "$@"
