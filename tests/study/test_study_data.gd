extends TestSuite
## The study's data layer without levels: number and timestamp formats, the condition
## orders, the settings, the durable store (headers once, never overwriting), and the
## resume scan (complete, interrupted, truncated and corrupt folders).

const Support := preload("res://tests/study/study_test_support.gd")

## Every study script, compiled with the project's warnings raised to errors.
const STUDY_SCRIPTS: PackedStringArray = [
	"res://game/study/data/participant_state.gd",
	"res://game/study/data/study_config.gd",
	"res://game/study/data/study_format.gd",
	"res://game/study/data/study_store.gd",
	"res://game/study/levels/maze_walls.gd",
	"res://game/study/levels/study_goal.gd",
	"res://game/study/levels/study_level.gd",
	"res://game/study/levels/wall_segments.gd",
	"res://game/study/screens/centre_gauge.gd",
	"res://game/study/screens/final_screen.gd",
	"res://game/study/screens/message_screen.gd",
	"res://game/study/screens/rating_screen.gd",
	"res://game/study/screens/start_screen.gd",
	"res://game/study/screens/study_stage.gd",
	"res://game/study/screens/study_theme.gd",
	"res://game/study/session/answer_flow.gd",
	"res://game/study/session/condition_order.gd",
	"res://game/study/session/session_start.gd",
	"res://game/study/session/study_launch.gd",
	"res://game/study/session/study_runner.gd",
	"res://game/study/trials/condition_rig.gd",
	"res://game/study/trials/maze_map.gd",
	"res://game/study/trials/practice_flow.gd",
	"res://game/study/trials/study_participant.gd",
	"res://game/study/trials/study_probe.gd",
	"res://game/study/trials/trial_flow.gd",
	"res://game/study/trials/trial_recorder.gd",
	"res://game/study/data/trial_result.gd",
	"res://tests/drivers/scripted_participant.gd",
	"res://tests/drivers/study_pilot.gd",
	"res://tests/drivers/study_scripted.gd",
	"res://tests/drivers/wall_pushes.gd",
	"res://tests/study/study_test_support.gd",
	"res://tests/study/tour/study_tour.gd",
]

var _root: String = ""


func before_each() -> void:
	_root = Support.fresh_root("data")


func after_each() -> void:
	Support.remove_tree(_root)


func test_every_study_script_compiles_without_warnings() -> void:
	var enabled: int = await assert_scripts_compile_without_warnings(STUDY_SCRIPTS)
	assert_gt(enabled, 0, "project.godot enables some GDScript warnings")


func test_numbers_and_timestamps_follow_the_format() -> void:
	assert_eq(StudyFormat.number(1.23456, 3), "1.235")
	assert_eq(StudyFormat.number(-0.0001, 3), "0", "no negative zero")
	assert_eq(StudyFormat.number(NAN, 3), "0", "no nan")
	assert_eq(StudyFormat.number(INF, 3), "0", "no inf")
	assert_true(StudyFormat.is_number(StudyFormat.number(123456.789, 2)))
	var stamp: String = StudyFormat.timestamp(1746095467.125)
	assert_eq(stamp, "2025-05-01T10:31:07.125Z")
	assert_true(StudyFormat.is_timestamp(StudyFormat.timestamp()))
	assert_true(StudyFormat.is_valid_id("P07"))
	assert_true(StudyFormat.is_valid_id("p-7_a"))
	assert_false(StudyFormat.is_valid_id("_P07"))
	assert_false(StudyFormat.is_valid_id("P 07"))
	assert_false(StudyFormat.is_valid_id("P,07"))


