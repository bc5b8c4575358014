# gdlint: disable=max-public-methods
class_name TestSuite
extends Node
## Base class of every test suite run by [code]tests/runner/runner.tscn[/code].
##
## A suite is a file [code]tests/**/test_*.gd[/code] that extends [TestSuite] (or
## [code]"res://tests/runner/test_suite.gd"[/code], which works even before the editor has
## refreshed the global class cache). Each method named [code]test_*[/code] without required
## arguments is a test; tests run in file order. The suite is a [Node] inside the running
## scene tree, so tests may add children, use autoloads and [code]await[/code] frames.
## [br][br]
## Hooks, all optional and all allowed to [code]await[/code]: [method before_all],
## [method before_each], [method after_each], [method after_all].
## [br][br]
## Assertions never stop the test (GDScript has no exceptions); they record a failure with
## the caller's file:line and return [code]false[/code], so a test can bail out with
## [code]if not assert_not_null(x): return[/code].
## [br][br]
## Any engine or script error logged while a test runs (push_error, a failed engine check,
## a script runtime error) fails that test, unless the test declared it first with
## [method expect_error]. Warnings never fail a test. Each phase (hook or test) must finish
## within [member timeout_seconds]; [method set_timeout] changes it for the running test.
## [br][br]
## A suite that runs whole scenes for seconds or starts other processes declares
## [code]const SLOW := true[/code]: the runner's [code]--quick[/code] (make check) leaves it out.

## The record assertions write into ([code]tests/runner/result.gd[/code]).
const TestResult := preload("res://tests/runner/result.gd")

## Timeout in seconds for each hook and test of this suite; 0 uses the runner's
## [code]--timeout[/code] (30 s unless given). Set it in [code]_init()[/code] or
## [method before_all].
var timeout_seconds: float = 0.0

var _runner_result: TestResult = null
var _runner_autofree: Array[Object] = []


## Runs once before the first test of the suite.
func before_all() -> void:
	pass


func before_each() -> void:
	pass


## Runs after each test, also after a failed or timed-out one.
func after_each() -> void:
	pass


## Runs once after the last test of the suite.
func after_all() -> void:
	pass


## Passes if [param actual] equals [param expected]. Ints and floats compare by value;
## values of unrelated types are never equal (no engine error).
func assert_eq(actual: Variant, expected: Variant, message: String = "") -> bool:
	if _assert_equal(actual, expected):
		return true
	return _assert_fail(
		"expected %s, got %s" % [_assert_repr(expected), _assert_repr(actual)], message
	)


## Passes if [param actual] differs from [param unexpected].
func assert_ne(actual: Variant, unexpected: Variant, message: String = "") -> bool:
	if not _assert_equal(actual, unexpected):
		return true
	return _assert_fail("expected a value other than %s" % _assert_repr(unexpected), message)


## Passes if [param value] is the boolean [code]true[/code].
func assert_true(value: Variant, message: String = "") -> bool:
	if typeof(value) == TYPE_BOOL and value:
		return true
	return _assert_fail("expected true, got %s" % _assert_repr(value), message)


## Passes if [param value] is the boolean [code]false[/code].
func assert_false(value: Variant, message: String = "") -> bool:
	if typeof(value) == TYPE_BOOL and not value:
		return true
	return _assert_fail("expected false, got %s" % _assert_repr(value), message)


## Passes if [param value] is [code]null[/code] or a freed object.
func assert_null(value: Variant, message: String = "") -> bool:
	if _assert_is_null(value):
		return true
	return _assert_fail("expected null, got %s" % _assert_repr(value), message)


## Passes if [param value] is neither [code]null[/code] nor a freed object.
func assert_not_null(value: Variant, message: String = "") -> bool:
	if not _assert_is_null(value):
		return true
	return _assert_fail("expected a non-null value, got %s" % _assert_repr(value), message)


## Passes if [param actual] is within [param tolerance] of [param expected]: numbers, or
## vectors and colors compared component by component (Vector2/3/4 and their integer forms).
func assert_almost_eq(
	actual: Variant, expected: Variant, tolerance: float, message: String = ""
) -> bool:
	var a: PackedFloat64Array = _assert_components(actual)
	var e: PackedFloat64Array = _assert_components(expected)
	if a.is_empty() or a.size() != e.size():
		return _assert_fail(
			(
				"cannot compare %s with %s approximately"
				% [_assert_repr(actual), _assert_repr(expected)]
			),
			message
		)
	for i: int in a.size():
		if not absf(a[i] - e[i]) <= tolerance:
			return _assert_fail(
				(
					"expected %s within %s of %s"
					% [_assert_repr(actual), _assert_repr(tolerance), _assert_repr(expected)]
				),
				message
			)
	return true


