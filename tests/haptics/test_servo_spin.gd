extends TestSuite
## The servo's busy-wait before each deadline, set where a game developer works: the second
## argument of Haptics.servo.start (on a door of the test's own here), and the project setting
## haptics/servo/spin_us the Haptics autoload reads. Refused spins name the field and its
## range and leave the servo as it was. The stats give it in seconds: [method _spin_us] reads
## it in microseconds.

const Haptics := preload("res://addons/haptics/door/haptics.gd")
const SETTING := "haptics/servo/spin_us"
const REFUSED_AT_1000_HZ := "spin_us must be in [0, 500] (half a period at 1000 Hz)"

var door: HapticsTestKit.Door = null
var servo: HapticsServo = null
var _setting_before: Variant = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	servo = door.servo
	_setting_before = ProjectSettings.get_setting(SETTING, null)


func after_each() -> void:
	# null erases the setting when the project had none.
	ProjectSettings.set_setting(SETTING, _setting_before)


func test_the_spin_given_to_start_is_the_one_in_use() -> void:
	assert_true(servo.start(1000.0, 0.0))
	assert_eq(servo.get_stats().spin_s, 0.0, "0: sleep to the deadline")
	servo.stop()
	assert_true(servo.start(1000.0, 100.0))
	assert_true(servo.is_running())
	assert_almost_eq(_spin_us(servo), 100.0, 1e-9, "100 us = 1e-4 s")
	servo.stop()
	assert_true(servo.start())
	var stats: HapticServoStats = servo.get_stats()
	assert_almost_eq(
		stats.spin_s * 1e6,
		_servo_default_us(stats),
		1e-9,
		"none given: the servo's own, by what the thread was granted"
	)
	assert_eq(
		HapticServoConstants.DEFAULT_SPIN_NS, 50000, "the measured default (README, Servo timing)"
	)


func test_the_longest_spin_is_half_a_period_at_the_rate_asked() -> void:
	assert_true(servo.start(HapticServoConstants.MIN_RATE_HZ, 2000.0), "250 Hz: up to 2000 us")
	servo.stop()
	expect_error("spin_us must be in [0, 125] (half a period at 4000 Hz)")
	assert_false(servo.start(HapticServoConstants.MAX_RATE_HZ, 126.0))
	assert_false(servo.is_running())


func test_a_spin_over_half_a_period_is_refused_and_changes_nothing() -> void:
	assert_true(servo.start(1000.0, 100.0))
	servo.stop()
	expect_error(REFUSED_AT_1000_HZ + ", or -1 for the servo's default (got 600)")
	assert_false(servo.start(1000.0, 600.0))
	assert_false(servo.is_running(), "the servo did not start")
	assert_almost_eq(_spin_us(servo), 100.0, 1e-9, "the last run's spin stands")


func test_nan_and_other_negatives_are_refused() -> void:
	expect_error(REFUSED_AT_1000_HZ + ", or -1 for the servo's default (got nan)")
	assert_false(servo.start(1000.0, NAN))
	assert_false(servo.is_running())
	expect_error("(got -5)")
	assert_false(servo.start(1000.0, -5.0))
	expect_error("(got inf)")
	assert_false(servo.start(1000.0, INF))
	assert_false(servo.is_running())


func test_a_bad_rate_is_reported_as_the_rate_not_the_spin() -> void:
	expect_error("rate")
	assert_false(servo.start(10.0, 50.0))
	assert_false(servo.is_running())


func test_the_door_passes_the_spin_on_and_keeps_its_default_across_restarts() -> void:
	assert_true(servo.start(0.0, 100.0))
	assert_almost_eq(_spin_us(servo), 100.0, 1e-9)
	assert_eq(servo.get_stats().nominal_rate_hz, HapticServoConstants.DEFAULT_RATE_HZ, "rate 0")
	servo.stop()
	servo.default_spin_us = 0.0
	assert_true(servo.start())
	assert_eq(servo.get_stats().spin_s, 0.0, "start() without a spin: the door's default")
	servo.stop()
	expect_error(REFUSED_AT_1000_HZ)
	assert_false(servo.start(0.0, NAN))
	assert_false(servo.is_running())


