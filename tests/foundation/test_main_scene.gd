extends TestSuite
## The main scene in a separate engine process, headless: the product's own system check
## (what an export runs) shows the main menu and quits with 0; the autopilot driver
## (tests/drivers/game_autopilot.tscn, what `make play` runs without a display) plays level 1
## with one status line per second and quits with 0.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_the_system_check_shows_the_menu_and_exits_cleanly() -> void:
	var text: String = _run(["--", "--system-check"], 0)
	assert_has(text, "System check: haptics ")
	assert_has(text, "device(s) found")
	assert_has(text, "System check: the main menu showed for %d frames" % Main.SYSTEM_CHECK_FRAMES)
	assert_false(text.contains("Autopilot on"), "the product has no autopilot")
	assert_false(text.contains("t= 1.0s"), "and plays no level by itself")


func test_headless_autopilot_prints_status_lines_and_exits_cleanly() -> void:
	var text: String = _run(
		["res://tests/drivers/game_autopilot.tscn", "--", "--autopilot-seconds=2"], 0
	)
	assert_has(text, "Autopilot on")
	assert_has(text, "t= 1.0s")
	assert_has(text, "t= 2.0s")


# Runs the project headless with [param args]; checks the exit code and that no script
# failed; returns the output.
func _run(args: PackedStringArray, expected_code: int) -> String:
	var godot: String = ProjectSettings.globalize_path("res://tools/godot")
	var project: String = ProjectSettings.globalize_path("res://")
	var command: PackedStringArray = [godot, "--headless", "--path", project]
	command.append_array(args)
	var output: Array = []
	var code: int = OS.execute("bash", command, output, true)
	var text: String = "\n".join(output)
	assert_eq(code, expected_code, text)
	assert_false(text.contains("SCRIPT ERROR"), text)
	return text
