extends TestSuite
## The native extension as GDScript sees it: registration, both call paths, device list,
## and errors for bad calls that leave the game running.


func test_class_is_registered() -> void:
	assert_true(ClassDB.class_exists(&"HapticsSystem"))
	assert_eq(ClassDB.get_parent_class(&"HapticsSystem"), &"RefCounted")
	assert_true(ClassDB.class_has_method(&"HapticsSystem", &"list_devices"))


func test_the_autoload_reaches_the_library() -> void:
	assert_true(Haptics.is_available())
	assert_has(Haptics.get_version(), "haptics ")


func test_simulated_device_is_listed_first_with_its_documented_fields() -> void:
	# The binding's own bytes, decoded as the door decodes them.
	var list: HapticDeviceList = HapticDeviceList.decode(HapticsSystem.new().list_devices())
	if not assert_not_null(list, HapticsWireReader.last_error):
		return
	assert_gt(list.devices.size(), 0)
	var first: HapticDeviceInfo = list.devices[0]
	assert_eq(first.id, "simulated")
	assert_eq(first.backend, "simulated")
	assert_true(first.known_haptic)
	assert_has(first.model, "Simulated")
	assert_eq(first.driver, "simulated")
	assert_true(first.openable)


func test_ids_are_unique() -> void:
	var seen: Dictionary[String, bool] = {}
	for device: HapticDeviceInfo in Haptics.device.list_present():
		assert_false(seen.has(device.id), "duplicate id %s" % device.id)
		seen[device.id] = true


func test_typed_ptrcall_and_untyped_call_agree() -> void:
	var typed: HapticsSystem = HapticsSystem.new()
	var untyped: Variant = HapticsSystem.new()
	@warning_ignore("unsafe_method_access")
	assert_eq(typed.get_version(), untyped.get_version())
	var by_ptrcall: PackedByteArray = typed.get_device_capabilities()
	@warning_ignore("unsafe_method_access")
	var by_call: PackedByteArray = untyped.get_device_capabilities()
	assert_eq(by_ptrcall, by_call, "no device open: the same bytes")
	assert_true(typed.open_device("simulated"))
	@warning_ignore("unsafe_method_access")
	assert_true(untyped.open_device("simulated"))
	by_ptrcall = typed.get_device_capabilities()
	@warning_ignore("unsafe_method_access")
	by_call = untyped.get_device_capabilities()
	assert_eq(by_ptrcall, by_call, "the simulated device open: the same bytes")
	var capabilities: HapticDeviceCapabilities = HapticDeviceCapabilities.decode(by_ptrcall)
	if assert_not_null(capabilities, HapticsWireReader.last_error):
		assert_false(capabilities.physical, "the simulated device's")
	assert_eq(
		typed.get_device_name(), HapticDeviceList.decode(typed.list_devices()).devices[0].model
	)


func test_too_many_arguments_is_a_call_error_and_the_game_goes_on() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	expect_error("expected 0 argument(s), but called with 1")
	assert_null(server.callv(&"list_devices", [1]))
	var list: HapticDeviceList = HapticDeviceList.decode(server.list_devices())
	assert_gt(list.devices.size(), 0, "the server still answers")


func test_too_few_arguments_is_a_call_error() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	expect_error("expected 1 argument(s), but called with 0")
	assert_null(server.callv(&"open_device", []))


func test_wrong_argument_type_is_a_call_error() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	expect_error("Cannot convert argument 1 from Array to String")
	assert_null(server.callv(&"open_device", [[1, 2]]))
	assert_true(server.open_device("simulated"))
	assert_eq(server.get_device_id(), "simulated")


func test_unknown_device_id_reports_an_error_and_opens_nothing() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	expect_error("no device with id 'no-such-device'")
	assert_false(server.open_device("no-such-device"))
	assert_eq(server.get_device_id(), "")


func test_non_ascii_text_crosses_the_boundary_intact() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	expect_error("no device with id 'Überhaptik ✓'")
	assert_false(server.open_device("Überhaptik ✓"))


func test_enumeration_warnings_are_sentences() -> void:
	var list: HapticDeviceList = HapticDeviceList.decode(HapticsSystem.new().list_devices())
	if not assert_not_null(list, HapticsWireReader.last_error):
		return
	for warning: String in list.warnings:
		assert_ne(warning, "", "a warning says something")


func test_device_open_options_cross_typed_and_a_bad_value_is_refused() -> void:
	var server: HapticsSystem = HapticsSystem.new()
	var options: HapticDeviceOpenOptions = HapticDeviceOpenOptions.new()
	assert_false(options.take_gain, "the player's gain is left alone by default")
	assert_true(options.spring_off, "the centring spring is turned off by default")
	options.take_gain = true
	assert_true(server.set_device_open_options(options.encode()))
	var other: PackedByteArray = HapticDeviceCapabilities.new().encode()
	expect_error("set_device_open_options")
	assert_false(server.set_device_open_options(other), "another value's bytes")
	assert_true(server.open_device("simulated"), "the options stay usable")
