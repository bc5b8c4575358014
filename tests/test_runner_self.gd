extends TestSuite
## Tests of the test runner itself.
##
## The assertions and helpers are checked in-process; whole runs over the fixtures in
## res://tests/fixtures are checked in a subprocess (exit code, result lines, summary line,
## JUnit XML), since a deliberately failing run cannot happen inside this one.

const Runner := preload("res://tests/runner/runner.gd")

const RUNNER_SCENE: String = "res://tests/runner/runner.tscn"
const SCRATCH_DIR: String = "user://runner_self"
const FALLING_BODY_SCENE: String = "res://tests/fixtures/scenes/falling_body.tscn"
## Upper bound for one subprocess run, in seconds (the child has its own per-test timeouts).
const SUBPROCESS_LIMIT_SECONDS: int = 180
## Every GDScript file of the runner and its fixtures, checked for GDScript warnings.
const OWN_SCRIPTS: PackedStringArray = [
	"res://tests/runner/error_capture.gd",
	"res://tests/runner/junit.gd",
	"res://tests/runner/result.gd",
	"res://tests/runner/runner.gd",
	"res://tests/runner/test_suite.gd",
	"res://tests/test_runner_self.gd",
	"res://tests/fixtures/failing/test_fixture_failing.gd",
	"res://tests/fixtures/failing/test_fixture_failing_before_all.gd",
	"res://tests/fixtures/passing/test_fixture_passing.gd",
	"res://tests/fixtures/quitting/test_fixture_quitting.gd",
]


## What one subprocess run of the runner produced.
class Run:
	extends RefCounted

	var exit_code: int = -1
	## Standard output, line by line.
	var lines: PackedStringArray = PackedStringArray()
	var stderr: String = ""

	## The last line printed, which must be the summary.
	func last_line() -> String:
		return lines[lines.size() - 1] if not lines.is_empty() else ""

	## The first line starting with [param prefix], or "" if none.
	func line_starting(prefix: String) -> String:
		for line: String in lines:
			if line.begins_with(prefix):
				return line
		return ""

	## Output for failure messages.
	func describe() -> String:
		return (
			"exit code %d\n--- stdout ---\n%s\n--- stderr (tail) ---\n%s"
			% [exit_code, "\n".join(lines), stderr.right(2000)]
		)


var _run_count: int = 0
var _cached_runs: Dictionary[String, Run] = {}


func before_all() -> void:
	DirAccess.make_dir_recursive_absolute(SCRATCH_DIR)


func test_failed_assertion_reports_file_line_and_message() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var returned: bool = probe.assert_eq(1, 2, "one is not two")
	var line: int = get_stack()[0]["line"]
	assert_false(returned)
	assert_eq(
		result.failures,
		PackedStringArray(
			["res://tests/test_runner_self.gd:%d: one is not two: expected 2, got 1" % (line - 1)]
		)
	)


func test_each_assertion_fails_on_bad_input() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var outcomes: Array[bool] = [
		probe.assert_eq("1", 1),
		probe.assert_ne(2, 2.0),
		probe.assert_true(1),
		probe.assert_false(null),
		probe.assert_null(self),
		probe.assert_not_null(null),
		probe.assert_almost_eq(1.0, 1.2, 0.1),
		probe.assert_almost_eq(Vector2(0, 0), Vector2(0, 0.5), 0.1),
		probe.assert_almost_eq(Vector3(0, 0, 0), Vector3(0, 0, 0.5), 0.1),
		probe.assert_almost_eq(Vector3.ZERO, Vector2.ZERO, 0.1),
		probe.assert_gt(1, 1),
		probe.assert_lt(2, 1.5),
		probe.assert_gt("a", 1),
		probe.assert_has([1, 2], 3),
		probe.assert_has({"a": 1}, "b"),
		probe.assert_has("abc", "d"),
		probe.assert_has(PackedInt32Array([1]), 2),
		probe.assert_has(5, 5),
	]
	probe.fail("explicit")
	assert_false(outcomes.has(true), "every assertion returned false: %s" % [outcomes])
	assert_eq(result.failures.size(), outcomes.size() + 1, "\n".join(result.failures))
	assert_has(result.failures[0], 'expected 1, got "1"')
	assert_has(result.failures[9], "cannot compare (0.0, 0.0, 0.0) with (0.0, 0.0)")
	assert_has(result.failures[17], "5 is not a container")
	assert_has(result.failures[18], "explicit")


