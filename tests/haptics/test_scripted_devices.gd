extends TestSuite
## Real device drivers through HapticsServer, each over its scripted transport (a software
## model of the hardware, "scripted:<driver>"): listed only when HAPTICS_SCRIPTED_DEVICES=1,
## a wall is felt through the driver's protocol, unplugging stops rendering with the
## driver's own reason, the cable stays out across reopen attempts, and replugging reopens.

const VARIABLE := "HAPTICS_SCRIPTED_DEVICES"
## Every driver with a scripted model.
const SCRIPTED_DRIVERS: Array[String] = ["falcon", "dualsense", "evdev", "hid-pid"]

var server: HapticsServer = null


func before_each() -> void:
	OS.set_environment(VARIABLE, "1")
	server = HapticsServer.new()


func after_each() -> void:
	server.close_device()
	OS.unset_environment(VARIABLE)


func test_scripted_devices_are_listed_only_when_asked_for() -> void:
	var ids: Array[String] = _listed_ids()
	for driver: String in SCRIPTED_DRIVERS:
		assert_has(ids, "scripted:" + driver)
		var entry: Dictionary = server.get_device("scripted:" + driver)
		assert_eq(entry["driver"], driver)
		assert_true(entry["openable"], "%s can be opened" % driver)
	OS.unset_environment(VARIABLE)
	for id: String in _listed_ids():
		assert_false(id.begins_with("scripted:"), "%s is hidden from players" % id)


func test_a_wall_is_felt_through_each_driver() -> void:
	for driver: String in SCRIPTED_DRIVERS:
		assert_true(server.open_device("scripted:" + driver), driver)
		var capabilities: Dictionary = server.get_device_capabilities()
		assert_true(capabilities["physical"], "%s is rendered as a physical device" % driver)
		assert_true(server.start())
		# The floor under the avatar; the stylus pushed down into it (game axes: y down).
		var pressed: bool = await _press_into_floor(0.4)
		assert_true(pressed, "%s: the floor pushes back up through the driver" % driver)
		var stats: Dictionary = server.get_stats()
		assert_gt(stats["device_io_cycles"], 10, "%s: its own I/O thread ran" % driver)
		server.stop()
		assert_eq(server.get_device_status()["io"], "ok")


func test_unplug_stops_rendering_and_the_cable_stays_out_until_replugged() -> void:
	for driver: String in SCRIPTED_DRIVERS:
		var id: String = "scripted:" + driver
		assert_true(server.open_device(id))
		assert_true(server.start())
		await wait_seconds(0.1)
		assert_true(server.set_simulated_plugged(false))
		var stopped: bool = await wait_until(func() -> bool: return not server.is_running(), 3.0)
		assert_true(stopped, "%s: the servo stopped by itself" % driver)
		var status: Dictionary = server.get_device_status()
		assert_eq(status["io"], "disconnected", driver)
		assert_ne(status["reason"], "", "%s says why" % driver)
		assert_has(server.get_servo_status(), "disconnected")
		assert_false(server.get_device(id)["openable"], "%s: unplugged, not openable" % driver)
		expect_error("unplugged")
		assert_false(server.open_device(id), "%s: reopening fails while unplugged" % driver)
		assert_true(server.set_simulated_plugged(true))
		assert_true(server.get_device(id)["openable"])
		assert_true(server.open_device(id), "%s: replugged, it reopens" % driver)
		assert_true(server.start())
		await wait_seconds(0.1)
		assert_true(server.is_running())
		server.stop()


func _listed_ids() -> Array[String]:
	var ids: Array[String] = []
	for device: Dictionary in server.list_devices():
		ids.append(str(device["id"]))
	return ids


# Pushes the stylus 2 cm into a floor for up to p_seconds; true once the rendered force
# points up (game axes: negative y) by more than 0.1 N.
func _press_into_floor(seconds: float) -> bool:
	server.set_hand_target(Vector2(0.0, 0.02))
	var deadline: float = Time.get_ticks_msec() + seconds * 1000.0
	while Time.get_ticks_msec() < deadline:
		server.submit_frame({"contacts": [{"normal": Vector2.UP}]})
		await wait_physics_frames(1)
		var total: Vector2 = server.get_forces()["total"]
		if total.y < -0.1:
			return true
	return false
