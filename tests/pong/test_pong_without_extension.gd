extends TestSuite
## Pong without the native library: a copy of the project without its built libraries asked for
## the headless demo (tests/drivers/pong_demo.tscn) says why there is no game (the ball lives
## only in the servo) and exits with an error, without script errors.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_the_pong_demo_says_it_needs_the_extension() -> void:
	set_timeout(120.0)
	var script: String = ProjectSettings.globalize_path("res://tools/run-without-extension.sh")
	var output: Array = []
	var code: int = OS.execute("bash", [script, "res://tests/drivers/pong_demo.tscn"], output, true)
	var text: String = "\n".join(output)
	assert_eq(code, 1, text)
	assert_has(text, PongScreen.OFFLINE_TEXT)
	assert_false(text.contains("SCRIPT ERROR"), "no script failed to parse or run")
	assert_false(text.contains("Parse Error"), "no parse errors")
