extends RefCounted
## The outcome of one test, or of one suite-level phase such as loading or before_all.
##
## Assertions and the runner add failures here; engine errors captured while the test ran
## are matched against the errors the test declared with [code]expect_error()[/code].

const ErrorCapture := preload("res://tests/runner/error_capture.gd")

## Name of the suite (the script's file name without extension).
var suite_name: String = ""
## Name of the test method, or a phase name such as [code]<load>[/code].
var test_name: String = ""
var script_path: String = ""
## Failure messages, in the order they happened.
var failures: PackedStringArray = PackedStringArray()
## Notes printed under the result line without failing it.
var notes: PackedStringArray = PackedStringArray()
## True once [method skip] was called.
var skipped: bool = false
var skip_reason: String = ""
## Wall-clock duration in seconds, set by [method finish].
var duration_seconds: float = 0.0
## Time.get_ticks_msec() after which the running phase counts as hung.
var deadline_msec: int = 0
## Time.get_ticks_msec() when the running phase started.
var phase_started_msec: int = 0

var _started_msec: int = 0
var _expected: PackedStringArray = PackedStringArray()
var _expected_seen: Array[bool] = []


func _init(p_suite_name: String, p_test_name: String, p_script_path: String) -> void:
	suite_name = p_suite_name
	test_name = p_test_name
	script_path = p_script_path
	_started_msec = Time.get_ticks_msec()


## "suite::test", as printed on the result line.
func full_name() -> String:
	return "%s::%s" % [suite_name, test_name]


func is_failed() -> bool:
	return not failures.is_empty()


## True if the test was skipped and nothing failed.
func is_skipped() -> bool:
	return skipped and failures.is_empty()


func add_failure(message: String) -> void:
	failures.append(message)


func skip(reason: String) -> void:
	skipped = true
	skip_reason = reason


## Declares that an error whose text contains [param needle] is expected.
func expect_error(needle: String) -> void:
	_expected.append(needle)
	_expected_seen.append(false)


## Starts a phase that may run for [param timeout_seconds] before it counts as hung.
func begin_phase(timeout_seconds: float) -> void:
	phase_started_msec = Time.get_ticks_msec()
	set_phase_timeout(timeout_seconds)


## Moves the running phase's deadline to [param timeout_seconds] after the phase began.
func set_phase_timeout(timeout_seconds: float) -> void:
	deadline_msec = phase_started_msec + int(ceilf(timeout_seconds * 1000.0))


## Matches captured engine errors against the expected ones; unexpected errors fail.
func absorb_errors(entries: Array[ErrorCapture.Entry]) -> void:
	for entry: ErrorCapture.Entry in entries:
		var expected: bool = false
		for i: int in _expected.size():
			if entry.matches(_expected[i]):
				_expected_seen[i] = true
				expected = true
		if not expected and not entry.is_warning():
			add_failure("unexpected engine error: " + entry.describe())


## Closes the result: expected errors that never appeared fail it; records the duration.
func finish() -> void:
	for i: int in _expected.size():
		if not _expected_seen[i]:
			add_failure('expected an error containing "%s", but none was logged' % _expected[i])
	duration_seconds = (Time.get_ticks_msec() - _started_msec) / 1000.0