func test_the_criteria_have_the_papers_wording() -> void:
	var expected: Dictionary = {
		"realism": ["Realism", "How realistic is the control scheme?"],
		"ease": ["Ease", "How easy is it to control the character?"],
		"aptness": ["Aptness", "How appropriate does the control feel?"],
		"intuitiveness": ["Intuitiveness", "How natural is the control?"],
		"enthusiasm": ["Enthusiasm", "How much did you enjoy this method?"],
		"partiality": ["Partiality", "How much do you prefer this method?"],
	}
	assert_eq(StudyFormat.criteria, PackedStringArray(expected.keys()))
	for criterion: String in expected:
		var text: Array = expected[criterion]
		assert_eq(StudyFormat.criterion_title(criterion), text[0])
		assert_eq(StudyFormat.criterion_question(criterion), text[1])


func test_demographic_values_are_the_format_lists() -> void:
	assert_eq(
		StudyFormat.demographic_values("age_band"),
		PackedStringArray(["under_20", "20-29", "30-39", "40-49", "50-59", "60+", "undisclosed"])
	)
	assert_eq(
		StudyFormat.demographic_values("gender"),
		PackedStringArray(["female", "male", "non_binary", "other", "undisclosed"])
	)
	assert_eq(
		StudyFormat.demographic_values("handedness"),
		PackedStringArray(["left", "right", "ambidextrous", "undisclosed"])
	)
	assert_eq(StudyFormat.demographic_values("hand_used"), PackedStringArray(["left", "right"]))
	assert_eq(
		StudyFormat.demographic_values("gaming_experience"),
		PackedStringArray(["none", "little", "some", "extensive"])
	)


func test_random_orders_are_reproducible_permutations() -> void:
	var seen: Dictionary[String, bool] = {}
	for order_seed: int in 60:
		var order: PackedStringArray = ConditionOrder.random_order(order_seed)
		assert_eq(order, ConditionOrder.random_order(order_seed), "same seed, same order")
		var sorted: PackedStringArray = order.duplicate()
		sorted.sort()
		assert_eq(sorted, PackedStringArray(["constraint", "movement", "none"]))
		seen[",".join(order)] = true
	assert_eq(seen.size(), 6, "all six orders occur")


func test_the_latin_square_balances_positions_and_carryover() -> void:
	var positions: Dictionary[String, int] = {}
	var pairs: Dictionary[String, int] = {}
	for row: int in 6:
		var order: PackedStringArray = ConditionOrder.latin_square_order(row)
		assert_eq(order, ConditionOrder.latin_square_order(row + 6), "rows repeat every 6")
		for i: int in 3:
			var key: String = "%s@%d" % [order[i], i]
			positions[key] = positions.get(key, 0) + 1
			if i > 0:
				var pair: String = order[i - 1] + ">" + order[i]
				pairs[pair] = pairs.get(pair, 0) + 1
	assert_eq(positions.size(), 9)
	for key: String in positions:
		assert_eq(positions[key], 2, "each condition twice in each position: " + key)
	assert_eq(pairs.size(), 6)
	for pair: String in pairs:
		assert_eq(pairs[pair], 2, "each ordered pair twice: " + pair)


func test_settings_merge_and_report_bad_values() -> void:
	var config: StudyConfig = StudyConfig.load_default()
	assert_true(config.is_valid(), ", ".join(config.errors))
	assert_eq(config.trials_per_condition(), 1)
	assert_true(config.force_enabled("movement", "normal"))
	assert_false(
		config.force_enabled("movement", "friction"), "the study renders normal force only"
	)
	assert_eq(config.condition("none")["force_scale"], 0.0)
	assert_eq(str(config.condition("constraint")["update"]), "servo")
	assert_eq(str(config.condition("movement")["contact_model"]), "paper_sum", "as the paper")
	assert_eq(str(config.condition("none")["contact_model"]), "paper_sum")
	config.merge({"conditions": {"movement": {"contact_model": "per_contact"}}})
	assert_true(config.is_valid(), ", ".join(config.errors))
	assert_eq(StudyConfig.choices("conditions.none.contact_model"), StudyFormat.contact_models)
	config.merge({"conditions": {"movement": {"forces": {"friction": true}}}})
	assert_true(config.force_enabled("movement", "friction"), "a single force switches")
	assert_true(config.force_enabled("movement", "normal"), "the others stay")
	config.merge({"trials_per_condition": 3.0, "conditions": {"constraint": {"update": "frame"}}})
	assert_true(config.is_valid(), ", ".join(config.errors))
	assert_eq(config.trials_per_condition(), 3)
	assert_eq(str(config.condition("constraint")["update"]), "frame")
	(
		config
		. merge(
			{
				"trials_per_condition": 0,
				"telemetry_decimation": 9,
				"bogus": 1,
				"counterbalancing": "alphabetical",
				"conditions":
				{
					"constraint": {"update": "sometimes"},
					"movement": {"contact_model": "sideways"},
				},
				"study_root": "res://study",
			}
		)
	)
	var text: String = "\n".join(config.errors)
	assert_has(text, "trials_per_condition")
	assert_has(text, "telemetry_decimation")
	assert_has(text, "unknown setting 'bogus'")
	assert_has(text, "counterbalancing")
	assert_has(text, "conditions.constraint.update")
	assert_has(text, "'conditions.movement.contact_model' must be per_contact or paper_sum")
	assert_has(text, "study_root")


