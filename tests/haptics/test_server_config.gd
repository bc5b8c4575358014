extends TestSuite
## The native server's configuration through the field table: every field described once,
## keys with their units, values that read back, names from before 0.3.0 still accepted
## with a deprecation warning, and the typed limits and enums.

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


var server: HapticsServer = null
var warnings: WarningLog = null


func before_each() -> void:
	server = HapticsServer.new()
	assert_true(server.open_device(server.get_simulated_device_id()))
	warnings = WarningLog.new()
	OS.add_logger(warnings)


func after_each() -> void:
	OS.remove_logger(warnings)
	server.close_device()


func test_every_field_is_in_the_config_with_its_default_and_unit() -> void:
	var config: Dictionary = server.get_config()
	var fields: Array = server.get_config_fields()
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
	assert_true(server.set_config("safety", {"slew_rate_n_per_s": 150.0, "force_scale": 0.5}))
	assert_true(server.set_config("telemetry", {"decimation": 4, "enabled": false}))
	assert_true(server.set_config("constraint", {"update": "frame", "max_iterations": 3.0}))
	var config: Dictionary = server.get_config()
	assert_eq(config["safety"]["slew_rate_n_per_s"], 150.0)
	assert_eq(config["safety"]["force_scale"], 0.5)
	assert_eq(typeof(config["telemetry"]["decimation"]), TYPE_INT)
	assert_eq(config["telemetry"]["decimation"], 4)
	assert_false(config["telemetry"]["enabled"])
	assert_eq(config["constraint"]["update"], HapticsServer.PROXY_UPDATE_FRAME_RATE)
	assert_eq(config["constraint"]["max_iterations"], 3)


func test_wrong_kinds_are_refused_by_name() -> void:
	expect_error("telemetry.decimation must be a whole number")
	assert_false(server.set_config("telemetry", {"decimation": 2.5}))
	expect_error("smoothing.enabled: expected a bool")
	assert_false(server.set_config("smoothing", {"enabled": 1}))
	expect_error("constraint.update: unknown value 7")
	assert_false(server.set_config("constraint", {"update": 7}))
	expect_error("safety.slew_rate_n_per_s must be 0 (no slew limit) or in [1, 1e+06]")
	assert_false(server.set_config("safety", {"slew_rate_n_per_s": 0.5}))
	assert_eq(server.get_config()["safety"]["slew_rate_n_per_s"], 200.0, "unchanged")


func test_old_key_names_still_work_and_say_what_replaces_them() -> void:
	assert_true(server.set_config("safety", {"slew_rate": 120.0, "startup_ramp": 0.0}))
	assert_eq(server.get_config()["safety"]["slew_rate_n_per_s"], 120.0)
	assert_eq(server.get_config()["safety"]["startup_ramp_s"], 0.0)
	assert_has(warnings.text(), "safety.slew_rate is deprecated: use safety.slew_rate_n_per_s")
	assert_has(warnings.text(), "0.4.0")


func test_old_frame_keys_render_the_same_force_as_the_new_ones() -> void:
	assert_true(server.set_config("safety", {"startup_ramp_s": 0.0, "slew_rate_n_per_s": 0.0}))
	assert_true(server.set_config("smoothing", {"enabled": false}))
	assert_true(server.set_hand_target(Vector2(0.05, 0.03)))
	var forces: Array[Vector2] = []
	for contact: Dictionary in [
		{"normal": Vector2.UP, "stiffness_n": 3.0, "friction_n": 0.5},
		{"normal": Vector2.UP, "stiffness": 3.0, "damping": 0.5},
	]:
		for tick: int in 300:
			assert_true(server.submit_frame({"contacts": [contact], "time": 0.0}))
			assert_true(server.step(0.001))
		forces.append(server.get_forces()["total"])
	assert_almost_eq(forces[1], forces[0], 1e-5)
	assert_gt(forces[0].length(), 0.5, "a real force, not two zeros")
	assert_has(
		warnings.text(), "frame.contacts.damping is deprecated: use frame.contacts.friction_n"
	)


func test_a_frame_holds_max_contacts_and_not_one_more() -> void:
	var contacts: Array[Dictionary] = []
	for i: int in HapticsServer.MAX_CONTACTS:
		contacts.append({"normal": Vector2.UP})
	assert_true(server.submit_frame({"contacts": contacts}))
	contacts.append({"normal": Vector2.UP})
	expect_error("at most %d" % HapticsServer.MAX_CONTACTS)
	assert_false(server.submit_frame({"contacts": contacts}))
	var resting: Array[Dictionary] = []
	for i: int in HapticsServer.MAX_RESTING_OBJECTS + 1:
		resting.append({"normal": Vector2.DOWN, "mass_kg": 1.0})
	expect_error("at most %d" % HapticsServer.MAX_RESTING_OBJECTS)
	assert_false(server.submit_frame({"resting": resting}))


func test_enums_and_rates_are_the_servos_own() -> void:
	assert_true(server.start(HapticsServer.MAX_RATE_HZ))
	assert_eq(server.get_stats()["nominal_rate_hz"], float(HapticsServer.MAX_RATE_HZ))
	server.stop()
	var rates: Array[int] = [HapticsServer.MIN_RATE_HZ, HapticsServer.MAX_RATE_HZ]
	expect_error("rate_hz must be in [%d, %d]" % rates)
	assert_false(server.start(HapticsServer.MIN_RATE_HZ - 1))
	assert_eq(server.get_render_mode(), HapticsServer.RENDER_MODE_MOVEMENT)
	var mapping: Dictionary = {
		"maze_min": Vector2.ZERO,
		"maze_max": Vector2(100, 100),
		"workspace": HapticsServer.WORKSPACE_SQUARE,
	}
	assert_true(server.set_constraint_geometry(PackedVector2Array(), mapping))
	assert_eq(HapticsServer.TELEMETRY_FLAG_PROXY_CONTACT, 1 << 8)