func test_each_assertion_passes_on_good_input() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var freed: Node = Node.new()
	freed.free()
	var outcomes: Array[bool] = [
		probe.assert_eq(2, 2.0),
		probe.assert_eq(&"name", "name"),
		probe.assert_eq(null, null),
		probe.assert_ne(self, null),
		probe.assert_null(freed),
		probe.assert_almost_eq(1, 1.05, 0.1),
		probe.assert_almost_eq(Vector2i(1, 2), Vector2(1.01, 2.0), 0.1),
		probe.assert_almost_eq(Color(0.5, 0.5, 0.5), Color(0.5, 0.51, 0.5), 0.02),
		probe.assert_gt(2.5, 2),
		probe.assert_lt("a", "b"),
		probe.assert_has(PackedVector2Array([Vector2.ONE]), Vector2.ONE),
		probe.assert_has(&"string name", "name"),
	]
	assert_false(outcomes.has(false), "every assertion returned true: %s" % [outcomes])
	assert_eq(result.failures, PackedStringArray())


func test_expected_engine_error_does_not_fail() -> void:
	expect_error('Node not found: "no_such_child"')
	assert_null(get_node_or_null("no_such_child"))
	get_node("no_such_child")


func test_timeout_can_be_raised_for_one_test() -> void:
	set_timeout(60.0)
	await wait_physics_frames(1)


func test_instances_a_scene_and_steps_physics() -> void:
	var scene: PackedScene = load(FALLING_BODY_SCENE) as PackedScene
	if not assert_not_null(scene):
		return
	var root: Node = add_child_autofree(scene.instantiate())
	var ball: RigidBody2D = root.get_node("Ball") as RigidBody2D
	var start: Vector2 = ball.global_position
	await wait_physics_frames(10)
	assert_gt(ball.global_position.y - start.y, 5.0, "gravity moved the body down")
	assert_almost_eq(ball.global_position.x, start.x, 0.001)


func test_autoloads_are_available() -> void:
	var checked: int = 0
	for property: Dictionary in ProjectSettings.get_property_list():
		var setting: String = property["name"]
		if not setting.begins_with("autoload/"):
			continue
		var autoload_name: String = setting.trim_prefix("autoload/")
		var script_path: String = str(ProjectSettings.get_setting(setting)).trim_prefix("*")
		if not ResourceLoader.exists(script_path):
			continue
		assert_not_null(get_node_or_null("/root/" + autoload_name), autoload_name)
		checked += 1
	if checked == 0:
		skip("no autoload script exists yet")


func test_default_discovery_skips_fixtures_and_runner() -> void:
	var found: PackedStringArray = Runner._discover("res://tests")
	assert_has(found, "res://tests/test_runner_self.gd")
	for path: String in found:
		assert_false(path.begins_with("res://tests/fixtures/"), path)
		assert_false(path.begins_with("res://tests/runner/"), path)
	var fixtures: PackedStringArray = Runner._discover("res://tests/fixtures/passing")
	assert_eq(fixtures, PackedStringArray(["res://tests/fixtures/passing/test_fixture_passing.gd"]))


func test_own_scripts_have_no_gdscript_warnings() -> void:
	var enabled: int = await assert_scripts_compile_without_warnings(OWN_SCRIPTS)
	assert_gt(enabled, 0, "project.godot enables some GDScript warnings")


func test_passing_fixture_exits_zero() -> void:
	var run: Run = _run_runner(["--dir=res://tests/fixtures/passing"])
	assert_eq(run.exit_code, 0, run.describe())
	assert_eq(run.last_line(), "6 passed, 0 failed, 1 skipped", run.describe())
	assert_has(run.lines, "PASS test_fixture_passing::test_expected_error_is_allowed")
	assert_has(run.lines, "SKIP test_fixture_passing::test_skips_itself — fixture skip")


