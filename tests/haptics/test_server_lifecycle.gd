extends TestSuite
## The servo thread as the game uses it: start, stats, stop, device loss, bad devices.

var server: HapticsServer = null


func before_each() -> void:
	server = HapticsServer.new()


func after_each() -> void:
	server.close_device()


func test_the_thread_runs_and_reports_its_statistics() -> void:
	assert_true(server.open_device("simulated"))
	assert_true(server.start())
	assert_true(server.is_running())
	await wait_seconds(0.3)
	var stats: Dictionary = server.get_stats()
	assert_true(stats["running"])
	assert_eq(stats["nominal_rate_hz"], 1000.0)
	assert_gt(stats["ticks"], 100)
	assert_has(["normal", "realtime_fifo", "realtime_rr"], stats["scheduler"])
	for key: String in ["period_p99_ms", "tick_cost_p50_us", "late_ticks", "frame_age_ms"]:
		assert_has(stats, key)
	server.stop()
	assert_false(server.is_running())


func test_the_stats_say_which_realtime_techniques_were_granted() -> void:
	assert_true(server.open_device("simulated"))
	assert_true(server.start())
	await wait_seconds(0.3)
	var stats: Dictionary = server.get_stats()
	server.stop()
	var types: Dictionary[String, int] = {
		"memory_locked": TYPE_BOOL,
		"cpu_latency_held": TYPE_BOOL,
		"pinned_cpu": TYPE_INT,
		"stack_prefaulted_kb": TYPE_INT,
		"timer_slack_minimised": TYPE_BOOL,
		"realtime_kit": TYPE_STRING,
		"realtime_kit_nice": TYPE_INT,
		"realtime_kit_reason": TYPE_STRING,
		"spin_us": TYPE_FLOAT,
		"servo_cpu_percent": TYPE_FLOAT,
		"latency_p99_us": TYPE_FLOAT,
		"latency_max_us": TYPE_FLOAT,
	}
	for key: String in types:
		if assert_has(stats, key):
			assert_eq(typeof(stats[key]), types[key], key)
	# Real time and the timer-slack fallback exclude each other.
	assert_ne(stats["realtime"], stats["timer_slack_minimised"])
	var cpu_percent: float = stats["servo_cpu_percent"]
	var latency_max_us: float = stats["latency_max_us"]
	var latency_p99_us: float = stats["latency_p99_us"]
	assert_true(cpu_percent >= 0.0)
	assert_true(latency_max_us >= latency_p99_us)


func test_frames_from_the_game_reach_the_thread() -> void:
	assert_true(server.open_device("simulated"))
	assert_true(server.start(500.0))
	for i: int in 5:
		server.submit_frame({"contacts": [{"normal": Vector2.UP}]})
		await wait_physics_frames(1)
	assert_gt(server.get_stats()["frames_received"], 0)


func test_out_of_range_rate_is_refused() -> void:
	assert_true(server.open_device("simulated"))
	expect_error("rate")
	assert_false(server.start(10.0))
	assert_false(server.is_running())


func test_unplugging_the_device_stops_rendering_with_a_reason() -> void:
	assert_true(server.open_device("simulated"))
	assert_true(server.start())
	await wait_seconds(0.05)
	assert_true(server.set_simulated_plugged(false))
	var stopped: bool = await wait_until(func() -> bool: return not server.is_running(), 2.0)
	assert_true(stopped, "the servo stopped by itself")
	assert_ne(server.get_servo_status(), "", "and says why")


func test_opening_an_unknown_device_keeps_the_current_one() -> void:
	assert_true(server.open_device("simulated"))
	expect_error("no device with id 'usb:9-9'")
	assert_false(server.open_device("usb:9-9"))
	assert_eq(server.get_device_id(), "simulated")
	assert_ne(server.get_device_name(), "")


func test_without_a_device_rendering_cannot_start() -> void:
	expect_error("start")
	assert_false(server.start())


func test_many_start_stop_cycles_through_the_binding() -> void:
	assert_true(server.open_device("simulated"))
	for i: int in 50:
		assert_true(server.start())
		server.stop()
	assert_false(server.is_running())


func test_freeing_a_running_server_stops_its_thread() -> void:
	var running: HapticsServer = HapticsServer.new()
	assert_true(running.open_device("simulated"))
	assert_true(running.start())
	running = null  # the last reference: the engine frees it, the core joins the thread
	await wait_physics_frames(1)
	# The process survived the join; the simulated device can be driven again at once.
	assert_true(server.open_device("simulated"))
	assert_true(server.start())
