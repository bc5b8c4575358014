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
# shellcheck source=tools/venv.sh
source "$project/tools/venv.sh"

if [[ $# -eq 0 ]]; then
  echo "usage: tools/analysis/run.sh SCRIPT.py [ARGS...] | -m MODULE [ARGS...]" >&2
  exit 2
fi

venv=$(ensure_venv analysis "$requirements")

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
