# Sourced by the tool runners: ensure_venv NAME REQUIREMENTS [EXECUTABLE] makes sure the
# ignored virtualenv .venv/NAME holds exactly REQUIREMENTS (pinned) for $PYTHON (default
# python3), rebuilding it only when it is missing, the requirements file or the interpreter
# changed, or EXECUTABLE is missing from its bin/. Prints the virtualenv's path.
ensure_venv() {
  local name=$1 requirements=$2 executable=${3:-python}
  local project venv python hash wanted stamp
  project=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  venv="$project/.venv/$name"
  python=${PYTHON:-python3}
  # What the installed virtualenv must match: the requirements and the interpreter chosen.
  # (A venv whose base interpreter vanished has a dangling bin/python: -x catches that.)
  hash=$(sha256sum "$requirements" 2>/dev/null || shasum -a 256 "$requirements")
  wanted="${hash%% *} $python"
  stamp="$venv/.installed"
  if [[ ! -x $venv/bin/python || ! -x $venv/bin/$executable || ! -f $stamp ||
    $(<"$stamp") != "$wanted" ]]; then
    mkdir -p "$project/.venv"
    # One installer at a time (parallel make jobs); the others wait and then re-check.
    exec 9>"$project/.venv/$name.lock"
    if command -v flock >/dev/null; then flock 9; fi
    if [[ ! -x $venv/bin/python || ! -x $venv/bin/$executable || ! -f $stamp ||
      $(<"$stamp") != "$wanted" ]]; then
      echo "installing the pinned packages of ${requirements#"$project"/} into .venv/$name" >&2
      rm -rf "$venv"
      "$python" -m venv "$venv" >&2
      "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        --no-input -r "$requirements" >&2
      echo "$wanted" >"$stamp"
    fi
    exec 9>&-
  fi
  echo "$venv"
}
