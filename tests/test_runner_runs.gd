extends TestSuite
## Whole runs of the test runner over the fixtures in res://tests/fixtures, each in a fresh
## engine process (exit code, result lines, summary line, JUnit XML), since a deliberately
## failing run cannot happen inside this one.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const RUNNER_SCENE: String = "res://tests/runner/runner.tscn"
const SCRATCH_DIR: String = "user://runner_self"
## Upper bound for one subprocess run, in seconds (the child has its own per-test timeouts).
const SUBPROCESS_LIMIT_SECONDS: int = 180


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


func test_shards_split_the_files_between_them() -> void:
	var suites: Array[String] = ["test_fixture_failing::", "test_fixture_failing_before_all::"]
	for shard: int in 2:
		var run: Run = _run_runner(
			["--dir=res://tests/fixtures/failing", "--shard=%d/2" % (shard + 1)]
		)
		assert_eq(run.exit_code, 1, run.describe())
		for other: int in 2:
			var lines: int = 0
			for line: String in run.lines:
				if line.contains(" " + suites[other]):
					lines += 1
			assert_eq(
				lines > 0,
				other == shard,
				"shard %d, %s\n%s" % [shard + 1, suites[other], run.describe()]
			)
	var bad: Run = _run_runner(["--dir=res://tests/fixtures/failing", "--shard=3/2"])
	assert_eq(bad.exit_code, 2, bad.describe())


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
