extends TestSuite
## The study's levels follow the [Level] contract and the paper's layout: the maze starts
## at its centre with the goal in the lower right; every level has walls for the
## constraint renderer, a start, a goal and an autopilot path that keeps clear of the
## walls (so the scripted participant reaches the goal).

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const LEVELS: PackedStringArray = [
	"res://game/study/levels/maze.tscn",
	"res://game/study/levels/demo_open.tscn",
	"res://game/study/levels/demo_corridors.tscn",
	"res://tests/study/fixtures/tiny_maze.tscn",
]


func test_every_level_follows_the_contract() -> void:
	for path: String in LEVELS:
		var level: StudyLevel = _load(path)
		if not assert_not_null(level, path + " is a StudyLevel"):
			continue
		assert_not_null(level.player, path + " has a Player")
		assert_not_null(level.get_goal(), path + " has a Goal")
		assert_true(StudyFormat.is_valid_level(level.level_id), path + " level id")
		var bounds: Rect2 = level.get_bounds()
		assert_true(bounds.has_area(), path + " has bounds")
		var segments: PackedVector2Array = level.get_wall_segments()
		assert_gt(segments.size(), 8, path + " has walls")
		assert_eq(segments.size() % 2, 0, path + " segments come in pairs")
		var route: PackedVector2Array = level.get_autopilot_path()
		assert_gt(route.size(), 1, path + " has an autopilot path")
		assert_almost_eq(route[0], level.get_spawn_position(), 1.0, path + " path starts at Start")
		assert_almost_eq(
			route[route.size() - 1], level.get_goal().global_position, 1.0, path + " ends at Goal"
		)
		assert_true(bounds.grow(1.0).has_point(level.get_spawn_position()), path + " start inside")
		level.free()


func test_the_maze_starts_at_the_centre_and_ends_lower_right() -> void:
	var level: StudyLevel = _load(LEVELS[0])
	var bounds: Rect2 = level.get_bounds()
	assert_eq(level.level_id, "maze")
	assert_almost_eq(level.get_spawn_position(), bounds.get_center(), 1.0, "start at the centre")
	var goal: Vector2 = level.get_goal().global_position
	assert_gt(goal.x, bounds.position.x + bounds.size.x * 0.85, "goal at the right")
	assert_gt(goal.y, bounds.position.y + bounds.size.y * 0.8, "goal at the bottom")
	assert_gt(level.get_autopilot_path().size(), 5, "a maze: several turns on the way")
	level.free()


func test_autopilot_paths_keep_clear_of_the_walls() -> void:
	for path: String in LEVELS:
		var level: StudyLevel = _load(path)
		var segments: PackedVector2Array = level.get_wall_segments()
		var route: PackedVector2Array = level.get_autopilot_path()
		var closest: float = INF
		for i: int in range(1, route.size()):
			for s: int in range(0, segments.size(), 2):
				closest = minf(
					closest, _segment_distance(route[i - 1], route[i], segments[s], segments[s + 1])
				)
		assert_gt(closest, Player.RADIUS + 4.0, "%s: path clearance %.1f px" % [path, closest])
		level.free()


func test_the_scripted_hand_solves_the_real_maze_in_both_control_schemes() -> void:
	set_timeout(60.0)
	var saved: Dictionary = ConditionRig.save_haptics()
	var config: StudyConfig = StudyConfig.load_default()
	for condition: String in ["movement", "constraint"]:
		var level: StudyLevel = _load(LEVELS[0])
		var rig: ConditionRig = add_child_autofree(ConditionRig.new()) as ConditionRig
		rig.piloted = true
		assert_true(rig.setup(level, condition, config.condition(condition)))
		var start: Vector2 = rig.start_hand()
		Haptics.device.set_hand_target(start)
		await wait_until(
			func() -> bool: return Haptics.device.get_position().distance_to(start) < 0.03, 3.0
		)
		rig.go()
		var pilot: StudyPilot = StudyPilot.new(
			level.get_autopilot_path(), config.number("autopilot_speed")
		)
		var began: int = Time.get_ticks_msec()
		var reached: bool = await wait_until(
			func() -> bool:
				rig.set_hand(pilot.steer(rig, 1.0 / Engine.physics_ticks_per_second))
				return level.is_goal_reached,
			25.0
		)
		var seconds: float = (Time.get_ticks_msec() - began) / 1000.0
		assert_true(reached, "%s: the goal is reached (%.1f s)" % [condition, seconds])
		rig.release()
		level.queue_free()
	ConditionRig.restore_haptics(saved)
	Haptics.device.set_hand_target(Vector2.ZERO)


func _load(path: String) -> StudyLevel:
	var scene: PackedScene = load(path) as PackedScene
	var level: StudyLevel = scene.instantiate() as StudyLevel
	if level != null:
		add_child(level)
	return level


# Shortest distance between segments ab and cd (they never cross here, checked below).
static func _segment_distance(a: Vector2, b: Vector2, c: Vector2, d: Vector2) -> float:
	if Geometry2D.segment_intersects_segment(a, b, c, d) != null:
		return 0.0
	return minf(
		minf(_point_distance(a, c, d), _point_distance(b, c, d)),
		minf(_point_distance(c, a, b), _point_distance(d, a, b))
	)


static func _point_distance(p: Vector2, a: Vector2, b: Vector2) -> float:
	return p.distance_to(Geometry2D.get_closest_point_to_segment(p, a, b))
