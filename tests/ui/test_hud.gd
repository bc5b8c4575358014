extends TestSuite
## The HUD fed with forces directly (not polling the haptics): arrow lengths and
## directions by component, the legend, the cap on long arrows, the mouse left to the game,
## the arrows following the player, the stylus widget, and the servo's status lines.

const HUD_SCENE: PackedScene = preload("res://game/ui/hud.tscn")
const MAX_FORCE: float = 3.3

var _hud: Hud = null


func before_each() -> void:
	_hud = HUD_SCENE.instantiate() as Hud
	_hud.live = false
	add_child_autofree(_hud)
	_hud.set_max_force(MAX_FORCE)


func test_each_component_becomes_an_arrow_along_its_force() -> void:
	var arrows: ForceArrows = _hud.get_world_arrows()
	var full: float = arrows.full_length
	(
		_hud
		. show_forces(
			(
				HapticsTestKit
				. forces_of(
					{
						"normal": Vector2(-MAX_FORCE, 0.0),
						"friction": Vector2(0.0, -MAX_FORCE * 0.25),
						"weight": Vector2(0.0, MAX_FORCE * 0.5),
						"drag": Vector2(MAX_FORCE * 0.1, MAX_FORCE * 0.1),
						"inertia": Vector2(0.0, 0.33),
						"impact": Vector2(0.0, -1.65),
						"total": Vector2(-MAX_FORCE, 0.2),
					}
				)
			)
		)
	)
	assert_almost_eq(arrows.get_arrow("normal"), Vector2(-full, 0.0), 1e-3, "full force, left")
	assert_almost_eq(arrows.get_arrow("friction"), Vector2(0.0, -full * 0.25), 1e-3)
	assert_almost_eq(arrows.get_arrow("weight"), Vector2(0.0, full * 0.5), 1e-3, "y down")
	assert_almost_eq(arrows.get_arrow("drag"), Vector2(full, full) * 0.1, 1e-3)
	assert_almost_eq(arrows.get_arrow("inertia"), Vector2(0.0, full * 0.1), 1e-3)
	assert_almost_eq(arrows.get_arrow("impact"), Vector2(0.0, -full * 0.5), 1e-3)
	assert_almost_eq(arrows.get_arrow("total"), Vector2(-MAX_FORCE, 0.2) * full / MAX_FORCE, 1e-3)


func test_the_arrows_at_the_player_show_the_same_forces() -> void:
	_hud.show_forces(HapticsTestKit.forces_of({"normal": Vector2(0.0, -1.0)}))
	var world: ForceArrows = _hud.get_world_arrows()
	assert_almost_eq(world.get_arrow("normal"), Vector2(0.0, -world.full_length / MAX_FORCE), 1e-3)


func test_zero_components_draw_nothing_and_unknown_names_have_no_arrow() -> void:
	_hud.show_forces(HapticsTestKit.forces_of({"weight": Vector2(0.0, 1.0)}))
	var arrows: ForceArrows = _hud.get_world_arrows()
	assert_ne(arrows.get_arrow("weight"), Vector2.ZERO)
	assert_eq(arrows.get_arrow("normal"), Vector2.ZERO)
	assert_eq(arrows.get_arrow("total"), Vector2.ZERO)
	assert_eq(arrows.get_arrow("mystery"), Vector2.ZERO)
	_hud.show_forces(HapticForces.new())
	assert_eq(arrows.get_arrow("weight"), Vector2.ZERO, "a later frame without it clears it")


func test_the_components_are_named_from_the_renderers_parts() -> void:
	var forces: HapticForces = HapticForces.new()
	for part: int in forces.parts.size():
		forces.parts[part] = Vector2(part + 1, 0.0)
	forces.impact = Vector2(0.0, 6.0)
	forces.total = Vector2(0.0, 7.0)
	forces.continuous = Vector2(9.0, 9.0)
	var named: Dictionary[String, Vector2] = ForceArrows.components_of(forces)
	assert_eq(named["normal"], Vector2(1.0, 0.0))
	assert_eq(named["friction"], Vector2(2.0, 0.0))
	assert_eq(named["weight"], Vector2(3.0, 0.0))
	assert_eq(named["drag"], Vector2(4.0, 0.0))
	assert_eq(named["inertia"], Vector2(5.0, 0.0))
	assert_eq(named["impact"], Vector2(0.0, 6.0))
	assert_eq(named["total"], Vector2(0.0, 7.0))
	assert_eq(named.keys(), Hud.LEGEND_ORDER, "every component of the legend, in its order")