## Passes if [param actual] > [param bound] (numbers, or two values of the same type).
func assert_gt(actual: Variant, bound: Variant, message: String = "") -> bool:
	if not _assert_comparable(actual, bound):
		return _assert_fail(
			"cannot compare %s with %s" % [_assert_repr(actual), _assert_repr(bound)], message
		)
	if actual > bound:
		return true
	return _assert_fail("expected %s > %s" % [_assert_repr(actual), _assert_repr(bound)], message)


## Passes if [param actual] < [param bound] (numbers, or two values of the same type).
func assert_lt(actual: Variant, bound: Variant, message: String = "") -> bool:
	if not _assert_comparable(actual, bound):
		return _assert_fail(
			"cannot compare %s with %s" % [_assert_repr(actual), _assert_repr(bound)], message
		)
	if actual < bound:
		return true
	return _assert_fail("expected %s < %s" % [_assert_repr(actual), _assert_repr(bound)], message)


## Passes if [param container] holds [param item]: an element of an Array or packed array,
## a key of a Dictionary, or a substring of a String.
func assert_has(container: Variant, item: Variant, message: String = "") -> bool:
	var found: bool = false
	match typeof(container):
		TYPE_STRING, TYPE_STRING_NAME:
			if typeof(item) in [TYPE_STRING, TYPE_STRING_NAME]:
				found = str(item).is_empty() or str(container).contains(str(item))
		TYPE_DICTIONARY:
			var dictionary: Dictionary = container
			found = dictionary.has(item)
		TYPE_ARRAY:
			var array: Array = container
			found = array.any(func(element: Variant) -> bool: return _assert_equal(element, item))
		_:
			if typeof(container) >= TYPE_PACKED_BYTE_ARRAY and typeof(container) < TYPE_MAX:
				for element: Variant in container:
					if _assert_equal(element, item):
						found = true
						break
			else:
				return _assert_fail("%s is not a container" % _assert_repr(container), message)
	if found:
		return true
	return _assert_fail(
		"expected %s to contain %s" % [_assert_repr(container), _assert_repr(item)], message
	)


## Fails the running test with [param message].
func fail(message: String) -> void:
	_assert_fail(message, "")


## Marks the running test skipped (counted apart, does not fail the run). Return right
## after calling it; a skipped test that also fails counts as failed.
func skip(reason: String) -> void:
	if _runner_result != null:
		_runner_result.skip(reason)


## Declares that the running test (or hook) logs an engine error containing
## [param substring]; the error then does not fail the test, and the test fails if no such
## error is logged before it ends. Call it before the code that logs the error. Matching is
## case-sensitive against the message, as printed after "ERROR:" / "SCRIPT ERROR:".
func expect_error(substring: String) -> void:
	if _runner_result == null:
		print("    note: expect_error() called outside a test")
		return
	_runner_result.expect_error(substring)


## Sets the timeout of the running test (or hook) to [param seconds] from its start.
func set_timeout(seconds: float) -> void:
	if _runner_result != null:
		_runner_result.set_phase_timeout(seconds)


## Adds [param node] as a child of the suite and frees it after the running test.
func add_child_autofree(node: Node) -> Node:
	add_child(node)
	_runner_autofree.append(node)
	return node


## Frees [param object] after the running test (nodes with queue_free(); RefCounted objects
## are only released).
func autofree(object: Object) -> Object:
	_runner_autofree.append(object)
	return object


## Waits for [param count] physics frames (each one physics tick, 1/50 s of game time here).
func wait_physics_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame


## Waits for [param count] process (idle) frames.
func wait_process_frames(count: int) -> void:
	for i: int in count:
		await get_tree().process_frame


## Waits [param seconds] of game time (a SceneTree timer; runs while the tree is paused).
func wait_seconds(seconds: float) -> void:
	await get_tree().create_timer(seconds).timeout


## Asserts that each script in [param paths] compiles with every GDScript warning the
## project enables raised to an error. Fresh copies are compiled, standing in at each
## script's path only while they compile, so the live scripts are never recompiled in place.
## Returns how many warnings the project enables (0 would make the check vacuous).
func assert_scripts_compile_without_warnings(paths: PackedStringArray) -> int:
	var raised: Dictionary[String, int] = {}
	var enabled: int = 0
	for property: Dictionary in ProjectSettings.get_property_list():
		var setting: String = property["name"]
		var level: Variant = ProjectSettings.get_setting(setting)
		if setting.begins_with("debug/gdscript/warnings/") and typeof(level) == TYPE_INT:
			enabled += 1 if level != 0 else 0
			if level == 1:
				raised[setting] = 1
				ProjectSettings.set_setting(setting, 2)
	# The raised levels apply from the next frame on.
	await wait_process_frames(1)
	for path: String in paths:
		# The copy stands in at the script's path while it compiles, so that its own class
		# name and `self` are the script's; the cached script is put back at once.
		var original: Resource = ResourceLoader.load(path)
		var copy: GDScript = GDScript.new()
		copy.source_code = FileAccess.get_file_as_string(path)
		copy.take_over_path(path)
		var compiled: Error = copy.reload()
		original.take_over_path(path)
		assert_eq(compiled, OK, "%s compiles with warnings as errors" % path)
	for setting: String in raised:
		ProjectSettings.set_setting(setting, raised[setting])
	await wait_process_frames(1)
	return enabled


