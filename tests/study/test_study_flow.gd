extends TestSuite
## Whole study sessions in this process, on the tiny maze: a scripted participant goes from
## the start screen through practice, the three conditions (autopilot-driven trials) and
## their ratings to the favourite, and the files match FORMAT.md (also according to the
## analysis tool); a duplicate id is refused; a truncated ratings.csv is reported at resume
## and nothing is changed; invalid settings stop the study with a message.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const Support := preload("res://tests/study/study_test_support.gd")
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")

var _root: String = ""


func before_each() -> void:
	_root = Support.fresh_root("flow")


func after_each() -> void:
	Haptics.device.set_hand_target(Vector2.ZERO)
	Support.remove_tree(_root)


func test_a_scripted_participant_completes_the_study() -> void:
	set_timeout(150.0)
	var started: int = Time.get_ticks_msec()
	var study: StudyRunner = _study("P01")
	var recorded: Array[TrialResult] = []
	study.trial_recorded.connect(func(result: TrialResult) -> void: recorded.append(result))
	var done: bool = await wait_until(
		func() -> bool: return study.phase == StudySession.Phase.DONE, 60.0
	)
	if not assert_true(done, "the session ends (phase %d)" % study.phase):
		return
	print("    session took %.1f s" % ((Time.get_ticks_msec() - started) / 1000.0))
	assert_true(study.get_screen() is MessageScreen, "the thank-you shows")
	var folder: String = _root.path_join("P01")
	var meta: Dictionary = Support.json_of(folder.path_join("participant.json"))
	var order: PackedStringArray = ConditionOrder.random_order(12345)
	assert_eq(meta["format_version"], float(StudyFormat.format_version))
	assert_eq(meta["participant_id"], "P01")
	assert_eq(meta["seed"], 12345.0, "the seed from the settings is recorded")
	var written: Array = meta["condition_order"]
	assert_eq(PackedStringArray(written), order, "the order drawn from it")
	assert_eq(meta["counterbalancing"], "random")
	var profile: Dictionary = ScriptedParticipant.profile_of("P01")
	assert_eq(meta["demographics"], profile["demographics"], "the scripted demographics")
	assert_true(StudyFormat.is_timestamp(str(meta["started"])))
	assert_true(StudyFormat.is_timestamp(str(meta["finished"])), "finished is set at the end")
	_check_ratings(folder, order)
	_check_trials(folder, order, recorded)
	var final: Dictionary = Support.json_of(folder.path_join("final.json"))
	assert_eq(final["participant_id"], "P01")
	var favourite: Array = []
	for position: int in profile["favourite"]:
		favourite.append(order[position])
	assert_eq(final["favourite"], favourite, "the scripted favourite, by presentation position")
	assert_has(str(final["differences_text"]), "Scripted run")
	var state: ParticipantState = ParticipantState.scan(_root, "P01")
	assert_eq(state.problems, PackedStringArray(), "the study's own checker accepts it")
	assert_eq(state.next_step(1)["step"], ParticipantState.Step.DONE)
	_check_with_the_analysis_tool()


func test_scripted_participants_vary_their_demographics_and_favourites() -> void:
	var values: Dictionary[String, Dictionary] = {}
	var counts: Dictionary[int, int] = {}
	var favourites: Dictionary[String, bool] = {}
	for i: int in 30:
		var profile: Dictionary = ScriptedParticipant.profile_of("P%02d" % i)
		var demographics: Dictionary = profile["demographics"]
		for key: String in StudyFormat.demographic_keys():
			var value: String = demographics[key]
			assert_has(StudyFormat.demographic_values(key), value, key)
			var seen: Dictionary = values.get_or_add(key, {})
			seen[value] = true
		var favourite: PackedInt32Array = profile["favourite"]
		counts[favourite.size()] = counts.get(favourite.size(), 0) + 1
		favourites[str(favourite)] = true
	for key: String in StudyFormat.demographic_keys():
		var seen: Dictionary = values[key]
		assert_gt(seen.size(), 1, "%s varies across participants" % key)
	for size: int in [0, 1, 2]:
		assert_gt(counts.get(size, 0), 0, "some participants name %d favourites" % size)
	assert_gt(favourites.size(), 3, "and not always the same ones")


