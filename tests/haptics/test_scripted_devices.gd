extends TestSuite
## Real device drivers through a door of the test's own, each over its scripted transport (a
## software model of the hardware, "scripted:<driver>"): listed only when
## HAPTICS_SCRIPTED_DEVICES=1, a wall is felt through the driver's protocol, unplugging stops
## rendering with the driver's own reason, the cable stays out across reopen attempts, and
## replugging reopens.

const VARIABLE := "HAPTICS_SCRIPTED_DEVICES"
## Every driver with a scripted model.
const SCRIPTED_DRIVERS: Array[String] = ["falcon", "dualsense", "evdev", "hid-pid"]

var door: HapticsTestKit.Door = null


func before_each() -> void:
	OS.set_environment(VARIABLE, "1")
	door = autofree(HapticsTestKit.Door.new())


func after_each() -> void:
	door.device.close()
	OS.unset_environment(VARIABLE)


func test_scripted_devices_are_listed_only_when_asked_for() -> void:
	var ids: Array[String] = _listed_ids()
	for driver: String in SCRIPTED_DRIVERS:
		assert_has(ids, "scripted:" + driver)
		var entry: HapticDeviceInfo = HapticsTestKit.find_device(door, "scripted:" + driver)
		if not assert_not_null(entry, driver):
			continue
		assert_eq(entry.driver, driver)
		assert_true(entry.openable, "%s can be opened" % driver)
	OS.unset_environment(VARIABLE)
	for id: String in _listed_ids():
		assert_false(id.begins_with("scripted:"), "%s is hidden from players" % id)


func test_a_wall_is_felt_through_each_driver() -> void:
	for driver: String in SCRIPTED_DRIVERS:
		assert_true(door.device.open("scripted:" + driver), driver)
		var capabilities: HapticDeviceCapabilities = door.device.get_capabilities()
		assert_true(capabilities.physical, "%s is rendered as a physical device" % driver)
		assert_true(door.servo.start())
		# The floor under the avatar; the stylus pushed down into it (game axes: y down).
		var pressed: bool = await _press_into_floor(0.4)
		assert_true(pressed, "%s: the floor pushes back up through the driver" % driver)
		var stats: HapticServoStats = door.servo.get_stats()
		assert_gt(stats.device_io_cycles, 10, "%s: its own I/O thread ran" % driver)
		door.servo.stop()
		assert_eq(door.device.get_status().io, HapticDeviceKinds.DeviceIo.OK)


func test_unplug_stops_rendering_and_the_cable_stays_out_until_replugged() -> void:
	for driver: String in SCRIPTED_DRIVERS:
		var id: String = "scripted:" + driver
		assert_true(door.device.open(id))
		assert_true(door.servo.start())
		await wait_seconds(0.1)
		assert_true(door.device.set_simulated_plugged(false))
		var stopped: bool = await wait_until(
			func() -> bool: return not door.servo.is_running(), 3.0
		)
		assert_true(stopped, "%s: the servo stopped by itself" % driver)
		var status: HapticDeviceStatus = door.device.get_status()
		assert_eq(status.io, HapticDeviceKinds.DeviceIo.DISCONNECTED, driver)
		assert_ne(status.reason, "", "%s says why" % driver)
		assert_has(door.servo.get_status(), "disconnected")
		assert_true(door.device.is_lost())
		assert_false(_openable(id), "%s: unplugged, not openable" % driver)
		expect_error("unplugged")
		assert_false(door.device.open(id), "%s: reopening fails while unplugged" % driver)
		assert_true(door.device.set_simulated_plugged(true))
		assert_true(_openable(id))
		assert_true(door.device.open(id), "%s: replugged, it reopens" % driver)
		assert_true(door.servo.start())
		await wait_seconds(0.1)
		assert_true(door.servo.is_running())
		door.servo.stop()


func _listed_ids() -> Array[String]:
	var ids: Array[String] = []
	for device: HapticDeviceInfo in door.device.list_present():
		ids.append(device.id)
	return ids


func _openable(id: String) -> bool:
	var entry: HapticDeviceInfo = HapticsTestKit.find_device(door, id)
	return entry != null and entry.openable


# Pushes the stylus 2 cm into a floor for up to p_seconds; true once the rendered force
# points up (game axes: negative y) by more than 0.1 N.
func _press_into_floor(seconds: float) -> bool:
	HapticsTestKit.set_hand_m(door, Vector2(0.0, 0.02))
	var deadline: float = Time.get_ticks_msec() + seconds * 1000.0
	while Time.get_ticks_msec() < deadline:
		door.submit_frame(HapticsTestKit.wall(Vector2.UP))
		await wait_physics_frames(1)
		if door.get_forces().total.y < -0.1:
			return true
	return false
