# Sourced by the scripts that need a display: starts Xvfb on a free display.
#   xvfb_start SCRATCH_DIR   sets XVFB_PID and XVFB_DISPLAY (":N"), or fails with Xvfb's log
#   xvfb_stop                stops it (safe to call when it never started)
# The caller's EXIT trap should call xvfb_stop.
XVFB_PID=""
XVFB_DISPLAY=""

xvfb_start() {
  local scratch=$1
  command -v Xvfb >/dev/null || {
    echo "Xvfb missing (make deps installs it)" >&2
    return 1
  }
  # -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
  Xvfb -displayfd 3 -screen 0 1280x720x24 -nolisten tcp 3>"$scratch/xvfb.display" \
    2>"$scratch/xvfb.log" &
  XVFB_PID=$!
  for _ in $(seq 100); do
    [[ -s $scratch/xvfb.display ]] && break
    kill -0 "$XVFB_PID" 2>/dev/null || break
    sleep 0.1
  done
  [[ -s $scratch/xvfb.display ]] || {
    echo "Xvfb did not start: $(cat "$scratch/xvfb.log")" >&2
    return 1
  }
  XVFB_DISPLAY=:$(head -n 1 "$scratch/xvfb.display")
}

xvfb_stop() {
  if [[ -n $XVFB_PID ]]; then
    kill "$XVFB_PID" 2>/dev/null || true
    wait "$XVFB_PID" 2>/dev/null || true
    XVFB_PID=""
  fi
}