func test_forces_beyond_the_device_maximum_are_capped_but_keep_their_direction() -> void:
	var arrows: ForceArrows = _hud.get_world_arrows()
	_hud.show_forces(HapticsTestKit.forces_of({"impact": Vector2(30.0, -40.0)}))
	var arrow: Vector2 = arrows.get_arrow("impact")
	assert_almost_eq(arrow.length(), arrows.full_length * arrows.max_length_ratio, 1e-3)
	assert_almost_eq(arrow.normalized(), Vector2(0.6, -0.8), 1e-4)


func test_the_scale_follows_the_device_maximum_force() -> void:
	_hud.set_max_force(8.0)
	var arrows: ForceArrows = _hud.get_world_arrows()
	_hud.show_forces(HapticsTestKit.forces_of({"normal": Vector2(4.0, 0.0)}))
	assert_almost_eq(arrows.get_arrow("normal"), Vector2(arrows.full_length * 0.5, 0.0), 1e-3)
	assert_eq(_hud.get_plot().y_max, 8.0)


func test_the_legend_shows_each_magnitude() -> void:
	_hud.show_forces(
		HapticsTestKit.forces_of({"normal": Vector2(3.0, 4.0), "total": Vector2(0.0, -1.234)})
	)
	assert_eq(_hud.get_legend_value("normal").text, "5.00 N")
	assert_eq(_hud.get_legend_value("friction").text, "0.00 N")
	assert_eq(_hud.get_legend_value("total").text, "1.23 N")
	for component: String in Hud.LEGEND_ORDER:
		assert_not_null(_hud.get_legend_value(component), component)


func test_every_hud_control_lets_the_mouse_through() -> void:
	var blocking: Array[String] = []
	_collect_blocking(_hud, blocking)
	assert_eq(blocking, [] as Array[String])


func test_the_plot_samples_the_total_magnitude_each_frame() -> void:
	_hud.show_forces(HapticsTestKit.forces_of({"total": Vector2(0.0, 2.0)}))
	await wait_process_frames(12)
	var plot: ForcePlot = _hud.get_plot()
	assert_gt(plot.buffer.size(), 0)
	assert_almost_eq(plot.buffer.last(), 2.0, 1e-6)


func test_the_world_arrows_sit_on_the_player() -> void:
	var body: Node2D = Node2D.new()
	body.position = Vector2(321.0, 123.0)
	add_child_autofree(body)
	_hud.set_player(body)
	await wait_process_frames(2)
	var world: ForceArrows = _hud.get_world_arrows()
	assert_false(world.visible, "the compact view draws nothing over the player")
	_hud.view = Hud.View.LAB
	await wait_process_frames(2)
	assert_true(world.visible, "the lab view does")
	assert_almost_eq(world.position, body.get_global_transform_with_canvas().origin, 0.01)
	_hud.set_player(null)
	assert_false(world.visible)


func test_the_device_widget_places_both_dots() -> void:
	var widget: DeviceWidget = _hud.get_device_widget()
	widget.set_positions(Vector2(0.5, 0.0), Vector2(-1.0, 0.0))
	var centre: Vector2 = widget.size * 0.5
	assert_gt(widget.to_local_point(Vector2(0.5, 0.0)).x, centre.x)
	assert_lt(widget.to_local_point(Vector2(-1.0, 0.0)).x, centre.x)
	assert_almost_eq(widget.to_local_point(Vector2.ZERO), centre, 1e-4)


func test_run_info_shows_time_and_items() -> void:
	_hud.set_run_info(75.25, 2, 5)
	var time_label: Label = _hud.find_child("TimeValue", true, false) as Label
	var items_label: Label = _hud.find_child("ItemsValue", true, false) as Label
	assert_eq(time_label.text, "01:15.2")
	assert_eq(items_label.text, "2 / 5")


func test_the_servo_line_names_the_techniques_granted() -> void:
	var granted: HapticServoStats = HapticServoStats.new()
	granted.period_p99_s = 1.0234e-3
	granted.scheduler = HapticRealtime.SchedulerKind.REALTIME_FIFO
	granted.realtime = true
	granted.realtime_priority = 80
	granted.memory_locked = true
	granted.cpu_latency_held = true
	granted.pinned_cpu = 1
	granted.spin_s = 25e-6
	assert_eq(
		Hud.servo_running_text(999.6, granted),
		"servo 1000 Hz  ·  p99 1.02 ms  ·  RT 80  ·  mlock  ·  C-states held  ·  CPU 1  ·  spin 25 µs"
	)
	var refused: HapticServoStats = HapticServoStats.new()
	refused.period_p99_s = 1.2e-3
	refused.scheduler = HapticRealtime.SchedulerKind.NORMAL
	refused.pinned_cpu = -1
	assert_eq(Hud.servo_running_text(1000.0, refused), "servo 1000 Hz  ·  p99 1.20 ms")
	# Without the hold the spin is the machine's learned wake-up lateness, and says so.
	var learned: HapticServoStats = HapticServoStats.new()
	learned.period_p99_s = 1.0e-3
	learned.scheduler = HapticRealtime.SchedulerKind.REALTIME_RR
	learned.realtime = true
	learned.realtime_priority = 20
	learned.pinned_cpu = -1
	learned.spin_s = 197e-6
	learned.spin_learned = true
	assert_eq(
		Hud.servo_running_text(1000.0, learned),
		"servo 1000 Hz  ·  p99 1.00 ms  ·  RT 20 (RealtimeKit)  ·  spin 197 µs (learned)"
	)


