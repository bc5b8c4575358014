extends TestSuite
## The servo's configuration through the field table, on a door of the test's own: every
## field described once, keys with their units, values that read back, setting names from
## before 0.3.0 still accepted with a deprecation warning, and the typed limits and enums.

const UNIT_SUFFIXES: Dictionary[String, String] = {
	"s": "_s", "Hz": "_hz", "m": "_m", "N": "_n", "N/s": "_n_per_s", "N/m": "_n_per_m"
}


## Collects the warnings logged while it is installed.
class WarningLog:
	extends Logger

	var lines: PackedStringArray = PackedStringArray()
	var _mutex: Mutex = Mutex.new()

	func _log_error(
		_function: String,
		_file: String,
		_line: int,
		code: String,
		rationale: String,
		_editor_notify: bool,
		error_type: int,
		_script_backtraces: Array[ScriptBacktrace]
	) -> void:
		if error_type == ERROR_TYPE_WARNING:
			_mutex.lock()
			lines.append(rationale if not rationale.is_empty() else code)
			_mutex.unlock()

	func text() -> String:
		_mutex.lock()
		var joined: String = "\n".join(lines)
		_mutex.unlock()
		return joined


var door: TestHaptics.Door = null
var warnings: WarningLog = null


func before_each() -> void:
	door = autofree(TestHaptics.manual())
	warnings = WarningLog.new()
	OS.add_logger(warnings)


func after_each() -> void:
	OS.remove_logger(warnings)


func test_every_field_is_in_the_config_with_its_default_and_unit() -> void:
	var config: Dictionary = door.get_config()
	var fields: Array = TestHaptics.config_fields()
	assert_gt(fields.size(), 20)
	var seen: Dictionary[String, bool] = {}
	for field: Dictionary in fields:
		var section: String = field["section"]
		var key: String = field["key"]
		assert_false(seen.has(section + "." + key), "%s.%s once" % [section, key])
		seen[section + "." + key] = true
		assert_has(config, section)
		assert_has(config[section], key)
		assert_eq(config[section][key], field["default"], "%s.%s default" % [section, key])
		if UNIT_SUFFIXES.has(field["unit"]):
			assert_true(key.ends_with(UNIT_SUFFIXES[field["unit"]]), "%s carries its unit" % key)
	var sections: Array[String] = []
	for section: String in config:
		sections.append(section)
		for key: String in config[section]:
			assert_true(seen.has(section + "." + key), "%s.%s is in the table" % [section, key])
	sections.sort()
	assert_eq(
		sections,
		["constraint", "force_model", "plane_hold", "pong", "safety", "smoothing", "telemetry"]
	)


func test_values_read_back_in_their_own_types() -> void:
	assert_true(door.configure("safety", {"slew_rate_n_per_s": 150.0, "force_scale": 0.5}))
	assert_true(door.configure("telemetry", {"decimation": 4, "enabled": false}))
	assert_true(door.configure("constraint", {"update": "frame", "max_iterations": 3.0}))
	var config: Dictionary = door.get_config()
	assert_eq(config["safety"]["slew_rate_n_per_s"], 150.0)
	assert_eq(config["safety"]["force_scale"], 0.5)
	assert_eq(typeof(config["telemetry"]["decimation"]), TYPE_INT)
	assert_eq(config["telemetry"]["decimation"], 4)
	assert_false(config["telemetry"]["enabled"])
	assert_eq(typeof(config["constraint"]["update"]), TYPE_INT, "a choice reads as its index")
	assert_eq(door.get_choice("constraint", "update"), "frame")
	assert_eq(config["constraint"]["max_iterations"], 3)


func test_wrong_kinds_are_refused_by_name() -> void:
	expect_error("telemetry.decimation must be a whole number")
	assert_false(door.configure("telemetry", {"decimation": 2.5}))
	expect_error("smoothing.enabled: expected a bool")
	assert_false(door.configure("smoothing", {"enabled": 1}))
	expect_error("constraint.update: unknown value 7")
	assert_false(door.configure("constraint", {"update": 7}))
	expect_error("safety.slew_rate_n_per_s must be 0 (no slew limit) or in [1, 1e+06]")
	assert_false(door.configure("safety", {"slew_rate_n_per_s": 0.5}))
	assert_eq(door.get_config()["safety"]["slew_rate_n_per_s"], 200.0, "unchanged")


func test_old_key_names_still_work_and_say_what_replaces_them() -> void:
	assert_true(door.configure("safety", {"slew_rate": 120.0, "startup_ramp": 0.0}))
	assert_eq(door.get_config()["safety"]["slew_rate_n_per_s"], 120.0)
	assert_eq(door.get_config()["safety"]["startup_ramp_s"], 0.0)
	assert_has(warnings.text(), "safety.slew_rate is deprecated: use safety.slew_rate_n_per_s")
	assert_has(warnings.text(), "0.4.0")


func test_a_frame_holds_max_contacts_and_not_one_more() -> void:
	var contacts: Array[HapticContact] = []
	for i: int in HapticFrameLimits.MAX_CONTACTS:
		contacts.append(TestHaptics.contact(Vector2.UP))
	assert_true(door.submit_frame(TestHaptics.frame_of(contacts)))
	contacts.append(TestHaptics.contact(Vector2.UP))
	expect_error(
		(
			"submit_frame: HapticFrame.contacts: %d items, at most %d"
			% [HapticFrameLimits.MAX_CONTACTS + 1, HapticFrameLimits.MAX_CONTACTS]
		)
	)
	assert_false(door.submit_frame(TestHaptics.frame_of(contacts)))
	var crowded: HapticFrame = HapticFrame.new()
	for i: int in HapticFrameLimits.MAX_RESTING_OBJECTS + 1:
		crowded.resting.append(TestHaptics.load(Vector2.DOWN, 1.0))
	expect_error("at most %d" % HapticFrameLimits.MAX_RESTING_OBJECTS)
	assert_false(door.submit_frame(crowded))
	assert_null(HapticFrame.decode(crowded.encode()), "the scripts' own reader refuses it too")
	assert_has(HapticsWireReader.last_error, "HapticFrame.resting")


func test_enums_and_rates_are_the_servos_own() -> void:
	assert_true(door.servo.start(HapticServoConstants.MAX_RATE_HZ))
	assert_eq(door.servo.get_stats().nominal_rate_hz, HapticServoConstants.MAX_RATE_HZ)
	door.servo.stop()
	var rates: Array[float] = [HapticServoConstants.MIN_RATE_HZ, HapticServoConstants.MAX_RATE_HZ]
	expect_error("rate_hz must be in [%d, %d]" % rates)
	assert_false(door.servo.start(HapticServoConstants.MIN_RATE_HZ - 1))
	assert_eq(door.get_render_mode(), &"movement")
	var mapping: HapticMazeMapping = HapticMazeMapping.new()
	mapping.maze_max = Vector2(100, 100)
	mapping.workspace_shape = HapticConstraint.WorkspaceShape.SQUARE
	assert_true(HapticsConstraint.of(door).set_walls(PackedVector2Array(), mapping))
	assert_eq(HapticConstraint.TELEMETRY_FLAG_PROXY_CONTACT, 1 << 8)
