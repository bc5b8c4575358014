#!/usr/bin/env bash
# Runs a study-analysis script or module with the pinned Python packages of
# tools/requirements-analysis.txt, from the ignored virtualenv .venv/analysis. The virtualenv
# is (re)built only when it is missing or the requirements file (or $PYTHON) changed;
# otherwise this only execs Python.
#
#   tools/analysis/run.sh analyze.py STUDY_DIR [--out OUT_DIR] [--skip-invalid]
#   tools/analysis/run.sh export_csv.py STUDY_DIR OUT.csv
#   tools/analysis/run.sh synth_study.py OUT_DIR            a synthetic study to try things
#   tools/analysis/run.sh -m pytest tools/analysis/tests -q
#
# A script is looked up as given, then in tools/analysis/. Set PYTHON to choose the
# interpreter for the virtualenv (default python3, 3.11 or newer).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
project=$(cd "$here/../.." && pwd)
requirements="$project/tools/requirements-analysis.txt"
venv="$project/.venv/analysis"
python=${PYTHON:-python3}

if [[ $# -eq 0 ]]; then
  echo "usage: tools/analysis/run.sh SCRIPT.py [ARGS...] | -m MODULE [ARGS...]" >&2
  exit 2
fi

# What the installed virtualenv must match: the requirements and the interpreter chosen.
# (A venv whose base interpreter vanished has a dangling bin/python: -x catches that.)
hash=$(sha256sum "$requirements" 2>/dev/null || shasum -a 256 "$requirements")
wanted="${hash%% *} $python"
stamp="$venv/.installed"

if [[ ! -x $venv/bin/python || ! -f $stamp || $(<"$stamp") != "$wanted" ]]; then
  mkdir -p "$project/.venv"
  # One installer at a time (parallel make jobs); the others wait and then re-check.
  exec 9>"$project/.venv/analysis.lock"
  if command -v flock >/dev/null; then flock 9; fi
  if [[ ! -x $venv/bin/python || ! -f $stamp || $(<"$stamp") != "$wanted" ]]; then
    echo "tools/analysis/run.sh: installing the analysis packages into .venv/analysis" >&2
    rm -rf "$venv"
    "$python" -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
      --no-input -r "$requirements" >&2
    echo "$wanted" >"$stamp"
  fi
  exec 9>&-
fi

# No display needed; caches (bytecode, matplotlib's font cache) stay inside the virtualenv
# so nothing appears in the source tree.
export MPLBACKEND=Agg
export MPLCONFIGDIR="$venv/mplconfig"
export PYTHONPYCACHEPREFIX="$venv/pycache"

if [[ $1 == -m ]]; then
  exec "$venv/bin/python" "$@"
fi
script=$1
shift
if [[ ! -f $script && -f $here/$script ]]; then
  script=$here/$script
fi
if [[ ! -f $script ]]; then
  echo "tools/analysis/run.sh: no such script: $script (looked in . and tools/analysis/)" >&2
  exit 2
fi
exec "$venv/bin/python" "$script" "$@"