func test_a_duplicate_id_is_refused() -> void:
	var store: StudyStore = StudyStore.new(_root, "P02")
	assert_true(store.create({"participant_id": "P02", "note": "earlier session"}))
	var before: String = FileAccess.get_file_as_string(store.path_of("participant.json"))
	var study: StudyRunner = _study("P02")
	await wait_process_frames(5)
	assert_eq(study.phase, StudySession.Phase.START, "the study does not start")
	var screen: StartScreen = study.get_screen() as StartScreen
	assert_has(screen.problem_label.text, "P02 already has data")
	assert_has(screen.problem_label.text, "Resume participant")
	assert_true(screen.problem_label.visible)
	assert_eq(FileAccess.get_file_as_string(store.path_of("participant.json")), before, "untouched")


func test_a_truncated_ratings_file_is_reported_at_resume() -> void:
	var store: StudyStore = StudyStore.new(_root, "P03")
	var order: Array = ["movement", "none", "constraint"]
	assert_true(store.create(Support.meta("P03", order)))
	assert_true(store.append_telemetry("telemetry/movement_0.csv", "0,0,0,1,1,0,0,0\n"))
	var trial: TrialResult = TrialResult.new()
	trial.condition = "movement"
	trial.level = "tiny_maze"
	trial.telemetry_file = "telemetry/movement_0.csv"
	assert_true(store.append_trial(trial))
	var ratings: Dictionary = {}
	for criterion: String in StudyFormat.criteria:
		ratings[criterion] = 6
	assert_true(store.append_rating("movement", 0, ratings))
	var durable: DurableFile = DurableFile.new()
	durable.append(StudyStore.native_path(store.path_of("ratings.csv")), "P03,none,1,7,7")
	var before: String = FileAccess.get_file_as_string(store.path_of("ratings.csv"))
	expect_error("P03/ratings.csv:3: truncated record")
	var study: StudyRunner = _study("P03", true)
	await wait_process_frames(5)
	assert_eq(study.phase, StudySession.Phase.START, "the session is not resumed")
	var screen: StartScreen = study.get_screen() as StartScreen
	assert_has(screen.problem_label.text, "Cannot resume P03")
	assert_has(screen.problem_label.text, "P03/ratings.csv:3: truncated record")
	assert_has(
		study.report,
		(
			"P03/ratings.csv:3: truncated record: the last line has no "
			+ ("terminating newline ('P03,none,1,7,7')")
		)
	)
	assert_eq(FileAccess.get_file_as_string(store.path_of("ratings.csv")), before, "untouched")


func test_invalid_settings_stop_the_study_with_a_message() -> void:
	_write_root_config('{"trials_per_condition": 0}')
	expect_error("trials_per_condition")
	var study: StudyRunner = _study("P04")
	await wait_process_frames(3)
	assert_eq(study.phase, StudySession.Phase.STOPPED)
	var screen: MessageScreen = study.get_screen() as MessageScreen
	if assert_not_null(screen, "a message explains why"):
		assert_has(screen.body.text, "trials_per_condition")
	assert_false(DirAccess.dir_exists_absolute(_root.path_join("P04")), "nothing written")


func test_a_trial_that_runs_out_of_time_is_recorded_unfinished() -> void:
	set_timeout(30.0)
	_write_root_config('{"trial_timeout_s": 1.0}')
	var study: StudyRunner = _study("P05")
	(study.participant as ScriptedParticipant).hold_s = 3.0
	var recorded: Array[TrialResult] = []
	study.trial_recorded.connect(func(result: TrialResult) -> void: recorded.append(result))
	var ended: bool = await wait_until(func() -> bool: return not recorded.is_empty(), 20.0)
	if not assert_true(ended, "the first trial ends"):
		return
	assert_false(recorded[0].completed, "the goal was not reached")
	assert_almost_eq(recorded[0].time_s, 1.0, 0.021, "it ended at the time limit")
	var records: Array[Dictionary] = Support.records_of(_root.path_join("P05/trials.csv"))
	assert_eq(records.size(), 1)
	assert_eq(records[0]["completed"], "0")