## Waits until [param condition] (a Callable returning bool) holds, checking once per
## physics frame, for at most [param max_seconds]. Returns whether it held.
func wait_until(condition: Callable, max_seconds: float) -> bool:
	var deadline: int = Time.get_ticks_msec() + int(max_seconds * 1000.0)
	while true:
		if condition.call():
			return true
		if Time.get_ticks_msec() >= deadline:
			return false
		await get_tree().physics_frame
	return false


## Called by the runner: assertions now record into [param result] (null between tests).
func _runner_bind_result(result: TestResult) -> void:
	_runner_result = result


## Called by the runner after each test: frees what was registered for freeing.
func _runner_free_autofree() -> void:
	for object: Object in _runner_autofree:
		if not is_instance_valid(object) or object is RefCounted:
			continue
		if object is Node:
			(object as Node).queue_free()
		else:
			object.free()
	_runner_autofree.clear()


func _assert_fail(reason: String, message: String) -> bool:
	var text: String = reason if message.is_empty() else "%s: %s" % [message, reason]
	var location: String = _assert_location()
	if not location.is_empty():
		text = "%s: %s" % [location, text]
	if _runner_result != null:
		_runner_result.add_failure(text)
	else:
		print("    assertion failed outside a test: " + text)
	return false


## "file:line" of the innermost frame outside this file: the assertion's caller.
func _assert_location() -> String:
	var stack: Array = get_stack()
	if stack.is_empty():
		return ""
	var own_source: String = stack[0]["source"]
	for frame: Dictionary in stack:
		var source: String = frame["source"]
		if source != own_source:
			var line: int = frame["line"]
			return "%s:%d" % [source, line]
	return ""


static func _assert_is_null(value: Variant) -> bool:
	if value == null:
		return true
	return typeof(value) == TYPE_OBJECT and not is_instance_valid(value)


static func _assert_is_number(value: Variant) -> bool:
	return typeof(value) == TYPE_INT or typeof(value) == TYPE_FLOAT


static func _assert_is_text(value: Variant) -> bool:
	return typeof(value) == TYPE_STRING or typeof(value) == TYPE_STRING_NAME


static func _assert_equal(a: Variant, b: Variant) -> bool:
	if typeof(a) == typeof(b):
		return a == b
	if _assert_is_number(a) and _assert_is_number(b):
		return a == b
	if _assert_is_text(a) and _assert_is_text(b):
		return str(a) == str(b)
	if typeof(a) == TYPE_NIL or typeof(b) == TYPE_NIL:
		return _assert_is_null(a) and _assert_is_null(b)
	return false


static func _assert_comparable(a: Variant, b: Variant) -> bool:
	if _assert_is_number(a) and _assert_is_number(b):
		return true
	if _assert_is_text(a) and _assert_is_text(b):
		return true
	return typeof(a) == typeof(b) and typeof(a) != TYPE_NIL and typeof(a) != TYPE_OBJECT


static func _assert_components(value: Variant) -> PackedFloat64Array:
	match typeof(value):
		TYPE_INT, TYPE_FLOAT:
			var number: float = value
			return PackedFloat64Array([number])
		TYPE_VECTOR2, TYPE_VECTOR2I:
			var v2: Vector2 = value
			return PackedFloat64Array([v2.x, v2.y])
		TYPE_VECTOR3, TYPE_VECTOR3I:
			var v3: Vector3 = value
			return PackedFloat64Array([v3.x, v3.y, v3.z])
		TYPE_VECTOR4, TYPE_VECTOR4I:
			var v4: Vector4 = value
			return PackedFloat64Array([v4.x, v4.y, v4.z, v4.w])
		TYPE_COLOR:
			var color: Color = value
			return PackedFloat64Array([color.r, color.g, color.b, color.a])
	return PackedFloat64Array()


static func _assert_repr(value: Variant) -> String:
	var text: String
	match typeof(value):
		TYPE_NIL:
			text = "null"
		TYPE_STRING:
			text = '"%s"' % str(value).c_escape()
		TYPE_STRING_NAME:
			text = '&"%s"' % str(value).c_escape()
		TYPE_OBJECT:
			text = str(value) if is_instance_valid(value) else "<freed object>"
		_:
			text = str(value)
	if text.length() > 300:
		text = text.left(297) + "..."
	return text