func test_the_store_writes_each_header_once_and_never_overwrites() -> void:
	var store: StudyStore = StudyStore.new(_root, "P01")
	assert_false(store.has_data())
	assert_true(store.create(Support.meta("P01")), store.last_error)
	assert_true(store.has_data())
	assert_false(store.create(Support.meta("P01")), "participant.json is never written twice")
	assert_has(store.last_error, "never overwritten")
	assert_true(store.append_rating("none", 0, _ratings(5)), store.last_error)
	assert_true(store.append_rating("movement", 1, _ratings(7)), store.last_error)
	var lines: PackedStringArray = Support.lines_of(store.path_of("ratings.csv"))
	assert_eq(lines.size(), 3, "header + two records")
	assert_eq(lines[0], ",".join(StudyFormat.ratings_columns))
	assert_true(lines[1].begins_with("P01,none,0,5,5,5,5,5,5,"))
	assert_false(store.append_rating("constraint", 2, _ratings(11)), "out of range is refused")
	assert_eq(Support.lines_of(store.path_of("ratings.csv")).size(), 3, "and nothing written")
	assert_true(store.write_final(PackedStringArray(["constraint"]), 'text, with "quotes"'))
	assert_false(store.write_final(PackedStringArray(), ""), "final.json is never replaced")
	var final: Dictionary = Support.json_of(store.path_of("final.json"))
	assert_eq(final["favourite"], ["constraint"])
	assert_eq(final["differences_text"], 'text, with "quotes"')
	assert_eq(store.check_complete("ratings.csv"), 1)


func test_a_finished_session_replaces_only_participant_json() -> void:
	var store: StudyStore = StudyStore.new(_root, "P02")
	var meta: Dictionary = Support.meta("P02")
	assert_true(store.create(meta))
	meta["finished"] = StudyFormat.timestamp()
	assert_true(store.replace_participant(meta), store.last_error)
	var read: Dictionary = Support.json_of(store.path_of("participant.json"))
	assert_true(StudyFormat.is_timestamp(str(read["finished"])))
	assert_false(FileAccess.file_exists(store.path_of("participant.json.tmp")))


func test_a_resumed_record_keeps_its_integers() -> void:
	# A resumed session re-reads participant.json, where Godot's JSON parser turns every
	# number into a float; writing it back must not produce "seed": 12345.0.
	var store: StudyStore = StudyStore.new(_root, "P09")
	assert_true(store.create(Support.meta("P09")))
	var reread: Dictionary = Support.json_of(store.path_of("participant.json"))
	assert_eq(typeof(reread["seed"]), TYPE_FLOAT, "what the parser gives back")
	reread["finished"] = StudyFormat.timestamp()
	assert_true(store.replace_participant(reread), store.last_error)
	var text: String = FileAccess.get_file_as_string(store.path_of("participant.json"))
	assert_false(text.contains(".0,") or text.contains(".0\n"), text)
	assert_has(text, '"format_version": %d,' % StudyFormat.format_version)


