extends Node
## `make bench` part for Haptic Battle Pong: computer-vs-computer matches with the servo
## stepped by the game (no thread), run back to back as fast as they go. Prints, per match
## and in total, the simulated seconds against the wall seconds (how much faster than real
## time a headless match runs) and the wall cost of one 10 ms match update with its ten
## servo ticks.
##
## tools/godot --headless --path . res://tests/bench/pong_bench.tscn -- [--matches=N]
##     [--health=N] [--json=PATH]

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
## Simulated seconds after which a match is cut short.
const MAX_MATCH_S: float = 600.0

var _matches: int = 3
var _health: int = 15
var _json_path: String = ""


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--matches="):
			_matches = maxi(1, arg.get_slice("=", 1).to_int())
		elif arg.begins_with("--health="):
			_health = maxi(1, arg.get_slice("=", 1).to_int())
		elif arg.begins_with("--json="):
			_json_path = arg.get_slice("=", 1)
	if not PongServo.shared().is_available():
		print("pong_bench: the extension has no Pong renderer; nothing to measure")
		get_tree().quit(1)
		return
	var runs: Array[Dictionary] = []
	for i: int in _matches:
		runs.append(await _run(i + 1))
	_report(runs)
	get_tree().quit(0)


func _run(seed_value: int) -> Dictionary:
	var pong: PongScreen = PongTestScreen.stepped(PongMatch.Mode.DEMO, 2, _health, true)
	var match_node: PongMatch = pong.get_node(^"Match") as PongMatch
	match_node.ai_seed = seed_value
	add_child(pong)
	await get_tree().process_frame
	var start_us: int = Time.get_ticks_usec()
	match_node.run_until(match_node.rules.is_over, MAX_MATCH_S)
	var wall_s: float = (Time.get_ticks_usec() - start_us) / 1e6
	var result: Dictionary = {
		"simulated_s": match_node.now,
		"wall_s": wall_s,
		"speed_x": match_node.now / wall_s,
		"update_us": wall_s * 1e6 / (match_node.now / PongMatch.STEP_CHUNK_S),
		"winner": match_node.rules.winner,
		"serves": match_node.referee.serves,
	}
	remove_child(pong)
	pong.free()
	await get_tree().process_frame
	get_tree().paused = false
	return result


func _report(runs: Array[Dictionary]) -> void:
	print("")
	print("Pong, computer vs computer, health %d, stepped servo, %d matches" % [_health, _matches])
	print(
		(
			"%-8s %12s %10s %10s %20s %8s"
			% ["match", "simulated s", "wall s", "speed x", "update+10 ticks (us)", "winner"]
		)
	)
	var simulated: float = 0.0
	var wall: float = 0.0
	for i: int in runs.size():
		var run: Dictionary = runs[i]
		var run_simulated: float = run["simulated_s"]
		var run_wall: float = run["wall_s"]
		simulated += run_simulated
		wall += run_wall
		print(
			(
				"%-8d %12.1f %10.2f %10.1f %20.1f %8d"
				% [
					i + 1,
					run["simulated_s"],
					run["wall_s"],
					run["speed_x"],
					run["update_us"],
					run["winner"]
				]
			)
		)
	print("%-8s %12.1f %10.2f %10.1f" % ["total", simulated, wall, simulated / wall])
	if _json_path.is_empty():
		return
	var file: FileAccess = FileAccess.open(_json_path, FileAccess.WRITE)
	if file == null:
		push_error("pong_bench: cannot write %s" % _json_path)
		return
	file.store_string(
		JSON.stringify({"runs": runs, "simulated_s": simulated, "wall_s": wall}, "  ")
	)
	print("wrote %s" % _json_path)