func test_several_trials_per_condition_count_their_indices() -> void:
	set_timeout(30.0)
	_write_root_config('{"trials_per_condition": 2}')
	var study: StudyRunner = _study("P07")
	var phases: Array[StudySession.Phase] = []
	study.phase_changed.connect(func(phase: StudySession.Phase) -> void: phases.append(phase))
	var rated: bool = await wait_until(
		func() -> bool: return StudySession.Phase.RATING in phases, 20.0
	)
	if not assert_true(rated, "the first condition's rating comes after its trials"):
		return
	var records: Array[Dictionary] = Support.records_of(_root.path_join("P07/trials.csv"))
	assert_eq(records.size(), 2, "two trials before the rating")
	var first: String = ConditionOrder.random_order(12345)[0]
	for i: int in records.size():
		assert_eq(records[i]["condition"], first)
		assert_eq(records[i]["trial_index"], str(i))
		assert_eq(records[i]["telemetry_file"], "telemetry/%s_%d.csv" % [first, i])


func test_latin_square_orders_follow_the_participants_in_the_folder() -> void:
	_write_root_config('{"counterbalancing": "latin_square"}')
	for id: String in ["A1", "A2"]:
		assert_true(StudyStore.new(_root, id).create({"participant_id": id}))
	var study: StudyRunner = _study("A3")
	var started: bool = await wait_until(
		func() -> bool: return study.phase == StudySession.Phase.PRACTICE, 5.0
	)
	assert_true(started)
	var meta: Dictionary = Support.json_of(_root.path_join("A3/participant.json"))
	assert_eq(meta["counterbalancing"], "latin_square")
	assert_eq(meta["participant_number"], 2.0, "the third participant of the folder")
	var order: Array = meta["condition_order"]
	assert_eq(PackedStringArray(order), ConditionOrder.latin_square_order(2))


func test_leaving_the_study_gives_back_the_haptics_settings() -> void:
	var saved: float = Haptics.force_scale
	Haptics.force_scale = 0.7
	var model: HapticMovementFacts.ContactModel = _contact_model()
	var study: StudyRunner = _study("P06")
	var in_trial: bool = await wait_until(
		func() -> bool: return study.phase == StudySession.Phase.TRIAL, 15.0
	)
	assert_true(in_trial, "a trial runs")
	assert_false(Haptics.hand_follows_input, "the scripted participant holds the hand")
	var condition: String = study.current_condition()
	if not StudyFormat.is_position_control(condition):
		assert_eq(_contact_model(), HapticMovementFacts.ContactModel.PAPER_SUM, condition)
	study.queue_free()
	await wait_process_frames(2)
	assert_almost_eq(Haptics.force_scale, 0.7, 1e-6, "force scale given back")
	assert_true(Haptics.hand_follows_input, "the mouse moves the hand again")
	assert_true(Haptics.smoothing_enabled)
	assert_eq(str(Haptics.get_render_mode()), "movement")
	assert_eq(_contact_model(), model, "contact model given back")
	Haptics.force_scale = saved


func _write_root_config(text: String) -> void:
	var file: FileAccess = FileAccess.open(_root.path_join("study_config.json"), FileAccess.WRITE)
	file.store_string(text)
	file.close()


func _study(id: String, resume: bool = false) -> StudyRunner:
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = _root
	study.config_path = Support.TINY_CONFIG
	ScriptedParticipant.new(id, resume).take_part_in(study)
	add_child_autofree(study)
	return study


