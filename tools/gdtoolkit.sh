#!/usr/bin/env bash
# Runs gdtoolkit's gdlint or gdformat, pinned by tools/requirements-gdtoolkit.txt, from the
# ignored virtualenv .venv/gdtoolkit. The virtualenv is (re)built only when it is missing
# or the requirements file (or $PYTHON) changed; otherwise it only execs the tool.
#
#   tools/gdtoolkit.sh gdlint scripts tests          lint (config: ./gdlintrc)
#   tools/gdtoolkit.sh gdformat --check scripts tests
#   tools/gdtoolkit.sh gdformat scripts tests        reformat in place
#
# gdlint and gdformat look for gdlintrc / gdformatrc from the working directory upwards:
# run from the project root (or below). Set PYTHON to choose the interpreter (default
# python3, 3.9 or newer).
set -euo pipefail

project=$(cd "$(dirname "$0")/.." && pwd)
requirements="$project/tools/requirements-gdtoolkit.txt"
venv="$project/.venv/gdtoolkit"
python=${PYTHON:-python3}

tool=${1:-}
case $tool in
  gdlint | gdformat) shift ;;
  *)
    echo "usage: tools/gdtoolkit.sh gdlint|gdformat [ARGS...]" >&2
    exit 2
    ;;
esac

# What the installed virtualenv must match: the requirements and the interpreter chosen.
# (A venv whose base interpreter vanished has a dangling bin/python: -x catches that.)
hash=$(sha256sum "$requirements" 2>/dev/null || shasum -a 256 "$requirements")
wanted="${hash%% *} $python"
stamp="$venv/.installed"

if [[ ! -x $venv/bin/python || ! -x $venv/bin/$tool || ! -f $stamp || $(<"$stamp") != "$wanted" ]]; then
  mkdir -p "$project/.venv"
  # One installer at a time (parallel make jobs); the others wait and then re-check.
  exec 9>"$project/.venv/gdtoolkit.lock"
  if command -v flock >/dev/null; then flock 9; fi
  if [[ ! -x $venv/bin/python || ! -x $venv/bin/$tool || ! -f $stamp || $(<"$stamp") != "$wanted" ]]; then
    echo "tools/gdtoolkit.sh: installing gdtoolkit into .venv/gdtoolkit" >&2
    rm -rf "$venv"
    "$python" -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
      --no-input -r "$requirements" >&2
    echo "$wanted" >"$stamp"
  fi
  exec 9>&-
fi

exec "$venv/bin/$tool" "$@"
