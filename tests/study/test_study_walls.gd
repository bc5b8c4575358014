extends TestSuite
## The participant who touches the walls: a whole scripted session on the tiny maze in
## which, in every condition, the scripted hand first pushes into the walls around the start
## (straight in and at ±30°, then turned away; in position control through them) and then
## goes to the goal. The data must say what each condition's configuration says: one probe
## on the avatar at every tick, no impact transient anywhere (impacts are off), the
## movement condition's force bounded by k |i| and equal to the paper's -k (i.n) n once
## settled, its pull into a wall after turning away no longer than two physics frames, no
## force at all without feedback, a constraint proxy that rests on the walls and never enters
## one, contact flags that match the geometry, and trial metrics a reader recomputes from
## the files.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const Support := preload("res://tests/study/study_test_support.gd")
const Geometry := preload("res://tests/study/wall_geometry.gd")
const Checks := preload("res://tests/study/telemetry_checks.gd")
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")
const TINY_MAZE: PackedScene = preload("res://tests/study/fixtures/tiny_maze.tscn")
const WALL_CONFIG: String = "res://tests/study/fixtures/wall_study.json"
const PARTICIPANT: String = "W01"
## Game seconds the session may take (seven pushes and the way to the goal per condition).
const SESSION_S: float = 150.0
## Rows the force needs to settle after the input or the contact changed: 0.12 s at 500 Hz
## (the 13 Hz smoothing's step response is within 1 % after about 0.08 s).
const SETTLE_ROWS: int = 60
## Input change (input units) a settled row may have seen in its window.
const STEADY_INPUT: float = 0.01
## The movement force law's tolerance, newtons (stiffness 3 instead of 2 is off by ~0.4 N).
const LAW_N: float = 0.05
## The smoothing's largest overshoot of a step (2nd-order Butterworth: 4.3 %), as a factor.
const OVERSHOOT: float = 1.05
## Longest pull into a wall after turning away: two physics frames, plus one row.
const MAX_PULL_S: float = 2.0 / 50.0 + 0.002
## The same in the recorded force, which the 13 Hz smoothing delays by ~17 ms and lets
## settle within ~40 ms of the rendered pull's end: two frames plus that settling.
const MAX_FELT_PULL_S: float = MAX_PULL_S + 0.04
## Contact flags match the walls in at least this share of rows.
const AGREEMENT: float = 0.95
## Pushes of the scripted hand that must show up as wall collisions, at least.
const MIN_COLLISIONS: int = 5
## Releases seen in the data, at least (5 to 7 of the 7 pushes are: a release counts only
## while the row before it still has the contact flag).
const MIN_RELEASES: int = 3
## The phases in which the maze is shown under the current condition.
const CONDITION_SET_UP: Array[StudySession.Phase] = [
	StudySession.Phase.INTRO,
	StudySession.Phase.CENTRING,
	StudySession.Phase.TRIAL,
	StudySession.Phase.ENDED,
]

var _root: String = ""
# Per condition (or "practice"): the probe counts seen on the avatar at the physics ticks
# its maze was shown, and the largest impact force the server rendered during its trial.
var _probe_counts: Dictionary[String, Array] = {}
var _largest_impact: Dictionary[String, float] = {}


func before_each() -> void:
	_root = Support.fresh_root("walls")
	_probe_counts.clear()
	_largest_impact.clear()


func after_each() -> void:
	Haptics.device.set_hand_target(Vector2.ZERO)
	Support.remove_tree(_root)


func test_the_rig_leaves_the_avatar_exactly_one_probe() -> void:
	var saved: Dictionary = ConditionRig.save_haptics()
	var level: StudyLevel = add_child_autofree(TINY_MAZE.instantiate()) as StudyLevel
	var rig: ConditionRig = add_child_autofree(ConditionRig.new()) as ConditionRig
	rig.piloted = true
	var config: StudyConfig = StudyConfig.load_default()
	assert_eq(ConditionRig.probes_on(level.player).size(), 1, "the player scene brings one")
	for condition: String in ["movement", "none", "constraint", "movement"]:
		assert_true(rig.setup(level, condition, config.condition(condition)), condition)
		var probes: Array[HapticProbe] = ConditionRig.probes_on(level.player)
		assert_eq(probes.size(), 1, "%s: one probe on the avatar" % condition)
		if not probes.is_empty():
			assert_eq(probes[0], rig.probe, "%s: the rig's own" % condition)
		await wait_physics_frames(2)
		rig.release()
	assert_eq(ConditionRig.probes_on(level.player).size(), 0, "released: none left")
	ConditionRig.restore_haptics(saved)


