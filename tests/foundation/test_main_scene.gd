extends TestSuite
## The main scene as `make play` runs it without a display: a separate engine process
## running the autopilot, one status line per second, exit code 0.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_headless_autopilot_prints_status_lines_and_exits_cleanly() -> void:
	var godot: String = ProjectSettings.globalize_path("res://tools/godot")
	var project: String = ProjectSettings.globalize_path("res://")
	var output: Array = []
	var code: int = OS.execute(
		"bash",
		[godot, "--headless", "--path", project, "--", "--autopilot", "--autopilot-seconds=2"],
		output,
		true
	)
	var text: String = "\n".join(output)
	assert_eq(code, 0, text)
	assert_has(text, "Autopilot on")
	assert_has(text, "t= 1.0s")
	assert_has(text, "t= 2.0s")
	assert_false(text.contains("SCRIPT ERROR"), text)
