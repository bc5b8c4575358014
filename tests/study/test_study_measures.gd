extends TestSuite
## What a trial measures, in each condition, against the real servo loop: the avatar is
## pushed into the wall right of the tiny maze's start, and the recorder must see the
## contact, count the collision, measure the rendered force (none: zero) and write a
## telemetry file of the documented shape; in position control the proxy must stop at the
## wall however far the device goes, and the telemetry's avatar is the proxy.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const Support := preload("res://tests/study/study_test_support.gd")
const TINY_MAZE: PackedScene = preload("res://tests/study/fixtures/tiny_maze.tscn")
## The wall right of the start: its face, minus the avatar's radius.
const WALL_STOP_X: float = 240.0 - 7.0 - Player.RADIUS
## Physics ticks of pushing.
const PUSH_TICKS: int = 60

var _root: String = ""
var _level: StudyLevel = null
var _rig: ConditionRig = null
var _config: StudyConfig = null
var _saved: Dictionary = {}


func before_each() -> void:
	_root = Support.fresh_root("measures")
	_saved = ConditionRig.save_haptics()
	_config = StudyConfig.load_default()
	_level = add_child_autofree(TINY_MAZE.instantiate()) as StudyLevel
	_rig = add_child_autofree(ConditionRig.new()) as ConditionRig
	_rig.piloted = true


func after_each() -> void:
	_rig.release()
	ConditionRig.restore_haptics(_saved)
	Haptics.device.set_hand_target(Vector2.ZERO)
	Support.remove_tree(_root)


func test_movement_renders_the_normal_force_and_counts_the_collision() -> void:
	var result: TrialResult = await _push("movement", Vector2(0.8, 0.0))
	assert_gt(result.wall_collisions, 0, "the wall was hit")
	assert_lt(result.wall_collisions, 4, "pushing steadily is one contact, not many")
	assert_gt(result.contact_time_s, 0.4, "in contact most of the time")
	assert_gt(result.max_force_n, 0.5, "the wall pushes back")
	assert_gt(result.mean_force_n, 0.1)
	assert_gt(result.path_length_px, 20.0, "the avatar moved")
	assert_lt(_level.player.global_position.x, WALL_STOP_X + 1.0, "and stopped at the wall")
	var rows: Array[Dictionary] = _telemetry(result)
	# One sample every second servo tick: 500 per second of servo time (the file's time_s).
	# How many servo seconds the 60 physics ticks last depends on the machine's load (a
	# loaded machine misses servo deadlines), so only a generous floor is put on that.
	var span: float = str(rows[rows.size() - 1]["time_s"]).to_float()
	assert_almost_eq((rows.size() - 1) / span, 500.0, 5.0, "about 500 Hz of samples")
	assert_gt(span, PUSH_TICKS / 50.0 * 0.5, "at least half of the trial's 1.2 s recorded")
	var pushed_back: bool = false
	for row: Dictionary in rows:
		if row["in_contact"] == "1" and str(row["force_x"]).to_float() < -0.3:
			pushed_back = true
	assert_true(pushed_back, "the force in contact points away from the wall (-x)")


func test_no_feedback_renders_nothing_but_still_counts_contacts() -> void:
	var result: TrialResult = await _push("none", Vector2(0.8, 0.0))
	assert_gt(result.wall_collisions, 0)
	assert_gt(result.contact_time_s, 0.4)
	assert_eq(result.max_force_n, 0.0, "no force at all")
	assert_eq(result.mean_force_n, 0.0)