func test_a_scan_finds_where_to_resume() -> void:
	var store: StudyStore = StudyStore.new(_root, "P03")
	assert_true(store.create(Support.meta("P03", ["movement", "none", "constraint"])))
	var state: ParticipantState = ParticipantState.scan(_root, "P03")
	assert_true(state.can_resume(), "\n".join(state.report_lines()))
	assert_eq(state.next_step(1)["step"], ParticipantState.Step.PRACTICE, "nothing done yet")
	assert_true(store.append_telemetry("telemetry/movement_0.csv", "0,0,0,1,1,0,0,0\n"))
	assert_true(store.append_trial(_trial("movement", 0)))
	state = ParticipantState.scan(_root, "P03")
	assert_eq(state.next_step(1), {"step": ParticipantState.Step.RATING, "order_index": 0})
	assert_eq(state.next_step(2), {"step": ParticipantState.Step.TRIALS, "order_index": 0})
	assert_true(store.append_rating("movement", 0, _ratings(6)))
	state = ParticipantState.scan(_root, "P03")
	assert_eq(state.next_step(1), {"step": ParticipantState.Step.TRIALS, "order_index": 1})
	assert_eq(state.next_index["movement"], 1)
	assert_eq(state.next_index["none"], 0)


func test_an_interrupted_trial_never_gets_its_index_again() -> void:
	var store: StudyStore = StudyStore.new(_root, "P04")
	assert_true(store.create(Support.meta("P04")))
	assert_true(store.append_telemetry("telemetry/none_0.csv", "0,0,0,1,1,0,0,0\n"))
	assert_true(store.append_trial(_trial("none", 0)))
	assert_true(store.append_rating("none", 0, _ratings(4)))
	# A crash during the next trial leaves its telemetry without a trials.csv record.
	assert_true(store.append_telemetry("telemetry/movement_0.csv", "0,0,0,1,1,0,0,0\n"))
	var state: ParticipantState = ParticipantState.scan(_root, "P04")
	assert_true(state.can_resume(), "\n".join(state.report_lines()))
	assert_eq(state.trial_counts["movement"], 0, "the interrupted trial does not count")
	assert_eq(state.next_index["movement"], 1, "but its index is used up")
	assert_has("\n".join(state.notes), "movement_0.csv: no trials.csv record")


func test_a_truncated_or_corrupt_file_is_reported() -> void:
	var store: StudyStore = StudyStore.new(_root, "P05")
	assert_true(store.create(Support.meta("P05")))
	assert_true(store.append_rating("none", 0, _ratings(4)))
	var durable: DurableFile = DurableFile.new()
	var native: String = StudyStore.native_path(store.path_of("ratings.csv"))
	durable.append(native, "P05,movement,1,4,4")
	var state: ParticipantState = ParticipantState.scan(_root, "P05")
	assert_false(state.can_resume())
	assert_has("\n".join(state.problems), "P05/ratings.csv:3: truncated record")
	# A record with a bad value is a problem too, with its line.
	var trials: String = StudyStore.native_path(store.path_of("trials.csv"))
	var header: String = ",".join(StudyFormat.trials_columns) + "\n"
	durable.append(trials, header + "P05,none,maze,0,paper_sum,-1,1,0,0,0,0,0,,x\n")
	durable.append(trials, "P05,movement,maze,0,sum,1,1,0,0,0,0,0,,%s\n" % StudyFormat.timestamp())
	state = ParticipantState.scan(_root, "P05")
	var text: String = "\n".join(state.problems)
	assert_has(text, "P05/trials.csv:2: time_to_goal_s '-1'")
	assert_has(text, "P05/trials.csv:2: timestamp 'x'")
	assert_has(text, "P05/trials.csv:3: contact_model 'sum' is not empty or one of")


