class_name TrialFlow
extends Node
## The recorded maze trials of the condition being run: the instructions card, the wait
## for the handle at the start, then the trial itself (a [TrialRecorder] fed every physics
## tick) until the goal or the time limit; its record is written, then the next trial or
## the ratings follow.

## What the participant is asked to do in the maze.
const TASK_TEXT: String = (
	"Steer the submarine from the centre of the maze to the flag in the lower right. "
	+ "You will bump into walls on the way; that is part of it."
)

var _recorder: TrialRecorder = null
var _ticks: int = 0
var _maze: PackedScene = null

@onready var _runner: StudyRunner = get_parent() as StudyRunner


## The maze under the current condition, with the card announcing the next trial.
func show_intro() -> void:
	var stage: StudyStage = _runner.use_stage()
	stage.show_practice_controls(false)
	var condition: String = _runner.current_condition()
	if not _runner.load_level(_maze_scene(), condition):
		return
	var done: int = _runner.trial_counts[condition]
	var total: int = _runner.config.trials_per_condition()
	var heading: String = _runner.method_heading()
	var trial_text: String = "Trial %d of %d" % [done + 1, total] if total > 1 else ""
	stage.set_status(heading, trial_text if not trial_text.is_empty() else "The maze")
	var body: String = TASK_TEXT
	if not trial_text.is_empty():
		body = "%s. %s" % [trial_text, TASK_TEXT]
	stage.show_card(heading, body, "Start", false)
	_runner.phase = StudyRunner.Phase.INTRO


## The card's Start button: wait for the handle at the start.
func on_start_pressed() -> void:
	if _runner.phase != StudyRunner.Phase.INTRO:
		return
	_runner.show_centring()
	_runner.phase = StudyRunner.Phase.CENTRING


## The handle is at the start: the trial begins (its telemetry file is created).
func begin_trial() -> void:
	var condition: String = _runner.current_condition()
	var index: int = _runner.next_index[condition]
	_runner.next_index[condition] = index + 1
	var rig: ConditionRig = _runner.rig
	var config: StudyConfig = _runner.config
	var level: StudyLevel = _runner.get_stage().level
	var stiffness: float = config.condition(condition).get("stiffness", 0.0)
	_recorder = TrialRecorder.new(
		_runner.store, condition, level.level_id, index, rig.map, stiffness
	)
	_recorder.decimation = config.telemetry_decimation()
	_recorder.flush_s = config.number("telemetry_flush_s")
	_recorder.contact_gap_s = config.number("contact_gap_s")
	rig.go()
	if not _recorder.begin(rig.avatar_position()):
		_runner.fatal(_recorder.error)
		return
	_runner.pilot = StudyPilot.new(level.get_autopilot_path(), config.number("autopilot_speed"))
	_runner.pilot.hold_s = _runner.scripted_hold_s
	_ticks = 0
	_runner.get_stage().hide_card()
	_runner.get_stage().show_hand(Vector2.ZERO, false)
	_runner.phase = StudyRunner.Phase.TRIAL


## One physics tick of the trial.
func tick(delta: float) -> void:
	_ticks += 1
	var rig: ConditionRig = _runner.rig
	if _runner.autopilot and _runner.pilot != null:
		rig.set_hand(_runner.pilot.steer(rig, delta))
	if not _recorder.tick(rig.avatar_position(), delta):
		_runner.fatal(_recorder.error)
		return
	if _ticks * delta >= _runner.config.number("trial_timeout_s"):
		end_trial(false)


## Ends the trial ([param completed]: the goal was reached) and writes its record.
func end_trial(completed: bool) -> void:
	if _runner.phase != StudyRunner.Phase.TRIAL:
		return
	var time_s: float = float(_ticks) / Engine.physics_ticks_per_second
	var rig: ConditionRig = _runner.rig
	rig.hold()
	if not _recorder.finish(rig.avatar_position(), time_s, completed):
		_runner.fatal(_recorder.error)
		return
	var result: TrialResult = _recorder.result
	_runner.last_result = result
	if not _runner.store.append_trial(result):
		_runner.fatal(_runner.store.last_error)
		return
	_recorder = null
	_runner.count_trial(result)
	_runner.phase = StudyRunner.Phase.ENDED
	_runner.get_stage().toast("Goal!" if completed else "Time is up")
	# A timer calling back (not an await): if the study is closed meanwhile, nothing runs.
	var timer: SceneTreeTimer = get_tree().create_timer(_runner.pause_after_trial_s)
	timer.timeout.connect(_after_trial.bind(result.condition))


func _after_trial(condition: String) -> void:
	if _runner.phase != StudyRunner.Phase.ENDED:
		return
	if _runner.trial_counts[condition] < _runner.config.trials_per_condition():
		show_intro()
	else:
		_runner.answers.show_rating()


func _maze_scene() -> PackedScene:
	if _maze == null:
		_maze = load(_runner.config.maze_level()) as PackedScene
	return _maze