func test_constraint_stops_the_proxy_at_the_wall_and_pulls_the_device_back() -> void:
	var target: Vector2 = Vector2(330.0, 180.0)
	var result: TrialResult = await _push("constraint", Vector2.INF, target)
	assert_gt(result.wall_collisions, 0)
	assert_gt(result.contact_time_s, 0.4)
	assert_gt(result.max_force_n, 1.0, "k_c (proxy - device) pulls back")
	var rows: Array[Dictionary] = _telemetry(result)
	var furthest: float = -INF
	for row: Dictionary in rows:
		furthest = maxf(furthest, str(row["avatar_x"]).to_float())
	assert_lt(furthest, WALL_STOP_X + 0.5, "the proxy never crosses the wall")
	assert_gt(furthest, WALL_STOP_X - 2.0, "it rests on the wall")
	var last: Dictionary = rows[rows.size() - 1]
	assert_almost_eq(
		Vector2(str(last["avatar_x"]).to_float(), str(last["avatar_y"]).to_float()),
		_level.player.global_position,
		2.0,
		"the telemetry's avatar is the proxy the avatar is drawn at"
	)


func test_the_fifty_hertz_proxy_variant_moves_only_on_frames() -> void:
	_config.merge({"conditions": {"constraint": {"update": "frame"}}})
	var constraint: HapticsConstraint = HapticsConstraint.of(Haptics)
	var earlier: int = constraint.get_proxy().updates
	var result: TrialResult = await _push("constraint", Vector2.INF, Vector2(330.0, 180.0))
	var updates: int = constraint.get_proxy().updates
	var moved: int = updates - earlier if updates >= earlier else updates
	assert_gt(moved, 30, "the proxy moves on frames")
	assert_lt(moved, PUSH_TICKS * 3, "at the frame rate, not 1 kHz")
	assert_gt(result.wall_collisions, 0)
	assert_lt(_level.player.global_position.x, WALL_STOP_X + 0.5, "still stopped by the wall")


# Runs one recorded "trial": hand at the start, live, then the hand held at [hand]
# (normalised; or, in position control, over the maze point [point]) for PUSH_TICKS.
func _push(condition: String, hand: Vector2, point: Vector2 = Vector2.ZERO) -> TrialResult:
	set_timeout(20.0)
	var settings: Dictionary = _config.condition(condition)
	assert_true(_rig.setup(_level, condition, settings), "the server takes the condition")
	Haptics.device.set_hand_target(_rig.start_hand())
	var start: Vector2 = _rig.start_hand()
	var centred: bool = await wait_until(
		func() -> bool: return Haptics.device.get_position().distance_to(start) < 0.03, 3.0
	)
	assert_true(centred, "the simulated hand reaches the start")
	var settled: bool = await wait_until(func() -> bool: return _rig.is_settled(), 3.0)
	assert_true(settled, "no force is left over from before")
	_rig.go()
	var store: StudyStore = StudyStore.new(_root, "M01")
	store.create({})
	var stiffness: float = settings.get("stiffness", 0.0)
	var recorder: TrialRecorder = TrialRecorder.new(
		store, condition, "tiny_maze", 0, _rig.map, stiffness
	)
	assert_true(recorder.begin(_rig.avatar_position()), recorder.error)
	var target: Vector2 = hand if hand != Vector2.INF else _rig.map.hand_of(point)
	for i: int in PUSH_TICKS:
		Haptics.device.set_hand_target(target)
		await get_tree().physics_frame
		assert_true(recorder.tick(_rig.avatar_position(), 1.0 / Engine.physics_ticks_per_second))
	assert_true(recorder.finish(_rig.avatar_position(), PUSH_TICKS / 50.0, false))
	return recorder.result


func _telemetry(result: TrialResult) -> Array[Dictionary]:
	var path: String = _root.path_join("M01").path_join(result.telemetry_file)
	var lines: PackedStringArray = Support.lines_of(path)
	assert_eq(lines[0], ",".join(StudyFormat.telemetry_columns), "telemetry header")
	var rows: Array[Dictionary] = Support.records_of(path)
	var previous: float = -1.0
	for row: Dictionary in rows:
		var t: float = str(row["time_s"]).to_float()
		if t < previous:
			fail("time_s decreases at %s" % t)
			break
		previous = t
	var span: float = previous
	if span > 0.0:
		assert_gt((rows.size() - 1) / span, 250.0, "at least 250 Hz")
	return rows