func test_the_servo_line_says_what_realtimekit_gave_a_normal_user() -> void:
	var rr: HapticServoStats = _stats_p99_1_ms()
	rr.realtime = true
	rr.realtime_priority = 20
	rr.scheduler = HapticRealtime.SchedulerKind.REALTIME_RR
	rr.realtime_kit.outcome = HapticRealtime.RtkitOutcome.REALTIME
	assert_eq(
		Hud.servo_running_text(1000.0, rr), "servo 1000 Hz  ·  p99 1.00 ms  ·  RT 20 (RealtimeKit)"
	)
	var nice: HapticServoStats = _stats_p99_1_ms()
	nice.realtime_kit.outcome = HapticRealtime.RtkitOutcome.HIGH_PRIORITY
	nice.realtime_kit.nice = -15
	assert_eq(
		Hud.servo_running_text(1000.0, nice),
		"servo 1000 Hz  ·  p99 1.00 ms  ·  nice -15 (no real time outside a desktop session)"
	)
	var none: HapticServoStats = _stats_p99_1_ms()
	none.realtime_kit.outcome = HapticRealtime.RtkitOutcome.UNAVAILABLE
	assert_eq(
		Hud.servo_running_text(1000.0, none),
		"servo 1000 Hz  ·  p99 1.00 ms  ·  no real time: install rtkit (sudo apt install rtkit)"
	)
	var refused: HapticServoStats = _stats_p99_1_ms()
	refused.realtime_kit.outcome = HapticRealtime.RtkitOutcome.REFUSED
	assert_eq(
		Hud.realtime_missing_text(refused),
		"no real time: RealtimeKit refused (no desktop session?)"
	)
	assert_eq(Hud.realtime_missing_text(_stats_p99_1_ms()), "", "not asked: nothing to say")


func test_a_device_that_takes_no_force_is_told_in_both_views() -> void:
	var moving: HapticDeviceStatus = HapticDeviceStatus.new()
	assert_eq(Hud.device_stuck_text(moving), "", "the wire moves: nothing to say")
	var stuck: HapticDeviceStatus = HapticDeviceStatus.new()
	stuck.output_stuck_s = 1.46
	stuck.reason = "the device has taken no output for 1.46 s"
	var text: String = Hud.device_stuck_text(stuck)
	assert_eq(text, "device not taking force for 1.5 s: it holds the last one")
	assert_eq(Hud.view_hint_text(false, text), text + "  ·  H: more", "the compact view")
	assert_eq(Hud.view_hint_text(false, ""), "H: lab view (forces, device)")
	assert_eq(Hud.view_hint_text(true, text), "H: hide the lab view", "the lab view's servo line")


func test_the_stopped_servo_line_says_why() -> void:
	var ok: HapticDeviceStatus = HapticDeviceStatus.new()
	assert_eq(Hud.servo_stopped_text("", ok), "servo off")
	var unplugged: HapticDeviceStatus = HapticDeviceStatus.new()
	unplugged.io = HapticDeviceKinds.DeviceIo.DISCONNECTED
	unplugged.reason = "USB transfer failed"
	assert_eq(
		Hud.servo_stopped_text("device disconnected", unplugged),
		(
			"device unplugged (USB transfer failed): zero force, playing on the keyboard; "
			+ "plug it back in to resume"
		)
	)
	var failed: HapticDeviceStatus = HapticDeviceStatus.new()
	failed.io = HapticDeviceKinds.DeviceIo.FAILED
	assert_eq(Hud.servo_stopped_text("I/O error", failed), "servo stopped: I/O error")


# Stats of a servo without real time whose period's 99th percentile is 1 ms.
func _stats_p99_1_ms() -> HapticServoStats:
	var stats: HapticServoStats = HapticServoStats.new()
	stats.period_p99_s = 1e-3
	stats.scheduler = HapticRealtime.SchedulerKind.NORMAL
	stats.pinned_cpu = -1
	return stats


func _collect_blocking(node: Node, out: Array[String]) -> void:
	if node is Control and (node as Control).mouse_filter != Control.MOUSE_FILTER_IGNORE:
		out.append(str(node.get_path()))
	for child: Node in node.get_children():
		_collect_blocking(child, out)