func test_failing_fixture_reports_every_failure() -> void:
	var run: Run = _run_runner(["--dir=res://tests/fixtures/failing"])
	assert_eq(run.exit_code, 1, run.describe())
	assert_eq(run.last_line(), "1 passed, 8 failed, 0 skipped", run.describe())
	var suite: String = "test_fixture_failing::"
	var fixture: String = "res://tests/fixtures/failing/test_fixture_failing.gd"
	var expected: Dictionary[String, String] = {
		"PASS %stest_passes" % suite: "",
		"FAIL %stest_assert_eq_fails — " % suite:
		fixture + ":14: one is not two: expected 2, got 1",
		"FAIL %stest_fail_called — " % suite: fixture + ":18: explicit failure",
		"FAIL %stest_unexpected_push_error — " % suite:
		"unexpected engine error: ERROR: unexpected fixture error (%s:22)" % fixture,
		"FAIL %stest_expected_error_missing — " % suite:
		'expected an error containing "an error nobody logs", but none was logged',
		"FAIL %stest_runtime_error — " % suite:
		"SCRIPT ERROR: Cannot call method 'get_name' on a null value.",
		"FAIL %stest_error_after_await — " % suite: "late fixture error",
		"FAIL %stest_times_out — " % suite: "timed out after 0.3 s in test_times_out()",
		"FAIL test_fixture_failing_before_all::before_all — ": "before_all fails on purpose",
	}
	for prefix: String in expected:
		var line: String = run.line_starting(prefix)
		if assert_ne(line, "", "a line starts with %s\n%s" % [prefix, run.describe()]):
			assert_has(line, expected[prefix])
	assert_eq(run.line_starting("FAIL test_fixture_failing_before_all::test_never_runs"), "")


func test_unexpected_error_fails_a_test_and_expect_error_passes_it() -> void:
	var failing: Run = _run_runner(["--dir=res://tests/fixtures/failing"])
	assert_has(
		failing.line_starting("FAIL test_fixture_failing::test_unexpected_push_error"),
		"unexpected fixture error",
		failing.describe()
	)
	var passing: Run = _run_runner(["--dir=res://tests/fixtures/passing"])
	assert_has(passing.lines, "PASS test_fixture_passing::test_expected_error_is_allowed")


func test_junit_xml_lists_every_result() -> void:
	var junit_path: String = ProjectSettings.globalize_path(SCRATCH_DIR.path_join("junit.xml"))
	DirAccess.remove_absolute(junit_path)
	var run: Run = _run_runner(["--dir=res://tests/fixtures/failing", "--junit=" + junit_path])
	assert_eq(run.exit_code, 1, run.describe())
	var parser: XMLParser = XMLParser.new()
	if not assert_eq(parser.open(junit_path), OK, "JUnit file exists"):
		return
	var counts: Dictionary[String, int] = {"testsuite": 0, "testcase": 0, "failure": 0}
	var root_attributes: Dictionary[String, String] = {}
	while parser.read() == OK:
		if parser.get_node_type() != XMLParser.NODE_ELEMENT:
			continue
		var element: String = parser.get_node_name()
		if counts.has(element):
			counts[element] += 1
		if element == "testsuites":
			for i: int in parser.get_attribute_count():
				root_attributes[parser.get_attribute_name(i)] = parser.get_attribute_value(i)
	assert_eq(counts, {"testsuite": 2, "testcase": 9, "failure": 8})
	assert_eq(root_attributes.get("tests"), "9")
	assert_eq(root_attributes.get("failures"), "8")


func test_script_that_fails_to_parse_fails_the_run() -> void:
	var dir: String = _stage_fixture(
		"res://tests/fixtures/parse_error/test_fixture_parse_error.gd.txt"
	)
	var run: Run = _run_runner(["--dir=" + dir])
	assert_eq(run.exit_code, 1, run.describe())
	assert_eq(run.last_line(), "0 passed, 1 failed, 0 skipped", run.describe())
	var line: String = run.line_starting("FAIL test_fixture_parse_error::<load> — ")
	assert_has(line, "could not load or parse the script", run.describe())
	assert_has("\n".join(run.lines), "Parse Error", run.describe())


func test_warnings_as_errors_rejects_untyped_suite() -> void:
	var dir: String = _stage_fixture("res://tests/fixtures/warnings/test_fixture_untyped.gd.txt")
	var lenient: Run = _run_runner(["--dir=" + dir])
	assert_eq(lenient.exit_code, 0, lenient.describe())
	assert_eq(lenient.last_line(), "1 passed, 0 failed, 0 skipped", lenient.describe())
	var strict: Run = _run_runner(["--dir=" + dir, "--warnings-as-errors"])
	assert_eq(strict.exit_code, 1, strict.describe())
	assert_eq(strict.last_line(), "0 passed, 1 failed, 0 skipped", strict.describe())
	assert_has("\n".join(strict.lines), "(Warning treated as error.)", strict.describe())


