class_name TrialFlow
extends Node
## The recorded maze trials of the condition being run: the instructions card, the wait
## for the handle at the start, then the trial itself (a [TrialRecorder] fed every physics
## tick) until the goal or the time limit; its record is written, then the next trial or
## the ratings follow.

## A trial's record was written (and counted in the session).
signal trial_recorded(result: TrialResult)
## The condition's trials are all recorded: its ratings are due.
signal trials_done
## A record could not be written: the study stops.
signal failed(error: String)

## What the participant is asked to do in the maze.
const TASK_TEXT: String = (
	"Steer the submarine from the centre of the maze to the flag in the lower right. "
	+ "You will bump into walls on the way; that is part of it."
)

var _context: StudyContext = null
var _pause_after_trial_s: float = 1.0
var _session: StudySession = null
var _recorder: TrialRecorder = null
var _ticks: int = 0
var _maze: PackedScene = null


## Hands the flow what it works with (before [method show_intro]), and how many seconds
## the "Goal!" message shows before the next screen.
func setup(context: StudyContext, pause_after_trial_s: float) -> void:
	_context = context
	_session = context.session
	_pause_after_trial_s = pause_after_trial_s


## The maze under the current condition, with the card announcing the next trial (the
## stage is showing).
func show_intro() -> void:
	var stage: StudyStage = _context.stage
	stage.show_practice_controls(false)
	var condition: String = _session.current_condition()
	if not _context.load_level(_maze_scene(), condition):
		return
	var done: int = _session.trial_counts[condition]
	var total: int = _session.config.trials_per_condition()
	var heading: String = _session.method_heading()
	var trial_text: String = "Trial %d of %d" % [done + 1, total] if total > 1 else ""
	stage.set_status(heading, trial_text if not trial_text.is_empty() else "The maze")
	var body: String = TASK_TEXT
	if not trial_text.is_empty():
		body = "%s. %s" % [trial_text, TASK_TEXT]
	stage.show_card(heading, body, "Start", false)
	_session.phase = StudySession.Phase.INTRO


## The card's Start button: wait for the handle at the start.
func on_start_pressed() -> void:
	if _session.phase != StudySession.Phase.INTRO:
		return
	_context.show_centring()
	_session.phase = StudySession.Phase.CENTRING


## One physics tick of waiting for the handle at the start; the trial begins once it is
## held there.
func centre(delta: float) -> void:
	if _context.centre(delta):
		_begin_trial()


## One physics tick of the trial.
func tick(delta: float) -> void:
	_ticks += 1
	var rig: ConditionRig = _context.rig
	_context.steer(delta)
	if not _recorder.tick(rig.avatar_position(), delta):
		failed.emit(_recorder.error)
		return
	if _ticks * delta >= _session.config.number("trial_timeout_s"):
		end_trial(false)


## Ends the trial ([param completed]: the goal was reached) and writes its record.
func end_trial(completed: bool) -> void:
	if _session.phase != StudySession.Phase.TRIAL:
		return
	var time_s: float = float(_ticks) / Engine.physics_ticks_per_second
	var rig: ConditionRig = _context.rig
	rig.hold()
	if not _recorder.finish(rig.avatar_position(), time_s, completed):
		failed.emit(_recorder.error)
		return
	var result: TrialResult = _recorder.result
	_session.last_result = result
	if not _session.store.append_trial(result):
		failed.emit(_session.store.last_error)
		return
	_recorder = null
	_session.trial_counts[result.condition] += 1
	trial_recorded.emit(result)
	_session.phase = StudySession.Phase.ENDED
	_context.stage.toast("Goal!" if completed else "Time is up")
	# A timer calling back (not an await): if the study is closed meanwhile, nothing runs.
	var timer: SceneTreeTimer = get_tree().create_timer(_pause_after_trial_s)
	timer.timeout.connect(_after_trial.bind(result.condition))


# The handle is at the start: the trial begins (its telemetry file is created).
func _begin_trial() -> void:
	var condition: String = _session.current_condition()
	var index: int = _session.next_index[condition]
	_session.next_index[condition] = index + 1
	var rig: ConditionRig = _context.rig
	var config: StudyConfig = _session.config
	var level: StudyLevel = _context.stage.level
	var stiffness: float = config.condition(condition).get("stiffness", 0.0)
	_recorder = TrialRecorder.new(
		_session.store, condition, level.level_id, index, rig.map, stiffness
	)
	_recorder.decimation = config.telemetry_decimation()
	_recorder.flush_s = config.number("telemetry_flush_s")
	_recorder.contact_gap_s = config.number("contact_gap_s")
	rig.go()
	if not _recorder.begin(rig.avatar_position()):
		failed.emit(_recorder.error)
		return
	if _context.participant != null:
		_context.participant.start_level(rig, true)
	_ticks = 0
	_context.stage.hide_card()
	_context.stage.show_hand(Vector2.ZERO, false)
	_session.phase = StudySession.Phase.TRIAL


func _after_trial(condition: String) -> void:
	if _session.phase != StudySession.Phase.ENDED:
		return
	if _session.trial_counts[condition] < _session.config.trials_per_condition():
		show_intro()
	else:
		trials_done.emit()


func _maze_scene() -> PackedScene:
	if _maze == null:
		_maze = load(_session.config.maze_level()) as PackedScene
	return _maze