func test_the_wall_touching_participant_records_what_each_condition_renders() -> void:
	set_timeout(SESSION_S + 60.0)
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = _root
	study.config_path = WALL_CONFIG
	var participant: ScriptedParticipant = ScriptedParticipant.new(PARTICIPANT)
	participant.touch_walls = true
	participant.take_part_in(study)
	add_child_autofree(study)
	var frames: int = 0
	while study.phase != StudySession.Phase.DONE and frames < SESSION_S * 50.0:
		await get_tree().physics_frame
		_sample(study)
		frames += 1
	if not assert_eq(study.phase, StudySession.Phase.DONE, "the session ends"):
		return
	var folder: String = _root.path_join(PARTICIPANT)
	var meta: Dictionary = Support.json_of(folder.path_join("participant.json"))
	var gap: float = meta.get("contact_gap_s", -1.0)
	assert_almost_eq(gap, study.config.number("contact_gap_s"), 1e-9, "the gap is recorded")
	assert_eq(_probe_counts.get("practice", []), [1], "practice: always one probe")
	var geometry: Geometry = Geometry.new()
	geometry.read_level(TINY_MAZE)
	var checks: Checks = Checks.new(geometry)
	checks.dead_zone = Haptics.servo.get_settings().input.dead_zone
	var records: Array[Dictionary] = Support.records_of(folder.path_join("trials.csv"))
	assert_eq(records.size(), 3, "one trial per condition")
	for record: Dictionary in records:
		var condition: String = record["condition"]
		var rows: Array[PackedFloat64Array] = Checks.read_rows(
			folder.path_join(str(record["telemetry_file"]))
		)
		if not assert_gt(rows.size(), 500, "%s: telemetry" % condition):
			continue
		assert_eq(_probe_counts.get(condition, []), [1], "%s: one probe at every tick" % condition)
		var impact: float = _largest_impact.get(condition, -1.0)
		assert_almost_eq(impact, 0.0, 1e-6, "%s: no impact transient (impacts off)" % condition)
		assert_eq(record["completed"], "1", "%s: the goal reached after the pushes" % condition)
		_check_metrics(condition, record, rows, gap)
		_check_contacts(condition, rows, checks)
		var settings: Dictionary = study.config.condition(condition)
		match condition:
			"none":
				assert_eq(Checks.metrics(rows, gap)["max_force_n"], 0.0, "none: never a force")
			"movement":
				var k: float = settings.get("stiffness", 0.0)
				_check_movement(rows, checks, k)
			"constraint":
				_check_constraint(rows, checks)


func _sample(study: StudyRunner) -> void:
	var stage: StudyStage = study.get_stage()
	if stage == null or not is_instance_valid(stage.level):
		return
	var phase: StudySession.Phase = study.phase
	var key: String = "practice" if phase == StudySession.Phase.PRACTICE else ""
	if phase in CONDITION_SET_UP:
		key = study.current_condition()
	if phase == StudySession.Phase.TRIAL:
		var impact: Vector2 = Haptics.get_forces().impact
		var largest: float = _largest_impact.get(key, 0.0)
		_largest_impact[key] = maxf(largest, impact.length())
	if key.is_empty():
		return
	var count: int = ConditionRig.probes_on(stage.level.player).size()
	var seen: Array = _probe_counts.get_or_add(key, [])
	if count not in seen:
		seen.append(count)


func _check_metrics(
	condition: String, record: Dictionary, rows: Array[PackedFloat64Array], gap: float
) -> void:
	var recomputed: Dictionary = Checks.metrics(rows, gap)
	var tolerances: Dictionary = {
		"mean_force_n": 1.5e-4,
		"max_force_n": 1.5e-4,
		"contact_time_s": 1.5e-3,
		"path_length_px": 0.06,
		"wall_collisions": 0.0,
	}
	for metric: String in tolerances:
		var recorded: float = str(record[metric]).to_float()
		var expected: float = recomputed[metric]
		if metric == "contact_time_s":
			expected = minf(expected, str(record["time_to_goal_s"]).to_float())
		var tolerance: float = tolerances[metric]
		assert_almost_eq(
			recorded, expected, tolerance, "%s: %s recomputed from the file" % [condition, metric]
		)
	var collisions: int = recomputed["wall_collisions"]
	assert_gt(collisions, MIN_COLLISIONS - 1, "%s: the participant hit the walls" % condition)


