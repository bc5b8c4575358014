extends TestSuite
## The OpenHaptics driver through a door of the test's own with a runtime loaded at run
## time, as a Touch owner's install would be: HAPTICS_OPENHAPTICS_LIBRARY points at the test
## build's fake libHD (docs/devices/openhaptics.md's API over a scripted Touch-like device),
## so the listing, the real dlopen, HD's scheduler callback and the servo run end to end.
## Only a real Touch with 3D Systems' runtime confirms the device side
## (docs/devices/openhaptics.md).

const VARIABLE := "HAPTICS_OPENHAPTICS_LIBRARY"
const DEVICE_ID := "openhaptics:default"
## Built with the native tests (gdextension/CMakeLists.txt, target fake_hd).
const FAKE_RUNTIME := "res://.build/debug/libfake_hd.so"

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.Door.new())


func after_each() -> void:
	door.device.close()
	OS.unset_environment(VARIABLE)


func test_a_runtime_that_does_not_load_is_listed_with_the_reason() -> void:
	OS.set_environment(VARIABLE, "/nonexistent/libHD.so")
	var entry: HapticDeviceInfo = HapticsTestKit.find_device(door, DEVICE_ID)
	if not assert_not_null(entry, "the player's setting is answered in the list"):
		return
	assert_eq(entry.driver, "openhaptics")
	assert_false(entry.openable)
	var reason: String = entry.unavailable_reason
	assert_true(reason.contains("/nonexistent/libHD.so"), reason)
	expect_error("libHD")
	assert_false(door.device.open(DEVICE_ID), "it does not open")
	assert_eq(
		door.device.get_status().io,
		HapticDeviceKinds.DeviceIo.OK,
		"the current device is untouched"
	)


func test_the_touch_renders_through_the_loaded_runtime() -> void:
	var fake: String = ProjectSettings.globalize_path(FAKE_RUNTIME)
	assert_true(FileAccess.file_exists(fake), "the fake runtime is built (make build): " + fake)
	OS.set_environment(VARIABLE, fake)
	var entry: HapticDeviceInfo = HapticsTestKit.find_device(door, DEVICE_ID)
	if not assert_not_null(entry, "listed"):
		return
	assert_eq(entry.driver, "openhaptics")
	assert_true(entry.openable, entry.unavailable_reason)
	assert_true(door.device.open(DEVICE_ID))
	var capabilities: HapticDeviceCapabilities = door.device.get_capabilities()
	assert_eq(capabilities.input_dof, 6, "stylus position and gimbal")
	assert_eq(capabilities.output_dof, 3)
	assert_true(capabilities.has_orientation)
	assert_true(capabilities.physical)
	assert_almost_eq(capabilities.limits.max_force_n, 3.3, 1e-9, "HD_NOMINAL_MAX_FORCE")
	assert_true(door.servo.start())
	var ran: bool = await wait_until(
		func() -> bool: return door.servo.get_stats().device_io_cycles > 100, 5.0
	)
	assert_true(ran, "HD's scheduler called back into the device")
	door.submit_frame(HapticsTestKit.wall(Vector2.UP))
	await wait_physics_frames(5)
	var total: Vector2 = door.get_forces().total
	assert_true(total.is_finite())
	assert_lt(total.length(), 3.3 + 1e-6, "within the Touch's limit")
	door.servo.stop()
	assert_eq(door.device.get_status().io, HapticDeviceKinds.DeviceIo.OK)
	door.device.close()
	assert_eq(door.device.get_id(), "", "closed")
