extends Node
## `make bench` part for the game: Level 1 under the autopilot with fixed-FPS stepping
## (run with --fixed-fps 50), first with the haptic probe off (baseline), then on. Prints
## the wall time per physics frame of each run, their ratio, the speed against real time,
## and the probe's own cost per frame (build_frame + submit, timed directly).
##
## tools/godot --headless --path . --fixed-fps 50 res://tests/bench/game_bench.tscn --
##     [--frames=N] [--json=PATH]

const LEVEL := preload("res://game/levels/level_1.tscn")

var _frames: int = 1500
var _json_path: String = ""


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--frames="):
			_frames = maxi(50, arg.get_slice("=", 1).to_int())
		elif arg.begins_with("--json="):
			_json_path = arg.get_slice("=", 1)
	var baseline: Dictionary = await _run(false)
	var with_probe: Dictionary = await _run(true)
	_report(baseline, with_probe)
	get_tree().quit(0)


func _run(with_probe: bool) -> Dictionary:
	var level: Level = LEVEL.instantiate() as Level
	var probe: HapticProbe = level.get_node(^"Player/HapticProbe") as HapticProbe
	probe.drive_input = false
	# The probe's own tick is replaced by a timed call of the same work.
	probe.set_physics_process(false)
	add_child(level)
	level.player.use_keyboard = false
	var pilot: Autopilot = Autopilot.new(level.get_autopilot_path())
	var probe_us: Array[float] = []
	await get_tree().physics_frame
	var start_us: int = Time.get_ticks_usec()
	for i: int in _frames:
		await get_tree().physics_frame
		pilot.drive(level.player, 1.0 / Engine.physics_ticks_per_second)
		if with_probe:
			var before: int = Time.get_ticks_usec()
			probe.submit()
			probe_us.append(float(Time.get_ticks_usec() - before))
	var wall_s: float = (Time.get_ticks_usec() - start_us) / 1e6
	await get_tree().process_frame
	remove_child(level)
	level.free()
	probe_us.sort()
	var game_s: float = float(_frames) / Engine.physics_ticks_per_second
	return {
		"frames": _frames,
		"frame_ms": wall_s * 1000.0 / _frames,
		"speed_x": game_s / wall_s,
		"probe_p50_us": probe_us[probe_us.size() / 2] if not probe_us.is_empty() else 0.0,
		"probe_p99_us": probe_us[int(probe_us.size() * 0.99)] if not probe_us.is_empty() else 0.0,
	}


func _report(baseline: Dictionary, with_probe: Dictionary) -> void:
	var base_ms: float = baseline["frame_ms"]
	var probe_ms: float = with_probe["frame_ms"]
	print("")
	print("Game, Level 1 under the autopilot, %d physics frames, fixed-FPS stepping" % _frames)
	print("%-40s %12s %12s %10s" % ["metric", "no probe", "with probe", "ratio"])
	print(
		(
			"%-40s %12.3f %12.3f %10.2f"
			% ["wall time per physics frame (ms)", base_ms, probe_ms, probe_ms / base_ms]
		)
	)
	print(
		(
			"%-40s %12.1f %12.1f %10.2f"
			% [
				"speed vs real time (x)",
				baseline["speed_x"],
				with_probe["speed_x"],
				float(with_probe["speed_x"]) / float(baseline["speed_x"])
			]
		)
	)
	print("%-40s %12s %12.1f" % ["probe per frame p50 (us)", "-", with_probe["probe_p50_us"]])
	print("%-40s %12s %12.1f" % ["probe per frame p99 (us)", "-", with_probe["probe_p99_us"]])
	if _json_path.is_empty():
		return
	var file: FileAccess = FileAccess.open(_json_path, FileAccess.WRITE)
	if file == null:
		push_error("game_bench: cannot write %s" % _json_path)
		return
	file.store_string(JSON.stringify({"baseline": baseline, "with_probe": with_probe}, "  "))
	print("wrote %s" % _json_path)