func _check_contacts(condition: String, rows: Array[PackedFloat64Array], checks: Checks) -> void:
	var agreement: Dictionary = checks.contact_agreement(rows)
	var share: float = agreement["share"]
	var closest: float = agreement["closest"]
	print(
		(
			"    %s: contact flags match the walls in %.2f %% of %d rows; closest approach %.3f px"
			% [condition, share * 100.0, rows.size(), closest]
		)
	)
	assert_gt(share, AGREEMENT, "%s: contact flags match the geometry" % condition)
	# The proxy is kept exactly out (rounding to 0.01 px aside); the physics body may sink
	# by its safe margin.
	var allowed: float = 0.03 if StudyFormat.is_position_control(condition) else 0.5
	assert_gt(closest, Player.RADIUS - allowed, "%s: never inside a wall" % condition)


func _check_movement(rows: Array[PackedFloat64Array], checks: Checks, k: float) -> void:
	var bound: Dictionary = checks.force_bound(rows, k, OVERSHOOT, SETTLE_ROWS)
	var largest: float = bound["largest"]
	var largest_input: float = bound["largest_input"]
	print("    movement: largest force %.3f N (k |i| = %.3f N)" % [largest, k * largest_input])
	var excess: float = bound["excess"]
	# At rest both are 0: the excess is never above 0 (the file's rounding aside).
	assert_lt(excess, 1e-4, "the force never exceeds %.2f k |i| (k = %.1f)" % [OVERSHOOT, k])
	var law: Dictionary = checks.normal_force_law(rows, k, SETTLE_ROWS, STEADY_INPUT)
	var settled: int = law["rows"]
	var worst: float = law["worst"]
	print("    movement: %d settled rows, largest |F + k (i.n) n| %.4f N" % [settled, worst])
	assert_gt(settled, 100, "settled rows pressed into one wall")
	assert_lt(worst, LAW_N, "F = -k (i.n) n with the configured k")
	var pulls: Dictionary = checks.pulls(rows, k)
	var releases: int = pulls["releases"]
	print("    movement: %d releases of a wall the avatar touched" % releases)
	assert_gt(releases, MIN_RELEASES - 1, "the hand turned away from walls it touched")
	var by_model: Array = pulls["rendered"]
	var in_force: Array = pulls["felt"]
	var rendered: float = _print_durations("rendered by the model", by_model)
	assert_lt(rendered, MAX_PULL_S, "the model pulls for at most two physics frames")
	var felt: float = _print_durations("in the recorded (smoothed) force", in_force)
	assert_lt(felt, MAX_FELT_PULL_S, "the recorded pull ends when the smoothing has settled")


# Prints [param durations] (seconds) in milliseconds; returns the longest (0 without any).
func _print_durations(what: String, durations: Array) -> float:
	var shown: PackedStringArray = PackedStringArray()
	var longest: float = 0.0
	for duration: float in durations:
		shown.append("%.0f" % (duration * 1000.0))
		longest = maxf(longest, duration)
	print("    movement: pull into the wall after turning away, %s, ms:" % what)
	print("      [%s]" % ", ".join(shown))
	return longest


func _check_constraint(rows: Array[PackedFloat64Array], checks: Checks) -> void:
	var map: MazeMap = MazeMap.new(
		Rect2(0.0, 0.0, 360.0, 360.0), "disc", 0.0, Haptics.device.get_workspace_radius()
	)
	var law: Dictionary = checks.proxy_law(rows, map, 20)
	print(
		(
			(
				"    constraint: %d held rows, proxy off the wall's surface by at most %.3f px, "
				+ "force off the normal by at most %.4f; free rows' force at most %.4f N; "
				+ "the hand reached %.1f px from the proxy"
			)
			% [law["held"], law["off_surface"], law["off_normal"], law["free_force"], law["reach"]]
		)
	)
	assert_gt(law["held"], 100, "the proxy was held by walls")
	assert_lt(law["off_surface"], 0.1, "a held proxy rests on the wall's surface")
	assert_lt(law["off_normal"], 0.01, "the force pushes the hand back along the wall's normal")
	assert_lt(law["free_force"], 0.01, "a free proxy renders no force")
	assert_gt(law["reach"], Player.RADIUS + 14.0, "the hand went through the 14 px walls")