func test_a_broken_participant_json_is_reported() -> void:
	DirAccess.make_dir_recursive_absolute(_root.path_join("P06"))
	var file: FileAccess = FileAccess.open(
		_root.path_join("P06/participant.json"), FileAccess.WRITE
	)
	file.store_string('{"format_version": 1, "participant_id": ')
	file.close()
	var state: ParticipantState = ParticipantState.scan(_root, "P06")
	assert_false(state.can_resume())
	assert_has("\n".join(state.problems), "P06/participant.json:1: not valid JSON")


func test_wall_segments_cover_polygons_rectangles_and_circles() -> void:
	var space: Node2D = add_child_autofree(Node2D.new()) as Node2D
	space.position = Vector2(100.0, 50.0)
	var body: StaticBody2D = StaticBody2D.new()
	body.position = Vector2(10.0, 0.0)
	space.add_child(body)
	var polygon: CollisionPolygon2D = CollisionPolygon2D.new()
	polygon.polygon = PackedVector2Array([Vector2(0, 0), Vector2(10, 0), Vector2(10, 10)])
	body.add_child(polygon)
	var rect_holder: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = Vector2(20.0, 10.0)
	rect_holder.shape = rect
	rect_holder.position = Vector2(50.0, 50.0)
	body.add_child(rect_holder)
	var circle_holder: CollisionShape2D = CollisionShape2D.new()
	var circle: CircleShape2D = CircleShape2D.new()
	circle.radius = 5.0
	circle_holder.shape = circle
	body.add_child(circle_holder)
	var disabled: CollisionShape2D = CollisionShape2D.new()
	disabled.shape = rect
	disabled.disabled = true
	body.add_child(disabled)
	var segments: PackedVector2Array = WallSegments.extract([body] as Array[Node], space)
	var expected: int = 2 * (3 + 4 + WallSegments.ARC_SEGMENTS)
	assert_eq(segments.size(), expected, "3 + 4 + a 24-gon, the disabled shape skipped")
	assert_almost_eq(segments[0], Vector2(10.0, 0.0), 1e-4, "in the reference node's space")
	assert_almost_eq(segments[2], Vector2(20.0, 0.0), 1e-4)
	var box: Rect2 = WallSegments.bounds_of(segments.slice(6, 14))
	assert_almost_eq(box.position, Vector2(50.0, 45.0), 1e-4, "rectangle around its centre")
	assert_almost_eq(box.size, Vector2(20.0, 10.0), 1e-4)
	for i: int in range(14, segments.size()):
		assert_almost_eq(segments[i].distance_to(Vector2(10.0, 0.0)), 5.0, 1e-3, "on the circle")


func test_the_maze_map_matches_the_disc_mapping() -> void:
	var map: MazeMap = MazeMap.new(Rect2(0.0, 0.0, 300.0, 400.0), "disc", 0.0, 0.1)
	assert_almost_eq(map.metres_per_unit(), 0.2 / 500.0, 1e-9, "the diagonal spans 2R")
	assert_almost_eq(map.hand_of(Vector2(150.0, 200.0)), Vector2.ZERO, 1e-6, "centre to centre")
	assert_almost_eq(map.hand_of(Vector2(300.0, 400.0)).length(), 1.0, 1e-6, "corner on the rim")
	assert_almost_eq(map.point_of_hand(map.hand_of(Vector2(10, 20))), Vector2(10, 20), 1e-3)
	var square: MazeMap = MazeMap.new(Rect2(0.0, 0.0, 300.0, 400.0), "square", 0.05, 0.1)
	assert_almost_eq(square.metres_per_unit(), 0.1 / 400.0, 1e-9, "the longer side spans 2R")


func _ratings(value: int) -> Dictionary:
	var out: Dictionary = {}
	for criterion: String in StudyFormat.criteria:
		out[criterion] = value
	return out


func _trial(condition: String, index: int) -> TrialResult:
	var result: TrialResult = TrialResult.new()
	result.condition = condition
	result.level = "maze"
	result.trial_index = index
	result.time_s = 10.0
	result.completed = true
	result.telemetry_file = StudyFormat.telemetry_name(condition, index)
	return result