func _check_ratings(folder: String, order: PackedStringArray) -> void:
	var path: String = folder.path_join("ratings.csv")
	assert_eq(Support.lines_of(path)[0], ",".join(StudyFormat.ratings_columns))
	var records: Array[Dictionary] = Support.records_of(path)
	assert_eq(records.size(), 3, "one rating record per condition")
	for i: int in records.size():
		var record: Dictionary = records[i]
		assert_eq(record["condition"], order[i], "rated in the order presented")
		assert_eq(record["order_index"], str(i))
		for criterion: String in StudyFormat.criteria:
			var value: String = record[criterion]
			assert_true(StudyFormat.is_integer(value) and value.to_int() in range(1, 11), value)
		assert_true(StudyFormat.is_timestamp(str(record["timestamp"])))


func _check_trials(folder: String, order: PackedStringArray, recorded: Array[TrialResult]) -> void:
	var path: String = folder.path_join("trials.csv")
	assert_eq(Support.lines_of(path)[0], ",".join(StudyFormat.trials_columns))
	var records: Array[Dictionary] = Support.records_of(path)
	assert_eq(records.size(), 3, "one maze trial per condition")
	assert_eq(recorded.size(), 3, "trial_recorded for each")
	for i: int in records.size():
		var record: Dictionary = records[i]
		var condition: String = order[i]
		assert_eq(record["condition"], condition)
		assert_eq(record["level"], "tiny_maze")
		assert_eq(record["trial_index"], "0")
		var model: String = "" if StudyFormat.is_position_control(condition) else "paper_sum"
		assert_eq(record["contact_model"], model, "%s: the renderer's contact model" % condition)
		assert_eq(recorded[i].contact_model, model)
		assert_eq(record["completed"], "1", "the autopilot reached the goal")
		for column: String in ["time_to_goal_s", "contact_time_s", "path_length_px"]:
			assert_true(StudyFormat.is_number(str(record[column])), column)
		assert_gt(str(record["time_to_goal_s"]).to_float(), 0.2)
		assert_gt(str(record["path_length_px"]).to_float(), 150.0, "start to goal is ~240 px")
		if condition == "none":
			assert_eq(record["max_force_n"], "0", "no feedback renders no force")
		var telemetry: String = record["telemetry_file"]
		assert_eq(telemetry, "telemetry/%s_0.csv" % condition)
		var rows: PackedStringArray = Support.lines_of(folder.path_join(telemetry))
		assert_eq(rows[0], ",".join(StudyFormat.telemetry_columns))
		var seconds: float = str(record["time_to_goal_s"]).to_float()
		assert_gt(rows.size(), seconds * 250.0, "%s: at least 250 Hz" % telemetry)
		assert_eq(rows[rows.size() - 1].split(",").size(), 8)


# The analysis tool of the repository reads the folder without complaint (skipped when
# Python 3 is missing; the first run builds its virtualenv, ~40 s).
func _check_with_the_analysis_tool() -> void:
	if OS.execute("bash", ["-c", "command -v python3"]) != 0:
		print("    python3 missing: analysis check skipped")
		return
	var out: String = _root.path_join("_analysis")
	var output: Array = []
	var code: int = (
		OS
		. execute(
			"bash",
			[
				ProjectSettings.globalize_path("res://tools/analysis/run.sh"),
				"analyze.py",
				ProjectSettings.globalize_path(_root),
				"--out",
				ProjectSettings.globalize_path(out),
			],
			output,
			true
		)
	)
	assert_eq(code, 0, "analyze.py accepts the data:\n%s" % "".join(output))
	var summary: Dictionary = Support.json_of(out.path_join("summary.json"))
	assert_eq(summary.get("warnings"), [], "and has no warnings about it")
	assert_true(FileAccess.file_exists(out.path_join("report.md")))
	assert_true(FileAccess.file_exists(out.path_join("fig7_total.png")))


func _contact_model() -> HapticMovementFacts.ContactModel:
	return HapticsMovement.of(Haptics).get_settings().force_model.contact_model
