extends TestSuite
## The Haptics autoload, the one door from GDScript to the native library: its settings are
## the servo's (force scale and smoothing live in the servo's configuration), refused values
## leave them as they were, renderers come through by name and values as typed classes.

var _force_scale: float = 1.0
var _smoothing: bool = true
var _control_mode: StringName = &""
var _render_mode: StringName = &""


func before_each() -> void:
	_force_scale = Haptics.force_scale
	_smoothing = Haptics.smoothing_enabled
	_control_mode = Haptics.control_mode
	_render_mode = Haptics.get_render_mode()


func after_each() -> void:
	Haptics.force_scale = _force_scale
	Haptics.smoothing_enabled = _smoothing
	Haptics.control_mode = _control_mode
	Haptics.set_render_mode(_render_mode)


func test_the_force_scale_lives_in_the_servo_and_smoothing_in_the_renderer() -> void:
	Haptics.force_scale = 0.35
	assert_almost_eq(Haptics.servo.get_settings().safety.force_scale, 0.35, 1e-9)
	assert_almost_eq(Haptics.force_scale, 0.35, 1e-9)
	Haptics.smoothing_enabled = false
	assert_false(HapticsMovement.of(Haptics).get_settings().smoothing.enabled, "the renderer's")


func test_out_of_range_is_clamped_and_nan_refused() -> void:
	Haptics.force_scale = 0.5
	Haptics.force_scale = 7.5
	assert_eq(Haptics.force_scale, Haptics.get_force_scale_range().y)
	assert_eq(Haptics.get_force_scale_range(), Vector2(0.0, 2.0), "the servo's own range")
	Haptics.force_scale = 0.5
	expect_error("not a number")
	Haptics.force_scale = NAN
	assert_eq(Haptics.force_scale, 0.5, "the old value stays")
	expect_error("unknown mode 'telepathy'")
	Haptics.control_mode = &"telepathy"
	assert_true(Haptics.is_control_mode(Haptics.control_mode))


func test_reset_settings_gives_the_servos_defaults() -> void:
	Haptics.force_scale = 0.2
	Haptics.smoothing_enabled = false
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	Haptics.reset_settings()
	assert_eq(Haptics.force_scale, 1.0)
	assert_true(Haptics.smoothing_enabled)
	assert_eq(Haptics.control_mode, Haptics.CONTROL_DEVICE)


func test_renderers_by_name_and_values_as_typed_classes() -> void:
	assert_true(Haptics.set_render_mode(&"constraint"))
	assert_eq(Haptics.get_render_mode(), &"constraint")
	expect_error("unknown renderer 'joystick'")
	assert_false(Haptics.set_render_mode(&"joystick"))
	assert_eq(Haptics.get_render_mode(), &"constraint")
	assert_true(Haptics.set_render_mode(&"movement"))
	assert_eq(Haptics.get_render_mode(), &"movement")
	assert_eq(Haptics.device.get_simulated_id(), "simulated")
	assert_eq(Haptics.device.get_id(), Haptics.device.get_simulated_id())
	var forces: HapticForces = Haptics.get_forces()
	assert_eq(forces.parts.size(), HapticForceLimits.MAX_FORCE_PARTS, "every part, in order")
	var capabilities: HapticDeviceCapabilities = Haptics.device.get_capabilities()
	assert_gt(capabilities.limits.max_force_n, 0.0)
	assert_eq(Haptics.device.get_max_force(), capabilities.limits.max_force_n)
	assert_eq(Haptics.device.get_status().io, HapticDeviceKinds.DeviceIo.OK)
	var stats: HapticServoStats = Haptics.servo.get_stats()
	assert_true(stats.running, "the autoload's servo thread")
	assert_eq(stats.nominal_rate_hz, HapticServoConstants.DEFAULT_RATE_HZ)
