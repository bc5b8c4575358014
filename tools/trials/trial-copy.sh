# Sourced by the trials (physics_platformer.sh, truck_town.sh): what each does before its own
# install: the arguments, the native library check, and a fresh copy of the demo with the
# addon and the trial's driver scene in it.

# trial_args "$@": DEMO and REV (--addon-rev) from the trial's arguments; the trial's own
# usage() when they are wrong.
trial_args() {
	[[ $# -ge 1 ]] || usage
	DEMO="$1"
	shift
	REV=""
	while [[ $# -gt 0 ]]; do
		case "$1" in
		--addon-rev) REV="${2:?--addon-rev needs a revision}"; shift 2 ;;
		*) usage ;;
		esac
	done
}

# trial_copy NAME DRIVER: DEST = .build/trial/NAME-<rev|worktree>, rebuilt from DEMO without
# its import cache (a first import, as a developer's), with the addon (the worktree's, or its
# scripts at REV beside the worktree's native library) and res://trial/driver.tscn running
# DRIVER. OUT is .build/trial; GODOT runs hermetic in it (tools/godot points XDG_* into
# HAPTICS_XDG_ROOT).
trial_copy() {
	ls addons/haptics/bin/libhaptics.linux.template_debug.x86_64.so >/dev/null 2>&1 ||
		{ echo "trial: no native library in addons/haptics/bin (make import)" >&2; exit 1; }
	OUT="$ROOT/.build/trial"
	export HAPTICS_XDG_ROOT="$OUT/.xdg"
	GODOT="$ROOT/tools/godot"
	DEST="$OUT/$1-${REV:-worktree}"
	rm -rf "$DEST"
	mkdir -p "$DEST"
	cp -r "$DEMO/." "$DEST/"
	rm -rf "$DEST/.godot"
	if [[ -n "$REV" ]]; then
		git archive "$REV" addons/haptics | tar -x -C "$DEST"
		cp -r addons/haptics/bin "$DEST/addons/haptics/"
	else
		mkdir -p "$DEST/addons"
		cp -r addons/haptics "$DEST/addons/"
	fi
	mkdir -p "$DEST/trial"
	cp "$2" "$DEST/trial/driver.gd"
	cat >"$DEST/trial/driver.tscn" <<'TSCN'
[gd_scene load_steps=2 format=3]

[ext_resource type="Script" path="res://trial/driver.gd" id="1_driver"]

[node name="Trial" type="Node"]
script = ExtResource("1_driver")
TSCN
}

# trial_run PATTERN [LINE]: imports the copy, runs its driver scene (each bounded), prints the
# log's lines that start with PATTERN (an extended regular expression), then LINE, then any
# ERROR lines; fails with the run's exit status.
trial_run() {
	if ! timeout 300 "$GODOT" --headless --path "$DEST" --import >"$DEST/import.log" 2>&1; then
		tail -n 30 "$DEST/import.log" >&2
		echo "trial: the import failed (log: $DEST/import.log)" >&2
		exit 1
	fi
	local rc=0
	timeout 300 "$GODOT" --headless --path "$DEST" res://trial/driver.tscn >"$DEST/trial.log" 2>&1 || rc=$?
	grep -E "^($1)" "$DEST/trial.log" || true
	[[ -z "${2:-}" ]] || echo "$2"
	grep -E '^(ERROR|SCRIPT ERROR)' "$DEST/import.log" "$DEST/trial.log" | sort | uniq -c | head -n 20 >&2 || true
	[[ $rc -eq 0 ]] || { echo "trial: the run exited $rc (log: $DEST/trial.log)" >&2; exit 1; }
}