func test_filters_select_files_and_tests() -> void:
	var run: Run = _run_runner(
		["--dir=res://tests/fixtures", "--filter=passing", "--test=test_assertions_pass"]
	)
	assert_eq(run.exit_code, 0, run.describe())
	assert_eq(
		run.lines.slice(-2),
		PackedStringArray(
			["PASS test_fixture_passing::test_assertions_pass", "1 passed, 0 failed, 0 skipped"]
		),
		run.describe()
	)


func test_no_test_run_is_a_failure() -> void:
	var run: Run = _run_runner(["--dir=res://tests/fixtures/passing", "--test=no_such_test"])
	assert_eq(run.exit_code, 1, run.describe())
	assert_eq(run.last_line(), "0 passed, 0 failed, 0 skipped", run.describe())


func test_quitting_the_tree_fails_the_run() -> void:
	var run: Run = _run_runner(["--dir=res://tests/fixtures/quitting"])
	assert_eq(run.exit_code, 1, run.describe())
	assert_eq(run.last_line(), "0 passed, 1 failed, 0 skipped", run.describe())
	assert_has(run.line_starting("FAIL runner::<quit>"), "quit", run.describe())


func test_bad_option_exits_two() -> void:
	var run: Run = _run_runner(["--no-such-option"])
	assert_eq(run.exit_code, 2, run.describe())
	assert_has(run.lines, "error: unknown option --no-such-option")
	assert_eq(run.last_line(), "0 passed, 0 failed, 0 skipped", run.describe())


## A suite instance that is not run: its assertions record into a result we inspect.
func _probe() -> TestSuite:
	var probe: TestSuite = TestSuite.new()
	autofree(probe)
	return probe


func _bind_probe(probe: TestSuite) -> TestResult:
	var result: TestResult = TestResult.new("probe", "probe", "")
	probe._runner_bind_result(result)
	return result


## Copies a .gd.txt fixture to user:// as a .gd file; returns the folder to pass as --dir.
func _stage_fixture(source_path: String) -> String:
	var stage: String = SCRATCH_DIR.path_join(source_path.get_base_dir().get_file())
	DirAccess.make_dir_recursive_absolute(stage)
	var target: String = stage.path_join(source_path.get_file().trim_suffix(".txt"))
	var file: FileAccess = FileAccess.open(target, FileAccess.WRITE)
	file.store_string(FileAccess.get_file_as_string(source_path))
	file.close()
	return stage


## Runs the runner in a fresh engine process through tools/godot; identical runs are cached.
func _run_runner(args: PackedStringArray) -> Run:
	var key: String = " ".join(args)
	if _cached_runs.has(key) and not key.contains("--junit"):
		return _cached_runs[key]
	_run_count += 1
	var stderr_path: String = ProjectSettings.globalize_path(
		SCRATCH_DIR.path_join("stderr_%d.txt" % _run_count)
	)
	var command: PackedStringArray = [
		_write_launcher(),
		stderr_path,
		str(SUBPROCESS_LIMIT_SECONDS),
		ProjectSettings.globalize_path("res://tools/godot"),
		"--headless",
		"--path",
		ProjectSettings.globalize_path("res://"),
		RUNNER_SCENE,
		"--",
	]
	command.append_array(args)
	var run: Run = Run.new()
	# OS.execute() with an output array runs "/bin/sh -c" on a line built by wrapping each
	# argument in double quotes, unescaped: arguments must not contain $ ` " or \.
	var unsafe: RegEx = RegEx.create_from_string('[$`"\\\\]')
	for argument: String in command:
		if unsafe.search(argument) != null:
			fail("argument not safe for OS.execute: " + argument)
			return run
	var output: Array = []
	run.exit_code = OS.execute("bash", command, output)
	var stdout: String = ""
	for chunk: Variant in output:
		stdout += str(chunk)
	run.lines = stdout.strip_edges(false, true).split("\n")
	run.stderr = FileAccess.get_file_as_string(stderr_path)
	_cached_runs[key] = run
	return run


## Writes the launcher script: it sends the child's stderr to a file (kept for failure
## messages) and bounds the child's run time. Returns its absolute path.
func _write_launcher() -> String:
	var path: String = SCRATCH_DIR.path_join("launch.sh")
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	(
		file
		. store_string(
			(
				"\n"
				. join(
					[
						"# Usage: bash launch.sh STDERR_FILE SECONDS PROGRAM ARGS...",
						'err="$1"; limit="$2"; shift 2',
						'exec timeout "$limit" bash "$@" 2>"$err"',
						"",
					]
				)
			)
		)
	)
	file.close()
	return ProjectSettings.globalize_path(path)
