extends TestSuite
## The game without its native library: a separate engine runs a copy of the project without
## the addon's built libraries (addons/haptics/bin/) or their sources. It must parse, warn
## once, and play (no force feedback): level 1 under the autopilot driver
## (tests/drivers/game_autopilot.tscn).

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_the_game_plays_without_the_extension_and_says_so() -> void:
	var script: String = ProjectSettings.globalize_path("res://tools/run-without-extension.sh")
	var output: Array = []
	var code: int = OS.execute(
		"bash",
		[script, "res://tests/drivers/game_autopilot.tscn", "--", "--autopilot-seconds=2"],
		output,
		true
	)
	var text: String = "\n".join(output)
	assert_eq(code, 0, text)
	assert_has(text, "Haptics extension not loaded: playing without force feedback")
	assert_has(text, "t= 2.0s", "the level ran under the autopilot")
	assert_false(text.contains("SCRIPT ERROR"), "no script failed to parse or run")
	assert_false(text.contains("Parse Error"), "no parse errors")
