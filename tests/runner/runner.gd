extends Node
## Headless GDScript test runner (GUT / gdUnit4 conventions, no add-on needed).
##
## Run from the project root; runner options come after [code]--[/code]:
## [codeblock]
## tools/godot --headless --path . res://tests/runner/runner.tscn -- [options]
## [/codeblock]
## Options:
## [codeblock]
## --dir=PATH            Folder searched recursively for test_*.gd, or one test_*.gd file
##                       (repeatable). Default res://tests without res://tests/fixtures and
##                       res://tests/runner; a --dir inside fixtures searches there.
##                       user:// and absolute paths work too.
## --filter=TEXT         Only files whose path contains TEXT (repeatable: any may match).
## --test=TEXT           Only tests whose name or "suite::test" contains TEXT (repeatable).
## --timeout=SECONDS     Default timeout of each hook and each test (default 30).
## --junit=PATH          Also write JUnit XML; a relative PATH is taken from the caller's
##                       working directory.
## --shard=K/N          Only every Nth test file of the list, from the Kth: N runners side
##                       by side run each file once (make test-godot runs two).
## --quick              Leave out the suites that declare [code]const SLOW := true[/code]
##                       (they run whole scenes for seconds, or start other processes):
##                       make check's quick loop. They are counted on the summary line.
## --warnings-as-errors  Raise every GDScript warning enabled in the project settings to an
##                       error while test scripts load, so a warning in a test script (or
##                       in a script it loads for the first time) makes its suite fail.
## --help                Print this help.
## [/codeblock]
## Output: one line per test, [code]PASS suite::test[/code],
## [code]FAIL suite::test — reason[/code] (further reasons indented below it) or
## [code]SKIP suite::test — reason[/code]. A suite that fails to load is reported as
## [code]FAIL suite::<load>[/code]; a failing before_all or after_all as
## [code]FAIL suite::before_all[/code] / [code]FAIL suite::after_all[/code]. The last line
## printed is [code]N passed, N failed, N skipped[/code].
## [br]Exit code: 0 if nothing failed and at least one test ran, 1 otherwise, 2 for bad
## options.
## [br][br]
## The runner is the main scene, so autoloads exist before any test script is loaded.
## Tests must not change the current scene or call [code]get_tree().quit()[/code] (doing so
## is reported as a failure). See [code]tests/runner/test_suite.gd[/code] for the test API.

const ErrorCapture := preload("res://tests/runner/error_capture.gd")
const JUnit := preload("res://tests/runner/junit.gd")
const Result := preload("res://tests/runner/result.gd")
const SuiteBase := preload("res://tests/runner/test_suite.gd")
const Options := preload("res://tests/runner/options.gd")
const Discovery := preload("res://tests/runner/discovery.gd")


## Completion flag of one invoked hook or test.
class Invocation:
	extends RefCounted

	## Set when the invoked method (and everything it awaited) returned.
	var done: bool = false


var _capture: ErrorCapture = null
var _results: Array[Result] = []
var _passed: int = 0
var _failed: int = 0
var _skipped: int = 0
var _left_out: int = 0
var _finished: bool = false


func _ready() -> void:
	_main()


func _exit_tree() -> void:
	if _finished:
		return
	# Someone quit the tree (or changed the scene) mid-run: never let that pass as success.
	_finished = true
	_failed += 1
	print("FAIL runner::<quit> — the tree quit or the scene changed before all tests ran")
	_print_summary()
	get_tree().quit(1)


