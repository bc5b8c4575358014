extends TestSuite
## Data safety against a real crash: a child engine runs the study headless with a scripted
## participant (tests/drivers/study_scripted.tscn); once the first condition is rated and the
## second condition's trial is under way, the child is killed with SIGKILL ([method OS.kill]).
## Every record written before is intact and complete, the interrupted trial left only its
## telemetry, and resuming the participant in this process continues with the second
## condition, gives the new trial the next unused index, and finishes the study.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const Support := preload("res://tests/study/study_test_support.gd")
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")
## Seconds the child's scripted participant keeps still at the start of each trial, so the
## kill lands mid-trial.
const HOLD_SECONDS: float = 4.0

var _root: String = ""
var _pid: int = -1


func before_each() -> void:
	_root = Support.fresh_root("kill")


func after_each() -> void:
	if _pid > 0 and OS.is_process_running(_pid):
		OS.kill(_pid)
	_pid = -1
	Haptics.device.set_hand_target(Vector2.ZERO)
	Support.remove_tree(_root)


func test_a_session_killed_mid_trial_keeps_its_records_and_resumes() -> void:
	set_timeout(120.0)
	var folder: String = _root.path_join("PK")
	var args: PackedStringArray = [
		ProjectSettings.globalize_path("res://tools/godot"),
		"--headless",
		"--quiet",
		"--path",
		ProjectSettings.globalize_path("res://"),
		"res://tests/drivers/study_scripted.tscn",
		"--",
		"--study-root=" + ProjectSettings.globalize_path(_root),
		"--study-config=" + Support.TINY_CONFIG,
		"--scripted-participant=PK",
		"--hold=%s" % HOLD_SECONDS,
	]
	var started: int = Time.get_ticks_msec()
	_pid = OS.create_process("bash", args)
	if not assert_gt(_pid, 0, "the child engine starts"):
		return
	var ratings_path: String = folder.path_join("ratings.csv")
	var rated: bool = await wait_until(
		func() -> bool: return Support.records_of(ratings_path).size() >= 1, 60.0
	)
	if not assert_true(rated, "the child rates the first condition"):
		return
	var order: Array = Support.json_of(folder.path_join("participant.json"))["condition_order"]
	var second: String = str(order[1])
	var telemetry: String = folder.path_join("telemetry/%s_0.csv" % second)
	var in_trial: bool = await wait_until(
		func() -> bool: return Support.lines_of(telemetry).size() > 50, 30.0
	)
	if not assert_true(in_trial, "the second condition's trial is under way"):
		return
	# OS.kill sends SIGKILL and reaps the child: it is gone when this returns.
	assert_eq(OS.kill(_pid), OK, "the child is killed")
	_pid = -1
	print("    child killed after %.1f s" % ((Time.get_ticks_msec() - started) / 1000.0))
	_check_after_kill(folder, order)
	var resumed: bool = await _resume()
	if not assert_true(resumed, "the resumed session ends"):
		return
	_check_after_resume(folder, order)


func _check_after_kill(folder: String, order: Array) -> void:
	var store: StudyStore = StudyStore.new(_root, "PK")
	for file: String in ["ratings.csv", "trials.csv", "telemetry/%s_0.csv" % order[0]]:
		assert_eq(store.check_complete(file), 1, file + " ends with a complete record")
	assert_eq(Support.records_of(folder.path_join("ratings.csv")).size(), 1, "one rating")
	var trials: Array[Dictionary] = Support.records_of(folder.path_join("trials.csv"))
	assert_eq(trials.size(), 1, "one finished trial")
	assert_eq(trials[0]["condition"], order[0])
	var meta: Dictionary = Support.json_of(folder.path_join("participant.json"))
	assert_eq(meta["finished"], null, "not finished")
	assert_false(FileAccess.file_exists(folder.path_join("final.json")))
	var state: ParticipantState = ParticipantState.scan(_root, "PK")
	assert_true(state.can_resume(), "\n".join(state.report_lines()))
	assert_eq(state.next_step(1), {"step": ParticipantState.Step.TRIALS, "order_index": 1})
	assert_eq(state.next_index[str(order[1])], 1, "the interrupted trial's index is used up")


func _resume() -> bool:
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = _root
	study.config_path = Support.TINY_CONFIG
	ScriptedParticipant.new("PK", true).take_part_in(study)
	add_child_autofree(study)
	var phases: Array[StudySession.Phase] = []
	study.phase_changed.connect(func(phase: StudySession.Phase) -> void: phases.append(phase))
	var done: bool = await wait_until(
		func() -> bool: return study.phase == StudySession.Phase.DONE, 40.0
	)
	assert_false(StudySession.Phase.PRACTICE in phases, "a resumed session skips the practice")
	return done


func _check_after_resume(folder: String, order: Array) -> void:
	var ratings: Array[Dictionary] = Support.records_of(folder.path_join("ratings.csv"))
	assert_eq(ratings.size(), 3, "all three conditions rated")
	for i: int in ratings.size():
		assert_eq(ratings[i]["condition"], order[i])
	var trials: Array[Dictionary] = Support.records_of(folder.path_join("trials.csv"))
	assert_eq(trials.size(), 3)
	assert_eq(trials[1]["condition"], order[1])
	assert_eq(trials[1]["trial_index"], "1", "the resumed trial takes the next unused index")
	assert_eq(trials[1]["telemetry_file"], "telemetry/%s_1.csv" % order[1])
	assert_true(
		FileAccess.file_exists(folder.path_join("telemetry/%s_0.csv" % order[1])),
		"the interrupted trial's telemetry is kept"
	)
	var meta: Dictionary = Support.json_of(folder.path_join("participant.json"))
	assert_true(StudyFormat.is_timestamp(str(meta["finished"])))
	assert_true(FileAccess.file_exists(folder.path_join("final.json")))
	var state: ParticipantState = ParticipantState.scan(_root, "PK")
	assert_eq(state.problems, PackedStringArray())
	assert_eq(state.next_step(1)["step"], ParticipantState.Step.DONE)