func test_the_autoload_starts_the_servo_with_the_projects_setting() -> void:
	ProjectSettings.set_setting(SETTING, 0.0)
	var haptics: Haptics = add_child_autofree(Haptics.new())
	assert_true(haptics.servo.is_running())
	assert_eq(haptics.servo.get_stats().spin_s, 0.0, "the project's spin")
	haptics.servo.stop()
	assert_true(haptics.servo.start(), "a restart (a device reopened, a match ended)")
	assert_eq(haptics.servo.get_stats().spin_s, 0.0, "keeps it")
	haptics.servo.stop()
	ProjectSettings.set_setting(SETTING, 100)
	var with_int: Haptics = add_child_autofree(Haptics.new())
	assert_almost_eq(_spin_us(with_int.servo), 100.0, 1e-9, "an integer is read")
	with_int.servo.stop()


func test_without_the_setting_the_autoload_uses_the_servos_default() -> void:
	ProjectSettings.set_setting(SETTING, null)
	var haptics: Haptics = add_child_autofree(Haptics.new())
	assert_true(haptics.servo.is_running())
	var stats: HapticServoStats = haptics.servo.get_stats()
	assert_almost_eq(stats.spin_s * 1e6, _servo_default_us(stats), 1e-9)
	haptics.servo.stop()


func test_a_refused_setting_is_named_and_the_servo_runs_with_its_default() -> void:
	ProjectSettings.set_setting(SETTING, 900.0)
	expect_error(REFUSED_AT_1000_HZ)
	expect_error("project setting haptics/servo/spin_us = 900.0 refused")
	var haptics: Haptics = add_child_autofree(Haptics.new())
	assert_true(haptics.servo.is_running(), "force feedback goes on")
	var stats: HapticServoStats = haptics.servo.get_stats()
	assert_almost_eq(stats.spin_s * 1e6, _servo_default_us(stats), 1e-9)
	haptics.servo.stop()
	ProjectSettings.set_setting(SETTING, "fast")
	expect_error('project setting haptics/servo/spin_us = "fast" is not a number')
	var with_text: Haptics = add_child_autofree(Haptics.new())
	var text_stats: HapticServoStats = with_text.servo.get_stats()
	assert_almost_eq(text_stats.spin_s * 1e6, _servo_default_us(text_stats), 1e-9)
	with_text.servo.stop()


func test_the_setting_is_listed_with_the_servos_default_and_range() -> void:
	ProjectSettings.set_setting(SETTING, null)
	Haptics.add_project_settings()
	var default_us: float = HapticsServo.SPIN_US_DEFAULT
	assert_eq(ProjectSettings.get_setting(SETTING), default_us, "-1: the servo's own")
	assert_eq(ProjectSettings.property_get_revert(SETTING), default_us, "reverts to it")
	var listed: Dictionary = {}
	for property: Dictionary in ProjectSettings.get_property_list():
		if property["name"] == SETTING:
			listed = property
	assert_eq(listed.get("type"), TYPE_FLOAT)
	assert_eq(listed.get("hint"), PROPERTY_HINT_RANGE)
	var hint: String = listed.get("hint_string", "")
	assert_eq(hint.get_slice(",", 0), "-1", "from the servo's own")
	assert_eq(hint.get_slice(",", 1), "2000", "to half of 1/250 s")
	ProjectSettings.set_setting(SETTING, 20.0)
	Haptics.add_project_settings()
	assert_eq(ProjectSettings.get_setting(SETTING), 20.0, "a project's own value is kept")


# The spin [param of] runs with, in microseconds.
func _spin_us(of: HapticsServo) -> float:
	return of.get_stats().spin_s * 1e6


# The spin the servo chooses itself for a thread granted what [param stats] says, in
# microseconds.
func _servo_default_us(stats: HapticServoStats) -> float:
	if not stats.realtime:
		return 0.0
	if stats.cpu_latency_held:
		return HapticServoConstants.DEFAULT_SPIN_NS / 1e3
	return HapticServoConstants.UNHELD_SPIN_NS / 1e3