func _main() -> void:
	var options: Options = Options.parse(OS.get_cmdline_user_args())
	if options.help or not options.error.is_empty():
		if not options.error.is_empty():
			print("error: " + options.error)
		_print_usage()
		_finish(0 if options.error.is_empty() and options.help else 2)
		return

	var files: PackedStringArray = PackedStringArray()
	for root: String in options.roots:
		if not DirAccess.dir_exists_absolute(root) and not FileAccess.file_exists(root):
			print("error: --dir %s does not exist" % root)
			_finish(2)
			return
		for path: String in Discovery.discover(root):
			if not files.has(path) and _matches_any(path, options.file_filters):
				files.append(path)
	var share: PackedStringArray = PackedStringArray()
	for i: int in files.size():
		if i % options.shards == options.shard - 1:
			share.append(files[i])
	files = share

	if options.warnings_as_errors:
		await _promote_warnings_to_errors()

	_capture = ErrorCapture.new()
	OS.add_logger(_capture)
	for path: String in files:
		await _run_file(path, options)
	OS.remove_logger(_capture)

	if not options.junit_path.is_empty():
		var junit_path: String = _resolve_output_path(options.junit_path)
		var error: Error = JUnit.write(junit_path, _results)
		if error != OK:
			print(
				"FAIL runner::<junit> — could not write %s: %s" % [junit_path, error_string(error)]
			)
			_failed += 1
		else:
			print("JUnit XML written to " + junit_path)
	if _passed + _failed == 0:
		print("no tests ran (%d test files found)" % files.size())
	_finish(0 if _failed == 0 and _passed + _failed > 0 else 1)


func _finish(exit_code: int) -> void:
	_finished = true
	_print_summary()
	get_tree().quit(exit_code)


func _print_summary() -> void:
	var left_out: String = " (%d slow suites left out)" % _left_out if _left_out > 0 else ""
	print("%d passed, %d failed, %d skipped%s" % [_passed, _failed, _skipped, left_out])


func _print_usage() -> void:
	print(Options.USAGE)


static func _matches_any(text: String, needles: PackedStringArray) -> bool:
	if needles.is_empty():
		return true
	for needle: String in needles:
		if text.contains(needle):
			return true
	return false


func _promote_warnings_to_errors() -> void:
	for property: Dictionary in ProjectSettings.get_property_list():
		var setting: String = property["name"]
		if not setting.begins_with("debug/gdscript/warnings/"):
			continue
		var level: Variant = ProjectSettings.get_setting(setting)
		if typeof(level) == TYPE_INT and level == 1:
			ProjectSettings.set_setting(setting, 2)
	# The GDScript parser re-reads warning levels when settings_changed fires (deferred).
	await get_tree().process_frame
	await get_tree().process_frame


func _resolve_output_path(path: String) -> String:
	if path.is_absolute_path():
		return path
	var cwd: String = OS.get_environment("PWD")
	if cwd.is_empty():
		cwd = ProjectSettings.globalize_path("res://")
	return cwd.path_join(path).simplify_path()


func _run_file(path: String, options: Options) -> void:
	var suite_name: String = path.get_file().get_basename()
	var loading: Result = Result.new(suite_name, "<load>", path)
	loading.absorb_errors(_capture.drain())
	var script: GDScript = (
		ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_REUSE) as GDScript
	)
	var suite: SuiteBase = null
	if options.quick and script != null and script.get_script_constant_map().get("SLOW", false):
		_left_out += 1
		_capture.drain()
		return
	if script == null or not script.can_instantiate():
		loading.add_failure("could not load or parse the script")
	elif not _extends_suite(script):
		loading.add_failure("does not extend TestSuite (res://tests/runner/test_suite.gd)")
	else:
		var instance: Object = script.new()
		suite = instance as SuiteBase
		if suite == null:
			loading.add_failure("could not instantiate the suite (does _init() take arguments?)")
		else:
			suite.name = suite_name
			if suite.timeout_seconds <= 0.0:
				suite.timeout_seconds = options.timeout_seconds
			add_child(suite)
	loading.absorb_errors(_capture.drain())
	if loading.is_failed():
		if suite != null:
			suite.queue_free()
			await get_tree().process_frame
			_capture.drain()
		loading.finish()
		_record(loading)
		return

	var tests: PackedStringArray = PackedStringArray()
	var argument_counts: Dictionary[String, int] = {}
	for method: Dictionary in script.get_script_method_list():
		var method_name: String = method["name"]
		var flags: int = method["flags"]
		if not method_name.begins_with("test_") or argument_counts.has(method_name):
			continue
		if flags & METHOD_FLAG_STATIC:
			continue
		var args: Array = method["args"]
		var defaults: Array = method["default_args"]
		argument_counts[method_name] = args.size() - defaults.size()
		if (
			_matches_any(method_name, options.test_filters)
			or _matches_any("%s::%s" % [suite_name, method_name], options.test_filters)
		):
			tests.append(method_name)

	if not tests.is_empty():
		await _run_suite(suite, path, tests, argument_counts)
	suite.queue_free()
	await get_tree().process_frame
	_capture.drain()


