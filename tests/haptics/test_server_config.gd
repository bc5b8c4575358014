extends TestSuite
## The servo's and the renderers' settings through the door, on a door of the test's own: the
## native defaults are the schema's, values read back in their own types, refused ones are
## named by field and change nothing, and the typed limits and enums are the servo's.

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())


func test_the_native_defaults_are_the_schemas() -> void:
	assert_eq(door.servo.get_settings().encode(), HapticServoSettings.new().encode())
	var movement: HapticMovementSettings = HapticsMovement.of(door).get_settings()
	assert_eq(movement.encode(), HapticMovementSettings.new().encode())
	var constraint: HapticConstraintSettings = HapticsConstraint.of(door).get_settings()
	assert_eq(constraint.encode(), HapticConstraintSettings.new().encode())
	var pong: PongSettings = PongSettings.decode(door.renderer(&"pong").settings_bytes())
	assert_not_null(pong, HapticsWireReader.last_error)
	assert_eq(pong.encode(), PongSettings.new().encode())


func test_values_read_back_in_their_own_types() -> void:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.safety.slew_rate_n_per_s = 150.0
	settings.safety.force_scale = 0.5
	settings.telemetry.decimation = 4
	settings.telemetry.enabled = false
	assert_true(door.servo.apply_settings(settings))
	var constraint: HapticsConstraint = HapticsConstraint.of(door)
	var proxy: HapticConstraintSettings = constraint.get_settings()
	proxy.update = HapticConstraintFacts.ProxyUpdate.FRAME
	proxy.max_iterations = 3
	assert_true(constraint.apply_settings(proxy))
	var read: HapticServoSettings = door.servo.get_settings()
	assert_eq(read.safety.slew_rate_n_per_s, 150.0)
	assert_eq(read.safety.force_scale, 0.5)
	assert_eq(door.force_scale, 0.5, "the door's force scale is the servo's")
	assert_eq(read.telemetry.decimation, 4)
	assert_false(read.telemetry.enabled)
	assert_eq(constraint.get_settings().update, HapticConstraintFacts.ProxyUpdate.FRAME)
	assert_eq(constraint.get_settings().max_iterations, 3)


func test_refused_values_are_named_and_change_nothing() -> void:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.safety.slew_rate_n_per_s = 0.5
	expect_error("HapticServoSettings.safety.slew_rate_n_per_s")
	assert_false(door.servo.apply_settings(settings))
	assert_eq(door.servo.get_settings().safety.slew_rate_n_per_s, 200.0, "unchanged")
	var constraint: HapticsConstraint = HapticsConstraint.of(door)
	var proxy: HapticConstraintSettings = constraint.get_settings()
	var unknown_update: int = HapticConstraintFacts.ProxyUpdate.size()
	proxy.update = unknown_update as HapticConstraintFacts.ProxyUpdate
	expect_error("HapticConstraintSettings.update")
	assert_false(constraint.apply_settings(proxy))
	proxy.update = HapticConstraintFacts.ProxyUpdate.SERVO
	proxy.stiffness_n_per_m = NAN
	expect_error("HapticConstraintSettings.stiffness_n_per_m")
	assert_false(constraint.apply_settings(proxy))
	assert_eq(constraint.get_settings().encode(), HapticConstraintSettings.new().encode())
	var movement: HapticsMovement = HapticsMovement.of(door)
	expect_error("set_renderer_settings")
	assert_false(door.renderer(&"constraint").apply_settings(movement.get_settings()))


func test_choices_are_named_as_settings_files_name_them() -> void:
	var models: Dictionary = HapticMovementFacts.ContactModel
	var names: PackedStringArray = ["per_contact", "paper_sum"]
	assert_eq(HapticsValue.choice_names(models), names)
	assert_eq(
		HapticsValue.choice_name(models, HapticMovementFacts.ContactModel.PAPER_SUM), "paper_sum"
	)
	assert_eq(HapticsValue.choice_value(models, "paper_sum"), 1)
	assert_eq(HapticsValue.choice_value(models, "PAPER_SUM"), -1, "the file's spelling only")
	assert_eq(HapticsValue.choice_value(models, "sum"), -1)
	assert_eq(HapticsValue.choice_name(models, 9), "")


func test_a_frame_holds_max_contacts_and_not_one_more() -> void:
	var contacts: Array[HapticContact] = []
	for i: int in HapticFrameLimits.MAX_CONTACTS:
		contacts.append(HapticsTestKit.contact(Vector2.UP))
	assert_true(door.submit_frame(HapticsTestKit.frame_of(contacts)))
	contacts.append(HapticsTestKit.contact(Vector2.UP))
	expect_error(
		(
			"submit_frame: HapticFrame.contacts: %d items, at most %d"
			% [HapticFrameLimits.MAX_CONTACTS + 1, HapticFrameLimits.MAX_CONTACTS]
		)
	)
	assert_false(door.submit_frame(HapticsTestKit.frame_of(contacts)))
	var crowded: HapticFrame = HapticFrame.new()
	for i: int in HapticFrameLimits.MAX_RESTING_OBJECTS + 1:
		crowded.resting.append(HapticsTestKit.load(Vector2.DOWN, 1.0))
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
	mapping.workspace_shape = HapticConstraintFacts.WorkspaceShape.SQUARE
	assert_true(HapticsConstraint.of(door).set_walls(PackedVector2Array(), mapping))
	assert_eq(HapticConstraintFacts.TELEMETRY_FLAG_PROXY_CONTACT, 1 << 8)
