extends TestSuite
## The servo thread as the game uses it, through a door of the test's own: start, stats,
## stop, device loss, bad devices.

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.Door.new())


func test_the_thread_runs_and_reports_its_statistics() -> void:
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start())
	assert_true(door.servo.is_running())
	await wait_seconds(0.3)
	var stats: HapticServoStats = door.servo.get_stats()
	assert_true(stats.running)
	assert_eq(stats.nominal_rate_hz, 1000.0)
	assert_gt(stats.ticks, 100)
	assert_has(
		[
			HapticRealtime.SchedulerKind.NORMAL,
			HapticRealtime.SchedulerKind.REALTIME_FIFO,
			HapticRealtime.SchedulerKind.REALTIME_RR
		],
		stats.scheduler
	)
	assert_gt(stats.period_p99_s, 0.0)
	assert_gt(stats.tick_cost_p50_s, 0.0)
	door.servo.stop()
	assert_false(door.servo.is_running())


func test_a_device_closed_and_opened_again_renders_again() -> void:
	# The game's settings close the device and open it again with other options: the forces
	# and the simulated hand must come back (they stopped for good, and the keys no longer
	# moved the sub).
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start())
	door.device.close()
	assert_false(door.servo.is_running(), "no device, no rendering")
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.is_running(), "rendering again")
	var ticks: int = door.servo.get_stats().ticks
	await wait_seconds(0.2)
	assert_gt(door.servo.get_stats().ticks, ticks)
	# Stopped on purpose, a device opened after it does not start rendering.
	door.servo.stop()
	door.device.close()
	assert_true(door.device.open("simulated"))
	assert_false(door.servo.is_running(), "the game stopped rendering itself")


func test_the_stats_say_which_realtime_techniques_were_granted() -> void:
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start())
	await wait_seconds(0.3)
	var stats: HapticServoStats = door.servo.get_stats()
	door.servo.stop()
	# Real time and the timer-slack fallback exclude each other.
	assert_ne(stats.realtime, stats.timer_slack_minimised)
	assert_eq(
		stats.realtime,
		(
			stats.scheduler != HapticRealtime.SchedulerKind.NORMAL
			and stats.scheduler != HapticRealtime.SchedulerKind.MANUAL
		),
		"real time is a real-time scheduler"
	)
	assert_true(stats.pinned_cpu >= -1)
	assert_true(stats.stack_prefaulted_kb >= 0)
	assert_true(stats.spin_s >= 0.0)
	assert_true(stats.thread_cpu_fraction >= 0.0)
	assert_true(stats.latency_max_s >= stats.latency_p99_s)


func test_frames_from_the_game_reach_the_thread() -> void:
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start(500.0))
	for i: int in 5:
		door.submit_frame(HapticsTestKit.wall(Vector2.UP))
		await wait_physics_frames(1)
	assert_gt(door.servo.get_stats().frames_received, 0)


func test_out_of_range_rate_is_refused() -> void:
	assert_true(door.device.open("simulated"))
	expect_error("rate")
	assert_false(door.servo.start(10.0))
	assert_false(door.servo.is_running())


func test_unplugging_the_device_stops_rendering_with_a_reason() -> void:
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start())
	await wait_seconds(0.05)
	assert_true(door.device.set_simulated_plugged(false))
	var stopped: bool = await wait_until(func() -> bool: return not door.servo.is_running(), 2.0)
	assert_true(stopped, "the servo stopped by itself")
	assert_ne(door.servo.get_status(), "", "and says why")
	assert_true(door.device.is_lost())


func test_opening_an_unknown_device_keeps_the_current_one() -> void:
	assert_true(door.device.open("simulated"))
	expect_error("no device with id 'usb:9-9'")
	assert_false(door.device.open("usb:9-9"))
	assert_eq(door.device.get_id(), "simulated")
	assert_ne(door.device.get_name(), "")


func test_without_a_device_rendering_cannot_start() -> void:
	expect_error("start")
	assert_false(door.servo.start())


func test_many_start_stop_cycles_through_the_binding() -> void:
	assert_true(door.device.open("simulated"))
	for i: int in 50:
		assert_true(door.servo.start())
		door.servo.stop()
	assert_false(door.servo.is_running())


func test_freeing_a_running_door_stops_its_thread() -> void:
	var running: HapticsTestKit.Door = HapticsTestKit.manual()
	assert_true(running.servo.start())
	running.free()  # its server goes with it: the core joins the thread
	await wait_physics_frames(1)
	# The process survived the join; the simulated device can be driven again at once.
	assert_true(door.device.open("simulated"))
	assert_true(door.servo.start())