func _run_suite(
	suite: SuiteBase,
	path: String,
	tests: PackedStringArray,
	argument_counts: Dictionary[String, int]
) -> void:
	var setup: Result = Result.new(suite.name, "before_all", path)
	suite._runner_bind_result(setup)
	await _run_phase(suite, &"before_all", setup)
	setup.absorb_errors(_capture.drain())
	setup.finish()

	if setup.is_failed():
		_record(setup)
	else:
		for test_name: String in tests:
			if setup.is_skipped():
				var skipped: Result = Result.new(suite.name, test_name, path)
				skipped.skip(setup.skip_reason)
				_record(skipped)
			else:
				await _run_test(suite, path, test_name, argument_counts[test_name])

	var teardown: Result = Result.new(suite.name, "after_all", path)
	suite._runner_bind_result(teardown)
	await _run_phase(suite, &"after_all", teardown)
	suite._runner_free_autofree()
	await get_tree().process_frame
	teardown.absorb_errors(_capture.drain())
	teardown.finish()
	suite._runner_bind_result(null)
	if teardown.is_failed():
		_record(teardown)


func _run_test(suite: SuiteBase, path: String, test_name: String, required_arguments: int) -> void:
	var result: Result = Result.new(suite.name, test_name, path)
	if required_arguments > 0:
		result.add_failure("test methods must not take arguments")
		result.finish()
		_record(result)
		return
	result.absorb_errors(_capture.drain())
	suite._runner_bind_result(result)
	await _run_phase(suite, &"before_each", result)
	if not result.is_failed() and not result.skipped:
		await _run_phase(suite, StringName(test_name), result)
	await _run_phase(suite, &"after_each", result)
	suite._runner_free_autofree()
	# One frame so queued frees and deferred calls happen, and their errors count here.
	await get_tree().process_frame
	result.absorb_errors(_capture.drain())
	suite._runner_bind_result(null)
	result.finish()
	_record(result)


## Calls [param method] on [param suite] and waits for it, coroutine or not, until it
## returns or its deadline (which the test may move with set_timeout()) passes.
func _run_phase(suite: SuiteBase, method: StringName, result: Result) -> void:
	result.begin_phase(suite.timeout_seconds)
	var invocation: Invocation = Invocation.new()
	_invoke(suite, method, invocation)
	while not invocation.done:
		if Time.get_ticks_msec() >= result.deadline_msec:
			var limit: float = (result.deadline_msec - result.phase_started_msec) / 1000.0
			result.add_failure("timed out after %.1f s in %s()" % [limit, method])
			return
		await get_tree().process_frame


static func _invoke(target: Object, method: StringName, invocation: Invocation) -> void:
	await target.call(method)
	invocation.done = true


static func _extends_suite(script: Script) -> bool:
	var current: Script = script
	while current != null:
		if current == SuiteBase:
			return true
		current = current.get_base_script()
	return false


func _record(result: Result) -> void:
	_results.append(result)
	if result.is_failed():
		_failed += 1
		print("FAIL %s — %s" % [result.full_name(), result.failures[0]])
		for i: int in range(1, result.failures.size()):
			print("    " + result.failures[i])
	elif result.is_skipped():
		_skipped += 1
		print("SKIP %s — %s" % [result.full_name(), result.skip_reason])
	else:
		_passed += 1
		print("PASS " + result.full_name())
	for note: String in result.notes:
		print("    note: " + note)
